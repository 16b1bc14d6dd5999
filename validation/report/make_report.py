#!/usr/bin/env python3
"""Renders the report of a validation run: DIR/report/index.html (self-contained: figures are
embedded as base64 PNG) and DIR/report/summary.md, from DIR/summary.json and DIR/cases/*.toml
as written by `collide validate`. Called by `collide report DIR`; docs/reading-a-report.md is
a guided tour of the result.
"""
import base64
import html
import json
import os
import sys
import tomllib
from collections import OrderedDict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import animations  # noqa: E402
import figures  # noqa: E402
import stability  # noqa: E402

CHECK_ORDER = ["run", "momentum_drift", "energy_drift", "max_overlap", "mean_overlap", "overlapping_pairs",
               "wall_penetration", "trajectory_error", "pressure", "collision_rate", "speed_distribution",
               "stability"]


def load_case(directory, case):
    with open(os.path.join(directory, case["result_file"]), "rb") as f:
        return tomllib.load(f)


def scene_box(path):
    try:
        with open(path, "rb") as f:
            return tomllib.load(f).get("world", {}).get("box")
    except (OSError, tomllib.TOMLDecodeError):
        return None


def fmt(value):
    if value is None:
        return "n/a"
    if value == 0:
        return "0"
    return f"{value:.3g}"


def image(png, caption, alt):
    if png is None:
        return ""
    data = base64.b64encode(png).decode("ascii")
    return (f'<figure><img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{caption}</figcaption></figure>")


def representative_cases(summary, directory, scene):
    """One finished case per backend for a scene: the smallest dt (the most accurate) and the
    first seed, so the time series and pictures show each backend at its best setting."""
    chosen = OrderedDict()
    for case in summary["cases"]:
        if case["scene"] != scene or case["status"] != "completed":
            continue
        best = chosen.get(case["backend"])
        if best is None or case["dt"] < best["dt"] or (case["dt"] == best["dt"] and case["seed"] < best["seed"]):
            chosen[case["backend"]] = case
    return [(backend, case, load_case(directory, case)) for backend, case in chosen.items()]


def check_table(summary):
    """Rows: subjects (cases, or sweep groups for statistics); columns: checks."""
    rows = OrderedDict()
    for c in summary["checks"]:
        rows.setdefault(c["subject"], {})[c["check"]] = c
    present = [name for name in CHECK_ORDER if any(name in r for r in rows.values())]
    out = ['<table class="checks"><tr><th>case (scene__backend__sweep__seed)</th>']
    out += [f"<th>{html.escape(n.replace('_', ' '))}</th>" for n in present] + ["</tr>"]
    for subject, checks in rows.items():
        out.append(f"<tr><td class='subject'>{html.escape(subject)}</td>")
        for name in present:
            c = checks.get(name)
            if c is None:
                out.append("<td></td>")
                continue
            title = html.escape(c["detail"])
            if c["status"] == "left_out":
                out.append(f"<td class='left_out' title='{title}'>left out</td>")
            else:
                text = "ok" if name == "run" and c["status"] == "pass" else \
                    c["detail"].split(":")[0] if name == "stability" else \
                    f"{fmt(c['value'])} {html.escape(c['comparison'])} {fmt(c['tolerance'])}"
                out.append(f"<td class='{c['status']}' title='{title}'>{text}</td>")
        out.append("</tr>")
    out.append("</table>")
    return "\n".join(out)


def left_out_table(summary):
    reasons = OrderedDict()
    for c in summary["checks"]:
        if c["status"] == "left_out":
            reasons.setdefault((c["check"], c["detail"]), []).append(c["subject"])
    if not reasons:
        return "<p>No check was left out.</p>"
    out = ["<table><tr><th>check</th><th>reason</th><th>cases</th></tr>"]
    for (check, reason), subjects in reasons.items():
        scenes = sorted({s.split("__")[0] for s in subjects})
        out.append(f"<tr><td>{html.escape(check)}</td><td>{html.escape(reason)}</td>"
                   f"<td>{len(subjects)} ({html.escape(', '.join(scenes))})</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def failures(summary):
    failed = [c for c in summary["checks"] if c["status"] == "fail"]
    if not failed:
        return "<p class='pass'>Every applicable check passed.</p>"
    out = ["<table><tr><th>case</th><th>check</th><th>diagnostic</th></tr>"]
    for c in failed:
        out.append(f"<tr class='fail'><td>{html.escape(c['subject'])}</td><td>{html.escape(c['check'])}</td>"
                   f"<td><pre>{html.escape(c['detail'])}</pre></td></tr>")
    out.append("</table>")
    return "\n".join(out)


def order_table(summary):
    lines = summary["work_precision"]
    if not lines:
        return ("<p>No work-precision data: it needs the reference backend "
                f"'{html.escape(summary['reference'])}' and a scene compared by trajectory or statistics.</p>")
    out = ["<table><tr><th>scene</th><th>backend</th><th>error measure</th><th>points (dt: s per time unit, error)</th>"
           "<th>observed order</th></tr>"]
    for l in lines:
        pts = "; ".join(f"{p['dt']:g}: {fmt(p['seconds_per_time_unit'])} s, {fmt(p['error'])}" for p in l["points"])
        order = fmt(l["order"]) if l["order"] is not None else html.escape(l["order_note"])
        out.append(f"<tr><td>{html.escape(l['scene'])}</td><td>{html.escape(l['backend'])}</td>"
                   f"<td>{html.escape(l['error_kind'])}</td><td>{pts}</td><td>{order}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def timing_table(summary):
    out = ["<table><tr><th>case</th><th>status</th><th>disks</th><th>simulated time</th><th>wall time [s]</th>"
           "<th>s per time unit</th><th>steps / events</th><th>contacts / collisions</th><th>warm-up [s]</th></tr>"]
    for c in summary["cases"]:
        per_unit = c["wall_seconds"] / c["duration"] if c["duration"] else None
        out.append(f"<tr class='{'pass' if c['status'] == 'completed' else 'left_out' if c['status'] == 'left_out' else 'fail'}'>"
                   f"<td>{html.escape(c['id'])}</td><td>{html.escape(c['status'])}</td><td>{c['disks']}</td>"
                   f"<td>{fmt(c['duration'])}</td><td>{fmt(c['wall_seconds'])}</td><td>{fmt(per_unit)}</td>"
                   f"<td>{c['steps']}</td><td>{c['contacts']}</td><td>{fmt(c['warmup_seconds'])}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def provenance_table(summary):
    rows = dict(summary["provenance"])
    rows["command line"] = summary["command_line"]
    rows["suite file"] = summary["suite_file"]
    for scene, seeds in summary["seeds"].items():
        rows[f"seeds of {scene}"] = seeds
    for scene, path in summary["scene_files"].items():
        rows[f"scene file of {scene}"] = path
    devices = sorted({f"{c['backend']}: {v}" for c in summary["cases"] for k, v in c["provenance"].items()
                      if "device" in k or "platform" in k})
    if devices:
        rows["devices"] = "; ".join(devices)
    out = ["<table>"] + [f"<tr><th>{html.escape(k)}</th><td>{html.escape(str(v))}</td></tr>" for k, v in rows.items()]
    return "\n".join(out + ["</table>"])


STYLE = """
body { font-family: sans-serif; max-width: 1150px; margin: 1em auto; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em 0; font-size: 12px; }
th, td { border: 1px solid #ccc; padding: 2px 5px; text-align: left; vertical-align: top; }
td.pass, tr.pass td:nth-child(2) { background: #dff0d8; }
td.fail, tr.fail td { background: #f2dede; }
td.left_out { background: #eee; color: #777; }
td.subject { font-family: monospace; word-break: break-all; max-width: 260px; }
table.checks { font-size: 10.5px; } table.checks td { white-space: nowrap; }
figure { margin: 1em 0 2em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 13px; color: #444; max-width: 900px; }
p.verdict { font-size: 20px; font-weight: bold; } .pass { color: #2a7a2a; } .failed { color: #b02020; }
pre { white-space: pre-wrap; margin: 0; font-size: 11px; }
"""


def scene_sections(summary, directory):
    parts = []
    scenes = list(OrderedDict.fromkeys(c["scene"] for c in summary["cases"]))
    for scene in scenes:
        chosen = representative_cases(summary, directory, scene)
        parts.append(f"<h3>{html.escape(scene)}</h3>")
        if not chosen:
            parts.append("<p>No case of this scene finished; see the failures above.</p>")
            continue
        results = [(b, r) for b, _, r in chosen]
        parts.append(image(figures.work_precision(summary["work_precision"], scene),
                           f"<b>Work against precision, {html.escape(scene)}.</b> Each point is one time step "
                           "(labelled dt) of one backend: horizontal, the wall-clock seconds it needs per unit of "
                           "simulated time (after a warm-up, mean over replicates); vertical, its error against the "
                           f"exact event-driven reference '{html.escape(summary['reference'])}'. Down and to the left "
                           "is better. The observed order in the legend is the least-squares slope of log error "
                           "against log dt.", "work-precision diagram"))
        which = ", ".join(f"{b} at dt = {c['dt']:g}, seed {c['seed']}" for b, c, _ in chosen)
        parts.append(image(figures.conservation(results, scene),
                           f"<b>Conservation, {html.escape(scene)}.</b> Left: change of the energy (total energy "
                           "under gravity, else kinetic) since t = 0, divided by the largest kinetic energy seen. "
                           "Right: change of the total momentum, divided by sqrt(2 M K(0)). Exact dynamics keeps both "
                           "at zero where the scene conserves them (the checks table says where it does not). "
                           f"Cases shown: {html.escape(which)}.", "conservation time series"))
        hist = figures.overlap_histogram(results, scene)
        if hist:
            parts.append(image(hist, f"<b>Overlaps, {html.escape(scene)}.</b> Histogram of how deep overlapping "
                               "pairs of disks intersect in the final state, relative to their contact distance "
                               "(0 = touching, 1 = concentric). Hard disks never overlap; stepped solvers detect "
                               "contacts only after they happen, so some overlap is part of their rule. "
                               f"Cases shown: {html.escape(which)}.", "overlap histogram"))
        else:
            parts.append("<p>No overlapping pairs in the final state of the cases shown.</p>")
        backend, case, result = chosen[0]
        box = scene_box(summary["scene_files"].get(scene, ""))
        parts.append(image(figures.configuration(result, box, scene, backend),
                           f"<b>Configuration, {html.escape(scene)}.</b> The disks (drawn to scale, coloured by "
                           f"speed) at the start and at the end of the case {html.escape(case['id'])}, inside the "
                           "scene's box.", "initial and final configuration"))
        parts.append(animations.section(summary, directory, scene, image))  # motion strips, if frames were stored
    return "\n".join(parts)


def write_html(summary, directory, path):
    passed = summary["passed"]
    counts = summary["counts"]
    verdict = "PASSED" if passed else "FAILED"
    body = f"""<!DOCTYPE html><html><head><meta charset="utf-8">
<title>collide validation report: {html.escape(summary['suite'])}</title><style>{STYLE}</style></head><body>
<h1>Validation report: suite '{html.escape(summary['suite'])}'</h1>
<p>{html.escape(summary['description'])}</p>
<p class="verdict {'pass' if passed else 'failed'}">{verdict}: {counts['pass']} checks passed,
{counts['fail']} failed, {counts['left_out']} left out; {len(summary['cases'])} cases in {summary['wall_seconds']:.1f} s
(commit {html.escape(summary['provenance'].get('git_commit', '?')[:12])}{' dirty' if summary['provenance'].get('git_dirty') == 'true' else ''}).</p>
<h2>1. Failures</h2>{failures(summary)}
{stability.section(summary, image)}
<h2>2. Checks</h2>
<p>One row per case (statistical comparisons: per sweep group, over its replicates), one column per check.
A cell shows the measured value, how it must compare with the tolerance, and the tolerance; green passes, red
fails, grey is left out (hover for the reason; all reasons are listed below). Definitions and the derivation
of every tolerance: docs/validation.md.</p>
{check_table(summary)}
<h3>Left-out checks and why</h3>{left_out_table(summary)}
<h2>3. Error against run time</h2>{order_table(summary)}
<h2>4. Scenes</h2>{scene_sections(summary, directory)}
<h2>5. Timings</h2>
<p>Wall time is spent in the solver's advance_to() only (metrics and output excluded), measured after an untimed
warm-up run. Each case runs in its own process; timings on a shared machine are noisy.</p>
{timing_table(summary)}
<h2>6. Provenance</h2>{provenance_table(summary)}
</body></html>"""
    with open(path, "w", encoding="utf-8") as f:
        f.write(body)


def write_markdown(summary, path):
    counts = summary["counts"]
    lines = [f"# Validation report: suite '{summary['suite']}'", "",
             f"**{'PASSED' if summary['passed'] else 'FAILED'}**: {counts['pass']} checks passed, {counts['fail']} failed, "
             f"{counts['left_out']} left out; {len(summary['cases'])} cases in {summary['wall_seconds']:.1f} s; commit "
             f"{summary['provenance'].get('git_commit', '?')}"
             f"{' (dirty)' if summary['provenance'].get('git_dirty') == 'true' else ''}.", "",
             "## Failures", ""]
    failed = [c for c in summary["checks"] if c["status"] == "fail"]
    lines += [f"- `{c['subject']}` {c['check']}: {c['detail']}" for c in failed] or ["None."]
    lines += stability.markdown(summary)
    lines += ["", "## Checks", "", "| case | check | status | value | tolerance | note |", "|---|---|---|---|---|---|"]
    for c in summary["checks"]:
        lines.append(f"| `{c['subject']}` | {c['check']} | {c['status']} | {fmt(c['value']) if c['status'] != 'left_out' else ''} "
                     f"| {(c['comparison'] + ' ' + fmt(c['tolerance'])) if c['status'] != 'left_out' else ''} "
                     f"| {c['detail'].replace('|', '/').splitlines()[0] if c['detail'] else ''} |")
    lines += ["", "## Observed convergence order", "", "| scene | backend | order |", "|---|---|---|"]
    for l in summary["work_precision"]:
        lines.append(f"| {l['scene']} | {l['backend']} | {fmt(l['order']) if l['order'] is not None else l['order_note']} |")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_report.py RESULTS_DIR")
    directory = sys.argv[1]
    with open(os.path.join(directory, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    out = os.path.join(directory, "report")
    os.makedirs(out, exist_ok=True)
    write_html(summary, directory, os.path.join(out, "index.html"))
    write_markdown(summary, os.path.join(out, "summary.md"))
    print(f"report    {os.path.join(out, 'index.html')}")
    print(f"          {os.path.join(out, 'summary.md')}")


if __name__ == "__main__":
    main()
