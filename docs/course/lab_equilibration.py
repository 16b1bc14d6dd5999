"""Where equilibrium starts, chosen from the data (chapter 4.4): `lab.py equilibration SCENE.toml`.

A run that starts from a lattice first melts; the mean of what it measures must leave the melt
out. Instead of a fixed rule ("drop the first half"), collide takes the cut from the series
itself (core/statistics/batch_means.h, through the module: collide.stationary_mean): of the
starts t0 = 0, n/20, 2n/20, ... n/2, the one that leaves the most effectively independent
samples (n - t0) / (2 tau_int(t0)) (J. D. Chodera, J. Chem. Theory Comput. 12, 1799 (2016)).
While a drift is left in, it looks like a long correlation, tau_int is large and the count is
small; once the drift is cut away tau_int drops to the noise's own. Every pressure collide
records is cut this way; here the series is built in the open so the choice can be watched.

The series: `event`'s beta P d^2 in windows of equal length, from the collision virial V each
window adds (W = Delta V / (2 Delta t)): Z = 1 + ((N - 1) / N) W / K_int, beta P d^2 = Z rho d^2,
K_int the kinetic energy in the centre-of-mass frame (e = 1: conserved), the estimator of the
run record (core/thermo/pressure_estimator.h; docs/validation.md, "Error bars and mixing").
"""
import numpy as np

from lab_structure import collide

ENTRIES = 1000   # windows in the run, as many as the run record makes at least


def pressure_series(scene_path, duration=None, entries=ENTRIES):
    """(window length, beta P d^2 per window) of the scene (equal disks, periodic box) on `event`,
    run for its own duration or `duration`."""
    c = collide()
    scene = c.Scene.from_file(str(scene_path))
    if duration is not None:
        scene = scene.with_overrides({"run.duration": float(duration)})
    sim = c.Simulation(scene, "event")
    radii, masses, m = sim.radii, sim.masses, sim.metrics()
    if not (np.all(radii == radii[0]) and np.all(masses == masses[0]) and scene.periodic):
        raise SystemExit(f"{scene_path}: beta P d^2 is stated for equal disks in a periodic box")
    n, d = len(radii), 2 * float(radii[0])
    x0, y0, x1, y1 = scene.box
    k_int = m["kinetic_energy"] - (m["momentum_x"] ** 2 + m["momentum_y"] ** 2) / (2 * masses.sum())
    rho_d2 = n * d * d / ((x1 - x0) * (y1 - y0))
    window = scene.duration / entries
    series, before = [], 0.0
    for k in range(1, entries + 1):
        sim.advance_to(k * window)
        virial = sim.stats()["counters"]["virial_sum"]
        series.append((1 + (n - 1) / n * (virial - before) / (2 * window) / k_int) * rho_d2)
        before = virial
    return window, np.array(series)


def cuts(scene_path, duration=None):
    """The series of the scene, collide.stationary_mean of it with the cut from the data, and of
    the whole series and its second half for comparison: a dict of window, series, chosen,
    whole, second_half (each an estimate: mean, error, equilibration_cut, candidates ...)."""
    c = collide()
    window, series = pressure_series(scene_path, duration)
    return {"window": window, "series": series, "chosen": c.stationary_mean(series),
            "whole": c.stationary_mean(series, cut_from_data=False),
            "second_half": c.stationary_mean(series[len(series) // 2:], cut_from_data=False)}


def equilibration(scene_path, duration=None):
    """Prints the candidates of the cut, the one chosen and why, and the means it gives."""
    r = cuts(scene_path, duration)
    w, chosen = r["window"], r["chosen"]
    print(f"{len(r['series'])} windows of {w:g}: beta P d^2 on event")
    best = chosen["equilibration_cut"]
    for cut, effective in chosen["candidates"]:
        tau = collide().integrated_autocorrelation_time(r["series"][cut:])
        mark = "  <- the cut" if cut == best else ""
        print(f"  from t = {cut * w:5.2f}: mean {r['series'][cut:].mean():.4f}, tau_int {tau:5.2f}, "
              f"effective samples {effective:6.1f}{mark}")
    for name, what in (("chosen", f"from t = {best * w:g} (the cut from the data)"), ("whole", "the whole run"),
                       ("second_half", f"the second half, from t = {len(r['series']) // 2 * w:g}")):
        e = r[name]
        print(f"beta P d^2 = {e['mean']:.4f} +- {e['error']:.4f} over {what}")
