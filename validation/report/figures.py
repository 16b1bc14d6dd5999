"""Figures of the validation report, one function per figure kind.

Every function returns a PNG as bytes (or None when there is nothing to draw), reduced to a
256-colour palette (the figures are flat colours; a third of the size of full colour);
the templates (templates/*.html.j2) embed them as base64 with the caption beside each. Every number drawn is
one summary.json or a case record holds. Axes carry units: lengths and times
are in the scene's own units, run time in seconds of wall-clock time.
"""
import io

import matplotlib

matplotlib.use("Agg")  # no display: render to memory
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

# One fixed colour per backend, so a backend looks the same in every figure.
BACKEND_COLOURS = {"event": "black", "step": "tab:blue", "cpu": "tab:orange",
                   "opencl": "tab:green", "box2d": "tab:red"}


# Every other backend (a variant, an outside solver, an engine) gets a colour of its own from
# this list, distinct from the fixed ones and from each other: assign_styles() hands them out
# over the report's whole backend list before any figure is drawn (figures are drawn in forked
# processes, which could not agree on a colour handed out on first use).
VARIANT_COLOURS = ["tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan", "tab:gray", "gold", "navy",
                   "teal", "lime", "maroon", "darkorange", "indigo", "deeppink", "darkkhaki", "slateblue"]
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h", "p", "d", "H", "8", "1", "2", "3", "4"]
_ASSIGNED = {}
_MARKER = {}


def assign_styles(backends):
    """A distinct colour and marker for each of `backends` (in their order), for every figure of the report."""
    _ASSIGNED.clear()
    _MARKER.clear()
    free = [c for c in VARIANT_COLOURS]
    for k, b in enumerate(backends):
        _MARKER[b] = MARKERS[k % len(MARKERS)]
        if b in BACKEND_COLOURS:
            continue
        if free:
            start = sum(map(ord, b)) % len(free)  # stable for a backend whatever else runs, where free
            _ASSIGNED[b] = free.pop(start)
        else:  # more backends than colours: the colours repeat, the markers still tell them apart
            _ASSIGNED[b] = VARIANT_COLOURS[k % len(VARIANT_COLOURS)]


def colour(backend):
    """A backend's colour; a variant such as 'box2d[shipped]' gets its own, stable one."""
    if backend in BACKEND_COLOURS:
        return BACKEND_COLOURS[backend]
    if backend in _ASSIGNED:
        return _ASSIGNED[backend]
    return VARIANT_COLOURS[sum(map(ord, backend)) % len(VARIANT_COLOURS)]


def marker(backend):
    """A backend's marker: distinct across the report's backends (assign_styles), else a circle."""
    return _MARKER.get(backend, "o")


# Backends drawn in the same plot get different dash patterns and widths, widest first, so
# series that coincide (exact and stepped energy both at zero) stay visible one over the other.
STYLES = [("-", 3.2), ("--", 2.2), (":", 2.0), ("-.", 1.5), ((0, (1, 1)), 1.2), ((0, (5, 1)), 1.0)]


def smallest_text_px(fig, dpi):
    """The height in PNG pixels of the smallest visible text of `fig` saved at `dpi` (a point is
    1/72 inch): the browser test scales it to the displayed size and holds it to 10 px."""
    from matplotlib.text import Text
    sizes = [t.get_fontsize() for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
    return min(sizes) * dpi / 72 if sizes else None


def png(fig, dpi=80):
    """The figure as a 256-colour PNG whose text chunk `smallest-text-px` records its smallest
    text (smallest_text_px)."""
    smallest = smallest_text_px(fig, dpi)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=dpi)
    plt.close(fig)
    buffer.seek(0)
    from PIL import Image, PngImagePlugin  # Debian's python3-pil, a dependency of matplotlib
    with Image.open(buffer) as picture:
        palette = picture.convert("RGB").quantize(colors=256, method=Image.Quantize.FASTOCTREE)
    info = PngImagePlugin.PngInfo()
    if smallest is not None:
        info.add_text("smallest-text-px", f"{smallest:.2f}")
    out = io.BytesIO()
    palette.save(out, format="PNG", pnginfo=info)
    return out.getvalue()


def tex(text):
    """A label from data (scene or backend names) as literal text: '$' would start mathtext."""
    return str(text).replace("$", r"\$")


def draw_points(ax, points, colour_, label, marker="o", annotate=True, label_unresolved=True):
    """One line of a work-precision diagram. points: [{'x', 'y', 'se', 'resolved', 'upper'?,
    'label'}] sorted as they are to be joined. A resolved point is filled, with its error bar
    (±1 SE); an unresolved one (difference below 2 SE) is drawn hollow at its 95 % upper limit
    'upper' = |Δ| + 1.96 SE (summary.json) and labelled "not resolved". Returns the resolved
    points' line."""
    resolved = [p for p in points if p["resolved"]]
    line = None
    if resolved:
        line, = ax.plot([p["x"] for p in resolved], [p["y"] for p in resolved], "-", marker=marker,
                        color=colour_, label=tex(label) if label else None, markersize=6)
        ax.errorbar([p["x"] for p in resolved], [p["y"] for p in resolved],
                    yerr=[[min(p["se"], p["y"] * 0.999) for p in resolved], [p["se"] for p in resolved]],
                    fmt="none", ecolor=colour_, elinewidth=1, capsize=3)
    for p in points:
        if p["resolved"]:
            continue
        y = max(p["upper"], 1e-17)
        ax.plot([p["x"]], [y], linestyle="none", marker=marker, markerfacecolor="none", markeredgecolor=colour_,
                markersize=7, label=None if (line or resolved or not label) else tex(label) + " (not resolved)")
        if label_unresolved:
            ax.annotate("not resolved", (p["x"], y), textcoords="offset points", xytext=(5, -9), fontsize=TEXT_PT,
                        color=colour_)
    if annotate:
        for p in points:
            if p.get("label"):
                ax.annotate(p["label"], (p["x"], p["y"] if p["resolved"] else max(p["upper"], 1e-17)),
                            textcoords="offset points", xytext=(4, 4), fontsize=TEXT_PT)
    return line


def _dt_label(dt, substeps):
    return f"dt={dt:g}" + (f"/{substeps}" if substeps and substeps > 1 else "")


def trajectory_points(line):
    pts = sorted(line["points"], key=lambda p: -p["dt"])
    return [{"x": p["seconds_per_time_unit"], "y": max(p["error"] or 0, 1e-17),
             "se": p.get("error_standard_error") or 0.0, "resolved": True,
             "label": _dt_label(p["dt"], p.get("substeps", 1))} for p in pts if p["error"] is not None]


def statistical_line_points(stats):
    return [{"x": p["seconds"], "y": max(p["error"], 1e-17), "se": p["se"], "resolved": p["resolved"],
             "upper": p["upper"], "predicted": p["predicted"], "label": _dt_label(p["dt"], p["substeps"])}
            for p in sorted(stats, key=lambda p: -p["dt"])]


def draw_prediction(ax, points, colour_):
    """The stepped rule's predicted |relative bias| at each point, thin dashes (statistics_bias_model.h)."""
    predicted = [(p["x"], abs(p["predicted"])) for p in points if p.get("predicted")]
    if predicted:
        ax.plot([x for x, _ in predicted], [y for _, y in predicted], linestyle=(0, (2, 2)), linewidth=1,
                color=colour_, alpha=0.8)


def reference_costs(summary, scenes):
    """The exact solver's cost per time unit on each of `scenes` (summary.json's costs)."""
    return [(c["scene"], c["seconds_per_time_unit"]) for c in summary.get("costs", [])
            if c["backend"] == summary["reference"] and c["scene"] in scenes]


def draw_reference_costs(ax, summary, scenes, with_names=True):
    for scene, cost in reference_costs(summary, scenes):
        ax.axvline(cost, color=colour(summary["reference"]), linestyle="--", linewidth=1)
        if with_names:
            ax.annotate(tex(f"{summary['reference']} (exact), {scene}"), (cost, 0.02), xycoords=("data", "axes fraction"),
                        rotation=90, fontsize=TEXT_PT, xytext=(3, 0), textcoords="offset points")


SCENE_MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*"]


def alias_label(backend, aliases):
    """A backend's name in a legend; one that gives another's numbers bit for bit (`aliases`:
    backend -> that other backend) says whose."""
    return backend + (f" (numbers of {aliases[backend]})" if backend in aliases else "")


def headline(summary, digest, aliases):
    """The first screen's figure: work against precision for the trajectory scenes (mean
    error over phase replicates ± SE), pressure Z and collision rate (relative difference of
    the replicate means ± SE; hollow at the 95 % upper limit where not resolved; the stepped
    rule's predicted bias in thin dashes), every backend at its own measured cost (a backend with
    the numbers of another, `aliases`, too: equal errors, not equal costs), one marker per scene.
    The exact solver's own cost per time unit on each scene is a dashed vertical line on every
    panel (its error is statistical only, or zero)."""
    lines = [l for l in summary["work_precision"] if l["points"]]
    trajectory = [l for l in lines if l["error_kind"].startswith("trajectory")]
    statistical_scenes = list(dict.fromkeys(l["scene"] for l in lines if not l["error_kind"].startswith("trajectory")))
    panels = (1 if trajectory else 0) + 2 * (1 if statistical_scenes else 0)
    if not panels:
        return None
    # Every text at least 9.5 pt: 10.6 px at 80 dpi, drawn at its natural size on the page.
    with plt.rc_context({"font.size": HEADLINE_PT, "axes.titlesize": HEADLINE_PT, "axes.labelsize": HEADLINE_PT,
                         "xtick.labelsize": HEADLINE_PT, "ytick.labelsize": HEADLINE_PT}):
        return _headline(summary, digest, aliases, lines, trajectory, statistical_scenes, panels)


HEADLINE_PT = 9.5


def _headline(summary, digest, aliases, lines, trajectory, statistical_scenes, panels):
    fig, axes = plt.subplots(1, panels, figsize=(4.6 * panels, 4.3), squeeze=False)
    axes = list(axes[0])
    used_scenes = []
    every_scene = list(dict.fromkeys(l["scene"] for l in lines))

    def scene_marker(scene):
        return SCENE_MARKERS[every_scene.index(scene) % len(SCENE_MARKERS)]
    names = {b: alias_label(b, aliases) for b in dict.fromkeys(l["backend"] for l in lines)}
    if trajectory:
        ax = axes.pop(0)
        scenes = list(dict.fromkeys(l["scene"] for l in trajectory))
        for line in trajectory:
            marker = scene_marker(line["scene"])
            draw_points(ax, trajectory_points(line), colour(line["backend"]), None, marker, annotate=False)
        draw_reference_costs(ax, summary, scenes, with_names=False)
        ax.set_title("trajectory scenes: mean error ± SE over phase replicates")
        ax.set_ylabel("trajectory error / r_min [dimensionless]")
        used_scenes += [(sc, scene_marker(sc)) for sc in scenes]
    for check, title, ylabel in (("pressure", "pressure Z (contact-shell estimator)", "|Z − Z_ref| / Z_ref [dimensionless]"),
                                 ("collision_rate", "collision rate", "|ν − ν_ref| / ν_ref [dimensionless]")):
        if not statistical_scenes:
            break
        ax = axes.pop(0)
        for scene in statistical_scenes:
            marker = scene_marker(scene)
            for backend, stats in digest.statistical_points(summary, scene, check).items():
                points = statistical_line_points(stats)
                draw_points(ax, points, colour(backend), None, marker, annotate=False, label_unresolved=False)
                draw_prediction(ax, points, colour(backend))
        draw_reference_costs(ax, summary, statistical_scenes, with_names=False)
        ax.set_title(f"{title}: relative difference of means ± SE")
        ax.set_ylabel(ylabel)
        if check == "pressure":
            used_scenes += [(sc, scene_marker(sc)) for sc in statistical_scenes]
    for ax in fig.axes:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time per simulated time unit [s]")
        ax.grid(True, which="both", alpha=0.3)
    handles = [Line2D([], [], color=colour(b), marker="o", label=tex(names[b])) for b in names]
    seen = set()
    for scene, marker in used_scenes:
        if (scene, marker) not in seen:
            seen.add((scene, marker))
            handles.append(Line2D([], [], color="0.3", marker=marker, linestyle="none", label=tex(scene)))
    handles.append(Line2D([], [], color="0.3", marker="o", markerfacecolor="none", linestyle="none",
                          label="hollow: not resolved, at |Δ| + 1.96 SE"))
    handles.append(Line2D([], [], color=colour(summary["reference"]), linestyle="--",
                          label=tex(f"{summary['reference']} (exact): its cost per time unit")))
    if statistical_scenes:
        handles.append(Line2D([], [], color="0.3", linestyle=(0, (2, 2)), label="predicted bias of the stepped rule"))
    fig.tight_layout(rect=(0, 0.24, 1, 1))
    fig.legend(handles=handles, loc="lower center", ncol=min(len(handles), 5), fontsize=HEADLINE_PT, frameon=False)
    return png(fig)


def work_precision(summary, scene, digest, aliases, fits=None):
    """One scene's work-precision diagram: one line per backend, each at its own cost, dt as
    labels (once per backend: a backend with another's numbers is labelled by that one's name),
    error bars ±1 SE, unresolved statistical points hollow at their 95 % upper limit, the
    stepped rule's predicted bias dashed; the exact solver's cost per time unit as a dashed line.
    `fits`: {(scene, backend): fit} of digest.orders(summary), computed here when not given."""
    lines = [l for l in summary["work_precision"] if l["scene"] == scene and l["points"]]
    if not lines:
        return None
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    if fits is None:
        fits = {(f["scene"], f["backend"]): f for f in digest.orders(summary)}
    statistic = digest.statistic_of(lines[0]["error_kind"])  # Z, or τ / ν paired by seed
    statistical = statistic is not None
    stats = digest.statistical_points(summary, scene, "pressure" if statistic == "Z" else "paired") if statistical else {}
    for line in lines:
        b = line["backend"]
        label = alias_label(b, aliases)
        fit = fits.get((scene, b))
        if fit and fit["order"] is not None and b not in aliases:
            label += f" (order {fit['order']:.2f}" + (f" ± {fit['order_se']:.2f}" if fit["order_se"] is not None else "") + ")"
        points = statistical_line_points(stats.get(b, [])) if statistical else trajectory_points(line)
        draw_points(ax, points, colour(b), label, annotate=b not in aliases)
        if statistical:
            draw_prediction(ax, points, colour(b))
    for _, cost in reference_costs(summary, [scene]):
        ax.axvline(cost, color=colour(summary["reference"]), linestyle="--", linewidth=1,
                   label=tex(f"{summary['reference']} (exact): its cost"))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per simulated time unit [s]")
    if statistic == "Z":
        ax.set_ylabel("|Z − Z_ref| / Z_ref (means ± SE) [dimensionless]")
    elif statistical:
        ax.set_ylabel(f"|{statistic} − {statistic}_ref| / {statistic}_ref (per-seed differences ± SE) [dimensionless]")
    else:
        ax.set_ylabel("trajectory error / r_min, mean ± SE [dimensionless]")
    ax.set_title(tex(f"{scene}: work against precision"))
    ax.grid(True, which="both", alpha=0.3)
    handles, _ = ax.get_legend_handles_labels()
    if handles:
        ax.legend(title="backend", fontsize=TEXT_PT, title_fontsize=TEXT_PT, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    return png(fig)


QUIET = 1e-9  # a panel whose every line stays below this carries no information


def conservation(case_results, scene, jumps=None, labels=None, momentum_left_out=None):
    """Relative drift of energy and momentum against time, one line per backend; `jumps`:
    backend -> {'t0', 't1', 'change'}, the interval where its energy jumped, marked. A panel
    in which every backend stays below QUIET is left out and named in a note on the figure; so is
    the momentum panel where its check does not apply (`momentum_left_out`: the reason, e.g.
    reflecting walls exchange momentum: the exact solver's |P(t) − P(0)| is physics there)."""
    if not case_results:
        return None
    labels = labels or {}
    series = []
    for backend, result in case_results:
        s = result["series"]
        t = np.asarray(s["time"], dtype=float)
        if t.size == 0:
            continue
        kinetic = np.asarray(s["kinetic_energy"], dtype=float)
        total = np.asarray(s["total_energy"], dtype=float)
        scale = max(float(np.nanmax(kinetic)), 1e-300)
        energy = total if abs(total[0] - kinetic[0]) > 0 else kinetic
        px = np.asarray(s["momentum_x"], dtype=float)
        py = np.asarray(s["momentum_y"], dtype=float)
        mscale = np.sqrt(2 * max(result.get("total_mass", 0.0), 1e-300) * max(kinetic[0], 1e-300))
        series.append((backend, t, (energy - energy[0]) / scale, np.hypot(px - px[0], py - py[0]) / mscale))
    panels = [(k, title, ylabel) for k, title, ylabel in (
        (2, "energy drift", "(E(t) - E(0)) / max K [dimensionless]"),
        (3, "momentum drift", "|P(t) - P(0)| / sqrt(2 M K(0)) [dimensionless]"))
        if any(np.nanmax(np.abs(x[k])) >= QUIET for x in series if x[k].size) and not (k == 3 and momentum_left_out)]
    if not panels:
        return None
    fig, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 3.6), squeeze=False)
    for ax, (k, title, ylabel) in zip(axes[0], panels):
        for index, x in enumerate(series):
            style, width = STYLES[index % len(STYLES)]
            ax.plot(x[1], x[k], color=colour(x[0]), label=tex(labels.get(x[0], x[0])), linestyle=style,
                    linewidth=width, alpha=0.85)
            jump = (jumps or {}).get(x[0]) if k == 2 else None
            if jump:
                ax.axvspan(jump["t0"], jump["t1"], color=colour(x[0]), alpha=0.2)
        ax.set_xlabel("simulated time [scene time units]")
        ax.set_ylabel(ylabel, fontsize=TEXT_PT)
        ax.set_title(tex(f"{scene}: {title}"), fontsize=TEXT_PT)
        ax.grid(True, alpha=0.3)
        ax.legend(title="backend", fontsize=TEXT_PT, title_fontsize=TEXT_PT, loc="best", framealpha=0.6)
    if len(panels) == 1:
        if panels[0][0] == 2 and momentum_left_out:
            note = tex(f"momentum not drawn: {momentum_left_out}")
        else:
            note = f"{'momentum' if panels[0][0] == 2 else 'energy'}: every backend below {QUIET:g}, not drawn"
        fig.text(0.99, 0.01, note, ha="right", fontsize=TEXT_PT, color="0.4")
    fig.tight_layout()
    return png(fig)


FEW_PAIRS = 10  # fewer pairs than this are drawn one marker each: a histogram of one pair is a flat line
FEW_MARKERS = ("v", "^", "s", "D", "o")
TEXT_PT = 9  # the smallest text of a figure: 10 px at 80 dpi


def overlap_histogram(case_results, scene, labels=None):
    """Distribution of relative overlap depths in the final state, per backend; a backend with
    fewer than FEW_PAIRS pairs as one marker per pair on its own row, so that it stays visible."""
    depths = [(b, np.asarray(r["overlap_depths"], dtype=float)) for b, r in case_results]
    depths = [(b, d[d > 0]) for b, d in depths]
    if not any(d.size for _, d in depths):
        return None
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    low = min(d.min() for _, d in depths if d.size)
    high = max(d.max() for _, d in depths if d.size)
    bins = np.logspace(np.log10(max(low, 1e-17)), np.log10(max(high, low * 10)), 30)
    row = 0
    for backend, d in depths:
        if not d.size:
            continue
        name = (labels or {}).get(backend, backend)
        label = tex(f"{name} ({d.size} pair{'s' if d.size > 1 else ''})")
        if d.size < FEW_PAIRS:
            # one marker per pair at a count of 1, a shape per backend so that none hides another
            ax.plot(d, np.ones(d.size), linestyle="none", marker=FEW_MARKERS[row % len(FEW_MARKERS)], markersize=9,
                    markerfacecolor="none", markeredgewidth=1.6, color=colour(backend), label=label)
            row += 1
        else:
            ax.hist(d, bins=bins, histtype="step", linewidth=1.6, color=colour(backend), label=label)
    ax.set_xscale("log")
    ax.set_xlabel("relative overlap depth (r_i + r_j - d) / (r_i + r_j) [dimensionless]")
    ax.set_ylabel("overlapping pairs [count]")
    from matplotlib.ticker import MaxNLocator
    ax.yaxis.set_major_locator(MaxNLocator(integer=True))  # a count of pairs is an integer
    ax.set_ylim(bottom=0)
    ax.set_title(tex(f"{scene}: overlaps in the final state"), fontsize=TEXT_PT)
    ax.legend(title="backend", fontsize=TEXT_PT, title_fontsize=TEXT_PT, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    return png(fig)


def configuration(result, world, scene, backend):
    """The disks at the start and at the end of one case, side by side, drawn to scale."""
    fig, axes = plt.subplots(1, 2, figsize=(8, 3.9))
    for ax, key, title in ((axes[0], "initial", "initial (t = 0)"),
                           (axes[1], "final", f"final (t = {result['duration']:g})")):
        snap = result[key]
        diameters = 2 * np.asarray(snap["radius"], dtype=float)
        speeds = np.hypot(snap["vx"], snap["vy"]) if snap["vx"] else np.zeros(0)
        collection = EllipseCollection(diameters, diameters, np.zeros_like(diameters), units="xy",
                                       offsets=np.column_stack([snap["x"], snap["y"]]), offset_transform=ax.transData,
                                       cmap="viridis")
        collection.set_array(speeds)
        ax.add_collection(collection)
        if world:
            ax.set_xlim(world[0], world[2])
            ax.set_ylim(world[1], world[3])
        else:
            r = float(diameters.max()) if diameters.size else 1.0
            ax.set_xlim(min(snap["x"]) - r, max(snap["x"]) + r)
            ax.set_ylim(min(snap["y"]) - r, max(snap["y"]) + r)
        ax.set_aspect("equal")
        ax.set_xlabel("x [scene length units]")
        ax.set_ylabel("y [scene length units]")
        ax.set_title(tex(f"{scene} ({backend}): {title}"), fontsize=TEXT_PT)
        fig.colorbar(collection, ax=ax, label="speed |v| [length / time]", shrink=0.8)
    fig.tight_layout()
    return png(fig)
