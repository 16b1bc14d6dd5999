#!/usr/bin/env python3
"""Fills the numbers of docs/reading-a-report.md in from a run of the default suite, so that the
guided tour cannot go stale: every number there sits between markers

    <!--n:KEY-->VALUE<!--/n-->

and this script computes each KEY from RESULTS_DIR (summary.json and the rendered report).

usage: reading_numbers.py RESULTS_DIR DOC.md            rewrite the values in DOC.md
       reading_numbers.py RESULTS_DIR DOC.md --check    exit 1 listing every value that differs
       reading_numbers.py RESULTS_DIR DOC.md --keys     exit 1 if DOC.md names a key not computed
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import digest  # noqa: E402
from safe_files import safe_output  # noqa: E402  (python/collide/safe_output.py)

MARKER = re.compile(r"<!--n:([a-z0-9_.\[\]]+)-->(.*?)<!--/n-->", re.S)


def g(x):
    return f"{x:.3g}"


def numbers(directory):
    s = digest.load_summary(directory)
    fits = digest.orders(s)
    rows = {r["backend"]: r for r in digest.digest(s)}
    totals = digest.combination_totals(digest.combinations(s))
    index = os.path.join(directory, "report", "index.html")
    n = {"cases": str(len(s["cases"])), "cases_ran": str(sum(r["cases"] for r in rows.values())),
         "cases_cannot_run": str(sum(r["cases_cannot_run"] for r in rows.values())),
         **{f"combinations.{k}": str(v) for k, v in totals.items()},
         "index_kb": str(round(os.path.getsize(index) / 1000)) if os.path.exists(index) else "?",
         "pass": str(s["counts"]["pass"]), "fail": str(s["counts"]["fail"]),
         "left_out": str(s["counts"]["left_out"]), "wall": f"{s['wall_seconds']:.1f}",
         "backends": ", ".join(f"`{b}`" for b in rows)}
    for b, r in rows.items():
        n[f"{b}.cases"] = str(r["cases"])
        n[f"{b}.ties"] = str(r["ties"])
        n[f"{b}.pass"] = str(r["pass"])
        n[f"{b}.left_out"] = str(r["left_out"])
        if r["worst"]:
            n[f"{b}.worst"] = f"{r['worst'][0]:.2f}" if r["worst"][0] >= 0.01 else g(r["worst"][0])  # layout: as printed
            n[f"{b}.worst_where"] = f"{r['worst'][1]}: {r['worst'][2].replace('_', ' ')}"
        n[f"{b}.order_trajectory"] = digest.order_summary(r["orders"].get("trajectory", []))
    for f in fits:
        key = f"{f['scene']}.{f['backend']}"
        n[f"{key}.order"] = digest.describe_order(f)
        if f["floor"] or f["bending"]:
            n[f"{key}.floor"] = digest.describe_floor(f)
    for line in s["work_precision"]:
        if not line["error_kind"].startswith("trajectory"):
            continue
        for p in line["points"]:
            key = f"{line['scene']}.{line['backend']}.{p['dt']:g}"
            n[f"{key}.error"] = g(p["error"])
            n[f"{key}.se"] = g(p["error_standard_error"])
    for scene in digest.scenes_in_order(s):
        for b, pts in digest.statistical_points(s, scene, "pressure").items():
            for p in pts:
                key = f"{scene}.{b}.{p['dt']:g}"
                n[f"{key}.z_error"] = g(p["error"])
                n[f"{key}.z_se"] = g(p["se"])
                n[f"{key}.z_sigmas"] = f"{p['sigmas']:.1f}"
                n[f"{key}.z_upper"] = g(p["upper"])
                n[f"{key}.z_detectable"] = g(p["detectable"])
    for f in s.get("bias_fits", []):
        key = f"bias.{f['backend']}.{f['observable']}"
        n[f"{key}.constant"] = f"{f['constant']:.2f} ± {f['standard_error']:.2f}"
        n[f"{key}.model"] = f"{f['model']:.2f} ± {f['model_uncertainty']:.2f}"
        n[f"{key}.chi2_model"] = f"{f['chi2_model']:.1f} on {f['points']}"
    for c in s.get("costs", []):
        if c.get("relative_to_reference"):
            n[f"relative_cost.{c['scene']}.{c['backend']}"] = f"{c['relative_to_reference']:.0f}"
    for a, b, count in digest.identical_backends(s):
        n[f"identical.{b}"] = f"{b} gives the same numbers as {a} bit for bit ({count} compared values)"
    for c in s["checks"]:
        if c["status"] != "left_out":
            n[f"check.{c['subject']}.{c['check']}"] = g(c["value"])
        if isinstance(c.get("predicted"), (int, float)) and math.isfinite(c["predicted"]):
            n[f"predicted.{c['subject']}.{c['check']}"] = g(c["predicted"])
            n[f"predicted_se.{c['subject']}.{c['check']}"] = g(c["predicted_uncertainty"])
    for c in s["cases"]:
        if c["duration"] and c["wall_seconds"] is not None and c["seed"] == 1:
            n[f"cost.{c['id']}"] = g(c["wall_seconds"] / c["duration"])
    md = os.path.join(directory, "report", "summary.md")
    if os.path.exists(md):
        with safe_output.open_input(md, "r", encoding="utf-8") as f:
            n["summary_md_lines"] = str(len(f.read().splitlines()))
    return n


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    directory, doc = sys.argv[1], sys.argv[2]
    mode = sys.argv[3] if len(sys.argv) > 3 else "--write"
    try:
        n = numbers(directory)
    except digest.ReportInputError as e:
        sys.exit(f"reading_numbers: {e}")
    with safe_output.open_input(doc, "r", encoding="utf-8") as f:
        text = f.read()
    keys = MARKER.findall(text)
    unknown = sorted({k for k, _ in keys if k not in n})
    if unknown:
        print(f"{doc}: keys not computed from {directory}: {', '.join(unknown)}", file=sys.stderr)
        sys.exit(1)
    if mode == "--keys":
        return
    stale = [(k, v, n[k]) for k, v in keys if v != n[k]]
    if mode == "--check":
        for k, old, new in stale:
            print(f"{doc}: {k}: the page says {old!r}, the run says {new!r}", file=sys.stderr)
        sys.exit(1 if stale else 0)
    text = MARKER.sub(lambda m: f"<!--n:{m.group(1)}-->{n[m.group(1)]}<!--/n-->", text)
    safe_output.write_text(doc, text)  # atomic, and never into a device or a FIFO
    print(f"{doc}: {len(keys)} numbers from {directory} ({len(stale)} changed)")


if __name__ == "__main__":
    main()
