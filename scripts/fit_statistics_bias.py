#!/usr/bin/env python3
"""Fit the constants of the stepped rules' bias model in Z and in the collision rate.

The model (validation/models/statistics_bias_model.h, docs/validation.md) predicts, for a stepped
rule of step h = dt / substeps on a gas whose exact collision rate per disk is nu (from event),

    Z_step - Z_event   = c_Z  * nu h / (4 s (2 + s))      (s: the contact shell, 0.05)
    nu_step - nu_event = -c_nu * nu^2 h / 2

with c_Z = c_nu = 1 from the derivation. This script reads the case files of a
`collide validate` run of scripts/statistics_bias.toml (running it first unless --no-run),
forms replicate means with standard errors, and fits c_Z and c_nu by weighted least squares
through the origin, per scene and backend and pooled, printing residuals in standard errors.

    python3 scripts/fit_statistics_bias.py --collide build/release/collide --out results/statistics_bias

Pure Python (tomllib, Python >= 3.11): no NumPy needed.
"""
import argparse
import math
import os
import subprocess
import sys
import time
import tomllib
from collections import defaultdict

SHELL = 0.05  # validation/judge/observables.h: contact_shell


def mean_se(xs):
    n = len(xs)
    m = sum(xs) / n
    if n < 2:
        return m, float("nan")
    var = sum((x - m) ** 2 for x in xs) / (n - 1)
    return m, math.sqrt(var / n)


def load(out):
    groups = defaultdict(lambda: {"Z": [], "nu": []})
    folder = os.path.join(out, "cases")
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".toml"):
            continue
        with open(os.path.join(folder, name), "rb") as f:
            r = tomllib.load(f)
        if r.get("status") != "completed":
            continue
        scene = name.split("__")[0]
        backend = name.split("__")[1]
        h = r["dt"] / max(1, r.get("substeps", 1)) if backend != "event" else 0.0
        zs = r["compressibility"]
        g = groups[(scene, backend, h)]
        g["Z"].append(sum(zs) / len(zs))
        g["nu"].append(2.0 * r["contacts"] / (r["disks"] * r["duration"]))
    return groups


def fit_through_origin(xs, ys, ses):
    """y = c x, weights 1/se^2: c, its standard error, chi^2 / dof."""
    sw = sum(x * x / s ** 2 for x, s in zip(xs, ses))
    c = sum(x * y / s ** 2 for x, y, s in zip(xs, ys, ses)) / sw
    chi2 = sum(((y - c * x) / s) ** 2 for x, y, s in zip(xs, ys, ses))
    dof = max(1, len(xs) - 1)
    return c, math.sqrt(1 / sw), chi2 / dof


def run_suite(a):
    """Runs the suite into a.out. Its exit status cannot tell a refused suite from failed checks
    (1 for both), so the suite is planned first (`--plan`, which exits 1 only on a refusal), and
    the run must leave a summary.json newer than its start: a refused or crashed run must not
    leave an older run in a.out to be fitted as if it were this one."""
    planned = subprocess.run([a.collide, "validate", a.suite, "--plan"], capture_output=True, text=True)
    if planned.returncode != 0:
        sys.exit(f"{a.suite} cannot run: {planned.stderr.strip()}")
    started = time.time()
    # The pressure checks of this run are the plain or model checks of the build; their
    # verdicts do not matter here, only the case files.
    subprocess.run([a.collide, "validate", a.suite, "--out", a.out, "--jobs", a.jobs], stdout=subprocess.DEVNULL)
    summary = os.path.join(a.out, "summary.json")
    if not os.path.exists(summary) or os.path.getmtime(summary) < started:
        sys.exit(f"collide validate {a.suite} ended without writing {summary}: nothing to fit")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--collide", default="build/release/collide")
    ap.add_argument("--suite", default=os.path.join(os.path.dirname(__file__), "statistics_bias.toml"))
    ap.add_argument("--out", default="results/statistics_bias")
    ap.add_argument("--jobs", default="2")
    ap.add_argument("--no-run", action="store_true", help="only fit an existing run in --out")
    ap.add_argument("--backends", default="step,cpu", help="stepped backends pooled in the fit")
    ap.add_argument("--markdown", action="store_true", help="also print the residuals of the pooled backends as a Markdown table")
    a = ap.parse_args()
    if not a.no_run:
        run_suite(a)
    groups = load(a.out)
    pooled = set(a.backends.split(","))
    rows = []
    for (scene, backend, h), g in sorted(groups.items()):
        if backend == "event":
            continue
        ref = groups.get((scene, "event", 0.0))
        if not ref:
            continue
        z, z_se = mean_se(g["Z"])
        zr, zr_se = mean_se(ref["Z"])
        nu, nu_se = mean_se(g["nu"])
        nur, nur_se = mean_se(ref["nu"])
        rows.append(dict(scene=scene, backend=backend, h=h, n=len(g["Z"]),
                         dZ=z - zr, dZ_se=math.hypot(z_se, zr_se), Zref=zr,
                         dnu=nu - nur, dnu_se=math.hypot(nu_se, nur_se), nuref=nur,
                         xZ=nur * h / (4 * SHELL * (2 + SHELL)), xnu=-nur * nur * h / 2))

    def fit(sel, label):
        out = {}
        for q, x, y, s in (("Z", "xZ", "dZ", "dZ_se"), ("nu", "xnu", "dnu", "dnu_se")):
            c, c_se, chi = fit_through_origin([r[x] for r in sel], [r[y] for r in sel], [r[s] for r in sel])
            out[q] = (c, c_se, chi)
            print(f"{label:<34} c_{q:<2} = {c:.4f} +- {c_se:.4f}   chi2/dof = {chi:.2f}   ({len(sel)} points)")
        return out

    print("Fits of Z_b - Z_event = c_Z nu h/(4 s(2+s)) and nu_b - nu_event = -c_nu nu^2 h/2:")
    for scene in sorted({r["scene"] for r in rows}):
        for backend in sorted({r["backend"] for r in rows if r["scene"] == scene}):
            fit([r for r in rows if r["scene"] == scene and r["backend"] == backend], f"{scene} {backend}")
    for scene in sorted({r["scene"] for r in rows}):
        fit([r for r in rows if r["scene"] == scene and r["backend"] in pooled], f"{scene} " + "+".join(sorted(pooled)))
    sel = [r for r in rows if r["backend"] in pooled]
    best = fit(sel, "pooled " + "+".join(sorted(pooled)))
    (cz, cz_se, cz_chi), (cn, cn_se, cn_chi) = best["Z"], best["nu"]
    # Model uncertainty: the fit's error, inflated by sqrt(chi^2/dof) where the points scatter
    # more than their error bars (the model's second-order terms and correlated replicates).
    print(f"\nmodel constants: c_Z = {cz:.3f} +- {cz_se * max(1, math.sqrt(cz_chi)):.3f}, "
          f"c_nu = {cn:.3f} +- {cn_se * max(1, math.sqrt(cn_chi)):.3f}")
    print("\nscene          backend     h        Z_ref   dZ measured       dZ model  resid/SE  |dZ|/SE"
          "   nu_ref  dnu measured      dnu model  resid/SE")
    for r in rows:
        pz, pn = cz * r["xZ"], cn * r["xnu"]
        print(f"{r['scene']:<14} {r['backend']:<8} {r['h']:8.1e} {r['Zref']:7.4f} "
              f"{r['dZ']:+8.4f} +- {r['dZ_se']:.4f} {pz:+8.4f} {(r['dZ'] - pz) / r['dZ_se']:+7.2f} "
              f"{abs(r['dZ']) / r['dZ_se']:7.1f}   {r['nuref']:6.4f} {r['dnu']:+8.4f} +- {r['dnu_se']:.4f} "
              f"{pn:+8.4f} {(r['dnu'] - pn) / r['dnu_se']:+7.2f}")
    if a.markdown:
        print()
        for r in rows:
            if r["backend"] not in pooled:
                continue
            pz, pn = cz * r["xZ"], cn * r["xnu"]
            print(f"| {r['scene']} | {r['backend']} | {r['h']:.1e} | {r['dZ']:+.4f} ± {r['dZ_se']:.4f} | {pz:+.4f} "
                  f"| {(r['dZ'] - pz) / r['dZ_se']:+.2f} | {abs(r['dZ']) / r['dZ_se']:.1f} "
                  f"| {r['dnu']:+.4f} ± {r['dnu_se']:.4f} | {pn:+.4f} | {(r['dnu'] - pn) / r['dnu_se']:+.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
