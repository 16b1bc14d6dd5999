"""The numbers of the report, apart from how they are drawn: reading and checking the inputs,
the per-backend digest, margins, the convergence-order fit on the asymptotic range (with the
error floor named), whether a statistical difference is resolved, backends that give the same
numbers bit for bit, and jumps in conservation series.

Every function here takes plain data (the parsed summary.json, a case's result table) and
returns plain data, so tests can feed it synthetic input (tests/report/).
"""
import json
import math
import os
import re
import tomllib
import zlib
from collections import OrderedDict


class ReportInputError(Exception):
    """A malformed input file; the message names the file and what is wrong with it."""


# Keys the renderer reads, with their types (int where a float is expected is fine).
NUMBER = (int, float)
SUMMARY_KEYS = {"suite": str, "passed": bool, "counts": dict, "cases": list, "checks": list,
                "work_precision": list, "provenance": dict, "wall_seconds": NUMBER, "reference": str}
CASE_KEYS = {"id": str, "scene": str, "backend": str, "status": str, "seed": int, "dt": NUMBER,
             "duration": NUMBER, "wall_seconds": NUMBER}
CHECK_KEYS = {"subject": str, "check": str, "status": str, "detail": str}
LINE_KEYS = {"scene": str, "backend": str, "points": list, "error_kind": str}
POINT_KEYS = {"dt": NUMBER, "error": NUMBER, "seconds_per_time_unit": NUMBER}


def _require(record, keys, path, where):
    if not isinstance(record, dict):
        raise ReportInputError(f"{path}: {where}: expected an object, found {type(record).__name__}")
    for key, kind in keys.items():
        if key not in record:
            raise ReportInputError(f"{path}: {where}: missing key '{key}'")
        value = record[key]
        if value is None and kind is NUMBER:
            continue  # JSON null for a number the writer could not compute (NaN)
        if not isinstance(value, kind) or (kind is NUMBER and isinstance(value, bool)):
            expected = "a number" if kind is NUMBER else kind.__name__
            raise ReportInputError(f"{path}: {where}: key '{key}' should be {expected}, "
                                   f"found {type(value).__name__} {value!r:.40}")


def load_summary(directory):
    """summary.json of a validation run, checked for every key the report reads."""
    path = os.path.join(directory, "summary.json")
    try:
        with open(path, encoding="utf-8") as f:
            summary = json.load(f)
    except OSError as e:
        raise ReportInputError(f"{path}: cannot read: {e.strerror or e}") from None
    except UnicodeDecodeError as e:
        raise ReportInputError(f"{path}: not UTF-8 text ({e.reason} at byte {e.start})") from None
    except json.JSONDecodeError as e:
        raise ReportInputError(f"{path}: not valid JSON: {e.msg} at line {e.lineno}, column {e.colno}") from None
    _require(summary, SUMMARY_KEYS, path, "top level")
    for i, case in enumerate(summary["cases"]):
        _require(case, CASE_KEYS, path, f"cases[{i}]")
    for i, check in enumerate(summary["checks"]):
        _require(check, CHECK_KEYS, path, f"checks[{i}]")
    for i, line in enumerate(summary["work_precision"]):
        _require(line, LINE_KEYS, path, f"work_precision[{i}]")
        for j, point in enumerate(line["points"]):
            _require(point, POINT_KEYS, path, f"work_precision[{i}].points[{j}]")
    for key in ("pass", "fail", "left_out"):
        if not isinstance(summary["counts"].get(key), int):
            raise ReportInputError(f"{path}: counts: missing or non-integer '{key}'")
    return summary


CHECKSUM_LINE = re.compile(rb'checksum = "crc32:([0-9a-f]{8})"\n')


def verified_record_text(path, data):
    """The text of a case record after its first line, which holds the CRC-32 of the rest
    (validation/case_result.cpp writes it); a record without it, or whose contents no longer
    match it, is damaged and is not drawn."""
    line = CHECKSUM_LINE.match(data)
    if not line:
        raise ReportInputError(f"{path}: damaged case record: no checksum line (cut short, edited, or written "
                               "by an older collide); run `collide validate ... --resume` to run it again")
    body = data[line.end():]
    if int(line.group(1), 16) != zlib.crc32(body):
        raise ReportInputError(f"{path}: damaged case record: its checksum does not match its contents; "
                               "run `collide validate ... --resume` to run it again")
    return body.decode("utf-8")


def load_case(directory, case):
    """A case's result table (cases/<id>.toml), or a ReportInputError naming the file."""
    if not case.get("result_file"):
        raise ReportInputError(f"{os.path.join(directory, 'summary.json')}: case {case['id']}: no result_file")
    path = os.path.join(directory, case["result_file"])
    try:
        with open(path, "rb") as f:
            result = tomllib.loads(verified_record_text(path, f.read()))
    except OSError as e:
        raise ReportInputError(f"{path}: cannot read: {e.strerror or e}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise ReportInputError(f"{path}: not a valid case result (TOML): {e}") from None
    missing = [k for k in ("series", "initial", "final", "spec") if not isinstance(result.get(k), dict)]
    if missing:
        raise ReportInputError(f"{path}: not a complete case result: no table {', '.join(missing)} "
                               "(a truncated file?)")
    for k in ("initial", "final"):
        snap = result[k]
        if not all(isinstance(snap.get(v), list) for v in ("x", "y", "vx", "vy", "radius")):
            raise ReportInputError(f"{path}: table '{k}' lacks one of x, y, vx, vy, radius (a truncated file?)")
    series = result.get("series")
    if not isinstance(series, dict) or not all(isinstance(series.get(k), list) for k in
                                               ("time", "kinetic_energy", "total_energy", "momentum_x", "momentum_y")):
        raise ReportInputError(f"{path}: not a complete case result: the table 'series' with time, kinetic_energy, "
                               "total_energy, momentum_x and momentum_y is missing or incomplete")
    lengths = {len(series[k]) for k in ("time", "kinetic_energy", "total_energy", "momentum_x", "momentum_y")}
    if len(lengths) != 1:
        raise ReportInputError(f"{path}: series of unequal length {sorted(lengths)} (a truncated file?)")
    return result


# ---------------------------------------------------------------------------------------------
# Backends

FLOAT_BACKENDS = {"cpu", "opencl", "box2d"}


def base_backend(name):
    """'box2d[shipped]' -> 'box2d': a variant shares its base backend's precision and colour."""
    return name.split("[", 1)[0]


def is_float(backend):
    return base_backend(backend) in FLOAT_BACKENDS


def anchor(prefix, name):
    """An HTML id for any name (scene or backend names may hold brackets, dots, '$', spaces)."""
    safe = re.sub(r"[^A-Za-z0-9_-]", lambda m: f"_{ord(m.group()):x}_", name)
    return f"{prefix}-{safe}"


def backends_in_order(summary):
    return list(OrderedDict.fromkeys(c["backend"] for c in summary["cases"]))


def scenes_in_order(summary):
    return list(OrderedDict.fromkeys(c["scene"] for c in summary["cases"]))


# ---------------------------------------------------------------------------------------------
# Margins: how close a check came to its tolerance (1 = at the tolerance, above 1 fails)

def margin(check):
    """measured ÷ tolerance for an upper bound, tolerance ÷ measured for a lower bound (the
    KS p-value); None where there is no number to compare (run, stability, left out)."""
    if check["status"] not in ("pass", "fail") or check["check"] in ("run", "stability"):
        return None
    value, tolerance = check.get("value"), check.get("tolerance")
    if not isinstance(value, NUMBER) or not isinstance(tolerance, NUMBER) or isinstance(value, bool):
        return None
    if check.get("comparison") == ">=":
        if tolerance <= 0:
            return None
        return math.inf if value <= 0 else tolerance / value
    if tolerance <= 0:
        return None
    return abs(value) / tolerance


def digest(summary, orders=None, floors=None):
    """One row per backend: cases, checks passed / failed / left out, worst margin (with its
    case and check), orders per observable class and the error floor. The sums over backends
    equal summary['counts'] (a check belongs to the backend of its case or group)."""
    rows = OrderedDict()
    for b in backends_in_order(summary):
        rows[b] = {"backend": b, "cases": 0, "pass": 0, "fail": 0, "left_out": 0, "worst": None,
                   "orders": OrderedDict(), "floors": []}
    for c in summary["cases"]:
        rows[c["backend"]]["cases"] += 1
    for c in summary["checks"]:
        b = c.get("backend") or subject_backend(c["subject"], rows)
        row = rows.setdefault(b, {"backend": b, "cases": 0, "pass": 0, "fail": 0, "left_out": 0, "worst": None,
                                  "orders": OrderedDict(), "floors": []})
        if c["status"] in ("pass", "fail", "left_out"):
            row[c["status"]] += 1
        m = margin(c)
        if m is not None and (row["worst"] is None or m > row["worst"][0]):
            row["worst"] = (m, c["subject"], c["check"])
    for fit in (orders or []):
        row = rows.get(fit["backend"])
        if row is None:
            continue
        row["orders"].setdefault(fit["class"], []).append(fit)
        if fit["floor"]:
            row["floors"].append(fit)
    return list(rows.values())


def subject_backend(subject, rows):
    parts = subject.split("__")
    for part in parts[1:2]:
        if part in rows:
            return part
    return parts[1] if len(parts) > 1 else "?"


# ---------------------------------------------------------------------------------------------
# Statistical differences: resolved or not

DIFFERENCE = re.compile(r"([-+0-9.eE]+|nan|inf) \+- ([-+0-9.eE]+|nan|inf) vs reference "
                        r"([-+0-9.eE]+|nan|inf) \+- ([-+0-9.eE]+|nan|inf)")
RESOLVED_SE = 2.0  # a difference below this many standard errors is "not resolved"


def statistical_difference(check):
    """From a pressure or collision_rate check: relative difference |mu - mu_ref| / mu_ref, its
    standard error sqrt(se^2 + se_ref^2) / mu_ref, and whether it is resolved (>= 2 SE).
    None when the check has no such numbers (left out, or an unexpected detail)."""
    if check["status"] not in ("pass", "fail"):
        return None
    m = DIFFERENCE.search(check["detail"])
    if not m:
        return None
    mean, se, ref, ref_se = (float(x) for x in m.groups())
    if not all(math.isfinite(x) for x in (mean, se, ref, ref_se)) or ref == 0:
        return None
    combined = math.hypot(se, ref_se)
    diff = abs(mean - ref)
    return {"error": diff / abs(ref), "se": combined / abs(ref), "sigmas": diff / combined if combined > 0 else math.inf,
            "resolved": combined == 0 and diff > 0 or (combined > 0 and diff >= RESOLVED_SE * combined)}


def statistical_points(summary, scene, check_name):
    """Per backend, the work-precision points of a statistical observable: dt, run time per
    time unit, relative difference with its SE and resolution, from the group's check."""
    checks = {c["subject"]: c for c in summary["checks"] if c["check"] == check_name and c.get("scene", scene) == scene}
    lines = OrderedDict()
    for line in summary["work_precision"]:
        if line["scene"] != scene:
            continue
        for p in line["points"]:
            c = checks.get(p.get("group", ""))
            d = statistical_difference(c) if c else None
            if d is None:
                continue
            lines.setdefault(line["backend"], []).append(
                {"dt": p["dt"], "substeps": p.get("substeps", 1) or 1, "seconds": p["seconds_per_time_unit"], **d})
    return lines


def reference_cost(summary, scene):
    """Mean wall seconds per simulated time unit of the reference's cases of a scene."""
    costs = [c["wall_seconds"] / c["duration"] for c in summary["cases"]
             if c["scene"] == scene and c["backend"] == summary["reference"] and c["status"] == "completed"
             and c["duration"] and c["wall_seconds"] is not None]
    return sum(costs) / len(costs) if costs else None


# ---------------------------------------------------------------------------------------------
# Convergence order on the asymptotic range, with the error floor named

FLAT_SLOPE = 0.3  # below this local order the error has stopped falling with dt
FLOOR_SE = 2.0    # a statistical point lies on a floor only if it sits this many SE above the descent


def floor_kind(backend):
    """What sets an error floor: rounding for the float rules, Box2D's own tolerances (linear slop,
    restitution threshold, its iterations) for Box2D, otherwise the method itself."""
    base = base_backend(backend)
    if base == "box2d":
        return "solver floor"
    return "float floor" if is_float(backend) else "error floor"


def _flat(e_prev, e, h_prev, h, se_prev=None, se=None):
    """Whether the error stopped falling from one point to the next, finer one. With standard
    errors (statistical observables), only when the finer point lies significantly (FLOOR_SE
    combined SE) above the order-FLAT_SLOPE descent from the coarser one: a noisy point that the
    descent still explains is no floor."""
    if h_prev == h:
        return True
    slope = math.log(e_prev / e) / math.log(h_prev / h)
    if slope >= FLAT_SLOPE:
        return False
    if se is None or se_prev is None:
        return True
    descent = e_prev * (h / h_prev) ** FLAT_SLOPE
    return e - descent > FLOOR_SE * math.hypot(se, se_prev * (h / h_prev) ** FLAT_SLOPE)


def _log_slope(h, e, se=None):
    """Least-squares slope of log e against log h, and its standard error: weighted by the points'
    log-space error bars se/e where they have them (sigma of the slope from those bars), otherwise
    the unweighted fit's residual-based standard error (None with fewer than 3 points)."""
    x = [math.log(v) for v in h]
    y = [math.log(v) for v in e]
    w = [1.0 / (s / v) ** 2 if s else 1.0 for s, v in zip(se, e)] if se and all(se) else [1.0] * len(x)
    sw = sum(w)
    mx = sum(wi * a for wi, a in zip(w, x)) / sw
    my = sum(wi * b for wi, b in zip(w, y)) / sw
    sxx = sum(wi * (a - mx) ** 2 for wi, a in zip(w, x))
    slope = sum(wi * (a - mx) * (b - my) for wi, a, b in zip(w, x, y)) / sxx
    if se and all(se):
        return slope, math.sqrt(1.0 / sxx)
    if len(x) < 3:
        return slope, None
    resid = sum((b - my - slope * (a - mx)) ** 2 for a, b in zip(x, y)) / (len(x) - 2)
    return slope, math.sqrt(resid / sxx)


def fit_order(points, backend="", min_points=3):
    """points: [{'dt', 'substeps'?, 'error', 'se'?}] (any order). Sorted from coarse to fine, the
    asymptotic range ends where the error stops falling: the first point after which every
    local slope log(e_i-1 / e_i) / log(h_i-1 / h_i) is below FLAT_SLOPE (the error flattens or
    rises as dt shrinks; for points with standard errors, only where that is significant, see
    _flat). The order is the least-squares slope of log error against log h on that range
    (weighted by the error bars where there are some), with its standard error; the points below
    it are the floor. Returns {'order', 'order_se', 'used', 'floor': {'dt', 'error', 'excluded',
    'kind'} or None, 'note'}."""
    pts = sorted((p for p in points if p.get("error") and p["error"] > 0 and math.isfinite(p["error"])),
                 key=lambda p: -p["dt"] / max(1, p.get("substeps", 1) or 1))
    h = [p["dt"] / max(1, p.get("substeps", 1) or 1) for p in pts]
    e = [p["error"] for p in pts]
    se = [p.get("se") for p in pts]
    n = len(pts)
    end = n  # asymptotic range: pts[0:end]
    if n >= 2:
        flat = [_flat(e[i - 1], e[i], h[i - 1], h[i], se[i - 1], se[i]) for i in range(1, n)]
        # flat[i - 1] is about the step into point i; find the smallest k with all later steps flat
        for k in range(0, n - 1):
            if all(flat[k:]):
                end = k + 1
                break
    floor = None
    if end < n:
        floor = {"dt": pts[end - 1]["dt"], "error": e[end - 1], "excluded": n - end,
                 "finest": {"dt": pts[-1]["dt"], "error": e[-1]}, "kind": floor_kind(backend)}
    used = pts[:end]
    result = {"order": None, "order_se": None, "used": len(used), "points": n, "floor": floor, "note": ""}
    if len(used) >= min_points and len({h[i] for i in range(end)}) >= min_points:
        result["order"], result["order_se"] = _log_slope(h[:end], e[:end], se[:end])
        result["statistical"] = all(se[:end])  # order_se from the points' error bars
    elif len(used) == 2 and h[0] != h[1]:
        result["two_point"] = math.log(e[0] / e[1]) / math.log(h[0] / h[1])
        result["note"] = f"2 points above the floor (slope {result['two_point']:.2f} between them)"
    else:
        result["note"] = f"{len(used)} usable point(s); an order needs {min_points}"
    return result


FLOOR_CAUSE = {"float floor": "; rounding accumulates below it",
               "solver floor": "; Box2D's tolerances (linear slop, restitution threshold), not dt, set it"}


def describe_floor(floor):
    return (f"{floor['kind']} from dt ≈ {floor['dt']:g} at error ≈ {floor['error']:.2g} "
            f"({floor['finest']['error']:.2g} at dt = {floor['finest']['dt']:g})"
            + FLOOR_CAUSE.get(floor["kind"], ""))


def describe_order(fit):
    if fit["order"] is not None:
        text = f"{fit['order']:.2f}"
        if fit.get("statistical") and fit.get("order_se") is not None:
            text += f" ± {fit['order_se']:.2f}"  # a statistical order carries its error bar
        if fit["floor"]:
            text += f" (on {fit['used']} of {fit['points']} points)"
        return text
    return "n/a: " + fit["note"]


def all_orders(summary):
    """One fit per (scene, backend, observable class): 'trajectory' (mean error over phase
    replicates) and 'Z' (pressure, resolved points only)."""
    fits = []
    for line in summary["work_precision"]:
        trajectory = line["error_kind"].startswith("trajectory")
        if trajectory:
            points = [{"dt": p["dt"], "substeps": p.get("substeps", 1), "error": p["error"]} for p in line["points"]
                      if p["error"] is not None]
            fit = fit_order(points, line["backend"])
            fit["class"] = "trajectory"
        else:
            stats = statistical_points(summary, line["scene"], "pressure").get(line["backend"], [])
            resolved = [p for p in stats if p["resolved"]]
            fit = fit_order(resolved, line["backend"])
            fit["class"] = "Z"
            fit["resolved"] = len(resolved)
            fit["measured"] = len(stats)
            if fit["order"] is None:
                fit["note"] = f"{len(resolved)} of {len(stats)} points resolved (≥ {RESOLVED_SE:g} SE); " + fit["note"]
        fit.update(scene=line["scene"], backend=line["backend"])
        fits.append(fit)
    return fits


def order_summary(fits):
    """'1.06' or '0.97–1.10 (3 scenes)' for a list of fits of one class."""
    orders = [f["order"] for f in fits if f["order"] is not None]
    if not orders:
        return "n/a"
    if len(orders) == 1:
        return describe_order(next(f for f in fits if f["order"] is not None)).split(" (on")[0]
    return f"{min(orders):.2f}–{max(orders):.2f} ({len(orders)} scenes)"


# ---------------------------------------------------------------------------------------------
# Backends that give the same numbers bit for bit

def identical_backends(summary):
    """[(a, b, n)] where backend b gave exactly the numbers of backend a (n compared numbers:
    every check value and every work-precision point of every scene both ran)."""
    values = OrderedDict()
    for c in summary["checks"]:
        b = c.get("backend")
        if not b or c["status"] == "left_out":
            continue
        key = (c["subject"].replace(f"__{b}__", "__*__", 1).removesuffix(f"__{b}"), c["check"])
        values.setdefault(b, {})[key] = (c.get("value"), c["status"])
    for line in summary["work_precision"]:
        for p in line["points"]:
            values.setdefault(line["backend"], {})[(line["scene"], p["dt"], p.get("substeps", 1), "wp")] = \
                (p["error"], p.get("error_standard_error"))
    out = []
    names = list(values)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if any(b == y for _, y, _ in out):
                continue
            va, vb = values[a], values[b]
            if va and va.keys() == vb.keys() and all(va[k] == vb[k] for k in va):
                out.append((a, b, len(va)))
    return out


# ---------------------------------------------------------------------------------------------
# Jumps in conservation series

def energy_jumps(result, threshold=1e-3, factor=10.0):
    """The largest change of energy over one output interval, divided by max K, when it is
    above `threshold` and `factor` times the median change: {'t0', 't1', 'change', 'median',
    'scale' (max K)} or None."""
    s = result["series"]
    t, kinetic, total = s["time"], s["kinetic_energy"], s["total_energy"]
    if len(t) < 3:
        return None
    energy = total if abs(total[0] - kinetic[0]) > 0 else kinetic
    scale = max(max(abs(k) for k in kinetic), 1e-300)
    steps = [(energy[i] - energy[i - 1]) / scale for i in range(1, len(t))]
    if not all(math.isfinite(x) for x in steps):
        return None
    i = max(range(len(steps)), key=lambda j: abs(steps[j]))
    median = sorted(abs(x) for x in steps)[len(steps) // 2]
    if abs(steps[i]) < threshold or abs(steps[i]) < factor * median:
        return None
    return {"t0": t[i], "t1": t[i + 1], "change": steps[i], "median": median, "scale": scale}
