"""The trajectory figure of a scene compared by trajectory: the error of each drawn case against
the reference over time, the limit it was held to up to the predictability horizon, the
separation of the reference's twins, and the horizon T_h as a vertical line; with a sentence per
case saying which output times were judged. Every number is summary.json's (cases[].trajectory,
decided by `collide validate`: validation/compare/predictability_horizon.h); nothing is judged here.
"""
import numpy as np

import figures


def judged_cases(chosen):
    """[(backend, case)] of the drawn cases whose trajectory was compared (series recorded)."""
    return [(b, c) for b, c, _ in chosen if c.get("trajectory", {}).get("times")]


def judged_text(case):
    """Which output times of a case trajectory_error judged, in words."""
    j = case["trajectory"]
    n, outputs = j["judged_outputs"], j["outputs"]
    if not j["twins"]:
        return f"no twins recorded for its reference: all {outputs} output times judged against the tolerance."
    if not j["judged"]:
        return (f"not judged: the reference's twins part by more than the tolerance / {j['margin']:g} already at "
                f"t = {j['first_unjudged']:g}, before the first output time after the start (the horizon is shorter "
                f"than the output interval).")
    if not j["horizon_reached"]:
        return f"the twins stay within {j['threshold']:.3g} r_min to the end: all {outputs} output times judged."
    return (f"T_h = {j['horizon']:g}: output times t ≤ {j['horizon']:g} judged ({n} of {outputs}); from "
            f"t = {j['first_unjudged']:g} on only conservation and statistics judge.")


def figure(cases, scene, labels=None):
    """Error / r_min against time on a log scale, one colour per backend; dashed: the limit up
    to T_h; grey dotted: the reference twins' largest separation; vertical line: T_h."""
    if not cases:
        return None
    labels = labels or {}
    fig, ax = figures.plt.subplots(figsize=(7.5, 3.6))
    floor = 1e-17  # an error of exactly 0 (identical positions) drawn at the bottom
    horizons = set()
    for index, (backend, case) in enumerate(cases):
        j = case["trajectory"]
        t = np.asarray(j["times"], dtype=float)
        error = np.asarray([np.nan if e is None else max(e, floor) for e in j["error"]], dtype=float)
        style, width = figures.STYLES[index % len(figures.STYLES)]
        c = figures.colour(backend)
        ax.plot(t, error, color=c, linestyle=style, linewidth=min(width, 2.0),
                label=figures.tex(f"{labels.get(backend, backend)}, seed {case['seed']}"))
        if j["limit"]:
            ax.plot(t[:len(j["limit"])], j["limit"], color=c, linestyle="--", linewidth=0.8, alpha=0.7,
                    label=figures.tex(f"its limit, up to T_h{' (exact: margin × twins)' if j['exact'] else ''}"))
        if j["twins"]:
            twins = np.asarray([np.nan if s is None else max(s, floor) for s in j["twin_separation"]], dtype=float)
            ax.plot(t, twins, color="0.5", linestyle=":", linewidth=1.2,
                    label="reference twins" if index == 0 else None)
        if j["horizon_reached"] and j["horizon"] is not None and j["horizon"] not in horizons:
            horizons.add(j["horizon"])
            ax.axvline(j["horizon"], color=c, linestyle="-.", linewidth=1.0,
                       label=figures.tex(f"T_h = {j['horizon']:g} (seed {case['seed']})"))
    figures.log_scale(ax, "y")
    ax.set_xlabel("simulated time [scene time units]")
    ax.set_ylabel("position error / r_min [dimensionless]", fontsize=figures.TEXT_PT)
    ax.set_title(figures.tex(f"{scene}: trajectory error and the predictability horizon"), fontsize=figures.TEXT_PT)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=figures.TEXT_PT, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    return figures.png(fig)


def section(chosen, scene, labels=None):
    """{'png', 'margin', 'notes': [{'backend', 'case', 'text'}]} for a scene's drawn trajectory cases, or
    None where none was compared by trajectory."""
    cases = judged_cases(chosen)
    if not cases:
        return None
    return {"png": figure(cases, scene, labels), "margin": f"{cases[0][1]['trajectory']['margin']:g}",
            "notes": [{"backend": b, "case": c["id"], "text": judged_text(c)} for b, c in cases]}
