"""Strips of frames for the report: for each trajectory scene, the backend with the largest
measured error on it (largest_error.py) against the exact reference drawn as outlines, at the
largest and at the smallest time step of the sweep, so the sweep's error is seen and not only
read. The pictures are drawn by `collide render`
(the viewer's own drawing path, docs/viewer.md), never by a second drawing code here.

Needs run files written with frames (`[output] frames = true` in the suite, as suites/full.toml
has); a suite without frames gets a one-line note instead.
"""
import os
import subprocess
import tempfile

import largest_error
from collide_program import collide_program

FRAMES = 5          # panels per strip
PANEL = "320x180"   # pixels of one panel


def has_frames(case):
    """Whether the case's run file holds frames (summary.json's `frames`, which validate
    records from the suite's [output] frames; the file itself is read by `collide render`)."""
    return bool(case.get("frames")) and bool(case.get("hdf5_file"))


def trajectory_scenes(summary):
    ids = {c["subject"] for c in summary["checks"] if c["check"] == "trajectory_error" and c["status"] != "left_out"}
    # A check's subject is a case id, or a sweep group's id for checks over replicates.
    return {c["scene"] for c in summary["cases"] if c["id"] in ids or c.get("group") in ids}


def chosen_pair(summary, directory, scene, aliases=()):
    """(reference case, [case at largest dt, at smallest dt] of the backend with the largest
    measured error, the worst backend's work-precision line) or None."""
    done = [c for c in summary["cases"] if c["scene"] == scene and c["status"] == "completed" and c.get("hdf5_file")]
    refs = [c for c in done if c["reference"]]
    if not refs:
        return None
    ref = min(refs, key=lambda c: c["seed"])
    # Whether a case stored frames is in summary.json; only the cases drawn are opened, by
    # `collide render`.
    if not has_frames(ref):
        return None
    worst = largest_error.largest_error(summary, scene, aliases)
    if worst is None:
        return None
    runs = sorted((c for c in done if c["backend"] == worst["backend"] and c["seed"] == ref["seed"]),
                  key=lambda c: c["dt"])
    if not runs:
        return None
    drawn = [runs[-1]] if len(runs) == 1 else [runs[-1], runs[0]]
    if not all(has_frames(c) for c in drawn):
        return None
    return ref, drawn, worst


def render_strip(collide, directory, case, ref):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "strip.png")
        result = subprocess.run([collide, "render", os.path.join(directory, case["hdf5_file"]), "--compare",
                                 os.path.join(directory, ref["hdf5_file"]), "--out", out, "--frames", str(FRAMES),
                                 "--size", PANEL], capture_output=True, text=True)
        if result.returncode != 0:
            return None
        with open(out, "rb") as f:
            return f.read()


def section(summary, directory, scene, aliases=()):
    """One scene's strips for templates/scene.html.j2: None for a scene that is not compared by
    trajectory, {"why": ...} where there are none, else {"frames", "reference", "strips": [{"png",
    "backend", "dt", "error"}]} (a strip `collide render` could not draw has no png; `error`: the
    backend's measured error at that dt, largest_error.error_at)."""
    if scene not in trajectory_scenes(summary):
        return None
    pair = chosen_pair(summary, directory, scene, aliases)
    collide = collide_program()
    if pair is None or collide is None:
        return {"why": "the suite stored no frames" if pair is None else "no collide program was found to draw them"}
    ref, cases, worst = pair
    return {"frames": FRAMES, "reference": ref["backend"],
            "strips": [{"png": render_strip(collide, directory, case, ref), "backend": case["backend"],
                        "dt": f"{case['dt']:g}", "error": largest_error.error_at(worst, case["dt"])}
                       for case in cases]}
