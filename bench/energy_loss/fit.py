#!/usr/bin/env python3
"""Fit the energy-loss model of the stepped rules at e = 1 to the runs of measure.toml.

Model (docs/stepping-rules.md, "Energy at e = 1"): a disk that receives two or more impulses
from one Jacobi snapshot loses a fraction b of a disk's mean kinetic energy K/N; such
multi-contact disk-steps happen at a rate per disk per time unit r = a nu^2 dt, nu = collisions
per disk per time unit (two independent collisions of one disk falling in one step: Poisson
rate nu, probability of a second within dt ~ nu dt). Relative drift over a duration T:

    D = r T b = a b nu^2 dt T = c nu^2 dt T.

Usage: fit.py OUTDIR   (OUTDIR from `collide validate bench/energy_loss/measure.toml`)
"""
import glob
import math
import os
import sys
import tomllib
from collections import defaultdict


def load(outdir):
    cases = {}
    for path in glob.glob(os.path.join(outdir, "cases", "*.toml")):
        with open(path, "rb") as f:
            cases[os.path.basename(path)[:-5]] = tomllib.load(f)
    return cases


def main(outdir):
    for regime in ("box_gas_1000", "hexagonal_crystal"):
        print(f"\n== {regime}")
        fit(load(outdir), regime)


def fit(cases, regime):
    cases = {k: v for k, v in cases.items() if k.startswith(regime)}
    # collision frequency per disk per time unit from `event`, by (scene, parameters, seed)
    nu_event = {}
    for cid, c in cases.items():
        if c["spec"]["backend"] == "event" and c["status"] == "completed":
            key = cid.replace("__event", "")
            nu_event[key] = 2 * c["contacts"] / (c["disks"] * c["duration"])
    groups = defaultdict(list)
    for cid, c in cases.items():
        if c["spec"]["backend"] != "step" or c["status"] != "completed":
            continue
        parts = cid.split("__")
        seed = parts[-1]
        dt_part = parts[-2]
        key = "__".join([p for p in parts if p not in ("step", dt_part)])
        nu = nu_event[key]
        ke = c["series"]["kinetic_energy"]
        n, t = c["disks"], c["duration"]
        groups["__".join(parts[:-1])].append(dict(
            dt=c["dt"], nu=nu, n=n, t=t, multi=c["counters"].get("multi_contact_disks", 0),
            loss=(ke[0] - ke[-1]) / (ke[0] / n),  # in units of the mean disk energy
            drift=max(abs(k - ke[0]) for k in ke) / max(ke), seed=seed))
    rows = []
    for g, reps in sorted(groups.items()):
        multi = sum(r["multi"] for r in reps)
        exposure = sum(r["n"] * r["t"] for r in reps)
        nu = sum(r["nu"] for r in reps) / len(reps)
        dt = reps[0]["dt"]
        loss = sum(r["loss"] for r in reps)
        drifts = [r["drift"] for r in reps]
        sq = sum(r["loss"] ** 2 for r in reps)
        rows.append(dict(group=g, sq=sq, n=reps[0]["n"], dt=dt, nu=nu, x=nu * nu * dt, rate=multi / exposure, multi=multi,
                         per_event=loss / multi if multi else float("nan"),
                         drift=sum(drifts) / len(drifts), t=reps[0]["t"],
                         drift_sd=(sum((d - sum(drifts) / len(drifts)) ** 2 for d in drifts) /
                                   max(1, len(drifts) - 1)) ** 0.5))
    # a: Poisson maximum likelihood for counts M_g with mean a x_g exposure_g -> a = sum M / sum x E
    sm = sum(r["multi"] for r in rows)
    sx = sum(r["x"] * r["multi"] / r["rate"] for r in rows if r["rate"] > 0)
    a = sm / sx
    a_err = a / math.sqrt(sm)
    per = [r["per_event"] for r in rows if r["multi"] >= 4]
    b = sum(per) / len(per)
    b_sd = (sum((p - b) ** 2 for p in per) / (len(per) - 1)) ** 0.5
    # the change per event has either sign (mean b ~ 0 within its spread): the energy makes a
    # random walk, Var(Delta K / (K/N)) = s^2 M; s^2 pooled over the runs.
    s2 = sum(r["sq"] for r in rows) / sm
    s = math.sqrt(s2)
    s_err = s / math.sqrt(2 * len(rows))
    c = a * b
    c_err = abs(c) * math.hypot(a_err / a, b_sd / b)
    print(f"{'group':58s} {'dt':>7s} {'nu':>7s} {'nu2dt':>8s} {'rate':>9s} {'M':>5s} "
          f"{'loss/ev':>8s} {'drift':>8s} {'pred':>8s} {'rate/fit':>8s}")
    for r in rows:
        # expected max_t |K(t) - K(0)| / K of a random walk: sqrt(pi/2) s sqrt(M) / N
        pred = math.sqrt(math.pi / 2) * s * math.sqrt(a * r["x"] * r["t"] * r["n"]) / r["n"]
        print(f"{r['group']:58s} {r['dt']:7.1e} {r['nu']:7.3f} {r['x']:8.2e} {r['rate']:9.2e} "
              f"{r['multi']:5.0f} {r['per_event']:8.3f} {r['drift']:8.2e} {pred:8.2e} "
              f"{r['rate'] / (a * r['x']):8.2f}")
    print(f"\na = {a:.3f} +- {a_err:.3f}  (multi-contact disk-steps per disk per time = a nu^2 dt; {sm:.0f} events)")
    print(f"b = {b:.3f} +- {b_sd:.3f}  (loss per event / (K/N); sd over {len(per)} groups)")
    print(f"s = {s:.3f} +- {s_err:.3f}  (rms change per event / (K/N))")
    print(f"c = a b = {c:.3f} +- {c_err:.3f}  (drift = c nu^2 dt T)")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "energy_loss_out")
