"""Which backend the report shows beside the reference in a scene's configuration and motion
strips: the one with the largest measured error on that scene, so that a reader sees the worst
a backend of this suite does, not the best (docs/reading-a-report.md, "4. Scenes").

The error is summary.json's work-precision line of each backend (validation/compare: trajectory
error / r_min, mean over the phase replicates, or |Z - Z_ref| / Z_ref of the replicate means),
and a backend's error on a scene is the largest point of its line. Nothing is measured or
judged here: the largest of the numbers `collide validate` wrote is picked, and a backend whose
numbers are another's bit for bit (`aliases`) is left to that one.
"""


def lines(summary, scene, aliases=()):
    """{backend: its work-precision points with an error} on `scene`, aliases left out."""
    out = {}
    for line in summary.get("work_precision", []):
        if line["scene"] != scene or line["backend"] in aliases or line["backend"] == summary["reference"]:
            continue
        points = [p for p in line["points"] if p.get("error") is not None]
        if points:
            out[line["backend"]] = {"kind": line["error_kind"], "points": points}
    return out


def largest_error(summary, scene, aliases=()):
    """{'backend', 'kind', 'points'} of the backend with the largest measured error on `scene`
    (the first in summary order on a tie), or None where no backend was compared with the
    reference there."""
    found = lines(summary, scene, aliases)
    if not found:
        return None
    backend = max(found, key=lambda b: max(p["error"] for p in found[b]["points"]))
    return dict(found[backend], backend=backend)


def error_at(worst, dt):
    """A label for the worst backend's measured error at time step `dt`: 'trajectory error /
    r_min 3.64 ± 0.0012 (mean of 6 replicates)', or None where its line has no point there."""
    for p in worst["points"]:
        if p["dt"] == dt:
            se = p.get("error_standard_error")
            spread = f" ± {se:.2g}" if se else ""
            replicates = f" (mean of {p['replicates']} replicates)" if (p.get("replicates") or 1) > 1 else ""
            return f"{worst['kind']} = {p['error']:.3g}{spread}{replicates}"
    return None
