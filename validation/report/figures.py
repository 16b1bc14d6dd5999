"""Figures of the validation report, one function per figure kind.

Every function returns a PNG as bytes (or None when there is nothing to draw); make_report.py
embeds them as base64 and writes the caption beside each. Axes carry units: lengths and times
are in the scene's own units, run time in seconds of wall-clock time.
"""
import io

import matplotlib

matplotlib.use("Agg")  # no display: render to memory
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

# One fixed colour per backend, so a backend looks the same in every figure.
BACKEND_COLOURS = {"event": "black", "step": "tab:blue", "cpu": "tab:orange",
                   "opencl": "tab:green", "box2d": "tab:red"}


def colour(backend):
    return BACKEND_COLOURS.get(backend, "tab:purple")


def _png(fig):
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=90, bbox_inches="tight")
    plt.close(fig)
    return buffer.getvalue()


def work_precision(lines, scene):
    """Error against wall time per simulated time unit, one line per backend, dt as labels."""
    lines = [l for l in lines if l["scene"] == scene and l["points"]]
    if not lines:
        return None
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for line in lines:
        points = sorted(line["points"], key=lambda p: -p["dt"])
        x = [p["seconds_per_time_unit"] for p in points]
        y = [max(p["error"] or 0, 1e-17) for p in points]
        label = line["backend"]
        if line["order"] is not None:
            label += f" (order {line['order']:.2f})"
        ax.loglog(x, y, "o-", color=colour(line["backend"]), label=label)
        for p, xi, yi in zip(points, x, y):
            ax.annotate(f"dt={p['dt']:g}" + (f"/{p['substeps']}" if p["substeps"] > 1 else ""),
                        (xi, yi), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xlabel("wall time per simulated time unit [s]")
    ax.set_ylabel(lines[0]["error_kind"] + " [dimensionless]")
    ax.set_title(f"{scene}: work against precision")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(title="backend")
    return _png(fig)


def conservation(case_results, scene):
    """Relative drift of energy and momentum against time, one line per backend."""
    if not case_results:
        return None
    fig, (ax_e, ax_p) = plt.subplots(1, 2, figsize=(10, 3.8))
    for backend, result in case_results:
        s = result["series"]
        t = np.asarray(s["time"], dtype=float)
        if t.size == 0:
            continue
        kinetic = np.asarray(s["kinetic_energy"], dtype=float)
        total = np.asarray(s["total_energy"], dtype=float)
        scale = max(float(np.nanmax(kinetic)), 1e-300)
        energy = total if abs(total[0] - kinetic[0]) > 0 else kinetic
        ax_e.plot(t, (energy - energy[0]) / scale, color=colour(backend), label=backend)
        px = np.asarray(s["momentum_x"], dtype=float)
        py = np.asarray(s["momentum_y"], dtype=float)
        mscale = np.sqrt(2 * max(result.get("total_mass", 0.0), 1e-300) * max(kinetic[0], 1e-300))
        ax_p.plot(t, np.hypot(px - px[0], py - py[0]) / mscale, color=colour(backend), label=backend)
    ax_e.set_xlabel("simulated time [scene time units]")
    ax_e.set_ylabel("(E(t) - E(0)) / max K [dimensionless]")
    ax_e.set_title(f"{scene}: energy drift")
    ax_p.set_xlabel("simulated time [scene time units]")
    ax_p.set_ylabel("|P(t) - P(0)| / sqrt(2 M K(0)) [dimensionless]")
    ax_p.set_title(f"{scene}: momentum drift")
    for ax in (ax_e, ax_p):
        ax.grid(True, alpha=0.3)
        ax.legend(title="backend", fontsize=8)
    fig.tight_layout()
    return _png(fig)


def overlap_histogram(case_results, scene):
    """Distribution of relative overlap depths in the final state, per backend."""
    depths = [(b, np.asarray(r["overlap_depths"], dtype=float)) for b, r in case_results]
    depths = [(b, d[d > 0]) for b, d in depths]
    if not any(d.size for _, d in depths):
        return None
    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    low = min(d.min() for _, d in depths if d.size)
    high = max(d.max() for _, d in depths if d.size)
    bins = np.logspace(np.log10(max(low, 1e-17)), np.log10(max(high, low * 10)), 30)
    for backend, d in depths:
        if d.size:
            ax.hist(d, bins=bins, histtype="step", color=colour(backend), label=f"{backend} ({d.size} pairs)")
    ax.set_xscale("log")
    ax.set_xlabel("relative overlap depth (r_i + r_j - d) / (r_i + r_j) [dimensionless]")
    ax.set_ylabel("overlapping pairs [count]")
    ax.set_title(f"{scene}: overlaps in the final state")
    ax.legend(title="backend", fontsize=8)
    ax.grid(True, alpha=0.3)
    return _png(fig)


def configuration(result, world, scene, backend):
    """The disks at the start and at the end of one case, side by side."""
    fig, axes = plt.subplots(1, 2, figsize=(9, 4.4))
    for ax, key, title in ((axes[0], "initial", "initial (t = 0)"),
                           (axes[1], "final", f"final (t = {result['duration']:g})")):
        snap = result[key]
        circles = [Circle((x, y), r) for x, y, r in zip(snap["x"], snap["y"], snap["radius"])]
        speeds = np.hypot(snap["vx"], snap["vy"]) if snap["vx"] else np.zeros(0)
        collection = PatchCollection(circles, cmap="viridis", edgecolor="none")
        collection.set_array(speeds)
        ax.add_collection(collection)
        if world:
            ax.set_xlim(world[0], world[2])
            ax.set_ylim(world[1], world[3])
        else:
            ax.autoscale_view()
        ax.set_aspect("equal")
        ax.set_xlabel("x [scene length units]")
        ax.set_ylabel("y [scene length units]")
        ax.set_title(f"{scene} ({backend}): {title}")
        fig.colorbar(collection, ax=ax, label="speed |v| [length / time]", shrink=0.8)
    fig.tight_layout()
    return _png(fig)
