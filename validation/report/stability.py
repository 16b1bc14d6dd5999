"""Stability maps and the first-failure table of the report, drawn only when the summary has
stability outcomes (a suite with `stability = true`; docs/stability.md).

A stability map is drawn for every scene swept over dt and one scene parameter (`set` in the
suite file): one panel per backend, one cell per (dt, value), coloured by the case's outcome.
With several seeds per cell the most severe outcome is shown.
"""
import textwrap
import tomllib
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import figures  # noqa: E402
import printable  # noqa: E402
from safe_files import safe_output  # noqa: E402  (the input guard: no FIFO waited on)

# One fixed colour per outcome; their order, the most severe first, is summary.json's
# `outcome_order` (the classification's precedence, validation/judge/stability.h).
OUTCOME_COLOURS = {"crash": "#000000", "hang": "#8c564b", "nan": "#d62728", "stalled": "#1f77b4",
                   "tunnelling": "#9467bd",
                   "excessive_overlap": "#ff7f0e", "energy_growth": "#e6c200", "stable": "#2ca02c",
                   "left_out": "#d9d9d9"}

# Axis labels with units for the scene keys the suites sweep (the scene's own units).
PARAMETER_LABELS = {"mass": "mass (scene mass units)", "vx": "speed v_x (length / time)",
                    "vy": "speed v_y (length / time)", "radius": "radius (length)",
                    "spacing": "lattice spacing (length)", "count": "number of disks",
                    "restitution": "restitution e (dimensionless)", "maxwell": "kT (energy)"}


_SCENE_DT = {}


def scene_dt(summary, scene):
    """The time step in the scene file (a case that sweeps no dt runs at it), or None."""
    path = summary.get("scene_files", {}).get(scene)
    if path not in _SCENE_DT:
        try:
            with safe_output.open_input(path, "rb") as f:
                _SCENE_DT[path] = tomllib.load(f).get("run", {}).get("dt")
        except (OSError, TypeError, tomllib.TOMLDecodeError):
            _SCENE_DT[path] = None
    return _SCENE_DT[path]


def dt_text(summary, case):
    """'dt = 0.001', or for a case at the scene's own step 'dt = 0.002 (the scene's)'; the exact
    solver has none."""
    if case["dt"]:
        return f"dt = {case['dt']:g}"
    if case.get("reference"):
        return "no dt (exact)"
    dt = scene_dt(summary, case["scene"])
    return f"dt = {dt:g} (the scene's)" if isinstance(dt, (int, float)) else "the scene's dt"


def unexpected(summary):
    """The cases a stability suite does not expect, as `collide validate` found them
    (validation/judge/stability.h, unexpected_outcomes): summary.json's `unexpected_outcomes`."""
    return summary["unexpected_outcomes"]


def has_outcomes(summary):
    return any("outcome" in c for c in summary["cases"])


def worse(order, a, b):
    """The more severe of two outcomes in `order` (summary.json's `outcome_order`)."""
    return a if b is None or order.index(a) < order.index(b) else b


def parameter_label(path):
    return f"{path}: {PARAMETER_LABELS.get(path.split('.')[-1], 'value')}"


def swept_scenes(summary):
    """scene -> (parameter path, {backend: {(dt, value): outcome}}) for dt x one-parameter sweeps."""
    maps = OrderedDict()
    for c in summary["cases"]:
        params = c.get("parameters", {})
        if c["reference"] or len(params) != 1 or "outcome" not in c:
            continue
        (path, value), = params.items()
        entry = maps.setdefault(c["scene"], (path, OrderedDict()))
        cells = entry[1].setdefault(c["backend"], {})
        key = (c["dt"], value)
        cells[key] = worse(summary["outcome_order"], c["outcome"], cells.get(key))
    return OrderedDict((s, m) for s, m in maps.items()
                       if len({k[0] for cells in m[1].values() for k in cells}) > 1)


def stability_map(scene, path, backends, order):
    dts = sorted({k[0] for cells in backends.values() for k in cells})
    values = sorted({k[1] for cells in backends.values() for k in cells})
    fig, axes = plt.subplots(1, len(backends), figsize=(3.2 * len(backends) + 1.5, 3.4), squeeze=False,
                             layout="constrained")  # room for the rotated ticks, the title and the legend
    for ax, (backend, cells) in zip(axes[0], backends.items()):
        for i, dt in enumerate(dts):
            for j, v in enumerate(values):
                outcome = cells.get((dt, v))
                ax.add_patch(plt.Rectangle((i, j), 1, 1, facecolor=OUTCOME_COLOURS.get(outcome, "white"),
                                           edgecolor="white"))
        ax.set_xlim(0, len(dts))
        ax.set_ylim(0, len(values))
        # Cells are equally spaced: the sweeps are (roughly) geometric, so this is a log axis.
        ax.set_xticks([i + 0.5 for i in range(len(dts))], [f"{d:g}" for d in dts], rotation=45)
        ax.set_yticks([j + 0.5 for j in range(len(values))], [f"{v:g}" for v in values])
        ax.set_xlabel("time step dt (time)")
        ax.set_title(figures.tex(backend), color=figures.colour(backend))
    axes[0][0].set_ylabel(figures.tex(textwrap.fill(parameter_label(path), 30)))  # taller than the panel else
    present = [o for o in order if any(o in cells.values() for cells in backends.values())]
    axes[0][-1].legend(handles=[Patch(facecolor=OUTCOME_COLOURS[o], label=o) for o in present],
                       loc="center left", bbox_to_anchor=(1.02, 0.5), frameon=False)
    fig.suptitle(figures.tex(f"Stability map: {scene}"))
    return figures.png(fig)


def first_failures(summary):
    """(scene, backend) -> the smallest failing dt and the smallest failing value, with how."""
    rows = OrderedDict()
    for c in summary["cases"]:
        if "outcome" not in c or c["outcome"] == "left_out":
            continue
        row = rows.setdefault((c["scene"], c["backend"]), {"cases": 0, "failed": []})
        row["cases"] += 1
        if c["outcome"] != "stable":
            row["failed"].append(c)
    return rows


def describe(case, summary=None):
    params = ", ".join(f"{p.split('.')[-1]} = {v:g}" for p, v in case.get("parameters", {}).items())
    where = (dt_text(summary, case) if summary else f"dt = {case['dt']:g}") + (f", {params}" if params else "")
    return f"{case['outcome']} at {where}"


def _smallest_value(case):
    return min(case.get("parameters", {}).values(), default=0.0)


def first_failure_table(summary):
    """A row per (scene, backend): its cases, failures and first failures (None: stable)."""
    out = []
    for (scene, backend), row in first_failures(summary).items():
        failed, entry = row["failed"], {"scene": scene, "backend": backend, "cases": row["cases"],
                                        "failed": len(row["failed"]), "by_dt": None}
        if failed:
            by_dt = min(failed, key=lambda c: (c["dt"], _smallest_value(c)))
            by_value = min(failed, key=lambda c: (_smallest_value(c), c["dt"]))
            entry.update(by_dt=describe(by_dt, summary), reason=by_dt.get("outcome_reason", ""),
                         by_value=describe(by_value, summary) if by_value.get("parameters") else "")
        out.append(entry)
    return out


def first_failure_matrix(summary):
    """The stability suite's first screen: one row per scene, one column per backend, each cell
    the backend's first failure on that scene (smallest failing dt, then smallest value)."""
    rows = first_failures(summary)
    scenes = list(OrderedDict.fromkeys(s for s, _ in rows))
    backends = list(OrderedDict.fromkeys(b for _, b in rows))
    out = []
    for scene in scenes:
        cells = []
        for b in backends:
            row = rows.get((scene, b))
            if row is None:
                cells.append({"class": "left_out", "text": "left out", "title": None})
            elif not row["failed"]:
                cells.append({"class": "pass", "text": f"stable ({row['cases']})", "title": None})
            else:
                first = min(row["failed"], key=lambda c: (c["dt"], _smallest_value(c)))
                cells.append({"class": "fail", "title": first.get("outcome_reason", ""),
                              "text": f"{describe(first, summary)} ({len(row['failed'])}/{row['cases']})"})
        out.append({"scene": scene, "cells": cells})
    return {"backends": backends, "rows": out}


def section(summary):
    """The report's stability section for templates/stability.html.j2: a map per swept scene
    (PNG) and the first failures."""
    maps = [{"scene": scene, "path": path, "png": stability_map(scene, path, backends, summary["outcome_order"])}
            for scene, (path, backends) in swept_scenes(summary).items()]
    return {"maps": maps, "first_failures": first_failure_table(summary)}


def markdown(summary):
    if not has_outcomes(summary):
        return []
    lines = ["", "## Stability outcomes", "", "| scene | backend | cases | failed | first failure (smallest dt) |",
             "|---|---|---|---|---|"]
    for (scene, backend), row in first_failures(summary).items():
        failed = row["failed"]
        first = min(failed, key=lambda c: (c["dt"], _smallest_value(c))) if failed else None
        text = printable.markdown(describe(first, summary) + ": " + first.get("outcome_reason", "")) if first else "none"
        lines.append(f"| {scene} | {backend} | {row['cases']} | {len(failed)} | {text} |")
    return lines
