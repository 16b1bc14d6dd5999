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


def verdict(summary, row, aliases, by_combination=None, cheapest=None):
    """{'backend', 'verdict', 'trusted', 'not_for', 'cost', 'failed', 'anchor'} for one digest row;
    `by_combination` (digest.combinations) and `cheapest` (cheapest_by_scene), the same for every
    backend, are computed here when not given."""
    b = row["backend"]
    status = scene_status(summary, b, by_combination)
    trusted = [s for s, v in status.items() if v == "pass"]
    cannot = [s for s, v in status.items() if v == "cannot_run"]
    failed = [s for s, v in status.items() if v == "fail"]
    parts = []
    if b == summary["reference"]:
        parts.append("exact (the reference)")
    elif row["fail"]:
        parts.append(f"FAILS {row['fail']} checks")
    else:
        parts.append(f"passes {row['pass']} checks")
    if b in aliases:
        parts.append(f"the same numbers as {aliases[b]}, bit for bit")
    named = summary["verdicts"].get(b, {})  # what `collide validate` decided to name (verdict_facts.h)
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
    not_for = []
    if failed:
        not_for.append("fails on " + ", ".join(failed))
    if cannot:
        not_for.append("cannot run " + ", ".join(cannot))
    trusted_text = (f"every scene it runs ({len(trusted)})" if trusted and not failed and
                    len(trusted) + len(cannot) == len(status) else ", ".join(trusted) or "none")
    return {"backend": b, "verdict": "; ".join(parts), "trusted": trusted_text,
            "not_for": "; ".join(not_for) or "—", "cost": cost_text(summary, b, cheapest), "failed": bool(row["fail"]),
            "anchor": digest.anchor("backend", b)}


def all_verdicts(summary, rows, aliases, by_combination=None):
    """One verdict per digest row; what every backend shares is computed once."""
    if by_combination is None:
        by_combination = digest.combinations(summary)
    cheapest = cheapest_by_scene(summary)
    return [verdict(summary, r, aliases, by_combination, cheapest) for r in rows]
