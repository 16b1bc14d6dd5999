"""The checker of chapter 2's last exercise: a student's whole event loop, held to exact dynamics.

    python3 docs/course/lab.py check event_loop FILE.py

FILE.py defines a class EventLoop with the outside-solver protocol's members (load, advance_to,
positions, velocities: docs/your-solver.md). The check has two parts:

1. Probes, in this process: one disk against each wall, a head-on collision of masses 1 and 10,
   a glancing one, and a pair that collides while a third disk flies past. Each has an answer
   known by hand to rounding, so a slip is named at once (the wall's component, the masses'
   shares, the disks left behind at an event).
2. The few-body suite docs/course/event_loop_suite.toml, through `collide validate` with the
   class declared exact (`--solver-exact`): energy to 16 eps per collision, overlaps and wall
   penetration to 64 eps L / r, positions to 1000 times what rounding alone does to `event`,
   up to each chaotic run's predictability horizon (docs/validation.md). The first failing
   check is put in a student's words, with collide's own line beside it.
"""
import json
import math
import pathlib
import shutil
import signal
import subprocess
import tempfile

import numpy as np

from lab_check import ROOT, Unavailable, Wrong, load

SUITE = ROOT / "docs" / "course" / "event_loop_suite.toml"
PROBE_SECONDS = 5            # a probe of two or three disks takes milliseconds
TOLERANCE = 1e-12            # the probes' answers are exact to a few roundings of numbers near 10


# --- 1. Probes: answers known by hand ------------------------------------------------------

def scene(box, boundary="reflect"):
    """The scene dict the protocol's runner passes to load() (solver_runner.read_request)."""
    return {"start_time": 0.0, "xmin": box[0], "ymin": box[1], "xmax": box[2], "ymax": box[3],
            "boundary": boundary, "restitution": 1.0, "wall_restitution": 1.0, "friction": 0.0,
            "gravity_x": 0.0, "gravity_y": 0.0, "damping": 0.0}


def disks(*rows):
    """The initial dict of the protocol from rows (x, y, vx, vy, radius, mass)."""
    table = np.array(rows, dtype=float)
    return {"positions": table[:, 0:2].copy(), "velocities": table[:, 2:4].copy(),
            "radius": table[:, 4].copy(), "mass": table[:, 5].copy(), "stone": np.zeros(len(rows), bool)}


def wall_probes():
    """A disk of radius 0.5 from the centre of a 10 x 10 box into each wall: it touches at
    t = 4.5 (its centre 0.5 from the wall), and at t = 6 has come back 1.5 with the component
    normal to that wall reversed and the other one kept."""
    for name, v, x_end, v_end in (("x = 10", (1.0, 0.25), (8.0, 6.5), (-1.0, 0.25)),
                                  ("x = 0", (-1.0, 0.25), (2.0, 6.5), (1.0, 0.25)),
                                  ("y = 10", (0.25, 1.0), (6.5, 8.0), (0.25, -1.0)),
                                  ("y = 0", (0.25, -1.0), (6.5, 2.0), (0.25, 1.0))):
        hint = (f"at the wall {name} only the velocity component normal to that wall is reversed "
                f"({name[0]} = const reverses v{name[0]}), when the centre is one radius from it")
        yield (f"one disk from (5, 5) at v = {v} into the wall {name}", scene((0, 0, 10, 10)),
               disks((5.0, 5.0, *v, 0.5, 1.0)), 6.0, [x_end], [v_end], hint)


def pair_probes():
    root3 = math.sqrt(3.0)
    # Masses 1 and 10, head-on (data/scenes/head_on_mass_ratio_10.toml): contact at t = 3, then
    # v1 = (1 - 10)/11 = -9/11 and v2 = 2/11 (chapter 1).
    yield ("a disk of mass 1 at speed 1 into one of mass 10 at rest, head-on", scene((0, 0, 12, 4)),
           disks((3.0, 2.0, 1.0, 0.0, 0.5, 1.0), (7.0, 2.0, 0.0, 0.0, 0.5, 10.0)), 4.0,
           [(6.0 - 9.0 / 11.0, 2.0), (7.0 + 2.0 / 11.0, 2.0)], [(-9.0 / 11.0, 0.0), (2.0 / 11.0, 0.0)],
           "the collision rule weighs the masses: v_i' = v_i + 2 m_j / (m_i + m_j) ((v_j - v_i).d / d.d) d "
           "with d = x_j - x_i, and the opposite share 2 m_i / (m_i + m_j) for j")
    # Equal disks at 30 degrees (glancing.toml): contact at t = 4 - sqrt(3)/2 along the unit line
    # of centres n = (sqrt(3)/2, 1/2); the struck disk leaves along n with speed sqrt(3)/2, the
    # other at right angles to it, and at t = 5 both have flown 1 + sqrt(3)/2 time units on.
    hit, flown = (6.0 - root3 / 2, 2.0), 1.0 + root3 / 2
    v1, v2 = (0.25, -root3 / 4), (0.75, root3 / 4)
    yield ("equal disks meeting at 30 degrees", scene((0, 0, 10, 5)),
           disks((2.0, 2.0, 1.0, 0.0, 0.5, 1.0), (6.0, 2.5, 0.0, 0.0, 0.5, 1.0)), 5.0,
           [(hit[0] + v1[0] * flown, hit[1] + v1[1] * flown), (6.0 + v2[0] * flown, 2.5 + v2[1] * flown)],
           [v1, v2],
           "the impulse acts along the line of centres d = x_j - x_i: the components of v_j - v_i along d "
           "are exchanged (equal masses), across d they are kept")
    # head_on_equal's pair meets at t = 1.5 while a third disk flies through the top of the box.
    yield ("two equal disks meeting head-on at t = 1.5 while a third flies past", scene((0, 0, 10, 10)),
           disks((3.0, 2.0, 1.0, 0.0, 0.5, 1.0), (7.0, 2.0, -1.0, 0.0, 0.5, 1.0), (1.0, 7.0, 0.5, 0.25, 0.5, 1.0)),
           2.5, [(3.5, 2.0), (6.5, 2.0), (2.25, 7.625)], [(-1.0, 0.0), (1.0, 0.0), (0.5, 0.25)],
           "every disk flies on to the event's time, not only the disks in the event (advance all of them, "
           "or give each its own clock)")


class TooSlow(Exception):
    pass


def _too_slow(signum, frame):
    raise TooSlow


def run_probe(EventLoop, what, scene_dict, initial, t_end, x_want, v_want, hint):
    solver = EventLoop()
    previous = signal.signal(signal.SIGALRM, _too_slow)
    signal.alarm(PROBE_SECONDS)
    try:
        solver.load(scene_dict, initial)
        solver.advance_to(t_end)
        x, v = np.array(solver.positions, dtype=float), np.array(solver.velocities, dtype=float)
    except TooSlow:
        raise Wrong(f"{what}: advance_to({t_end:g}) did not return within {PROBE_SECONDS} s: an event found "
                    "again and again at the same time? (after a bounce or a collision the disks move apart: "
                    f"that pair or wall is not their next event); {hint}")
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    if x.shape != (len(x_want), 2) or v.shape != (len(x_want), 2):
        raise Wrong(f"{what}: positions {x.shape} and velocities {v.shape}, expected ({len(x_want)}, 2) each")
    for i in range(len(x_want)):
        x_off, v_off = np.max(np.abs(x[i] - x_want[i])), np.max(np.abs(v[i] - v_want[i]))
        if x_off > TOLERANCE or v_off > TOLERANCE:
            raise Wrong(f"{what}: at t = {t_end:g} disk {i} is at ({x[i][0]:.6g}, {x[i][1]:.6g}) with v = "
                        f"({v[i][0]:.6g}, {v[i][1]:.6g}), exact dynamics puts it at ({x_want[i][0]:.6g}, "
                        f"{x_want[i][1]:.6g}) with v = ({v_want[i][0]:.6g}, {v_want[i][1]:.6g}): "
                        + (NUDGED.format(x_off) if v_off <= TOLERANCE and x_off < 1e-6 else hint))


# Right velocities and a position a hair off: not a wrong rule, but a contact moved in time or space.
NUDGED = ("its velocity is right but its position is off by {:.1e}: an event a little late or early, or "
          "disks pushed apart after a contact so as not to find it again; exact dynamics takes every event "
          "at its time and moves nothing else (a pair that has just collided moves apart, b > 0: it is not "
          "found again)")


# --- 2. The suite, through collide validate ------------------------------------------------

# What each failed check says about an event loop, in the order they are reported: the first
# fault explains the others (a missed wall leaves the disk outside, and its positions then differ).
MEANING = {
    "run": "your class did not finish the run",
    "wall_penetration": ("a disk went through a wall: the wall contact comes when the centre is one radius from "
                         "the wall, and reverses the velocity component normal to it"),
    "max_overlap": "two disks overlap: a pair collision was missed or came late",
    "energy_drift": ("the kinetic energy changed: a collision rule that does not conserve it (with unequal "
                     "masses, the shares are 2 m_j / (m_i + m_j) and 2 m_i / (m_i + m_j))"),
    "momentum_drift": "the total momentum changed: the two disks' impulses must be equal and opposite",
    "trajectory_error": ("the disks are not where exact dynamics puts them: an event missed, one at the wrong "
                         "time, disks not moved to the event's time, or disks pushed apart after a contact"),
}
PERIODIC_OVERLAP = ("two disks overlap in the periodic box: a pair meets across the box's edge too, so try "
                    "each pair through the images of the other disk (shifted by -L, 0, +L in x and y) and "
                    "let a disk that leaves through one side enter through the other")


def collide_program():
    program = shutil.which("collide")
    if program is None:
        raise Unavailable("this exercise runs `collide validate`: put the built collide on your PATH "
                          "(0-before-you-start.md)")
    return program


def validate(path, out, collide=None):
    """The suite's summary with the class of `path` declared exact (collide: the program, else PATH's)."""
    command = [collide or collide_program(), "validate", str(SUITE), "--out", str(out), "--jobs", "2",
               "--python-solver", f"you={pathlib.Path(path).resolve()}:EventLoop", "--solver-exact", "you"]
    done = subprocess.run(command, capture_output=True, text=True)
    summary = out / "summary.json"
    if not summary.is_file():
        raise Unavailable(f"`{' '.join(command)}` wrote no summary:\n{done.stdout}{done.stderr}")
    return json.loads(summary.read_text())


def first_failure(summary):
    failed = [c for c in summary["checks"] if c["backend"] == "you" and c["status"] == "fail"]
    for name in MEANING:
        for c in failed:
            if c["check"] == name:
                return c
    return failed[0] if failed else None


def explain(check, summary):
    periodic = any(c["scene"] == check["scene"] and c["backend"] == "you" and c["check"] == "wall_penetration"
                   and c["status"] == "left_out" and "periodic" in c["detail"] for c in summary["checks"])
    words = PERIODIC_OVERLAP if periodic and check["check"].endswith("overlap") else \
        MEANING.get(check["check"], f"collide's check {check['check']} failed")
    return f"{check['subject']}: {words}. collide says: {check['check']}: {check['detail'][:400]}"


def horizons(summary):
    """'scene T_h' for the runs whose positions were judged up to a horizon before their end."""
    cut = [f"{c['scene']} seed {c['seed']} to t = {c['trajectory']['horizon']:g}" for c in summary["cases"]
           if c.get("backend") == "you" and (c.get("trajectory") or {}).get("horizon_reached")]
    return "; ".join(cut)


def refused(summary):
    return [f"{c['scene']} ({c['detail']})" for c in summary["checks"]
            if c["backend"] == "you" and c["check"] == "run" and c["status"] == "left_out"]


def check_event_loop(path):
    """EventLoop, a whole event-driven solver: probes known by hand, then the few-body suite as an
    exact solver to the predictability horizon."""
    try:
        EventLoop = load(path, "EventLoop")
    except Wrong as e:
        raise Wrong(str(e).replace("no function EventLoop()", "no class EventLoop")) from None
    probes = list(wall_probes()) + list(pair_probes())
    for probe in probes:
        run_probe(EventLoop, *probe)
    with tempfile.TemporaryDirectory(prefix="collide-event-loop-") as scratch:
        summary = validate(path, pathlib.Path(scratch) / "out")
    failure = first_failure(summary)
    if failure is not None:
        raise Wrong(explain(failure, summary))
    judged = sum(1 for c in summary["checks"] if c["backend"] == "you" and c["status"] == "pass")
    left = refused(summary)
    return (f"{len(probes)} probes exact; {judged} checks of exact dynamics passed on {SUITE.name}, positions "
            f"judged up to the horizon ({horizons(summary)})"
            + (f"; left out as your class refuses them: {', '.join(left)}" if left else ""))
