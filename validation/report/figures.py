"""Figures of the validation report, one function per figure kind.

Every function returns a PNG as bytes (or None when there is nothing to draw), reduced to a
256-colour palette (the figures are flat colours; a third of the size of full colour);
the templates (templates/*.html.j2) embed them as base64 with the caption beside each. Every number drawn is
one summary.json or a case record holds. Axes carry units: lengths and times
are in the scene's own units, run time in seconds of wall-clock time.
"""
import io
import json
import textwrap

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



def log_scale(ax, *axes):
    """Log scale on `axes` ("x", "y") with the minor ticks at 2 and 5 of each decade only: the
    default labels every minor tick of an axis spanning under a decade, and at a figure's width
    '4×10⁻³' runs into '6×10⁻³'. Labels at 2, 5 and 10 are at least 0.3 decade apart."""
    from matplotlib.ticker import LogFormatterSciNotation, LogLocator
    for name in axes:
        axis = ax.xaxis if name == "x" else ax.yaxis
        (ax.set_xscale if name == "x" else ax.set_yscale)("log")
        axis.set_minor_locator(LogLocator(subs=(2.0, 5.0)))
        axis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(1, 0.4)))

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


# Markers of several backends at one abscissa (the same area fraction, the same time step) are
# drawn this fraction of the axis' data range apart, centred on their abscissa (side_by_side).
SIDE_STEP = 0.025


def side_by_side(backends, step):
    """{backend: offset along x} that draws the markers of `backends` at one abscissa `step`
    apart, centred on it, in their order: values that agree (the two exact solvers, to rounding)
    stay visible beside each other instead of one hidden under the other. A figure that uses it
    states each backend's offset in its legend."""
    middle = (len(backends) - 1) / 2
    return {b: (k - middle) * step for k, b in enumerate(backends)}


def smallest_text_px(fig, dpi):
    """The height in PNG pixels of the smallest visible text of `fig` saved at `dpi` (a point is
    1/72 inch): the browser test scales it to the displayed size and holds it to 10 px."""
    from matplotlib.text import Text
    sizes = [t.get_fontsize() for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
    return min(sizes) * dpi / 72 if sizes else None


def _drawn_texts(fig):
    """[(text artist, its box in display pixels)] of every text `fig` draws, recorded while the
    canvas draws (the renderer is asked for every line of text it puts on the canvas), so a tick
    label outside the view or a hidden text is not counted. The renderer names the artist of a
    one-line text only; the artist being drawn names it for the lines of a longer one."""
    from matplotlib.text import Text
    renderer = fig.canvas.get_renderer()
    drawn, being_drawn = {}, []
    draw_text, text_draw = renderer.draw_text, Text.draw

    def drawing(self, renderer_):
        being_drawn.append(self)
        try:
            return text_draw(self, renderer_)
        finally:
            being_drawn.pop()

    def recording(gc, x, y, s, prop, angle, ismath=False, mtext=None):
        artist = mtext if mtext is not None else (being_drawn[-1] if being_drawn else None)
        if artist is not None and s.strip():
            drawn[id(artist)] = artist
        return draw_text(gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)
    renderer.draw_text, Text.draw = recording, drawing
    try:
        fig.canvas.draw()
    finally:
        del renderer.draw_text
        Text.draw = text_draw
    return [(text, text.get_window_extent(renderer)) for text in drawn.values()]


def drawn_text_boxes(fig):
    """[[left, top, right, bottom, text]] in pixels of the canvas (origin at the top left, as in
    the PNG) of every text `fig` draws: tick labels, axis labels, titles, legend entries,
    annotations."""
    height = fig.bbox.height
    return [[round(b.x0, 1), round(height - b.y1, 1), round(b.x1, 1), round(height - b.y0, 1), t.get_text()]
            for t, b in _drawn_texts(fig)]


def boxes_overlap(a, b, slack=1.0):
    """Whether two boxes [left, top, right, bottom, ...] share more than `slack` pixels in both
    directions (text boxes include the font's line spacing: touching is not overlapping)."""
    return (min(a[2], b[2]) - max(a[0], b[0]) > slack) and (min(a[3], b[3]) - max(a[1], b[1]) > slack)


# Where a point's label may go, in points from the point, with its alignment: right and above
# first (the old fixed place), then the other corners and sides.
LABEL_PLACES = [((4, 4), "left", "bottom"), ((4, -4), "left", "top"), ((-4, 4), "right", "bottom"),
                ((-4, -4), "right", "top"), ((6, 0), "left", "center"), ((-6, 0), "right", "center"),
                ((0, 7), "center", "bottom"), ((0, -7), "center", "top")]


def _marker_boxes(ax):
    """The boxes in display pixels of the markers of `ax`'s lines: a label is not put on a point."""
    boxes = []
    for line in ax.lines:
        if line.get_marker() in (None, "None", "none", "") or not line.get_visible():
            continue
        half = line.get_markersize() * DPI / 72 / 2
        xy = ax.transData.transform(np.column_stack([line.get_xdata(), line.get_ydata()]).astype(float))
        boxes += [[x - half, y - half, x + half, y + half] for x, y in xy if np.isfinite(x) and np.isfinite(y)]
    return boxes


def place_labels(ax, labels):
    """Annotates the points `labels` = [(x, y, text, colour)] in order, each at the first of
    LABEL_PLACES where it overlaps no text already drawn and stays inside the axes; a label with
    no such place is left out. Call after the figure's layout is final (the places are measured
    on the canvas at the PNG's resolution). Returns how many were left out."""
    fig = ax.figure
    fig.set_dpi(DPI)
    taken = [[b.x0, b.y0, b.x1, b.y1] for _, b in _drawn_texts(fig)] + _marker_boxes(ax)
    renderer = fig.canvas.get_renderer()
    inside = ax.get_window_extent(renderer)
    left_out = 0
    for x, y, text, colour_ in labels:
        for offset, ha, va in LABEL_PLACES:
            note = ax.annotate(text, (x, y), textcoords="offset points", xytext=offset, ha=ha, va=va,
                               fontsize=TEXT_PT, color=colour_)
            b = note.get_window_extent(renderer)
            box = [b.x0, b.y0, b.x1, b.y1]
            if (b.x0 >= inside.x0 and b.x1 <= inside.x1 and b.y0 >= inside.y0 and b.y1 <= inside.y1
                    and not any(boxes_overlap(box, t, slack=-1.0) for t in taken)):
                taken.append(box)
                break
            note.remove()
        else:
            left_out += 1
    return left_out


DPI = 80  # the PNGs' resolution: TEXT_PT = 9 pt is 10 px


def png(fig, dpi=DPI):
    """The figure as a 256-colour PNG whose text chunks record its smallest text
    (`smallest-text-px`, smallest_text_px) and the box of every text it draws (`text-boxes`,
    JSON of drawn_text_boxes): the report's tests hold them to 10 px at the displayed size,
    to no two texts overlapping and to no text cut by the figure's edge."""
    fig.set_dpi(dpi)  # the canvas is the PNG: drawn once, at the PNG's resolution
    smallest = smallest_text_px(fig, dpi)
    boxes = drawn_text_boxes(fig)
    from PIL import Image, PngImagePlugin  # Debian's python3-pil, a dependency of matplotlib
    picture = Image.frombuffer("RGBA", fig.canvas.get_width_height(), fig.canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
    palette = picture.convert("RGB").quantize(colors=256, method=Image.Quantize.FASTOCTREE)
    plt.close(fig)
    info = PngImagePlugin.PngInfo()
    if smallest is not None:
        info.add_text("smallest-text-px", f"{smallest:.2f}")
    info.add_text("text-boxes", json.dumps(boxes, ensure_ascii=False))
    out = io.BytesIO()
    palette.save(out, format="PNG", pnginfo=info)
    return out.getvalue()


def tex(text):
    """A label from data (scene or backend names) as literal text: '$' would start mathtext."""
    return str(text).replace("$", r"\$")


def draw_points(ax, points, colour_, label, marker="o", labels=None):
    """One line of a work-precision diagram. points: [{'x', 'y', 'se', 'resolved', 'upper'?,
    'label'}] sorted as they are to be joined. A resolved point is filled, with its error bar
    (±1 SE); an unresolved one (difference below 2 SE) is drawn hollow at its 95 % upper limit
    'upper' = |Δ| + 1.96 SE (summary.json) and labelled "not resolved". The points' labels (dt,
    "not resolved") are appended to `labels` as (x, y, text, colour) for place_labels, which
    puts them where they overlap nothing once the layout is final; without `labels` the points
    are not labelled. Returns the resolved points' line."""
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
    if labels is not None:
        for p in points:
            y = p["y"] if p["resolved"] else max(p["upper"], 1e-17)
            text = ", ".join(([p["label"]] if p.get("label") else []) +
                             (["not resolved"] if not p["resolved"] else []))
            if text:
                labels.append((p["x"], y, text, colour_))
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
            draw_points(ax, trajectory_points(line), colour(line["backend"]), None, marker)
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
                draw_points(ax, points, colour(backend), None, marker)
                draw_prediction(ax, points, colour(backend))
        draw_reference_costs(ax, summary, statistical_scenes, with_names=False)
        ax.set_title(f"{title}: relative difference of means ± SE")
        ax.set_ylabel(ylabel)
        if check == "pressure":
            used_scenes += [(sc, scene_marker(sc)) for sc in statistical_scenes]
    for ax in fig.axes:
        log_scale(ax, "x", "y")
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
    labels = []
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
        draw_points(ax, points, colour(b), label, labels=None if b in aliases else labels)
        if statistical:
            draw_prediction(ax, points, colour(b))
    for _, cost in reference_costs(summary, [scene]):
        ax.axvline(cost, color=colour(summary["reference"]), linestyle="--", linewidth=1,
                   label=tex(f"{summary['reference']} (exact): its cost"))
    log_scale(ax, "x", "y")
    ax.set_xlabel("wall time per simulated time unit [s]")
    if statistic == "Z":
        ax.set_ylabel("|Z − Z_ref| / Z_ref (means ± SE) [dimensionless]")
    elif statistical:
        ax.set_ylabel(f"|{statistic} − {statistic}_ref| / {statistic}_ref (paired ± SE)")
    else:
        ax.set_ylabel("trajectory error / r_min, mean ± SE [dimensionless]")
    ax.set_title(tex(f"{scene}: work against precision"))
    ax.grid(True, which="both", alpha=0.3)
    handles, _ = ax.get_legend_handles_labels()
    if handles:
        ax.legend(title="backend", fontsize=TEXT_PT, title_fontsize=TEXT_PT, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout(rect=(0, 0.05, 1, 1))  # the bottom strip: the note of labels left out
    left_out = place_labels(ax, labels)
    if left_out:
        fig.text(0.01, 0.01, f"{left_out} of {len(labels)} point labels left out where they would overlap",
                 fontsize=TEXT_PT, color="0.4")
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
    log_scale(ax, "x")
    # More than a decade: the log axis labels its decades only (its minor labels would overlap).
    ax.set_xlim(bins[0] / 1.5, bins[-1] * 1.5)
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


PANEL_INCHES = 3.0  # the width of one configuration panel
TITLE_CHARACTERS = 38  # a panel title longer than this is wrapped: 3 in at 9 pt
STRETCH = 10  # a box longer than this many times its height is drawn stretched, not to scale


def _disks(ax, snap, norm, outlined=None, stretched=False):
    """One snapshot's disks to scale, filled by speed; `outlined`: another snapshot drawn over
    them as black outlines (the reference, so that a lag or a missed collision shows). In a
    stretched panel a disk is a sliver: its centre is marked too."""
    diameters = 2 * np.asarray(snap["radius"], dtype=float)
    speeds = np.hypot(snap["vx"], snap["vy"]) if snap["vx"] else np.zeros(0)
    if stretched:
        ax.scatter(snap["x"], snap["y"], c=speeds, cmap="viridis", norm=norm, s=36, edgecolors="black", zorder=3)
    filled = EllipseCollection(diameters, diameters, np.zeros_like(diameters), units="xy",
                               offsets=np.column_stack([snap["x"], snap["y"]]), offset_transform=ax.transData,
                               cmap="viridis", norm=norm)
    filled.set_array(speeds)
    ax.add_collection(filled)
    if outlined is not None:
        d = 2 * np.asarray(outlined["radius"], dtype=float)
        ax.add_collection(EllipseCollection(d, d, np.zeros_like(d), units="xy", facecolors="none", edgecolors="black",
                                            linewidths=1.0, offsets=np.column_stack([outlined["x"], outlined["y"]]),
                                            offset_transform=ax.transData))
    return filled


def _frame(ax, world, snaps):
    """The scene's box (or the disks' extent without one), equal scales unless the box is more
    than STRETCH times longer than high; returns whether it was stretched."""
    if world:
        x0, y0, x1, y1 = world
    else:
        r = max([max(s["radius"]) for s in snaps if s["radius"]] + [1.0])
        x0, x1 = min(min(s["x"]) for s in snaps) - r, max(max(s["x"]) for s in snaps) + r
        y0, y1 = min(min(s["y"]) for s in snaps) - r, max(max(s["y"]) for s in snaps) + r
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    stretched = max(x1 - x0, y1 - y0) > STRETCH * max(min(x1 - x0, y1 - y0), 1e-300)  # layout: aspect of the panel
    ax.set_aspect("auto" if stretched else "equal")
    if stretched:
        from matplotlib.ticker import MaxNLocator
        ax.yaxis.set_major_locator(MaxNLocator(2))
    return stretched


def _aspect(world, snaps):
    """Height over width of what a configuration panel shows."""
    if world:
        return (world[3] - world[1]) / max(world[2] - world[0], 1e-300)
    xs = [x for s in snaps for x in s["x"]] or [0.0]
    ys = [y for s in snaps for y in s["y"]] or [0.0]
    return (max(ys) - min(ys) + 1.0) / (max(xs) - min(xs) + 1.0)


def configuration(scene, world, reference, worst=None, outlines=True):
    """The disks at the start and at the end of the reference case, and, where another backend
    was compared with it, that backend's final state beside it, with the reference's final disks
    as black outlines where `outlines` (trajectory scenes: in a many-body gas the positions
    decorrelate and only statistics are compared). `reference`: (backend, case record);
    `worst`: (backend, case record, label), the backend with the largest measured error
    (largest_error.py) and what that error is."""
    ref_name, ref = reference
    panels = [(ref["initial"], None, "initial (t = 0)"),
              (ref["final"], None, f"{ref_name}, final (t = {ref['duration']:g})")]
    if worst is not None:
        name, result, label = worst
        title = f"{name}, final" + (f" (outlines: {ref_name})" if outlines else "") + f" {label}"
        panels.append((result["final"], ref["final"] if outlines else None, textwrap.fill(title, TITLE_CHARACTERS)))
    snaps = [p[0] for p in panels]
    fastest = max([float(np.max(np.hypot(s["vx"], s["vy"]))) for s in snaps if s["vx"]] + [1e-300])
    norm = matplotlib.colors.Normalize(vmin=0, vmax=fastest)
    height = PANEL_INCHES * min(max(_aspect(world, snaps), 0.25), 1.0) + 1.5  # titles, labels
    fig, axes = plt.subplots(1, len(panels), figsize=(PANEL_INCHES * len(panels) + 1.2, height), squeeze=False,
                             layout="constrained")
    for ax, (snap, outlined, title) in zip(axes[0], panels):
        stretched = _frame(ax, world, snaps)
        filled = _disks(ax, snap, norm, outlined, stretched)
        ax.set_xlabel("x [length]" + (" (stretched: centres marked)" if stretched else ""))
        ax.set_ylabel("y [length]")
        ax.set_title(tex(title), fontsize=TEXT_PT)
    fig.colorbar(filled, ax=list(axes[0]), label="speed |v| [length / time]", shrink=0.8)
    fig.suptitle(tex(scene), fontsize=TEXT_PT)
    return png(fig)
