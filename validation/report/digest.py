"""The numbers of the report, as summary.json holds them, gathered for layout: reading and
checking the inputs, the per-backend digest, counts per (scene, backend, check), the orders and
floors and the statistical differences that `collide validate` computed, backends that give the
same numbers bit for bit, and jumps in conservation series. Nothing here fits, tests or parses
prose: every number is one summary.json holds.

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

from safe_files import safe_output  # the input guard: no FIFO waited on
import record_toml  # a case record as tomllib reads it, faster


class ReportInputError(Exception):
    """A malformed input file; the message names the file and what is wrong with it."""


# Keys the renderer reads, with their types (int where a float is expected is fine).
NUMBER = (int, float)
SUMMARY_KEYS = {"suite": str, "passed": bool, "counts": dict, "cases": list, "checks": list,
                "work_precision": list, "provenance": dict, "wall_seconds": NUMBER, "reference": str}
CASE_KEYS = {"id": str, "scene": str, "backend": str, "status": str, "seed": int, "dt": NUMBER,
             "duration": NUMBER, "wall_seconds": NUMBER, "drawn": bool}
CHECK_KEYS = {"subject": str, "scene": str, "backend": str, "check": str, "status": str, "detail": str}
LINE_KEYS = {"scene": str, "backend": str, "points": list, "error_kind": str}
POINT_KEYS = {"dt": NUMBER, "error": NUMBER, "seconds_per_time_unit": NUMBER}
# What `collide validate` decides and the report only lays out (docs/reading-a-report.md, "Where
# each verdict is decided"); a summary.json without them predates that and is rewritten by --resume.
DECIDED_KEYS = {"energy_jumps": list, "verdicts": dict, "verdict_thresholds": dict, "unexpected_outcomes": list,
                "outcome_order": list}
DECIDED_WHAT = {"energy_jumps": "the energy jumps explained", "verdicts": "what each backend's verdict names",
                "verdict_thresholds": "the thresholds of the verdicts",
                "unexpected_outcomes": "the stability outcomes a suite does not expect",
                "outcome_order": "the stability outcomes, most severe first"}


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
        with safe_output.open_input(path, "r", encoding="utf-8") as f:
            summary = json.load(f)
    except OSError as e:
        raise ReportInputError(f"{path}: cannot read: {e.strerror or e}") from None
    except UnicodeDecodeError as e:
        raise ReportInputError(f"{path}: not UTF-8 text ({e.reason} at byte {e.start})") from None
    except json.JSONDecodeError as e:
        raise ReportInputError(f"{path}: not valid JSON: {e.msg} at line {e.lineno}, column {e.colno}") from None
    _require(summary, SUMMARY_KEYS, path, "top level")
    if summary["cases"] and isinstance(summary["cases"][0], dict) and "drawn" not in summary["cases"][0]:
        raise ReportInputError(f"{path}: the cases do not say which the report draws ('drawn'): written by an "
                               "older collide; `collide validate SUITE --out DIR --resume` rewrites it")
    for key, kind in DECIDED_KEYS.items():
        if key not in summary:
            raise ReportInputError(f"{path}: no '{key}' ({DECIDED_WHAT[key]}): written by an older collide, which left "
                                   "it to the report; `collide validate SUITE --out DIR --resume` rewrites it")
        if not isinstance(summary[key], kind):
            raise ReportInputError(f"{path}: top level: key '{key}' should be {kind.__name__}, "
                                   f"found {type(summary[key]).__name__}")
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
    (validation/record/case_result.cpp writes it); a record without it, or whose contents no longer
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


def record_text(path, data):
    """The text of a case record after its checksum line. `collide report` has checked every
    listed record's checksum (apps/commands/report_command.cpp) before the renderer starts; it is
    not checked again here."""
    line = CHECKSUM_LINE.match(data)
    if not line:
        raise ReportInputError(f"{path}: damaged case record: no checksum line; "
                               "run `collide validate ... --resume` to run it again")
    return data[line.end():].decode("utf-8")


def load_case(directory, case):
    """A case's result table (cases/<id>.toml), or a ReportInputError naming the file."""
    if not case.get("result_file"):
        raise ReportInputError(f"{os.path.join(directory, 'summary.json')}: case {case['id']}: no result_file")
    path = os.path.join(directory, case["result_file"])
    try:
        with safe_output.open_input(path, "rb") as f:
            result = record_toml.loads(record_text(path, f.read()))  # tomllib's result, faster
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
# Backends: what summary.json says of each (precision, the stepping rule, the reference)

def facts(summary, backend):
    return (summary.get("backends") or {}).get(backend, {})


def anchor(prefix, name):
    """An HTML id for any name (scene or backend names may hold brackets, dots, '$', spaces)."""
    safe = re.sub(r"[^A-Za-z0-9_-]", lambda m: f"_{ord(m.group()):x}_", name)
    return f"{prefix}-{safe}"


def backends_in_order(summary):
    return list(OrderedDict.fromkeys(c["backend"] for c in summary["cases"]))


def scenes_in_order(summary):
    return list(OrderedDict.fromkeys(c["scene"] for c in summary["cases"]))


def check_order(summary):
    """The checks' names in the order the suite produced them (summary.json's check_order)."""
    return summary.get("check_order") or list(OrderedDict.fromkeys(c["check"] for c in summary["checks"]))


def subject_cases(summary):
    """subject (a case id or a sweep group's id) -> the cases it covers."""
    out = {}
    for c in summary["cases"]:
        out.setdefault(c["id"], []).append(c)
        if c.get("group") and c["group"] != c["id"]:
            out.setdefault(c["group"], []).append(c)
    return out


# ---------------------------------------------------------------------------------------------
# Margins: how close a check came to its tolerance (1 = at the tolerance, above 1 fails)

def margin(check):
    """summary.json's margin: measured ÷ tolerance (tolerance ÷ measured for a lower bound);
    None where there is no number to compare (run, stability, left out)."""
    m = check.get("margin")
    return m if isinstance(m, NUMBER) and not isinstance(m, bool) else None


# ---------------------------------------------------------------------------------------------
# Counts that mean something: one per (scene, backend, check)

def cannot_run(check, cases):
    """Whether a left-out check was left out because its backend cannot run the scene: every
    case it covers was left out (`cases`: subject_cases(summary))."""
    covered = cases.get(check["subject"], [])
    return bool(covered) and all(x["status"] == "left_out" for x in covered)


def combinations(summary):
    """{(scene, backend, check): {'pass', 'fail', 'left_out', 'cannot_run'}} counts of checks;
    a left-out check whose case was left out (the backend cannot run the scene) counts as
    cannot_run, not as left_out (the check does not apply)."""
    cases = subject_cases(summary)
    out = OrderedDict()
    for c in summary["checks"]:
        key = (c["scene"], c["backend"], c["check"])
        counts = out.setdefault(key, {"pass": 0, "fail": 0, "left_out": 0, "cannot_run": 0})
        if c["status"] == "left_out":
            counts["cannot_run" if cannot_run(c, cases) else "left_out"] += 1
        elif c["status"] in counts:
            counts[c["status"]] += 1
    return out


def combination_status(counts):
    if counts["fail"]:
        return "fail"
    if counts["pass"]:
        return "pass"
    return "cannot_run" if counts["cannot_run"] else "left_out"


def combination_totals(by_combination):
    """How many (scene, backend, check) combinations pass, fail, do not apply and cannot run
    (`by_combination`: what combinations(summary) returns)."""
    totals = {"pass": 0, "fail": 0, "left_out": 0, "cannot_run": 0}
    for counts in by_combination.values():
        totals[combination_status(counts)] += 1
    return totals


def digest(summary, exclude_quantised=False):
    """One row per backend: cases that ran and that it cannot run; (scene, check) combinations
    passed / failed / not applicable / cannot run, and the checks behind them; the worst margin
    of every check with a margin, quantised counts included (a count of k / N can sit at its limit
    without measuring how close the backend came: how many do is counted beside), with how many
    checks tie at it; orders per observable class and the floors."""
    rows = OrderedDict()
    for b in backends_in_order(summary):
        rows[b] = {"backend": b, "cases": 0, "cases_cannot_run": 0, "pass": 0, "fail": 0, "left_out": 0,
                   "combinations": {"pass": 0, "fail": 0, "left_out": 0, "cannot_run": 0},
                   "worst": None, "ties": 0, "quantised_at_limit": 0, "orders": OrderedDict(), "floors": []}
    for c in summary["cases"]:
        rows[c["backend"]]["cases_cannot_run" if c["status"] == "left_out" else "cases"] += 1
    for c in summary["checks"]:
        row = rows[c["backend"]]
        if c["status"] in ("pass", "fail", "left_out"):
            row[c["status"]] += 1
        m = margin(c)
        if m is not None and c.get("quantised") and m == 1:
            row["quantised_at_limit"] += 1
        if m is None or (exclude_quantised and c.get("quantised")):
            continue
        if row["worst"] is None or m > row["worst"][0]:
            row["worst"], row["ties"] = (m, c["subject"], c["check"]), 1
        elif m == row["worst"][0]:
            row["ties"] += 1
    for (scene, b, check), counts in combinations(summary).items():
        rows[b]["combinations"][combination_status(counts)] += 1
    for fit in orders(summary):
        row = rows.get(fit["backend"])
        if row is None:
            continue
        row["orders"].setdefault(fit["class"], []).append(fit)
        if fit["floor"] or fit["bending"]:
            row["floors"].append(fit)
    return list(rows.values())


# ---------------------------------------------------------------------------------------------
# Statistical differences: the numbers validate wrote for each sweep point

OBSERVABLES = ("pressure", "collision_rate")

# The statistic a relative error kind measures (reference_comparison.cpp, the error kinds): Z,
# or for the scenes compared seed by seed (summary.json points[].paired) a cooling gas's Haff
# cooling time τ or the collision rate ν where Z is not measured.
STATISTICS = {"Z_ref": "Z", "tau_ref": "τ", "nu_ref": "ν"}


def statistic_of(error_kind):
    """'Z', 'τ' or 'ν' for a relative statistical error kind, None for a trajectory error."""
    return next((s for key, s in STATISTICS.items() if key in error_kind), None)


def statistical_points(summary, scene, observable):
    """Per backend, the work-precision points of a statistical observable: dt, run time per time
    unit, relative difference with its SE, resolution, 95 % upper limit and the smallest bias
    its check detects (summary.json: work_precision[].points[].pressure / .collision_rate)."""
    lines = OrderedDict()
    for line in summary["work_precision"]:
        if line["scene"] != scene:
            continue
        for p in line["points"]:
            d = p.get(observable)
            if not d:
                continue
            predicted = d.get("predicted")
            lines.setdefault(line["backend"], []).append(
                {"dt": p["dt"], "substeps": p.get("substeps", 1) or 1, "seconds": p["seconds_per_time_unit"],
                 "error": abs(d["relative"]), "relative": d["relative"], "se": d["relative_standard_error"],
                 "sigmas": d["sigmas"], "resolved": d["resolved"], "upper": d["upper_limit_95"],
                 "detectable": d["detectable"], "replicates": d["replicates"],
                 "predicted": predicted / d["reference"] if isinstance(predicted, NUMBER) else None})
    return lines


# ---------------------------------------------------------------------------------------------
# Convergence orders: validate fits them (validation/compare/convergence_order.h); here they are named

def floor_kind(summary, backend):
    """What sets an error floor: rounding for a float stepping rule, the solver's own tolerances
    for a float solver that is not a stepping rule (Box2D), otherwise the method itself."""
    f = facts(summary, backend)
    if f.get("float") and not f.get("stepping_rule"):
        return "solver floor"
    return "float floor" if f.get("float") else "error floor"


def orders(summary):
    """One per work-precision line: {'scene', 'backend', 'class' ('trajectory', 'Z', 'τ' or 'ν'), 'order',
    'order_se', 'used', 'points', 'h_coarse', 'h_fine', 'floor', 'bending', 'note', 'kind'}."""
    out = []
    for line in summary["work_precision"]:
        r = line.get("order_range") or {}
        out.append({"scene": line["scene"], "backend": line["backend"],
                    "class": statistic_of(line["error_kind"]) or "trajectory",
                    "order": line.get("order"), "order_se": line.get("order_standard_error"),
                    "used": r.get("used", 0), "points": r.get("points", 0), "h_coarse": r.get("h_coarse"),
                    "h_fine": r.get("h_fine"), "floor": r.get("floor"), "bending": bool(r.get("bending")),
                    "note": line.get("order_note", ""), "kind": floor_kind(summary, line["backend"])})
    return out


FLOOR_CAUSE = {"float floor": "; rounding accumulates below it",
               "solver floor": "; Box2D's tolerances (linear slop, restitution threshold), not dt, set it"}


def describe_floor(fit):
    f = fit["floor"]
    if not f:
        return (f"{fit['kind']} suspected: the local order falls along the range" + FLOOR_CAUSE.get(fit["kind"], "")
                if fit["bending"] else "")
    return (f"{fit['kind']} from h ≈ {f['h']:g} at error ≈ {f['error']:.2g} "
            f"({f['finest_error']:.2g} at h = {f['finest_h']:g})" + FLOOR_CAUSE.get(fit["kind"], ""))


def describe_order(fit):
    """One number with its range: '1.06 ± 0.05 on h 0.004–0.00025 (5 points)'."""
    if fit["order"] is None:
        return "n/a: " + fit["note"]
    se = f" ± {fit['order_se']:.2f}" if fit["order_se"] is not None else ""
    text = f"{fit['order']:.2f}{se} on h {fit['h_coarse']:g}–{fit['h_fine']:g} ({fit['used']} points)"
    if fit["floor"] or fit["bending"]:
        text += ", floor-contaminated" if fit["bending"] else f", {fit['floor']['excluded']} below the floor left out"
    return text


def order_summary(fits):
    """'1.06 ± 0.05' or '0.97–1.10 (3 scenes)' for a list of fits of one class; a '*' marks a
    range that includes a floor-contaminated order."""
    known = [f for f in fits if f["order"] is not None]
    if not known:
        return "n/a"
    mark = "*" if any(f["bending"] for f in known) else ""
    if len(known) == 1:
        f = known[0]
        return f"{f['order']:.2f}" + (f" ± {f['order_se']:.2f}" if f["order_se"] is not None else "") + mark
    values = [f["order"] for f in known]
    return f"{min(values):.2f}–{max(values):.2f} ({len(known)} scenes){mark}"


# ---------------------------------------------------------------------------------------------
# Backends that give the same numbers bit for bit

def _point_key(case):
    return (case["scene"], case["dt"], case.get("substeps", 1), json.dumps(case.get("parameters", {}), sort_keys=True))


def identical_backends(summary):
    """[(a, b, n)] where backend b gave exactly the numbers of backend a (n compared numbers:
    every check value and every work-precision point of every scene both ran). Checks are
    matched by scene, sweep point, seed (for a case's checks) and check name."""
    cases = subject_cases(summary)
    values = OrderedDict()
    for c in summary["checks"]:
        covered = cases.get(c["subject"])
        if c["status"] == "left_out" or not covered:
            continue
        seed = covered[0]["seed"] if len(covered) == 1 else None
        key = (_point_key(covered[0]), seed, c["check"])
        values.setdefault(c["backend"], {})[key] = (c.get("value"), c["status"])
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


