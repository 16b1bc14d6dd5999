"""The report's "Reference against physics" section: why the reference solver itself is right.

Every number here comes from summary.json's "physics" object (validation/compare/physics_rows.cpp
computes the rows, data/references/*.toml holds the published values and their citations); this
module only lays them out and draws the equation-of-state figure.
"""

import finite_n

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import figures  # noqa: E402  (TEXT_PT, the smallest text of a figure)

ROW_TITLES = {
    "equation_of_state": "Equation of state",
    "collision_rate": "Collision rate (Enskog)",
    "speed_distribution": "Speed distribution (Maxwell–Boltzmann)",
    "galperin": "Galperin's billiard (digits of π)",
    "haff": "Haff's law (granular cooling)",
    "published_finite_n": "Pressure at finite N (published)",
    "routes_agree": "Routes agree (a sampler against event, finite N)",
    "exact_agreement": "Two exact solvers agree",
}


def rows(summary):
    return (summary.get("physics") or {}).get("rows", [])


def _num(value, digits=4):
    if value is None:
        return "n/a"
    if value == int(value) and abs(value) < 1e7:  # layout: an integer is printed as one
        return f"{int(value)}"
    return f"{value:.{digits}g}"


def _value(r):
    if r["statistic"] == "exact":
        return _num(r["value"])
    if r["statistic"] == "p":
        return f"χ² = {r['value']:.1f} on {int(r['reference'])} d.o.f."
    return f"{_num(r['value'], 5)} ± {_num(r['standard_error'], 2)}"


def _reference(r):
    if r["statistic"] == "p":
        return r["reference_name"]
    text = f"{_num(r['reference'], 5)} ({r['reference_name']})"
    if r.get("second_reference") is not None:
        text += f"; {r['second_reference_name']}: {_num(r['second_reference'], 5)}"
    return text


def _score(r):
    if r.get("score") is None:  # a row shown, not judged (e.g. not mixed)
        return "n/a"
    if r["statistic"] == "exact":
        return "equal" if r["score"] == 0 else f"off by {_num(r['score'])}"
    if r["statistic"] == "p":
        return f"p = {r['score']:.3g}"
    f = r.get("score_from")
    if f and f.get("t") is not None:
        # A replicate scatter's SE: the quotient is Student's t, judged by the normal score of
        # equal tail probability (physics_rows.h).
        return (f"t = {f['t']:+.2f} from {f['value']:.6g} ± {f['standard_error']:.3g} against {f['reference']:.6g} ± "
                f"{f['reference_uncertainty']:.3g} ({f['estimator']}); {f['degrees_of_freedom']:.3g} degrees of "
                f"freedom give the normal score {r['score']:.2f}")
    if not f or f.get("z") is None:
        return f"|z| = {r['score']:.2f}"
    return f"{finite_n.z_with_its_numbers(f)} ({f['estimator']})"


def _verdict(r):
    word = {"pass": "pass", "fail": "FAIL", "shown": "shown, not judged"}[r["verdict"]]
    if r["row"] == "equation_of_state" and not r["resolved"]:
        word += " (not resolved: the error bar cannot tell the two published values apart)"
    return word


def summary_lines(summary):
    """One line per row kind: how many rows of the judged backends pass, and the worst score."""
    out = []
    for kind, title in ROW_TITLES.items():
        judged = [r for r in rows(summary) if r["row"] == kind and r["verdict"] != "shown"]
        if not judged:
            continue
        passed = sum(r["verdict"] == "pass" for r in judged)
        backends = sorted({r["backend"] for r in judged})
        out.append((title, passed, len(judged), ", ".join(backends), judged[0]["reference_name"]))
    return out


def table(summary):
    """Every row, as the texts of its cells."""
    return [{"row": ROW_TITLES.get(r["row"], r["row"]), "backend": r["backend"],
             "at": f"{r['parameter_name']} {_num(r['parameter'])}" if r["parameter_name"] else "",
             "measured": f"{r['measured']} ({r['estimator']})", "value": _value(r), "replicates": r["replicates"],
             "reference": _reference(r), "score": _score(r), "verdict": _verdict(r), "detail": r["detail"],
             "class": {"pass": "pass", "fail": "fail"}.get(r["verdict"], "lo")} for r in rows(summary)]


def citations(summary):
    seen = {}
    for r in rows(summary):
        seen.setdefault(r["reference_name"], r["citation"])
    for c in (summary.get("physics") or {}).get("curves", []):
        seen.setdefault(c["name"], c["citation"])
    return list(seen.items())


def eos_figure(summary):
    """Z against area fraction: the published curves and the measured points (top), and the
    relative difference from Kolafa & Rottner (bottom), where Henderson's 2 % at 0.65 shows.
    A point whose error bar cannot tell the two published values apart is drawn hollow. Each
    backend has its colour and marker of every figure and is drawn a small step aside in η
    (figures.side_by_side, said in its legend entry): `event` and `event-plain` agree to rounding
    and would otherwise hide one under the other."""
    physics = summary.get("physics") or {}
    points = [r for r in rows(summary) if r["row"] == "equation_of_state" and r["value"] is not None]
    curves = physics.get("curves", [])
    if not points or not curves:
        return None
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 6.6), sharex=True, gridspec_kw={"height_ratios": [3, 2]},
                                      layout="constrained")
    best = curves[0]
    styles = ["-", "--"]
    for c, style in zip(curves, styles):
        top.plot(c["eta"], c["z"], style, color="grey", label=c["name"], linewidth=1.2)
    base = dict(zip(best["eta"], best["z"]))
    for c, style in zip(curves[1:], styles[1:]):
        bottom.plot(c["eta"], [100 * (z / base[e] - 1) for e, z in zip(c["eta"], c["z"])], style, color="grey",
                    linewidth=1.2)
    bottom.axhline(0, color="grey", linewidth=1.2)
    backends = sorted({p["backend"] for p in points})
    etas = sorted({p["parameter"] for p in points})
    offsets = figures.side_by_side(backends, figures.SIDE_STEP * (etas[-1] - etas[0] if len(etas) > 1 else 1.0))
    for backend in backends:
        mine = [p for p in points if p["backend"] == backend]
        kw = dict(marker=figures.marker(backend), color=figures.colour(backend), linestyle="none", markersize=6)
        for p in mine:
            style = dict(kw, markerfacecolor=None if p["resolved"] else "white")
            x = p["parameter"] + offsets[backend]
            top.errorbar([x], [p["value"]], yerr=[p["standard_error"]], **style)
            rel = 100 * (p["value"] / p["reference"] - 1)
            bottom.errorbar([x], [rel], yerr=[100 * p["standard_error"] / p["reference"]], **style)
        top.plot([], [], label=figures.tex(f"{backend} ({mine[0]['estimator'].split(',')[0].split(' (')[0]}), "
                                           f"drawn at η {offsets[backend]:+.2g}"), **kw)
    top.plot([], [], marker="o", color="0.3", markerfacecolor="white", linestyle="none",
             label="hollow: error bar cannot tell the two curves apart")
    top.set_ylabel("Z = βP/ρ [dimensionless]")
    top.legend(fontsize=figures.TEXT_PT, loc="upper left")
    bottom.set_ylabel(f"Z / Z[{best['name'].split(' (')[0]}] − 1 [%]", fontsize=figures.TEXT_PT)
    bottom.set_xlabel("area fraction η = Nπr²/A [dimensionless]")
    rel_points = [100 * (p["value"] / p["reference"] - 1) for p in points]
    span = max([1.0] + [abs(v) + 100 * p["standard_error"] / p["reference"] for v, p in zip(rel_points, points)])
    bottom.set_ylim(-1.5 * span, 3 * span)  # Henderson's rise near 0.7 would hide the points
    return figures.png(fig)


def section(summary):
    """The section's data for templates/physics.html.j2 (None when the suite has no physics rows)."""
    if not rows(summary):
        return None
    return {"lines": summary_lines(summary), "table": table(summary), "citations": citations(summary),
            "figure": eos_figure(summary), "finite_n": finite_n.section(summary),
            "z_max": f"{(summary.get('physics') or {}).get('z_max', 3):g}"}


def markdown(summary):
    """The section's lines for summary.md."""
    if not rows(summary):
        return []
    out = ["## Reference against physics", "", "| row | judged | backends | published reference |", "|---|---|---|---|"]
    out += [f"| {t} | {p} of {n} pass | {b} | {ref} |" for t, p, n, b, ref in summary_lines(summary)]
    failed = [r for r in rows(summary) if r["verdict"] == "fail"]
    out += [f"- FAIL {r['row']} {r['backend']} {r['parameter_name']} {_num(r['parameter'])}: "
            f"{_value(r)} vs {_num(r['reference'], 5)} ({_score(r)})" for r in failed]
    return out + [""]
