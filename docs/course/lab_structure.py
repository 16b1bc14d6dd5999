"""The structure of a hard-disk configuration for the course (chapter 2.7 and 2.8): what
`lab.py structure RUN.h5` prints, and the checker of exercise 2.8 (`lab.py check gofr`); and
the self-diffusion of chapter 2.9 from a run's frames (the mean-square displacement, and the
velocity autocorrelation function with its Green-Kubo integral, against Enskog).

Every g(r) and psi6 here is collide's own (core/structure, through the Python module built
beside the `collide` program on PATH: collide.pair_correlation, collide.psi6); nothing here
computes them a second time. The checker holds a student's g(r) to collide's, and names the
usual slips by asking collide for the slipped quantity too (the same pairs in a box without
periodic images, for instance).
"""
import pathlib
import shutil
import sys

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "validation" / "report"))
from collide_program import collide_module  # noqa: E402  (the module beside the program)
from lab_check import Unavailable, Wrong, load  # noqa: E402

# The window of the contact value (chapter 2.7): a straight line through 10 bins over [d, 1.05 d]
# (its bias is of second order in the window over the decay length of g near contact, about
# 1 / (beta P d): small against the batch-means error up to eta 0.5, 0.7 % at 0.65).
CONTACT_WIDTH, CONTACT_BINS = 0.05, 10
# Blocks of frames for the batch-means error of the contact value (chapter 4.4).
BLOCKS = 10


def collide():
    """The module `collide`: the one already imported (the figure script loads it beside the
    program it was given), else the one built beside the program on PATH."""
    if "collide" in sys.modules:
        return sys.modules["collide"]
    program = shutil.which("collide")
    if program is None:
        raise Unavailable("this needs collide's Python module: put the built collide on your PATH "
                          "(0-before-you-start.md)")
    return collide_module(program)


def box_scene(width, height, boundary="periodic"):
    """A scene of the given box, for its world only (the module reads the box and boundary)."""
    return collide().Scene.from_toml(f"""description = "a box for g(r) and psi6"
seed = 1
[world]
box = [0.0, 0.0, {float(width)!r}, {float(height)!r}]
boundary = "{boundary}"
[run]
duration = 1.0
output_interval = 1.0
dt = 1e-3
[[particles]]
kind = "list"
disks = [{{ x = 0.5, y = 0.5, vx = 0.0, vy = 0.0, radius = 0.1, mass = 1.0 }}]
""")


# --- lab.py structure RUN.h5 ------------------------------------------------------------------

def batch_contact(c, scene, frames, diameter):
    """g(d) of the frames, and its batch-means error over BLOCKS equal blocks of them (the fit is
    linear in the counts, so the blocks' mean is the fit of all their frames)."""
    per_block = len(frames) // BLOCKS
    values = [c.pair_correlation(scene, frames[k * per_block:(k + 1) * per_block], diameter,
                                 CONTACT_WIDTH * diameter, CONTACT_BINS)["contact"] for k in range(BLOCKS)]
    return float(np.mean(values)), float(np.std(values, ddof=1) / np.sqrt(BLOCKS))


def psi6_per_frame(c, scene, frames, diameter):
    """|psi6| of each frame (neighbours within PSI6_CUTOFF_DIAMETERS diameters)."""
    return np.array([abs(c.psi6(scene, x, c.PSI6_CUTOFF_DIAMETERS * diameter)) for x in frames])


def cut_from_data(c, times, psi6):
    """The time where the run's |psi6| series is stationary, chosen from the series itself by
    collide.stationary_mean (the start that leaves the most effectively independent samples,
    Chodera 2016; chapter 4.4, lab_equilibration.py)."""
    return float(times[c.stationary_mean(psi6)["equilibration_cut"]])


def routes(run, start):
    """The structure of a run of equal disks in a periodic box, from its frames at t >= start
    (start "data": from the cut its |psi6| series chooses, cut_from_data):
    a dict of n, eta, frames, contact (g(d)) and contact_error, z_contact (1 + 2 eta g(d)) and
    its error, z_virial and its error and beta_pressure and its error (the run's collision
    virial, where it has one), mixed (the run's psi6 mixing check) and psi6 (the mean of |psi6|
    over the frames)."""
    c = collide()
    with h5py.File(run, "r") as f:
        if "frames" not in f:
            sys.exit(f"{run}: written without --frames: rerun `collide run ... --frames`")
        times, frames = f["frames/time"][:], f["frames/position"][:]
        radius = f["particles/radius"][:]
        scene = c.Scene.from_toml(f.attrs["scene_text"])
        counters = dict(f["stats/counters"].attrs)
    if not np.all(radius == radius[0]):
        sys.exit(f"{run}: g(r) and Z = 1 + 2 eta g(d) are stated for equal disks")
    n, d = len(radius), 2 * float(radius[0])
    psi6 = psi6_per_frame(c, scene, frames, d) if start == "data" else None
    if start == "data":
        start = cut_from_data(c, times, psi6)
    kept = times >= start
    frames = frames[kept]
    psi6 = psi6[kept] if psi6 is not None else psi6_per_frame(c, scene, frames, d)
    if len(frames) < BLOCKS:
        sys.exit(f"{run}: {len(frames)} frames at t >= {start:g}; at least {BLOCKS} wanted")
    x0, y0, x1, y1 = scene.box
    area = (x1 - x0) * (y1 - y0)
    eta = n * np.pi * d * d / (4 * area)
    contact, error = batch_contact(c, scene, frames, d)
    out = {"n": n, "eta": eta, "frames": len(frames), "contact": contact, "contact_error": error,
           "z_contact": 1 + 2 * eta * contact, "z_contact_error": 2 * eta * error,
           "start": start, "psi6": float(np.mean(psi6))}
    if "beta_pressure" in counters:
        scale = area / (n * d * d)   # Z = beta P / rho = beta P d^2 * A / (N d^2)
        out["z_virial"] = float(counters["beta_pressure"]) * scale
        out["z_virial_error"] = float(counters["beta_pressure_error"]) * scale
        out["beta_pressure"] = float(counters["beta_pressure"])
        out["beta_pressure_error"] = float(counters["beta_pressure_error"])
    if "psi6_mixed" in counters:   # whether the phase of psi6 crossed its range 3 times (Li et al. 2022)
        out["mixed"] = bool(counters["psi6_mixed"])
    return out


def structure(run, start):
    """Prints routes(run, start)."""
    r = routes(run, start)
    chosen = " (the cut from the data: where |psi6| per frame is stationary, chapter 4.4)" if start == "data" else ""
    print(f"{r['n']} disks, eta {r['eta']:.4f}, {r['frames']} frames from t = {r['start']:g}{chosen}")
    print(f"g(d) {r['contact']:.3f} +- {r['contact_error']:.3f} (a line through {CONTACT_BINS} bins over "
          f"[d, {1 + CONTACT_WIDTH:g} d])")
    print(f"Z contact 1 + 2 eta g(d) = {r['z_contact']:.3f} +- {r['z_contact_error']:.3f}")
    if "z_virial" in r:
        print(f"Z virial {r['z_virial']:.3f} +- {r['z_virial_error']:.3f} (the run's collision virial)")
    print(f"|psi6| {r['psi6']:.3f} (mean over the frames; neighbours within {collide().PSI6_CUTOFF_DIAMETERS:g} d)")


# --- Self-diffusion (chapter 2.9) ---------------------------------------------------------------

def unwrapped(frames, box):
    """Positions followed across the periodic box's edges: each frame's step is the nearest image
    of the displacement since the last frame (right while no disk flies half a box between
    frames), summed from the first frame."""
    steps = np.diff(frames, axis=0)
    steps -= box * np.round(steps / box)
    return np.concatenate([frames[:1], frames[0] + np.cumsum(steps, axis=0)])


def msd(x, lag):
    """<|r(t + lag) - r(t)|^2> over the disks and every time origin of the unwrapped frames x."""
    return ((x[lag:] - x[:-lag]) ** 2).sum(-1).mean()


def equilibrium_frames(run, start):
    """The frames at t >= start (evenly spaced) of a run of equal disks in a periodic box, with what
    Enskog's D_E = kT / (m nu) needs: a dict of dt, x (positions unwrapped across the box's edges),
    v (velocities), m, kt = K_int / (N - 1) (the kinetic energy less the centre of mass's, over the
    N - 1 degrees of freedom per dimension left; e = 1 conserves it, so the first frame's serves)
    and nu (the run's own collision rate per disk)."""
    with h5py.File(run, "r") as f:
        if "frames" not in f:
            sys.exit(f"{run}: written without --frames: rerun `collide run ... --frames`")
        times, frames, velocities = f["frames/time"][:], f["frames/position"][:], f["frames/velocity"][:]
        scene_box = [float(v) for v in collide().Scene.from_toml(f.attrs["scene_text"]).box]
        mass = f["particles/mass"][:]
        nu = float(f["stats/counters"].attrs["collision_rate"])
    if not np.all(mass == mass[0]):
        sys.exit(f"{run}: D_E = kT / (m nu) is stated for equal masses")
    box = np.array([scene_box[2] - scene_box[0], scene_box[3] - scene_box[1]])
    n, m = frames.shape[1], float(mass[0])
    p = m * velocities[0].sum(axis=0)
    kt = (0.5 * m * (velocities[0] ** 2).sum() - (p @ p) / (2 * m * n)) / (n - 1)
    later = times >= start
    return {"dt": float(times[1] - times[0]), "x": unwrapped(frames, box)[later], "v": velocities[later], "m": m,
            "kt": kt, "nu": nu}


def diffusion(run, start, lags, blocks=4):
    """D(tau), the slope of the mean-square displacement between tau and 2 tau,
    (MSD(2 tau) - MSD(tau)) / (4 tau) (a slope, so the ballistic start's offset cancels), over the
    disks and the time origins t >= start (frames evenly spaced), at each lag tau (in frames),
    relative to Enskog's D_E = kT / (m nu) with the run's own collision rate nu and
    kT = K_int / (N - 1): a dict of tau, ratio and its error (the spread of `blocks` consecutive
    stretches of origins, each with its own ratio; 2 tau must fit in a stretch), enskog and nu."""
    run = equilibrium_frames(run, start)
    x, dt, nu = run["x"], run["dt"], run["nu"]
    enskog = run["kt"] / (run["m"] * nu)
    slope = lambda y, lag: (msd(y, 2 * lag) - msd(y, lag)) / (4 * lag * dt) / enskog
    stretch = len(x) // blocks
    out = {"tau": [], "ratio": [], "error": [], "enskog": enskog, "nu": nu}
    for lag in lags:
        if 2 * lag >= stretch:
            raise ValueError(f"lag {lag} frames: 2 lags must fit in a stretch of {stretch} frames")
        per_block = [slope(x[b * stretch:(b + 1) * stretch], lag) for b in range(blocks)]
        out["tau"].append(lag * dt)
        out["ratio"].append(float(slope(x, lag)))
        out["error"].append(float(np.std(per_block, ddof=1) / np.sqrt(blocks)))
    return out


# --- The velocity autocorrelation function (chapter 2.9) ---------------------------------------

def velocity_autocorrelation(v, lags):
    """Z(k dt) = <v_i(t) . v_i(t + k dt)> for k = 0 .. lags - 1, over the disks i and every time
    origin t that leaves room for the lag (frames x disks x 2 velocities, evenly spaced): each
    disk's and component's correlation by the FFT, zero-padded to twice the length so that it
    does not wrap around (Allen & Tildesley 2017, section 8.3)."""
    frames = len(v)
    total = np.zeros(frames)
    for component in range(v.shape[2]):   # one at a time: the transform of all frames is large
        spectrum = np.fft.rfft(v[:, :, component], n=2 * frames, axis=0)
        total += np.fft.irfft(np.abs(spectrum) ** 2, axis=0)[:frames].sum(axis=1)
    origins = frames - np.arange(lags)
    return total[:lags] / (v.shape[1] * origins)


def green_kubo(z, dt):
    """D(t) = (1/2) int_0^t Z(s) ds at every lag of Z(s) = <v(0) . v(s)> (the trapezoid rule): the
    Green-Kubo diffusion coefficient in two dimensions, 1/d of the integral of the full dot
    product (Allen & Tildesley 2017, section 2.7; 1/3 in three dimensions)."""
    return 0.5 * np.concatenate([[0.0], np.cumsum((z[1:] + z[:-1]) * dt / 2)])


# The long-time tail measured over 5 to 40 mean free times, in 8 windows evenly spaced in log(nu t):
# after the exponential has died (exp(-5) = 0.7 %) and before the noise (about 0.0015 in C from
# 80 time units of 1152 disks) swamps C ~ 0.005 at nu t = 40; each window's mean of C is
# positive there, so its logarithm is defined.
TAIL_WINDOW, TAIL_BINS = (5.0, 40.0), 8


def tail_slope(collisions, c):
    """The slope p of log C against log(nu t) over TAIL_WINDOW (C ~ (nu t)^p; Alder & Wainwright
    1970: p = -1 in two dimensions) from C's means in TAIL_BINS windows, and the mean of
    nu t C(t) there (the tail's amplitude where p = -1)."""
    edges = np.geomspace(*TAIL_WINDOW, TAIL_BINS + 1)
    where = np.digitize(collisions, edges) - 1
    inside = (where >= 0) & (where < TAIL_BINS)
    mean_c = np.array([c[where == k].mean() for k in range(TAIL_BINS)])
    mean_t = np.array([collisions[where == k].mean() for k in range(TAIL_BINS)])
    amplitude = float(np.mean(collisions[inside] * c[inside]))
    if np.any(mean_c <= 0):   # noise has swamped the tail in a window: no logarithm, no slope
        return float("nan"), amplitude
    return float(np.polyfit(np.log(mean_t), np.log(mean_c), 1)[0]), amplitude


def vacf(run, start, t_max, blocks=4):
    """The velocity autocorrelation function of a run's frames at t >= start, to lag t_max: a dict of
    t, c = Z(t) / Z(0) (normalised, Z(0) = 2 kT / m) and its error, d_gk = D(t) / D_E by Green-Kubo
    and its error, enskog (D_E = kT / (m nu): tau_E = D_E m / kT = 1 / nu, so Enskog's C is
    exp(-nu t)), nu, slope (the tail's, tail_slope) and its error, and amplitude (the mean of
    nu t C) and its error; each error the spread of `blocks` consecutive stretches of origins."""
    run = equilibrium_frames(run, start)
    lags = int(round(t_max / run["dt"])) + 1
    enskog = run["kt"] / (run["m"] * run["nu"])
    stretch = len(run["v"]) // blocks
    if lags >= stretch:
        raise ValueError(f"t_max {t_max:g}: {lags} lags do not fit in a stretch of {stretch} frames")
    t = np.arange(lags) * run["dt"]

    def measured(v):
        z = velocity_autocorrelation(v, lags)
        return (z / z[0], green_kubo(z, run["dt"]) / enskog) + tail_slope(run["nu"] * t, z / z[0])

    whole = measured(run["v"])
    parts = [measured(run["v"][b * stretch:(b + 1) * stretch]) for b in range(blocks)]
    error = [np.std([p[k] for p in parts], axis=0, ddof=1) / np.sqrt(blocks) for k in range(4)]
    return {"t": t, "c": whole[0], "c_error": error[0], "d_gk": whole[1], "d_gk_error": error[1], "enskog": enskog,
            "nu": run["nu"], "slope": whole[2], "slope_error": float(error[2]), "amplitude": whole[3],
            "amplitude_error": float(error[3])}


def green_kubo_mean(result, t1, t2):
    """The mean of vacf's Green-Kubo D(t) / D_E over [t1, t2] (the trapezoid rule): what the slope
    of the mean-square displacement between t1 and t2 measures, since d MSD / dt = 4 D(t)."""
    inside = (result["t"] >= t1 - 1e-9) & (result["t"] <= t2 + 1e-9)
    t, d = result["t"][inside], result["d_gk"][inside]
    return float(np.sum((d[1:] + d[:-1]) * np.diff(t)) / 2 / (t[-1] - t[0]))


# --- Exercise 2.10: Green-Kubo --------------------------------------------------------------

def ornstein_uhlenbeck(disks, frames, dt, tau, kt_over_m, rng):
    """Velocities (frames x disks x 2) of disks whose every component is an Ornstein-Uhlenbeck
    process sampled exactly at spacing dt: <v(0) . v(t)> = 2 (kT/m) exp(-t / tau), D = (kT/m) tau."""
    a = np.exp(-dt / tau)
    v = np.empty((frames, disks, 2))
    v[0] = rng.normal(0, np.sqrt(kt_over_m), (disks, 2))
    kicks = rng.normal(0, np.sqrt(kt_over_m * (1 - a * a)), (frames, disks, 2))
    for k in range(1, frames):
        v[k] = a * v[k - 1] + kicks[k]
    return v


def green_kubo_hint(got, want, z0, z_end, dt):
    """The slip that explains a wrong D, where one does (got and want from the same velocities)."""
    ratio = got / want
    near = lambda value: abs(ratio - value) < 0.01 * value
    if near(2 / 3):
        return ("2/3 of D: 1/3 is three dimensions' factor; in d dimensions D = (1/d) int <v(0) . v(t)> dt, "
                "and a disk moves in d = 2")
    if near(2):
        return ("twice D: the factor 1/2 of two dimensions is missing (MSD = 4 D t and d MSD/dt = "
                "2 int_0^t <v(0) . v(s)> ds give D = (1/2) int <v(0) . v(t)> dt)")
    if near(0.5):
        return "half of D: <v(0) . v(t)> is the full dot product vx vx + vy vy, with the factor 1/2 taken once"
    if near(1 / z0):
        return ("D over <v . v>: that is the integral of the normalised C(t), a time; integrate "
                "<v(0) . v(t)> itself (D = (kT/m) int C dt)")
    if abs(got - (want + dt * (z0 - z_end) / 4)) < 0.002 * want:
        return "the rectangle rule: integrate with the trapezoid rule, half weight at t = 0 and t = t_max"
    return ("D = (1/2) int_0^t_max <v_i(t0) . v_i(t0 + t)> dt, averaged over the disks and every origin t0 that "
            "leaves room for the lag, the trapezoid rule over the frames")


def check_green_kubo(path):
    """green_kubo(v, dt, t_max) -> D = (1/2) int_0^t_max <v(0) . v(t)> dt of velocities v (frames x
    disks x 2) sampled every dt, held to this module's velocity_autocorrelation and green_kubo on
    Ornstein-Uhlenbeck velocities (relative 1 %: another choice of origins passes, the rectangle
    rule, 2 % off at these spacings, does not), whose exact D is printed beside."""
    d_of = load(path, "green_kubo")
    rng = np.random.default_rng(10)
    for disks, frames, dt, tau, kt_over_m, t_max in ((300, 3000, 0.02, 0.5, 0.7, 3.0),
                                                      (200, 2000, 0.08, 2.0, 1.3, 12.0)):
        v = ornstein_uhlenbeck(disks, frames, dt, tau, kt_over_m, rng)
        z = velocity_autocorrelation(v, int(round(t_max / dt)) + 1)
        want = green_kubo(z, dt)[-1]
        got = float(d_of(v.copy(), dt, t_max))
        if not abs(got - want) < 0.01 * want:
            exact = kt_over_m * tau * (1 - np.exp(-t_max / tau))
            raise Wrong(f"green_kubo on {disks} disks, {frames} frames every {dt:g}, kT/m = {kt_over_m:g}, velocity "
                        f"memory exp(-t/{tau:g}), t_max = {t_max:g}: D = {got:.5g}; these velocities give "
                        f"{want:.5g} (the process's exact D to t_max is {exact:.5g}): "
                        f"{green_kubo_hint(got, want, z[0], z[-1], dt)}")
    return "D within 1 % on two sets of Ornstein-Uhlenbeck velocities, 2-D's factor 1/2 and the trapezoid rule"


# --- Exercise 2.8: g(r) ---------------------------------------------------------------------

def random_disks(n, box, sigma, rng):
    """n disks of diameter sigma placed one by one at random, each where it overlaps none
    (nearest image): a configuration with pairs at every distance, many across the edges."""
    x = np.empty((0, 2))
    while len(x) < n:
        p = rng.uniform(0, 1, 2) * box
        d = x - p
        d -= box * np.round(d / box)
        if len(x) == 0 or (d ** 2).sum(axis=1).min() >= sigma * sigma:
            x = np.vstack([x, p])
    return x


def gofr_hint(got, want, r, mirror_free):
    """The slip that explains a wrong g, where one does."""
    both = (want > 0) & (got > 0)
    ratio = got[both] / want[both]
    if np.allclose(got, mirror_free, rtol=1e-9, atol=1e-12):
        return ("pairs across the box's edge are missing: the distance of a pair in a periodic box is that of the "
                "nearest image, each component of d brought into [-L/2, L/2] (d - L round(d / L))")
    if ratio.size and np.allclose(ratio, ratio[0], rtol=1e-9):
        return (f"every bin is off by the same factor {ratio[0]:.6g}: count each pair once and divide by the "
                "N (N - 1) / 2 pairs of an ideal gas of the same N (each disk has N - 1 partners, not N)")
    if ratio.size > 2 and np.allclose(ratio / r[both], ratio[0] / r[both][0], rtol=1e-9):
        return ("the bins are off by a factor that grows in proportion to r: the ideal gas puts pairs in a shell "
                "of area pi (r2^2 - r1^2) = 2 pi r dr, r the bin's centre (not the contact distance, not dr alone)")
    return "g = pairs in the bin / (N (N - 1) / 2 * pi (r2^2 - r1^2) / A), with nearest-image distances"


def check_gofr(path):
    """pair_correlation(x, box, sigma, width, bins) -> g in `bins` equal bins over [sigma,
    sigma + width] for one configuration x (N x 2) of disks in a periodic box (Lx, Ly), held to
    collide.pair_correlation bin by bin (relative 1e-9) on configurations with many pairs across
    the box's edges."""
    g_of = load(path, "pair_correlation")
    c = collide()
    rng = np.random.default_rng(8)
    cases = [((12.0, 10.4), 1.0, 60, 0.5, 10), ((9.0, 9.0), 1.0, 40, 0.1, 5), ((7.5, 11.0), 0.8, 50, 2.0, 40)]
    for box, sigma, n, width, bins in cases:
        x = random_disks(n, np.array(box), sigma, rng)
        theirs = c.pair_correlation(box_scene(*box), x, sigma, width, bins)
        want, r = np.asarray(theirs["g"]), np.asarray(theirs["r"])
        got = np.asarray(g_of(x.copy(), box, sigma, width, bins), dtype=float)
        if got.shape != want.shape:
            raise Wrong(f"pair_correlation on {n} disks, {bins} bins: an array of shape {got.shape}, {want.shape} wanted")
        if not np.allclose(got, want, rtol=1e-9, atol=1e-12):
            mirror_free = np.asarray(c.pair_correlation(box_scene(*box, "reflect"), x, sigma, width, bins)["g"])
            worst = int(np.argmax(np.abs(got - want)))
            raise Wrong(f"{n} disks of diameter {sigma:g} in a periodic {box[0]:g} x {box[1]:g} box, {bins} bins over "
                        f"[{sigma:g}, {sigma + width:g}]: bin {worst} (r = {r[worst]:.3f}) g = {got[worst]:.6g}, collide "
                        f"says {want[worst]:.6g}: {gofr_hint(got, want, r, mirror_free)}")
    return "g(r) equal to collide's in every bin on three configurations with pairs across the box's edges"
