"""The data of index.html's scene sections: each scene's figures, drawn by forked processes (one
scene each, as many at a time as there are cores), and the energy jumps `collide validate`
found and explained (summary.json's `energy_jumps`). templates/scene.html.j2 lays them out.
"""
import math
import multiprocessing
import os
import tomllib
from concurrent.futures import ProcessPoolExecutor, as_completed

import animations
import digest
import figures
import largest_error
import progress
import trajectory
from safe_files import safe_output  # the input guard: no FIFO waited on


def scene_box(path):
    try:
        with safe_output.open_input(path, "rb") as f:
            return tomllib.load(f).get("world", {}).get("box")
    except (OSError, tomllib.TOMLDecodeError):
        return None


def drawn_cases(summary, directory, scene):
    """[(backend, case, its record)] for the cases of a scene the report draws, one per backend,
    as summary.json marks them (`drawn`: the rule is validation/summary/drawn_cases.h, one
    definition, by which `collide validate` chooses the cases whose jumps it explains). Only these records
    are read (`collide report` has checked every listed record before the renderer starts)."""
    return [(case["backend"], case, digest.load_case(directory, case)) for case in summary["cases"]
            if case["scene"] == scene and case["drawn"]]


def energy_jumps(summary):
    """The energy jumps `collide validate` found in the drawn cases and explained, rerunning each
    case up to its jump (validation/explain/report_jumps.h): summary.json's `energy_jumps`. The
    report reads them and runs no solver (docs/refusals.md, "What collide never does")."""
    return summary["energy_jumps"]


def jumps_by_scene(a, jumps):
    """{scene: {backend: (case, jump)}} for the backends drawn (an alias is drawn as its twin)."""
    cases = {c["id"]: c for c in a.summary["cases"]}
    out = {}
    for j in jumps:
        if j["backend"] not in a.aliases and j["case"] in cases:
            out.setdefault(j["scene"], {})[j["backend"]] = (cases[j["case"]], j)
    return out


def explanation_text(jump):
    """The step, the disks and the kind of contact behind a jump, as `collide explain` words
    them (`collide validate` wrote them into summary.json); or why they could not be named."""
    if jump.get("problem") or not jump.get("explained"):
        return f" The step could not be named: {jump.get('problem') or 'no explanation recorded'}."
    found = jump["explained"]
    share = ""
    interval = jump["change"] * jump["scale"]  # the output interval's change
    if interval and math.isfinite(found["energy_change"]):
        share = f" That step is {100 * found['energy_change'] / interval:.0f} % of the interval's change."
    return f" In detail: {found['description']}.{share}"


def jump_notes(a, jumps):
    """The notes under a scene's conservation figure, or None without a jump."""
    notes = []
    for backend, (case, j) in jumps.items():
        note = {"backend": backend, "case": case["id"], "explanation": explanation_text(j), "change": None}
        if "change" in j:  # else its record could not be read back for the search
            note.update(change=f"{100 * j['change']:+.2g}", t0=f"{j['t0']:g}", t1=f"{j['t1']:g}",
                        median=f"{100 * j['median']:.2g}")
        notes.append(note)
    if not notes:
        return None
    return {"notes": notes, "box2d": any(digest.facts(a.summary, b).get("base") == "box2d" for b in jumps)}


def left_out_reason(summary, scene, check):
    """Why `check` does not apply to `scene` (the left-out reason `collide validate` gave for the
    reference's cases, e.g. reflecting walls for momentum), or None where it applies."""
    reasons = [c["detail"] for c in summary["checks"] if c["scene"] == scene and c["check"] == check and
               c["backend"] == summary["reference"]]
    judged = any(c["status"] != "left_out" for c in summary["checks"] if c["scene"] == scene and c["check"] == check
                 and c["backend"] == summary["reference"])
    return None if judged or not reasons else reasons[0]


def configuration_figure(summary, a, scene, chosen):
    """The configuration figure of a scene, the ids of the cases it draws and whether the
    reference is outlined on the other: the reference's drawn case (else the first drawn) and
    beside it the drawn case of the backend with the largest measured error on the scene
    (largest_error.py), labelled with that error."""
    by_backend = {b: (c, r) for b, c, r in chosen}
    first = summary["reference"] if summary["reference"] in by_backend else chosen[0][0]
    ref_case, ref_result = by_backend[first]
    worst = largest_error.largest_error(summary, scene, a.aliases)
    beside = None
    if worst is not None and worst["backend"] in by_backend:
        case, result = by_backend[worst["backend"]]
        label = f"at dt = {case['dt']:g}: " + (largest_error.error_at(worst, case["dt"]) or "no error measured")
        beside = (worst["backend"], result, label)
    outlines = beside is not None and worst["kind"].startswith("trajectory")
    png = figures.configuration(scene, scene_box(summary.get("scene_files", {}).get(scene, "")),
                                (first, ref_result), beside, outlines=outlines)
    return png, [ref_case["id"]] + ([by_backend[beside[0]][0]["id"]] if beside else []), outlines


def scene_section(summary, directory, a, scene, chosen, jumps):
    """One scene's figures (PNG bytes, None where a figure has nothing to show) and notes; the
    energy-jump notes are filled in by the process that lays the page out."""
    section = {"scene": scene, "anchor": digest.anchor("scene", scene), "empty": not chosen, "jumps": None}
    if not chosen:
        return section
    shown = [(b, r) for b, _, r in chosen if b not in a.aliases]
    labels = {b: " = ".join([b] + [x for x, y in a.aliases.items() if y == b]) for b, _ in shown}
    configuration, configuration_cases, outlines = configuration_figure(summary, a, scene, chosen)
    section.update(
        work_precision=figures.work_precision(summary, scene, digest, a.aliases, a.fit),
        shown=", ".join(f"{b} at dt = {c['dt']:g}, seed {c['seed']}" for b, c, _ in chosen),
        conservation=figures.conservation(shown, scene, {b: j for b, (_, j) in jumps.items()}, labels,
                                          left_out_reason(summary, scene, "momentum_drift")),
        overlaps=figures.overlap_histogram(shown, scene, labels),
        configuration=configuration, configuration_cases=configuration_cases, configuration_outlines=outlines,
        motion=animations.section(summary, directory, scene, a.aliases),
        trajectory=trajectory.section([(b, c, r) for b, c, r in chosen if b not in a.aliases], scene, labels))
    return section


_SHARED = {}  # what the drawing processes inherit when forked (nothing is pickled but a scene name)


def _scene_section_worker(scene):
    """A scene's section, its drawn records read in the drawing process (records are read in
    parallel, not one after another before the drawing starts)."""
    s = _SHARED
    chosen = drawn_cases(s["summary"], s["directory"], scene)
    return scene_section(s["summary"], s["directory"], s["a"], scene, chosen, s["requests"].get(scene, {}))


def _headline_worker(_):
    s = _SHARED
    return figures.headline(s["a"].summary, digest, s["a"].aliases)


def _with_progress(pool, scenes, meanwhile):
    """The headline figure and each scene's section from the pool (the headline submitted first:
    it is the largest single figure), in scene order, with a progress line on the way
    (progress.py: in place on a terminal, quiet in short logs). `meanwhile` runs in this process
    once the drawing has started."""
    headline = pool.submit(_headline_worker, None)
    futures = [pool.submit(_scene_section_worker, scene) for scene in scenes]
    if meanwhile is not None:
        meanwhile()
    line = progress.ProgressLine()
    done = 0
    for _ in as_completed(futures):
        done += 1
        line.update(done / len(futures), f"report: {done} of {len(futures)} scenes drawn")
    line.finish()
    return headline.result(), [f.result() for f in futures]


def sections(summary, directory, a, meanwhile=None):
    """The headline figure's PNG (None where it has nothing to show) and every scene's section,
    in scene order: all drawn by forked processes, as many at a time as there are cores.
    `meanwhile` (no arguments) runs in this process while they draw: it would otherwise wait
    idle, and the pages without figures need no figure (make_report.py)."""
    requests = jumps_by_scene(a, energy_jumps(summary))
    cores = max(1, os.cpu_count() or 1)
    _SHARED.update(summary=summary, directory=directory, a=a, requests=requests)
    try:
        with ProcessPoolExecutor(max_workers=cores, mp_context=multiprocessing.get_context("fork")) as pool:
            headline, drawn = _with_progress(pool, a.scenes, meanwhile)
    finally:
        _SHARED.clear()
    for section in drawn:
        section["jumps"] = jump_notes(a, requests.get(section["scene"], {}))
    return headline, drawn
