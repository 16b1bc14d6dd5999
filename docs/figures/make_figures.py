#!/usr/bin/env python3
"""Makes every figure of the course (docs/course/*.md) with the project's own programs.

    python3 docs/figures/make_figures.py [--collide build/release/collide] [--out docs/figures]
                                         [--only NAME ...]

Each figure runs `collide run` (or `collide bench`) on scenes of the library, sometimes with one
[run] key changed, reads the HDF5 run files (docs/output-format.md) and plots with matplotlib.
Nothing is simulated here. The figures of speed depend on the machine they are made on; their
captions in the course say so.
"""
import argparse
import io
import json
import pathlib
import re
import subprocess
import sys
import tempfile

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "data" / "scenes"
# The guard and atomic write every output of collide goes through (docs/refusals.md).
sys.path.insert(0, str(ROOT / "validation" / "report"))
import safe_output  # noqa: E402


class Lab:
    """Runs scenes through `collide run` in a scratch directory and opens the results."""

    def __init__(self, collide, scratch):
        self.collide = collide
        self.scratch = pathlib.Path(scratch)
        self.count = 0

    def scene(self, name, **changes):
        """The scene file `name` with some top-level-table keys replaced (e.g. dt=1e-2)."""
        text = (SCENES / name).read_text()
        for key, value in changes.items():
            text, n = re.subn(rf"(?m)^{key}\s*=.*$", f"{key} = {value}", text, count=1)
            if n != 1:
                raise SystemExit(f"make_figures: {name} has no key {key!r} to change")
        self.count += 1
        path = self.scratch / f"scene{self.count}.toml"
        path.write_text(text)
        return path

    def run(self, scene, backend, frames=False, extra=()):
        self.count += 1
        out = self.scratch / f"run{self.count}.h5"
        command = [self.collide, "run", str(scene), "--backend", backend, "--out", str(out), *extra]
        if frames:
            command.append("--frames")
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            raise SystemExit(f"make_figures: {' '.join(command)} failed:\n{done.stderr}")
        return h5py.File(out, "r")


def finish(fig, ax, out, name, xlabel, ylabel, title, legend=True, legend_loc=None):
    """Labels the axes, writes out/NAME.png and closes the figure."""
    if xlabel:
        ax.set_xlabel(xlabel)
    if ylabel:
        ax.set_ylabel(ylabel)
    ax.set_title(title)
    if legend:
        ax.legend(loc=legend_loc)
    fig.tight_layout()
    png = io.BytesIO()
    fig.savefig(png, format="png", dpi=110)
    safe_output.write_bytes(out / f"{name}.png", png.getvalue())
    plt.close(fig)
    print(f"wrote {out / name}.png")


# --- Chapter 1: one collision -------------------------------------------------------------

def head_on_mass_ratio(lab, out):
    f = lab.run(SCENES / "head_on_mass_ratio_10.toml", "event", frames=True)
    t, v = f["frames/time"][:], f["frames/velocity"][:, :, 0]
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.plot(t, v[:, 0], label="light disk (m = 1)")
    ax.plot(t, v[:, 1], label="heavy disk (m = 10)")
    for value, text in ((-9 / 11, "-9/11"), (2 / 11, "2/11")):
        ax.axhline(value, color="grey", lw=0.6, ls=":")
        ax.text(t[-1], value, f" {text}", va="center", fontsize=8)
    finish(fig, ax, out, "ch1_head_on_mass_ratio",
           "time", "velocity $v_x$", "head_on_mass_ratio_10 on event", legend_loc="center left")


def glancing(lab, out):
    f = lab.run(SCENES / "glancing.toml", "event", frames=True)
    x = f["frames/position"][:]
    fig, ax = plt.subplots(figsize=(6, 3.2))
    for i, label in enumerate(("striker", "target")):
        ax.plot(x[:, i, 0], x[:, i, 1], marker=".", ms=3, label=label)
        ax.add_patch(plt.Circle(x[0, i], 0.5, fill=False, color=f"C{i}", lw=0.8))
    ax.set_aspect("equal")
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 5)
    finish(fig, ax, out, "ch1_glancing", None, None, "glancing on event: the disks leave at a right angle",
           legend_loc="upper left")


def pi_circle(lab, out):
    # Output every 0.002 time units, so almost every state between two collisions is seen.
    f = lab.run(lab.scene("stiff/pi_billiard_k2.toml", output_interval="0.002", duration="12.0"),
                "event", frames=True)
    v = f["frames/velocity"][:, :, 0]
    m = f["particles/mass"][:]
    a, b = np.sqrt(m[0]) * v[:, 0], np.sqrt(m[1]) * v[:, 1]
    keep = np.r_[True, (np.abs(np.diff(a)) + np.abs(np.diff(b))) > 1e-12]
    fig, ax = plt.subplots(figsize=(4.6, 4.6))
    r = np.hypot(a[0], b[0])
    phi = np.linspace(0, 2 * np.pi, 400)
    ax.plot(r * np.cos(phi), r * np.sin(phi), color="grey", lw=0.6)
    ax.plot(a[keep], b[keep], lw=0.5, marker=".", ms=2)
    ax.set_aspect("equal")
    finish(fig, ax, out, "ch1_pi_circle",
           r"$\sqrt{m_1}\,v_1$", r"$\sqrt{m_2}\,v_2$", "pi_billiard_k2: states on the energy circle", legend=False)


# --- Chapter 2: many disks, exactly -------------------------------------------------------

def maxwell(lab, out):
    f = lab.run(lab.scene("box_gas_1000.toml", duration="5.0"), "event", frames=True)
    v, m = f["frames/velocity"][-1], f["particles/mass"][:]
    speed = np.hypot(v[:, 0], v[:, 1])
    kT = np.mean(0.5 * m * speed**2)  # 2D equipartition: <m v^2 / 2> = kT
    s = np.linspace(0, speed.max() * 1.05, 200)
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.hist(speed, bins=30, density=True, alpha=0.6, label="event, t = 5 (1000 disks)")
    ax.plot(s, s / kT * np.exp(-s**2 / (2 * kT)), label=r"$f(v) = (v/kT)\,e^{-v^2/2kT}$, m = 1")
    finish(fig, ax, out, "ch2_maxwell",
           "speed", "probability density", "box_gas_1000: Maxwell-Boltzmann speeds in 2D")


def equation_of_state(lab, out):
    # 400 disks of radius 0.5 in a periodic square box of side L: area fraction 400 pi 0.25 / L^2.
    fractions = [0.05, 0.15, 0.25, 0.35, 0.45, 0.5]
    z = []
    for phi in fractions:
        side = np.sqrt(400 * np.pi * 0.25 / phi)
        scene = lab.scene("periodic_gas.toml", box=f"[0.0, 0.0, {side:.6f}, {side:.6f}]",
                          count="400", duration="4.0")
        f = lab.run(scene, "event")
        pressure = float(f["stats/counters"].attrs["pressure"])
        kT = float(np.mean(f["metrics/kinetic_energy"][:])) / 400  # 2D: K = N kT
        z.append(pressure * side**2 / (400 * kT))
    p = np.linspace(0, 0.6, 200)
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.plot(p, (1 + p**2 / 8) / (1 - p) ** 2, label="Henderson (1975)")
    ax.plot(fractions, z, "o", label="event, 400 disks, t = 4")
    finish(fig, ax, out, "ch2_equation_of_state",
           "area fraction", "Z = PA / NkT", "Hard-disk equation of state from the collision virial")


def snapshot(lab, out):
    f = lab.run(SCENES / "box_gas_1000.toml", "event", frames=True)
    x, r = f["frames/position"][-1], f["particles/radius"][:]
    v = f["frames/velocity"][-1]
    fig, ax = plt.subplots(figsize=(4.6, 4.6))
    speed = np.hypot(v[:, 0], v[:, 1])
    colours = plt.cm.viridis(speed / speed.max())
    for i in range(len(r)):
        ax.add_patch(plt.Circle(x[i], r[i], color=colours[i], lw=0))
    ax.set_xlim(0, 50)
    ax.set_ylim(0, 50)
    ax.set_aspect("equal")
    finish(fig, ax, out, "ch2_snapshot", None, None, "box_gas_1000 at t = 10 (colour: speed)", legend=False)


# --- Chapter 3: many disks, stepped -------------------------------------------------------

GOLDEN = (np.sqrt(5) - 1) / 2


def phase_mean_error(lab, name, striker, backend, dt, phases=6):
    """Mean final position error of `backend` against `event` over collision phases.

    A stepped rule finds a collision at the first step that ends in overlap, so its error
    depends on where the exact collision time falls inside a step. As the validation suite
    does (validation/phase_shift.h), replicate k starts the striker frac(k phi) dt further along
    its path (phi the golden ratio), and the error is averaged over the replicates.
    """
    errors, seconds = [], []
    x0, vx = striker
    for k in range(phases):
        shift = (k * GOLDEN) % 1.0 * dt
        text = f"x = {x0 + vx * shift!r}, y"
        scene = lab.scene(name, dt=f"{dt:g}")
        scene.write_text(scene.read_text().replace(f"x = {x0}, y", text, 1))
        exact = lab.run(scene, "event", frames=True)["frames/position"][-1]
        f = lab.run(scene, backend, frames=True)
        errors.append(np.max(np.linalg.norm(f["frames/position"][-1] - exact, axis=1)))
        seconds.append(sum(float(s) for s in f["stats/phase_seconds"].attrs.values()))
    return float(np.mean(errors)), float(np.std(errors, ddof=1) / np.sqrt(phases)), float(np.mean(seconds))


def convergence(lab, out):
    steps = [2e-2, 1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4]
    fig, ax = plt.subplots(figsize=(6, 3.4))
    for backend in ("step", "cpu"):
        points = [phase_mean_error(lab, "glancing.toml", (2.0, 1.0), backend, dt) for dt in steps]
        ax.errorbar(steps, [p[0] for p in points], yerr=[p[1] for p in points], fmt="o-", capsize=2,
                    label=backend)
    ax.loglog(steps, np.array(steps) * 0.3, "k:", lw=0.8, label="slope 1")
    ax.set_xscale("log")
    ax.set_yscale("log")
    finish(fig, ax, out, "ch3_convergence",
           "dt", "mean position error at t = 5", "glancing: stepped rules against event (6 collision phases)")


def cradle(lab, out):
    fig, ax = plt.subplots(figsize=(6, 3.2))
    for backend, dt in (("event", "1e-3"), ("step", "1e-1"), ("step", "2e-2")):
        f = lab.run(lab.scene("stiff/newtons_cradle.toml", dt=dt), backend, frames=True)
        label = backend if backend == "event" else f"{backend}, dt = {dt}"
        ax.plot(f["frames/time"][:], f["frames/position"][:, 5, 0], label=label)
    ax.set_xlim(0.5, 3)
    finish(fig, ax, out, "ch3_cradle",
           "time", "x of the far disk", "newtons_cradle: the impulse crosses one contact per step")


def energy_crowd(lab, out):
    fig, ax = plt.subplots(figsize=(6, 3.2))
    for backend, dt in (("event", "1e-3"), ("step", "1e-3"), ("step", "2e-3")):
        f = lab.run(lab.scene("box_gas_1000.toml", dt=dt, duration="4.0"), backend)
        t, k = f["metrics/time"][:], f["metrics/kinetic_energy"][:]
        label = backend if backend == "event" else f"{backend}, dt = {dt}"
        ax.plot(t, (k - k[0]) / k[0], label=label)
    finish(fig, ax, out, "ch3_energy_crowd",
           "time", "relative kinetic energy change", "box_gas_1000 at e = 1: energy lost in multi-contact steps")


# --- Chapter 4: validating a solver -------------------------------------------------------

def work_precision(lab, out):
    fig, ax = plt.subplots(figsize=(6, 3.4))
    for backend in ("step", "cpu"):
        points = [phase_mean_error(lab, "head_on_equal.toml", (3.0, 1.0), backend, dt)
                  for dt in (1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2.5e-4)]
        ax.errorbar([p[2] for p in points], [p[0] for p in points], yerr=[p[1] for p in points],
                    fmt="o-", capsize=2, label=backend)
    ax.set_xscale("log")
    ax.set_yscale("log")
    finish(fig, ax, out, "ch4_work_precision",
           "solver time per run (s)", "mean position error at the end",
           "head_on_equal: error against run time (6 collision phases)")


def overlap_series(lab, out):
    fig, ax = plt.subplots(figsize=(6, 3.2))
    for backend in ("step", "cpu", "box2d"):
        f = lab.run(lab.scene("box_gas_1000.toml", duration="4.0"), backend)
        ax.semilogy(f["metrics/time"][:], np.maximum(f["metrics/max_overlap"][:], 1e-9), label=backend)
    finish(fig, ax, out, "ch4_overlap",
           "time", "largest overlap / contact distance", "box_gas_1000: overlap statistics at the output times")


def replicates(lab, out):
    # Pressure of the periodic gas from five seeds: the spread is what an error bar measures.
    z = []
    for seed in range(1, 6):
        f = lab.run(lab.scene("periodic_gas.toml", seed=str(seed), duration="2.0"), "event")
        z.append(float(f["stats/counters"].attrs["pressure"]))
    z = np.array(z)
    fig, ax = plt.subplots(figsize=(6, 3.0))
    ax.plot(range(1, 6), z, "o")
    mean, se = z.mean(), z.std(ddof=1) / np.sqrt(len(z))
    ax.axhspan(mean - se, mean + se, alpha=0.2, label=f"mean ± SE = {mean:.4f} ± {se:.4f}")
    finish(fig, ax, out, "ch4_replicates", "seed", "pressure", "periodic_gas on event, five replicates")


# --- Chapter 5: making it fast ------------------------------------------------------------

def speed_ladder(lab, out):
    prefix = lab.scratch / "bench"
    command = [lab.collide, "bench", "event", "--quick", "--out", str(prefix)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"make_figures: {' '.join(command)} failed:\n{done.stderr}")
    rows = json.loads((lab.scratch / "bench-event.json").read_text())["rows"]
    fig, ax = plt.subplots(figsize=(6, 3.2))
    for phi in sorted({r["area_fraction"] for r in rows}):
        pts = sorted((r["n"], r["ns_per_collision"]) for r in rows if r["area_fraction"] == phi)
        ax.semilogx(*zip(*pts), "o-", label=f"area fraction {phi:g}")
    ax.set_ylim(bottom=0)
    finish(fig, ax, out, "ch5_event_ladder",
           "disks N", "ns per collision", "event: time per collision (collide bench event --quick)")


def threads(lab, out):
    scene = lab.scene("box_gas_1000.toml", duration="2.0")
    fig, ax = plt.subplots(figsize=(6, 3.0))
    names, rates = [], []
    for backend, extra in (("step", ()), ("cpu", ("--threads", "1")), ("cpu", ("--threads", "2"))):
        f = lab.run(scene, backend, extra=extra)
        seconds = sum(float(s) for s in f["stats/phase_seconds"].attrs.values())
        rates.append(1000 * int(f["stats"].attrs["steps"]) / seconds)
        names.append(backend + (f", {extra[1]} thread{'s' if extra[1] != '1' else ''}" if extra else ""))
    ax.barh(names, rates)
    finish(fig, ax, out, "ch5_threads",
           "particle-steps per second", None, "box_gas_1000, 2000 steps: step (double) and cpu (float)",
           legend=False)


FIGURES = {f.__name__: f for f in (head_on_mass_ratio, glancing, pi_circle, maxwell, equation_of_state,
                                    snapshot, convergence, cradle, energy_crowd, work_precision,
                                    overlap_series, replicates, speed_ladder, threads)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--collide", default=str(ROOT / "build" / "release" / "collide"))
    parser.add_argument("--out", default=str(ROOT / "docs" / "figures"))
    parser.add_argument("--only", nargs="*", choices=sorted(FIGURES), help="make only these figures")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    try:
        # The folder is checked before the first run; each figure's file as it is written
        # (its name, e.g. ch1_glancing.png, is chosen by the figure).
        safe_output.make_output_directory(out)
        with tempfile.TemporaryDirectory(prefix="collide-figures-") as scratch:
            lab = Lab(args.collide, scratch)
            for name in args.only or FIGURES:
                FIGURES[name](lab, out)
    except safe_output.OutputPathError as e:
        raise SystemExit(f"make_figures: {e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
