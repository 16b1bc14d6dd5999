"""The physics section's published finite-N rows: `event`, `ecmc` and `metropolis` against
pressures published at the N and in the box shape that were simulated (Li et al. 2022, ECMC;
data/references/li_2022.toml), and against each other.

Every number comes from summary.json's physics rows of kind "published_finite_n" and
"routes_agree" (validation/compare/published_rows.cpp computes and judges them); this module lays
out one table row per published point and backend (N, box, estimator, equilibration cut,
correlation time, error bar, z), one row per point with the routes side by side, and draws
beta P d^2 against the area fraction for each N with the published points.
"""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import figures  # noqa: E402  (png, TEXT_PT)

KIND = "published_finite_n"
ROUTES = "routes_agree"
# One marker per route in the figure (the published points are open circles).
ROUTE_MARKERS = {"event": "x", "event-plain": "1", "ecmc": "+", "metropolis": "^"}


def rows(summary, kind=KIND):
    return [r for r in (summary.get("physics") or {}).get("rows", []) if r["row"] == kind]


def _signed_z(r):
    f = r.get("score_from") or {}
    return "n/a" if f.get("z") is None else f"{f['z']:+.2f}"


def z_with_its_numbers(f):
    """'z = +1.44 from 7.8262 ± 0.0021 against 7.82305 ± 0.00061' from a row's score_from: the
    numbers z was computed from, printed to the digits that recompute it (test_report_data.py);
    the physics table prints the same, with the estimator."""
    return (f"z = {f['z']:+.2f} from {f['value']:.6g} ± {f['standard_error']:.3g} against {f['reference']:.6g} ± "
            f"{f['reference_uncertainty']:.3g}")


def _z_with_its_numbers(r):
    f = r.get("score_from") or {}
    return z_with_its_numbers(f) if f.get("z") is not None else "z = n/a"


def _num(value, digits):
    return "n/a" if value is None else f"{value:.{digits}g}"


def _fact(r, name, digits=3):
    return _num((r.get("facts") or {}).get(name), digits)


def _verdict(r):
    if (r.get("facts") or {}).get("mixed") == 0:
        return "not mixed (shown, not judged)"
    return {"pass": "pass", "fail": "FAIL", "shown": "shown, not judged"}[r["verdict"]]


def table(summary):
    """One dictionary of cell texts per published row."""
    out = []
    for r in rows(summary):
        out.append({
            "published": r["published"], "backend": r["backend"], "disks": _fact(r, "disks", 9),
            "box": r["box"], "eta": _num(r["parameter"], 4), "estimator": r["estimator"],
            "equilibration": _fact(r, "equilibration"), "correlation_time": _fact(r, "correlation_time"),
            "value": f"{_num(r['value'], 7)} ± {_num(r['standard_error'], 2)}",
            "relative_error": _fact(r, "relative_error", 2), "relative_error_max": _fact(r, "relative_error_max", 2),
            "replicates": r["replicates"],
            "reference": f"{_num(r['reference'], 7)} ± {_num(r['reference_uncertainty'], 2)}",
            "z": _signed_z(r) if r.get("score_from") else _num(r["score"], 3), "verdict": _verdict(r), "detail": r["detail"],
            "class": {"pass": "pass", "fail": "fail"}.get(r["verdict"], "lo")})
    return out


def routes(summary):
    """One dictionary per published point: the published value, each route's value and z against
    it, and each route's z against `event` on the difference (the "routes_agree" rows)."""
    points = {}
    for r in rows(summary):
        p = points.setdefault(r["published"], {"published": r["published"], "disks": _fact(r, "disks", 9),
                                               "box": r["box"], "eta": _num(r["parameter"], 4),
                                               "reference": f"{_num(r['reference'], 7)} ± {_num(r['reference_uncertainty'], 2)}",
                                               "routes": [], "agreement": []})
        p["routes"].append({"backend": r["backend"], "z": _z_with_its_numbers(r), "verdict": _verdict(r)})
    for r in rows(summary, ROUTES):
        if r["published"] in points:
            points[r["published"]]["agreement"].append({
                "pair": f"{r['backend']} − {r['reference_name'].split(' ')[0]}", "z": _z_with_its_numbers(r),
                "verdict": _verdict(r), "detail": r["detail"],
                "class": {"pass": "pass", "fail": "fail"}.get(r["verdict"], "lo")})
    return list(points.values())


def figure(summary):
    """beta P d^2 against the area fraction, one panel per N: the published points (open, with
    their error bars) and the measured ones (filled); a row that has not mixed is drawn grey."""
    points = [r for r in rows(summary) if r["value"] is not None]
    if not points:
        return None
    sizes = sorted({int(r["facts"]["disks"]) for r in points})
    backends = sorted({r["backend"] for r in points}, key=lambda b: (b != "event", b))
    # The legends under the panels (constrained layout makes room): above them they hid points.
    fig, axes = plt.subplots(1, len(sizes), figsize=(4.6 * len(sizes), 5.2), squeeze=False, layout="constrained")
    for ax, n in zip(axes[0], sizes):
        mine = [r for r in points if int(r["facts"]["disks"]) == n]
        for box in sorted({r["box"] for r in mine}):
            at = [r for r in mine if r["box"] == box]
            line = ax.errorbar([r["parameter"] for r in at], [r["reference"] for r in at],
                               yerr=[r["reference_uncertainty"] for r in at], marker="o", markerfacecolor="white",
                               linestyle="none", label=f"{box}: {at[0]['reference_name']}")
            colour = line[0].get_color()
            for r in at:
                mixed = (r.get("facts") or {}).get("mixed") != 0
                # Each route drawn a little to the right of the published point, in its own place,
                # so that routes which agree do not hide one another.
                shift = 0.0012 * (1 + backends.index(r["backend"]))
                ax.errorbar([r["parameter"] + shift], [r["value"]], yerr=[r["standard_error"]],
                            marker=ROUTE_MARKERS.get(r["backend"], "s"), linestyle="none",
                            color=colour if mixed else "grey")
        for b in [b for b in backends if any(r["backend"] == b for r in mine)]:  # the routes of this panel
            ax.plot([], [], marker=ROUTE_MARKERS.get(b, "s"), linestyle="none", color="black", label=f"{b} (± 1 SE)")
        ax.set_title(f"N = {n}")
        ax.set_xlabel("area fraction η = Nπr²/A")
        ax.set_ylabel("βPd² (d the diameter)")
        ax.margins(x=0.08, y=0.12)  # no point on the frame
        ax.legend(fontsize=figures.TEXT_PT, loc="upper center", bbox_to_anchor=(0.5, -0.2))
    return figures.png(fig)


def section(summary):
    """The data of templates/finite_n.html.j2, or None when the suite has no published rows."""
    if not rows(summary):
        return None
    return {"table": table(summary), "routes": routes(summary), "figure": figure(summary)}
