"""The data of index.html's sections but the scenes (scenes.py): the digest, failures, the check
matrix, left-out checks, orders, bias fits, timings and provenance, as plain values for
templates/index.html.j2 to lay out. Nothing here is HTML.
"""
import math
from collections import OrderedDict

import backend_lines
import digest
import physics
import stability
from analysis import digest_rows, fmt, verdict_text

FAILURES_SHOWN = 200  # failed checks listed on the page; every one is on checks.html


def digest_table(a):
    c = a.summary["counts"]
    verdict_of = {v["backend"]: v for v in a.verdicts}
    empty = {"verdict": "", "low_power": None, "trusted": "", "use_for": [], "use_for_cell": [], "not_for": "", "not_for_list": [], "cannot_run": "", "cost": "", "cost_at_accuracy": [],
             "failed": False}
    what = {b["backend"]: b["short"] for b in backend_lines.backend_lines(a.summary)}
    rows = [dict(r, what=what.get(r["backend"], ""), **{k: v for k, v in verdict_of.get(r["backend"], empty).items()
                                                         if k in empty})
            for r in digest_rows(a)]
    t = a.summary["verdict_thresholds"]
    accuracy = {"z": t.get("confidence_z", 1.96), "trajectory": f"{t.get('trajectory_accuracy', 1e-2):.2g}",
                "pressure": f"{100 * t.get('pressure_accuracy', 5e-3):.2g}",
                "cooling": f"{100 * t.get('cooling_accuracy', 5e-3):.2g}",
                "collision_rate": f"{100 * t.get('collision_rate_accuracy', 5e-3):.2g}"}
    return {"rows": rows, "checks": f"{c['pass']} passed, {c['fail']} failed, {c['left_out']} left out",
            "accuracy": accuracy, "reference": a.summary["reference"]}


def failures(a):
    failed = [c for c in a.summary["checks"] if c["status"] == "fail"]
    return {"count": len(failed), "shown": failed[:FAILURES_SHOWN], "more": max(0, len(failed) - FAILURES_SHOWN)}


def check_matrix(a):
    """One table per scene: a row per backend, a column per check; each cell the counts of its
    cases or groups and the worst margin (None: no such combination)."""
    worst = {}
    for c in a.summary["checks"]:
        m = digest.margin(c)
        key = (c["scene"], c["backend"], c["check"])
        if m is not None and (key not in worst or m > worst[key][0]):
            worst[key] = (m, c.get("quantised", False))
    names = digest.check_order(a.summary)
    tables, anchored = [], set()
    for scene in a.scenes:
        keys = [k for k in a.combinations if k[0] == scene]
        present = [n for n in names if any(k[2] == n for k in keys)]
        rows = []
        for b in OrderedDict.fromkeys(k[1] for k in keys):
            rows.append({"backend": b, "anchor": None if b in anchored else digest.anchor("backend", b),
                         "cells": [cell(a.combinations.get((scene, b, n)), worst.get((scene, b, n))) for n in present]})
            anchored.add(b)  # the digest's links land on a backend's first row
        tables.append({"scene": scene, "anchor": digest.anchor("checks", scene), "combinations": len(keys),
                       "fails": sum(a.combinations[k]["fail"] for k in keys),
                       "checks": [n.replace("_", " ") for n in present], "rows": rows})
    without = [{"backend": b, "anchor": digest.anchor("backend", b)} for b in a.backends if b not in anchored]
    return {"tables": tables, "without_checks": without}


def cell(counts, worst):
    if not counts:
        return None
    status = digest.combination_status(counts)
    text = {"pass": f"{counts['pass']} ✓", "fail": f"{counts['fail']} ✗ of {counts['pass'] + counts['fail']}",
            "left_out": "n/a", "cannot_run": "cannot run"}[status]
    if status == "pass" and counts["left_out"]:
        text += f", {counts['left_out']} n/a"
    if worst and status in ("pass", "fail"):
        text += f" · {'≡' if worst[1] else ''}{fmt(worst[0])}"
    return {"status": status, "text": text}


def left_out(a):
    """Left-out checks grouped by why: how many (scene, backend, check) combinations and checks."""
    cases = digest.subject_cases(a.summary)
    reasons = OrderedDict()
    for c in a.summary["checks"]:
        if c["status"] != "left_out":
            continue
        covered = cases.get(c["subject"], [])
        kind = "cannot run" if digest.cannot_run(c, cases) else "does not apply"
        reason = c["detail"] if kind == "does not apply" else (covered[0].get("diagnostic") or c["detail"])
        entry = reasons.setdefault((kind, c["check"], reason), {"checks": 0, "combos": set(), "scenes": set()})
        entry["checks"] += 1
        entry["combos"].add((c["scene"], c["backend"]))
        entry["scenes"].add(c["scene"])
    return [{"kind": kind, "check": check, "reason": reason, "combinations": len(e["combos"]), "checks": e["checks"],
             "scenes": ", ".join(sorted(e["scenes"]))} for (kind, check, reason), e in reasons.items()]


def statistical_point_text(p):
    """'0.006: +0.0115 ± 0.00217 (z = +5.30, 64 replicates); ...': the relative difference Δ of
    the replicate means with its combined SE and the signed z = Δ / SE they give (summary.json's
    sigmas, signed), so that a reader can recompute z from the row."""
    z = math.copysign(p["sigmas"], p["relative"])
    counted = f", {p['replicates']} replicates" if p.get("replicates") else ""
    if p["resolved"]:
        text = f"{p['dt']:g}: {p['relative']:+.3g} ± {p['se']:.3g} (z = {z:+.2f}{counted})"
    else:
        text = (f"{p['dt']:g}: {p['relative']:+.3g} ± {p['se']:.3g} (z = {z:+.2f}{counted}; not resolved; "
                f"|Δ| ≤ {p['upper']:.2g} at 95 %)")
    if p["predicted"] is not None:
        text += f", predicted {p['predicted']:+.3g}"
    return text + f"; detectable ≥ {p['detectable']:.2g}; {fmt(p['seconds'])} s"


def statistical_limits(summary):
    """'pressure: z ≤ 4 (cpu, opencl, step); speed distribution: KS p ≥ 0.001 (…)': each limit a
    statistical check applied in this run, from its judged checks, stated beside the tables that
    show the numbers it was applied to."""
    kinds = {d["name"]: d["kind"] for d in summary.get("check_definitions", [])}
    limits = OrderedDict()
    for c in summary["checks"]:
        if kinds.get(c["check"]) != "statistics" or c["status"] == "left_out":
            continue
        statistic = "p" if c["comparison"] == ">=" else "|z|"
        key = (c["check"], f"{statistic} {'≥' if c['comparison'] == '>=' else '≤'} {c['tolerance']:g}")
        limits.setdefault(key, set()).add(c["backend"])
    return "; ".join(f"{check.replace('_', ' ')}: {limit} ({', '.join(sorted(b))})"
                     for (check, limit), b in limits.items())


def orders(a):
    """A row per work-precision line: its points (one line of text each) and its fitted order."""
    s, out = a.summary, []
    for line in s["work_precision"]:
        fit = a.fit.get((line["scene"], line["backend"]))
        b = line["backend"]
        if fit["class"] == "trajectory":
            measure = "trajectory error / r_min, mean ± SE over phase replicates"
            points = ["; ".join(f"{p['dt']:g}: {fmt(p['error'])} ± {fmt(p.get('error_standard_error'))}; "
                                f"{fmt(p['seconds_per_time_unit'])} s" for p in line["points"])]
        elif fit["class"] == "Z":
            measure = "(Z − Z_ref) / Z_ref, means ± combined SE"
            points = [statistical_point_text(p)
                      for p in digest.statistical_points(s, line["scene"], "pressure").get(b, [])]
        else:  # τ or ν, paired by seed (summary.json points[].paired)
            x = fit["class"]
            measure = f"({x} − {x}_ref) / {x}_ref, mean ± SE of the per-seed differences"
            points = [statistical_point_text(p)
                      for p in digest.statistical_points(s, line["scene"], "paired").get(b, [])]
        out.append({"scene": line["scene"], "backend": b, "same_as": a.aliases.get(b), "measure": measure,
                    "points": points, "order": digest.describe_order(fit), "floor": digest.describe_floor(fit)})
    return out


def bias_fit_rows(summary):
    out = []
    for f in summary.get("bias_fits", []):
        name = "c_Z" if f["observable"] == "pressure" else "c_ν"
        z = (f["constant"] - f["model"]) / math.hypot(f["standard_error"], f["model_uncertainty"])
        out.append({"backend": f["backend"], "name": name, "fitted": f"{f['constant']:.3g} ± {f['standard_error']:.2g}",
                    "model": f"{f['model']:.3g} ± {f['model_uncertainty']:.2g}", "z": f"{z:+.1f}",
                    "chi2": f"{f['chi2']:.1f} on {f['degrees_of_freedom']}",
                    "chi2_model": f"{f['chi2_model']:.1f} on {f['points']}", "points": f["points"]})
    return out


def machine_text(summary):
    """The machine the timings come from: processor, cores, load, and how many threads each
    case ran with times the cases run at once (summary.json's machine, execution — jobs per rank
    and ranks, validation/run/case_dispatch.cpp — and the cases' provenance), as sentences for the
    timings' paragraph."""
    m = summary.get("machine") or {}
    execution = summary.get("execution") or {}
    jobs = int(execution.get("jobs_per_rank") or 1)
    ranks = int(execution.get("ranks") or 1)
    at_once = jobs * ranks
    threads = OrderedDict()
    for c in summary["cases"]:
        for k, v in (c.get("provenance") or {}).items():
            if k.endswith(".threads") and str(v).isdigit():
                threads.setdefault(c["backend"], set()).add(int(v))
    cores = m.get("cores")
    per_rank = f" ({jobs} per rank × {ranks} ranks)" if ranks > 1 else ""
    parts = [f"Processor: {m.get('cpu_model', 'not recorded')}, {cores} cores; load average when the run ended "
             f"{fmt(m.get('load_1min'))} (1 min), {fmt(m.get('load_5min'))} (5 min), {fmt(m.get('load_15min'))} (15 min); "
             f"{at_once} case{'s' if at_once > 1 else ''} at a time (--jobs){per_rank}."]
    for b, values in threads.items():
        t = max(values)
        busy = t * at_once
        over = f", oversubscribing the {cores} cores" if cores and busy > cores else ""
        parts.append(f"{b}: {t} threads per case × {at_once} cases at a time = {busy} threads{over}.")
    return " ".join(parts)


def costs(summary):
    return [{"scene": c["scene"], "backend": c["backend"], "group": c["group"], "mean": fmt(c["seconds_per_time_unit"]),
             "spread": f"{fmt(c['fastest_replicate'])} – {fmt(c['slowest_replicate'])} ({c['replicates']})",
             "ratio": fmt(c.get("relative_to_reference"))} for c in summary.get("costs", [])]


def provenance(summary):
    rows = dict(summary["provenance"])
    rows["command line"] = summary.get("command_line", "")
    rows["suite file"] = summary.get("suite_file", "")
    for scene, seeds in summary.get("seeds", {}).items():
        rows[f"seeds of {scene}"] = seeds
    for scene, path in summary.get("scene_files", {}).items():
        rows[f"scene file of {scene}"] = path
    devices = sorted({f"{c['backend']}: {v}" for c in summary["cases"] for k, v in c.get("provenance", {}).items()
                      if "device" in k or "platform" in k})
    if devices:
        rows["devices"] = "; ".join(devices)
    return [(k, str(v)) for k, v in rows.items()]


def page(a, drawn):
    """Everything index.html.j2 shows; `drawn` = (headline PNG or None, scene sections) from
    scenes.sections(). The headline is None where the template says why: a stability suite, or
    no work-precision data."""
    headline, scene_sections = drawn
    s = a.summary
    return {"suite": s["suite"], "reference": s["reference"], "description": s.get("description", ""),
            "passed": a.passed, "verdict": verdict_text(a), "is_stability": a.stability,
            "first_failures": stability.first_failure_matrix(s) if a.stability else None,
            "stability": stability.section(s) if a.stability else None,
            "digest": digest_table(a), "backend_lines": backend_lines.backend_lines(s), "identical": a.identical, "physics": physics.section(s),
            "scenes_toc": [(digest.anchor("scene", sc), sc) for sc in a.scenes], "headline": headline,
            "unexpected": a.unexpected, "failures": failures(a), "check_matrix": check_matrix(a),
            "left_out": left_out(a), "has_work_precision": bool(s["work_precision"]), "orders": orders(a),
            "bias_fits": bias_fit_rows(s), "statistical_limits": statistical_limits(s), "scenes": scene_sections, "machine": machine_text(s),
            "costs": costs(s), "provenance": provenance(s)}

