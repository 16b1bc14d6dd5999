"""The page "Engines side by side" (report/engines.html; docs/engines.md): for each engine and
preset of a suite that runs two or more engines (backends that are neither exact nor a stepping
rule: Box2D, Chipmunk2D, the Node engines of engines/), the worst measured energy and momentum
drift, overlap and trajectory error, the pressure and collision-rate differences from the
reference, the cost per disk-step, the engine's version and package hashes, and the
work-precision figure. Each number links to the case it was measured in. It lays out
summary.json and the case records; it judges nothing."""

import math
import os
import statistics

import matplotlib.colors

import figures
import templating
from safe_files import safe_output

# (check, column title): the worst value over the backend's judged cases.
COLUMNS = [("energy_drift", "energy drift"), ("momentum_drift", "momentum drift"), ("max_overlap", "max overlap"),
           ("trajectory_error", "trajectory error / r_min"), ("pressure", "pressure: |z| vs event"),
           ("collision_rate", "collision rate: |z| vs event")]


def engines(summary):
    """The backends the page is about (neither exact, nor a stepping rule, nor a sampler, which has
    no dynamics to compare), in the summary's order."""
    return [name for name, b in summary.get("backends", {}).items()
            if not b.get("exact") and not b.get("stepping_rule") and not b.get("sampler")]


def applies(summary):
    """Two or more engine bases (the default suite's box2d and box2d[shipped] are one)."""
    return len({summary["backends"][b].get("base", b) for b in engines(summary)}) >= 2


def worst(summary, backend, check):
    """(value, case id) of the largest |value| of a measured check, or (None, None)."""
    found = [(abs(c["value"]), c["subject"]) for c in summary["checks"] if c["backend"] == backend and c["check"] == check
             and c["status"] in ("pass", "fail") and isinstance(c.get("value"), (int, float)) and math.isfinite(c["value"])]
    return max(found) if found else (None, None)


def case_link(summary, subject):
    """The record of the case `subject` (a case id, or a group id: its first case), from report/."""
    for case in summary["cases"]:
        if case["id"] == subject or case["group"] == subject:
            return "../" + case["result_file"]
    return None


def cost_per_disk_step(summary, backend):
    """Median seconds per disk and step over the backend's completed cases of its most disks."""
    cases = [c for c in summary["cases"] if c["backend"] == backend and c["status"] == "completed" and c["steps"] > 0]
    if not cases:
        return None, None
    most = max(c["disks"] for c in cases)
    big = [c for c in cases if c["disks"] == most]
    return statistics.median(c["wall_seconds"] / (c["steps"] * c["disks"]) for c in big), most


def provenance(summary, backend):
    """The engine's version, preset and hashed files: what its cases' provenance said it ran on
    (summary.json backends.B.ran_on, the same for every backend)."""
    ran_on = ((summary.get("backends") or {}).get(backend) or {}).get("ran_on") or {}
    return "; ".join(f"{k}: {ran_on[k]}" for k in ("version", "preset", "files_sha256") if k in ran_on)


def rows(summary):
    out = []
    for backend in engines(summary):
        cells = []
        for check, _ in COLUMNS:
            value, subject = worst(summary, backend, check)
            cells.append({"text": "–" if value is None else f"{value:.3g}",
                          "href": case_link(summary, subject) if subject else None})
        cost, disks = cost_per_disk_step(summary, backend)
        cells.append({"text": "–" if cost is None else f"{cost * 1e6:.3g} µs ({disks} disks: {cost * disks * 1e3:.3g} ms/step)",
                      "href": None})
        out.append({"backend": backend, "colour": matplotlib.colors.to_hex(figures.colour(backend)), "cells": cells,
                    "provenance": provenance(summary, backend)})
    return out


def work_precision_figure(summary):
    """Trajectory error against run time per simulated time unit, one line per engine and scene."""
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 5))
    names = engines(summary) + [b for b in summary["backends"] if b not in engines(summary)]
    drawn = False
    for backend in names:
        for line in summary.get("work_precision", []):
            if line["backend"] != backend or not line["error_kind"].startswith("trajectory"):
                continue
            points = [p for p in line["points"] if p.get("error") and p.get("seconds_per_time_unit")]
            if points:
                drawn = True
                ax.plot([p["seconds_per_time_unit"] for p in points], [p["error"] for p in points], "-",
                        marker=figures.marker(backend), color=figures.colour(backend), alpha=0.8)
        ax.plot([], [], "-", marker=figures.marker(backend), color=figures.colour(backend), label=figures.tex(backend))
    if drawn:
        figures.log_scale(ax, "x", "y")
    else:  # a suite of statistics scenes only: no trajectory error to draw
        ax.text(0.5, 0.5, "no trajectory scene in this suite", ha="center", va="center", transform=ax.transAxes,
                fontsize=figures.TEXT_PT)
    ax.set_xlabel("run time per simulated time unit (s)")
    ax.set_ylabel("trajectory error / r_min")
    ax.legend(fontsize=figures.TEXT_PT, ncol=2)
    fig.tight_layout()
    return figures.png(fig)


def write(directory, summary, out):
    """Writes report/engines.html where the suite runs two or more engines; returns its path or None."""
    if not applies(summary):
        return None
    path = os.path.join(out, "engines.html")
    safe_output.check_output_path(path)
    safe_output.write_text(path, templating.render("engines.html.j2", suite=summary["suite"],
                                                   columns=[t for _, t in COLUMNS] + ["cost per disk-step"],
                                                   rows=rows(summary), figure_png=work_precision_figure(summary)))
    return path
