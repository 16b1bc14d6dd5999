"""The first screen's answer to "which backend can I trust, for what, at what cost": one verdict
per backend, laid out from summary.json's numbers (its checks, its costs per scene) and what
`collide validate` decided each verdict names (summary.json's `verdicts`: a loose tolerance, a
large energy drift, a resolved pressure offset, against the suite's `[verdicts]` thresholds;
validation/summary/verdict_facts.h). Nothing is measured or judged here.
"""
from collections import OrderedDict

import digest


def _times(x):
    return f"{x:.2g}×" if x < 10 else f"{x:.0f}×"  # layout: two digits below 10×


def cost_text(summary, backend, cheapest=None):
    """'1.2–600× (5 scenes); cheapest on 5 of 5' from summary.json's costs (the cheapest sweep
    group of each scene, wall seconds per simulated time unit, over the reference's);
    `cheapest`: cheapest_by_scene(summary), computed here when not given."""
    costs = [c for c in summary.get("costs", []) if c["backend"] == backend]
    if not costs:
        return "not measured (no case ran)"
    if cheapest is None:
        cheapest = cheapest_by_scene(summary)
    wins = sum(1 for c in costs if cheapest.get(c["scene"]) == backend)
    scenes = len({c["scene"] for c in costs})
    tail = f"; the cheapest on {wins} of {scenes} scene{'s' if scenes > 1 else ''}" if wins else ""
    if backend == summary["reference"]:
        fastest = min(c["seconds_per_time_unit"] for c in costs)
        slowest = max(c["seconds_per_time_unit"] for c in costs)
        return f"1× ({fastest:.2g}–{slowest:.2g} s per time unit){tail}"
    ratios = [c["relative_to_reference"] for c in costs if c.get("relative_to_reference")]
    if not ratios:
        return f"{min(c['seconds_per_time_unit'] for c in costs):.2g} s per time unit (no reference cost){tail}"
    low, high = min(ratios), max(ratios)
    span = _times(low) if len(ratios) == 1 or _times(low) == _times(high) else f"{_times(low)}–{_times(high)}"
    return f"{span} ({len(ratios)} scene{'s' if len(ratios) > 1 else ''}){tail}"


def cost_at_accuracy_text(summary, backend):
    """Per scene, the cost at the stated accuracy over the reference's cost there
    ('periodic_gas 3.1× (2.5–4.0×)', 'box_gas_1000 not reached'), from summary.json's
    verdicts.B.accuracy.cost_at_accuracy (accuracy_verdicts.h: interpolated along the backend's
    work-precision line; the range is the two points that bracket the accuracy). The reference
    is at its own cost on every scene: its error is zero by construction."""
    accuracy = (summary["verdicts"].get(backend) or {}).get("accuracy") or {}
    reference = {c["scene"]: c["seconds_per_time_unit"] for c in summary.get("costs", [])
                 if c["backend"] == summary["reference"]}
    out = []
    for c in accuracy.get("cost_at_accuracy", []):
        if not c["reached"]:
            out.append(f"{c['scene']}: not reached")
            continue
        base = reference.get(c["scene"])
        if not base:
            out.append(f"{c['scene']}: {c['seconds_per_time_unit']:.2g} s per time unit")
            continue
        bound = "≤ " if c["at_most"] else ""
        spread = "" if c["at_most"] else f" ({_times(c['low'] / base)}–{_times(c['high'] / base)})"
        out.append(f"{c['scene']}: {bound}{_times(c['seconds_per_time_unit'] / base)}{spread}")
    return out


def cheapest_by_scene(summary):
    best = {}
    for c in summary.get("costs", []):
        if c["scene"] not in best or c["seconds_per_time_unit"] < best[c["scene"]][1]:
            best[c["scene"]] = (c["backend"], c["seconds_per_time_unit"])
    return {scene: b for scene, (b, _) in best.items()}


def scene_status(summary, backend, by_combination=None):
    """scene -> 'pass', 'fail' or 'cannot_run' from the (scene, backend, check) combinations
    (`by_combination`: digest.combinations(summary), computed here when not given)."""
    if by_combination is None:
        by_combination = digest.combinations(summary)
    out = OrderedDict()
    for (scene, b, _), counts in by_combination.items():
        if b != backend:
            continue
        status = digest.combination_status(counts)
        now = out.get(scene)
        if status == "fail" or now is None or (now in ("left_out", "cannot_run") and status == "pass"):
            out[scene] = status
    return out


def use_for_text(accuracy):
    """'dt ≤ 0.002: head_on_equal, head_on_mass_ratio_10', one entry per largest dt (and statistic:
    'dt ≤ 0.002 (τ, paired over 8 seeds): inelastic_gas' where the scene is judged by a statistic
    other than Z or the trajectory), the scenes in summary.json's order, from summary.json's
    verdicts.B.accuracy.use_for (accuracy_verdicts.h: decided there at 95 % confidence against
    the accuracy the digest's header states). Scenes that share an entry share it: the row stays
    a few lines high."""
    by_entry = OrderedDict()
    for u in accuracy.get("use_for", []):
        s = digest.statistic_of(u["error_kind"])
        by = f" ({s}, paired over {u['replicates']} seeds)" if s and s != "Z" else ""
        by_entry.setdefault(f"dt ≤ {u['dt']:.2g}{by}", []).append(u["scene"])
    return [f"{entry}: {', '.join(scenes)}" for entry, scenes in by_entry.items()]


def not_for_text(accuracy):
    """One entry per scene where some dt is not shown within the stated accuracy, naming the
    measured error (the signed relative bias of Z, of a cooling gas's τ or of ν) with its SE, z
    and replicates: 'periodic_gas dt 0.0048–0.006: Z +1.15 % ± 0.217 % (z = +5.30, 64 rep.),
    beyond'; 'stones_and_gas dt 0.004: ν +2.2 % ± 0.5 % (z = +4.40, 6 seeds paired), beyond';
    'undecided' where the error bar is too wide to tell (more replicates could clear it)."""
    out = []
    for n in accuracy.get("not_for", []):
        span = f"{n['dt']:.2g}" if n["dt_min"] == n["dt_max"] else f"{n['dt_min']:.2g}–{n['dt_max']:.2g}"
        statistic = digest.statistic_of(n["error_kind"])
        if statistic:
            z = f"z = {n['error'] / n['standard_error']:+.2f}, " if n["standard_error"] else ""
            count = f"{n['replicates']} rep." if statistic == "Z" else f"{n['replicates']} seeds paired"
            value = (f"{statistic} {100 * n['error']:+.3g} % ± {100 * n['standard_error']:.3g} % "
                     f"({z}{count})")
        else:
            value = f"{n['error']:.2g} ± {n['standard_error']:.2g} r_min ({n['replicates']} rep.)"
        out.append(f"{n['scene']} dt {span}: {value}, {'beyond' if n['resolved'] else 'undecided'}")
    return out


def checked_only_text(scenes, reasons):
    """'stones: checked only for conservation and overlaps, not against the reference (the
    reference backend cannot run this scene: ...)', one per scene, the reason from summary.json's
    verdicts.B.accuracy.checked_only_reasons (accuracy_verdicts.h)."""
    return [f"{s}: checked only for conservation and overlaps, not against the reference"
            + (f" ({reasons[s]})" if reasons.get(s) else "") for s in scenes]


def _error_and_se(n):
    """A not-for entry's measured error ± SE, short: 'Z +2.03 % ± 0.791 %', 'τ +0.26 % ± 0.24 %',
    '0.0079 ± 0.0019 r_min'."""
    s = digest.statistic_of(n["error_kind"])
    if s:
        return f"{s} {100 * n['error']:+.3g} % ± {100 * n['standard_error']:.3g} %"
    return f"{n['error']:.2g} ± {n['standard_error']:.2g} r_min"


def not_for_cell(accuracy, texts):
    """The first screen's not-for entries, [{'text', 'title'}]: each entry beyond the accuracy in
    full (`texts`: not_for_text(accuracy), one per summary.json not_for entry, in its order); the
    undecided ones gathered into one entry that names their scenes, dt and error ± SE, their z
    and replicates on hover ('title') as in §3 and summary.md. A suite with many compared scenes then keeps each
    backend's row a few lines high (the first screen holds every row)."""
    entries = list(zip(accuracy.get("not_for", []), texts))
    out = [{"text": t, "title": None} for n, t in entries if n["resolved"]]
    undecided = [(n, t) for n, t in entries if not n["resolved"]]
    if undecided:
        where = ", ".join(f"{n['scene']} dt " + (f"{n['dt']:.2g}" if n["dt_min"] == n["dt_max"] else
                                                  f"{n['dt_min']:.2g}–{n['dt_max']:.2g}") + f" ({_error_and_se(n)})"
                          for n, _ in undecided)
        out.append({"text": f"undecided: {where}",
                    "title": "; ".join(t for _, t in undecided)})
    return out


def low_power_text(accuracy):
    """'Z passes, but could only detect a bias ≥ 0.8 % (periodic_gas, 64 rep.), ≥ 2.4 %
    (box_gas_1000, 6 rep.)' from summary.json's verdicts.B.accuracy.low_power
    (accuracy_verdicts.h: the passing Z checks whose detectable bias exceeds the stated
    accuracy, decided there); None where every pass could have seen a bias of the accuracy."""
    low = accuracy.get("low_power") or []
    if not low:
        return None
    each = [f"≥ {100 * l['detectable']:.2g} % ({l['scene']}, {l['replicates']} rep.)" for l in low]
    return "Z passes, but could only detect a bias " + ", ".join(each)


def preset_text(accuracy):
    """'fails the physical model: 68 of 540 checks fail under box2d's limits (energy drift 55, ...)'
    for a variant judged against its own tolerances; None where it fails none or has no base."""
    u = accuracy.get("under_preset_limits")
    if not u or not u["failing"]:
        return None
    by = ", ".join(f"{k.replace('_', ' ')} {v}" for k, v in sorted(u["failing_by_check"].items(), key=lambda kv: -kv[1]))
    return (f"FAILS the physical model: {u['failing']} of its {u['compared']} checks fail under the limits of "
            f"{u['preset']} ({by}); passes only its own tolerances below")


def verdict(summary, row, aliases, by_combination=None, cheapest=None):
    """{'backend', 'verdict', 'low_power', 'trusted', 'not_for', 'cost', 'failed', 'anchor'} for one digest row;
    `by_combination` (digest.combinations) and `cheapest` (cheapest_by_scene), the same for every
    backend, are computed here when not given."""
    b = row["backend"]
    status = scene_status(summary, b, by_combination)
    trusted = [s for s, v in status.items() if v == "pass"]
    cannot = [s for s, v in status.items() if v == "cannot_run"]
    failed = [s for s, v in status.items() if v == "fail"]
    named = summary["verdicts"].get(b, {})  # what `collide validate` decided to name (verdict_facts.h)
    accuracy = named.get("accuracy") or {}
    physical = preset_text(accuracy)
    parts = []
    if b == summary["reference"]:
        parts.append("exact (the reference)")
    elif physical:
        parts.append(physical)
    elif row["fail"]:
        parts.append(f"FAILS {row['fail']} checks")
    else:
        parts.append(f"passes {row['pass']} checks")
    if b in aliases:
        parts.append(f"the same numbers as {aliases[b]}, bit for bit")
    loose = named.get("loosest_tolerance")
    if loose and loose["named"]:
        parts.append(f"against its own loose tolerance: {loose['check'].replace('_', ' ')} ≤ {loose['tolerance']:.3g}, "
                     f"{loose['ratio']:.0f}× the other backends'")
    drift = named.get("largest_energy_drift")
    if drift and drift["named"]:
        parts.append(f"energy drift up to {100 * drift['value']:.3g} % ({drift['scene']})")
    pressure = named.get("pressure_offset")
    if pressure and pressure["named"]:
        parts.append(f"gas pressure off by up to {pressure['sigmas']:.0f} SE" +
                     (" (that check is left out)" if pressure["left_out"] else ""))
    not_for = not_for_text(accuracy)
    cell = not_for_cell(accuracy, not_for)
    if failed:
        not_for.append("fails its checks on " + ", ".join(failed))
        cell.append({"text": not_for[-1], "title": None})
    use_for = use_for_text(accuracy)
    use_cell = [{"text": u, "title": None} for u in use_for]
    checked = [s for s in accuracy.get("checked_only", []) if s in trusted]
    if checked and b == summary["reference"]:
        use_for.append("every scene it runs (exact by construction; conservation checked)")
        use_cell.append({"text": use_for[-1], "title": None})
    elif checked:
        reasons = accuracy.get("checked_only_reasons") or {}
        use_for += checked_only_text(checked, reasons)
        # On the first screen in short, the reason on hover (the row stays a few lines high).
        use_cell += [{"text": f"{s}: checked only (conservation, overlaps)", "title": t}
                     for s, t in zip(checked, checked_only_text(checked, reasons))]
    low_power = low_power_text(accuracy)
    if b in aliases:  # the same numbers bit for bit give the same entries: said once, the row stays short
        same = f"as {aliases[b]}"
        use_for, cell = [same] if use_for else [], [{"text": same, "title": None}] if cell else []
        use_cell = [{"text": same, "title": None}] if use_cell else []
        low_power = f"Z passes with low power, {same}" if low_power else None
    cannot_run = ", ".join(accuracy.get("cannot_run") or cannot) or "—"
    return {"backend": b, "verdict": "; ".join(parts), "low_power": low_power,
            "trusted": "; ".join(use_for) or "none",
            "use_for": use_for, "use_for_cell": use_cell, "not_for_list": cell, "not_for": "; ".join(not_for) or "—", "cannot_run": cannot_run,
            "cost": cost_text(summary, b, cheapest), "cost_at_accuracy": cost_at_accuracy_text(summary, b), "failed": bool(row["fail"]) or bool(physical),
            "anchor": digest.anchor("backend", b)}


def all_verdicts(summary, rows, aliases, by_combination=None):
    """One verdict per digest row; what every backend shares is computed once."""
    if by_combination is None:
        by_combination = digest.combinations(summary)
    cheapest = cheapest_by_scene(summary)
    return [verdict(summary, r, aliases, by_combination, cheapest) for r in rows]
