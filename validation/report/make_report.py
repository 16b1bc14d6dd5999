#!/usr/bin/env python3
"""Renders the report of a validation run from DIR/summary.json and DIR/cases/*.toml as
written by `collide validate`:

  DIR/report/index.html       self-contained (figures embedded as base64 PNG); its first screen
                              holds the verdict, the per-backend digest, the table of contents
                              and the headline work-precision figure
  DIR/report/checks.html      every check of every case, one row each
  DIR/report/summary.md       the digest in at most about 80 lines (CI logs, pull requests)
  DIR/report/summary-full.md  every check, as Markdown

Called by `collide report DIR`; docs/reading-a-report.md is a guided tour of the result. A
malformed input file ends the renderer with exit status 2 and a message naming the file.
"""
import base64
import html
import json
import os
import sys
import math
import tomllib
from collections import OrderedDict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import animations  # noqa: E402
import digest  # noqa: E402
import figures  # noqa: E402
import physics  # noqa: E402
import safe_output  # noqa: E402
import stability  # noqa: E402
from collide_program import run_collide  # noqa: E402
from digest import ReportInputError, anchor  # noqa: E402



_CASES = {}


def load_case(directory, case):
    key = (directory, case["id"])
    if key not in _CASES:
        _CASES[key] = digest.load_case(directory, case)
    return _CASES[key]


def verify_cases(summary, directory):
    """Reads every finished case's result file, so that a truncated or unreadable one stops
    the report with its name rather than being skipped or drawn half."""
    for case in summary["cases"]:
        if case["status"] == "completed" and case.get("result_file"):
            load_case(directory, case)


def scene_box(path):
    try:
        with open(path, "rb") as f:
            return tomllib.load(f).get("world", {}).get("box")
    except (OSError, tomllib.TOMLDecodeError):
        return None


def fmt(value):
    if value is None or isinstance(value, str):
        return "n/a" if value is None else html.escape(value)
    if value == 0:
        return "0"
    return f"{value:.3g}"


def image(png, caption, alt, ident=None):
    if png is None:
        return ""
    data = base64.b64encode(png).decode("ascii")
    ident = f' id="{ident}"' if ident else ""
    return (f'<figure{ident}><img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{caption}</figcaption></figure>")


def representative_cases(summary, directory, scene):
    """One finished case per backend for a scene: the smallest dt (the most accurate) and the
    first seed, so the time series and pictures show each backend at its best setting."""
    chosen = OrderedDict()
    for case in summary["cases"]:
        if case["scene"] != scene or case["status"] != "completed" or not case.get("result_file"):
            continue
        best = chosen.get(case["backend"])
        if best is None or case["dt"] < best["dt"] or (case["dt"] == best["dt"] and case["seed"] < best["seed"]):
            chosen[case["backend"]] = case
    return [(backend, case, load_case(directory, case)) for backend, case in chosen.items()]


def left_out_table(summary):
    reasons = OrderedDict()
    for c in summary["checks"]:
        if c["status"] == "left_out":
            reasons.setdefault((c["check"], c["detail"]), []).append((c["scene"], c["subject"]))
    if not reasons:
        return "<p>No check was left out.</p>"
    out = ["<table><tr><th>check</th><th>reason</th><th>cases</th></tr>"]
    for (check, reason), subjects in reasons.items():
        scenes = sorted({s for s, _ in subjects})
        out.append(f"<tr><td>{html.escape(check)}</td><td>{html.escape(reason)}</td>"
                   f"<td>{len(subjects)} ({html.escape(', '.join(scenes))})</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def timing_table(summary):
    out = ["<table><tr><th>case</th><th>status</th><th>disks</th><th>simulated time</th><th>wall time [s]</th>"
           "<th>s per time unit</th><th>steps / events</th><th>contacts / collisions</th><th>warm-up [s]</th></tr>"]
    for c in summary["cases"]:
        per_unit = c["wall_seconds"] / c["duration"] if c["duration"] and c["wall_seconds"] is not None else None
        per_unit = per_unit if c["wall_seconds"] is not None else None
        out.append(f"<tr class='{'pass' if c['status'] == 'completed' else 'left_out' if c['status'] == 'left_out' else 'fail'}'>"
                   f"<td>{html.escape(c['id'])}</td><td>{html.escape(c['status'])}</td><td>{c['disks']}</td>"
                   f"<td>{fmt(c['duration'])}</td><td>{fmt(c['wall_seconds'])}</td><td>{fmt(per_unit)}</td>"
                   f"<td>{c.get('steps', '')}</td><td>{c.get('contacts', '')}</td><td>{fmt(c.get('warmup_seconds'))}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def provenance_table(summary):
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
    out = ["<table>"] + [f"<tr><th>{html.escape(k)}</th><td>{html.escape(str(v))}</td></tr>" for k, v in rows.items()]
    return "\n".join(out + ["</table>"])


# ---------------------------------------------------------------------------------------------
# The analysis every part of the report shares, computed once

class Analysis:
    def __init__(self, summary):
        self.summary = summary
        self.fits = digest.orders(summary)
        self.fit = {(f["scene"], f["backend"]): f for f in self.fits}
        self.rows = digest.digest(summary, exclude_quantised=False)
        for r in self.rows:
            r["cases"] += r["cases_cannot_run"]
        self.identical = digest.identical_backends(summary)
        self.aliases = {b: a for a, b, _ in self.identical}
        self.scenes = digest.scenes_in_order(summary)
        self.backends = digest.backends_in_order(summary)
        self.stability = stability.has_outcomes(summary)
        self.unexpected = stability.unexpected(summary) if self.stability else []

    @property
    def passed(self):
        """A stability suite passes when every case was classified and nothing unexpected
        happened (its failed checks are the map's findings); any other suite when no check failed."""
        return not self.unexpected if self.stability else self.summary["passed"]


def verdict_text(a):
    s, counts = a.summary, a.summary["counts"]
    commit = s["provenance"].get("git_commit", "?")[:12] + (" dirty" if s["provenance"].get("git_dirty") == "true" else "")
    word = "PASSED" if a.passed else "FAILED"
    if a.stability:
        classified = sum(1 for c in s["cases"] if "outcome" in c)
        tail = (f"{classified} of {len(s['cases'])} cases classified, {len(a.unexpected)} unexpected "
                f"({counts['fail']} failed checks are the map's findings)")
    else:
        tail = f"{counts['pass']} checks passed, {counts['fail']} failed, {counts['left_out']} left out"
        judged = [r for r in physics.rows(s) if r["verdict"] != "shown"]
        if judged:
            tail += (f"; reference against physics: {sum(r['verdict'] == 'pass' for r in judged)} of "
                     f"{len(judged)} rows pass")
    return f"{word}: {tail}; {len(s['cases'])} cases in {s['wall_seconds']:.1f} s (commit {commit})"


def margin_text(worst, link=True):
    if worst is None:
        return "n/a"
    m, subject, check = worst
    text = "∞" if m == math.inf else f"{m:.2f}" if 0.01 <= m < 1e4 else fmt(m)
    where = f"{subject}: {check.replace('_', ' ')}"
    return f"{text} <span class='where'>({html.escape(where)})</span>" if link else f"{text} ({where})"


def floor_text(fits, limit=1):
    if not fits:
        return ""
    parts = [f"{f['scene']}: from h ≈ {f['floor']['h']:g} at ≈ {f['floor']['error']:.2g}" if f["floor"] else
             f"{f['scene']}: floor-contaminated" for f in fits[:limit]]
    if len(fits) > limit:
        parts.append(f"+{len(fits) - limit} more")
    return "; ".join(parts)


def digest_table(a):
    out = ['<table id="digest" class="digest"><tr><th>backend</th><th>cases</th><th>checks passed</th><th>failed</th>'
           '<th>left out</th><th>worst margin (measured ÷ tolerance; case: check)</th>'
           '<th>order: trajectory</th><th>order: Z</th><th>error floor</th></tr>']
    for r in a.rows:
        b = r["backend"]
        same = f" <span class='where'>(= {html.escape(a.aliases[b])})</span>" if b in a.aliases else ""
        cls = "fail" if r["fail"] else "pass"
        out.append(f"<tr><td><a href='#{anchor('backend', b)}'>{html.escape(b)}</a>{same}</td><td>{r['cases']}</td>"
                   f"<td class='{cls}'>{r['pass']}</td><td class='{cls}'>{r['fail']}</td><td>{r['left_out']}</td>"
                   f"<td>{margin_text(r['worst'])}</td>"
                   f"<td>{digest.order_summary(r['orders'].get('trajectory', []))}</td>"
                   f"<td>{digest.order_summary(r['orders'].get('Z', []))}</td>"
                   f"<td>{html.escape(floor_text(r['floors']))}</td></tr>")
    total = {k: sum(r[k] for r in a.rows) for k in ("cases", "pass", "fail", "left_out")}
    out.append(f"<tr class='total'><td>all</td><td>{total['cases']}</td><td>{total['pass']}</td><td>{total['fail']}</td>"
               f"<td>{total['left_out']}</td><td colspan='4'>orders: least-squares slope of log error against log dt on "
               "the asymptotic range (<a href='#orders'>§3</a>); Z: resolved points only</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def identical_line(a):
    if not a.identical:
        return ""
    parts = [f"<b>{html.escape(b)}</b> gives the same numbers as <b>{html.escape(x)}</b> bit for bit ({n} compared "
             "values: every check value and work-precision point), so it is drawn once, labelled "
             f"“{html.escape(x)} = {html.escape(b)}”" for x, b, n in a.identical]
    return "<p class='identical'>" + "; ".join(parts) + ".</p>"


def toc(a):
    items = []
    if a.stability:
        items.append("<li><a href='#stability'>Stability: first failures and maps</a></li>")
    if physics.rows(a.summary):
        items.append("<li><a href='#physics'>Reference against physics</a></li>")
    items += ["<li><a href='#headline'>Work against precision (headline)</a></li>",
              "<li><a href='#failures'>1. Failures</a></li>",
              "<li><a href='#checks'>2. Checks by scene and backend</a> · <a href='checks.html'>every check</a></li>",
              "<li><a href='#orders'>3. Orders, floors and resolution</a></li>",
              "<li><a href='#scenes'>4. Scenes</a>: " + ", ".join(
                  f"<a href='#{anchor('scene', sc)}'>{html.escape(sc)}</a>" for sc in a.scenes) + "</li>",
              "<li><a href='#timings'>5. Timings</a></li>", "<li><a href='#provenance'>6. Provenance</a></li>"]
    backends = ", ".join(f"<a href='#{anchor('backend', b)}'>{html.escape(b)}</a>" for b in a.backends)
    return (f"<nav id='toc'><b>Contents</b><ul>{''.join(items)}</ul><p>Checks of backend: {backends}</p>"
            "<p class='where'>Margin: measured ÷ tolerance (above 1 fails). Trajectory error: “worst” is the worst "
            "phase replicate (the check), “mean ± SE” the mean over replicates (the figures). A statistical "
            "difference below 2 standard errors is drawn hollow: not resolved.</p></nav>")


def headline_figure(a):
    png = figures.headline(a.summary, digest, a.aliases)
    if png is None and a.stability:
        return "<p id='headline'>A stability suite draws maps instead of work-precision figures.</p>"
    if png is None:
        return (f"<p id='headline'>No work-precision data: it needs the reference backend "
                f"'{html.escape(a.summary['reference'])}' and a scene compared by trajectory or statistics.</p>")
    return image(png, "<b>Work against precision, every backend.</b> Horizontal: wall-clock seconds per unit of "
                 "simulated time (after a warm-up, mean over replicates). Vertical: left, the trajectory error "
                 "against the exact solver (mean over phase replicates ± 1 SE, one marker shape per scene); middle "
                 "and right, the relative difference between the replicate means of pressure Z and collision rate "
                 "and the exact solver's (± 1 combined SE). Points are joined in the order of dt (coarse on the "
                 "left). A hollow point is not resolved (difference below 2 SE) and sits at its 2 SE bound. The "
                 f"dashed lines are the exact solver '{html.escape(a.summary['reference'])}' own cost per time unit: "
                 "its error is statistical only. Down and to the left is better.",
                 "headline work-precision figure", "headline")


def failures(a):
    failed = [c for c in a.summary["checks"] if c["status"] == "fail"]
    if a.stability:
        lines = "".join(f"<li>{html.escape(u)}</li>" for u in a.unexpected)
        head = (f"<p class='failed'>Unexpected in a stability suite:</p><ul>{lines}</ul>" if a.unexpected else
                "<p class='pass'>Nothing unexpected: every case classified, the exact solver stable, no crash.</p>")
        return head + (f"<p>{len(failed)} checks failed; in a stability suite these are the findings the map "
                       "draws. Each is listed on <a href='checks.html'>checks.html</a>.</p>")
    if not failed:
        return "<p class='pass'>Every applicable check passed.</p>"
    out = ["<table><tr><th>case</th><th>check</th><th>diagnostic</th></tr>"]
    for c in failed:
        out.append(f"<tr class='fail'><td>{html.escape(c['subject'])}</td><td>{html.escape(c['check'])}</td>"
                   f"<td><pre>{html.escape(c['detail'])}</pre></td></tr>")
    out.append("</table>")
    return "\n".join(out)


CHECK_LABELS = {"trajectory_error": "trajectory error (worst replicate)"}


def predicted_text(c, percent=False):
    p, u = c.get("predicted"), c.get("predicted_uncertainty")
    if not isinstance(p, (int, float)) or isinstance(p, bool):
        return ""
    if percent:
        v = c.get("value")
        unc = f" ± {100 * u:.2g}" if isinstance(u, (int, float)) else ""
        # The drift is max_t |K(t) - K(0)| / K(0): multi-contact steps change K by either sign
        # (docs/stepping-rules.md, "Energy at e = 1"), so the model predicts its size, not a sign.
        return f"drifts {100 * abs(v or 0):.2g} % where the rule is expected to drift {100 * p:.2g}{unc} %"
    if c.get("check") in ("pressure", "collision_rate"):
        # The value is then the distance from the predicted difference in standard deviations;
        # the prediction is the stepped rule's bias against the reference (Z, or collisions per
        # disk per time), signed.
        unc = f" ± {u:.2g}" if isinstance(u, (int, float)) else ""
        what = "Z" if c["check"] == "pressure" else "the rate"
        return f"the rule is expected to shift {what} by {p:+.3g}{unc} from the reference"
    return f"expected {fmt(p)}" + (f" ± {fmt(u)}" if isinstance(u, (int, float)) else "")


def cell(c, name):
    title = html.escape(c["detail"], quote=True)
    if c["status"] == "left_out":
        return f"<td class='left_out' title='{title}'>left out</td>"
    if name == "run" and c["status"] == "pass":
        text = "ok"
    elif name == "stability":
        text = html.escape(c["detail"].split(":")[0])
    else:
        text = f"{fmt(c.get('value'))} {html.escape(c.get('comparison', ''))} {fmt(c.get('tolerance'))}"
        extra = predicted_text(c)
        if extra:
            text += f" <span class='where'>({html.escape(extra)})</span>"
    return f"<td class='{html.escape(c['status'])}' title='{title}'>{text}</td>"


def check_tables(a):
    """Case tables collapsed by scene and backend, each sorted by worst margin (failures first)."""
    by = OrderedDict()
    for c in a.summary["checks"]:
        b, scene = c["backend"], c["scene"]
        by.setdefault(scene, OrderedDict()).setdefault(b, OrderedDict()).setdefault(c["subject"], {})[c["check"]] = c
    out = []
    seen_backends = set()
    for scene, backends in by.items():
        n_fail = sum(1 for bs in backends.values() for cs in bs.values() for c in cs.values() if c["status"] == "fail")
        n_subjects = sum(len(bs) for bs in backends.values())
        out.append(f"<details class='scene' id='{anchor('checks', scene)}'{' open' if n_fail else ''}>"
                   f"<summary><b>{html.escape(scene)}</b>: {n_subjects} rows, {n_fail} failed checks</summary>")
        for b, subjects in backends.items():
            ident = "" if b in seen_backends else f" id='{anchor('backend', b)}'"
            seen_backends.add(b)

            def worst(item):
                ms = [digest.margin(c) for c in item[1].values()]
                fails = sum(1 for c in item[1].values() if c["status"] == "fail")
                return (-fails, -max([m for m in ms if m is not None], default=-1))
            rows = sorted(subjects.items(), key=worst)
            present = [n for n in digest.check_order(a.summary) if any(n in cs for cs in subjects.values())]
            fails = sum(1 for cs in subjects.values() for c in cs.values() if c["status"] == "fail")
            top = max((m for cs in subjects.values() for c in cs.values() if (m := digest.margin(c)) is not None),
                      default=None)
            out.append(f"<details class='backend'{ident}{' open' if fails else ''}><summary>{html.escape(b)}: "
                       f"{len(subjects)} rows, {fails} failed, worst margin {fmt(top)}</summary>")
            out.append("<table class='checks'><tr><th>case (scene__backend__sweep__seed)</th><th>worst margin</th>")
            out += [f"<th>{html.escape(CHECK_LABELS.get(n, n.replace('_', ' ')))}</th>" for n in present] + ["</tr>"]
            for subject, checks in rows:
                ms = [m for c in checks.values() if (m := digest.margin(c)) is not None]
                out.append(f"<tr><td class='subject'>{html.escape(subject)}</td><td>{fmt(max(ms)) if ms else ''}</td>")
                out += [cell(checks[n], n) if n in checks else "<td></td>" for n in present]
                out.append("</tr>")
            out.append("</table></details>")
        out.append("</details>")
    # A backend with no checks still gets its anchor (the digest links to it).
    for b in a.backends:
        if b not in seen_backends:
            out.append(f"<p id='{anchor('backend', b)}'>{html.escape(b)}: no checks.</p>")
    return "\n".join(out)


def orders_table(a):
    s = a.summary
    if not s["work_precision"]:
        return ("<p>No work-precision data: it needs the reference backend "
                f"'{html.escape(s['reference'])}' and a scene compared by trajectory or statistics.</p>")
    out = ["<table><tr><th>scene</th><th>backend</th><th>error measure</th>"
           "<th>points (dt: error ± SE; s per time unit)</th><th>order on the asymptotic range</th>"
           "<th>floor</th></tr>"]
    for line in s["work_precision"]:
        fit = a.fit.get((line["scene"], line["backend"]))
        b = line["backend"]
        if fit["class"] == "trajectory":
            measure = "trajectory error / r_min, mean ± SE over phase replicates"
            pts = "; ".join(f"{p['dt']:g}: {fmt(p['error'])} ± {fmt(p.get('error_standard_error'))}; "
                            f"{fmt(p['seconds_per_time_unit'])} s" for p in line["points"])
        else:
            measure = "|Z − Z_ref| / Z_ref, means ± combined SE"
            stats = digest.statistical_points(s, line["scene"], "pressure").get(b, [])
            pts = "; ".join(f"{p['dt']:g}: {fmt(p['error'])} ± {fmt(p['se'])} = {p['sigmas']:.1f} SE"
                            f"{'' if p['resolved'] else ' (not resolved)'}; {fmt(p['seconds'])} s" for p in stats)
        same = f" (= {html.escape(a.aliases[b])})" if b in a.aliases else ""
        floor = html.escape(digest.describe_floor(fit))
        out.append(f"<tr><td>{html.escape(line['scene'])}</td><td>{html.escape(b)}{same}</td><td>{measure}</td>"
                   f"<td>{pts}</td><td>{html.escape(digest.describe_order(fit))}</td><td>{floor}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def explain_jump(directory, case, jump):
    """The step, the disks and the kind of contact behind a jump, by `collide explain` (which
    reruns the case step by step over the jump's output interval), as HTML; or why not."""
    out, why = run_collide(["explain", directory, case["id"], "--from", repr(jump["t0"]), "--to", repr(jump["t1"]),
                            "--json"])
    if why:
        return f" The step could not be named: {html.escape(why)}."
    try:
        found = json.loads(out)
    except ValueError:
        return " The step could not be named: `collide explain` printed no JSON."
    jump["explained"] = found
    share = ""
    interval = jump.get("change", 0) * jump.get("scale", 0)  # the output interval's change
    if interval and math.isfinite(found["energy_change"]):
        share = f" That step is {100 * found['energy_change'] / interval:.0f} % of the interval's change."
    return f" In detail: {html.escape(found['description'])}.{share}"


def jump_notes(scene, chosen, a, directory):
    """Energy jumps of the cases shown, for scenes where energy is conserved (its check applies),
    each named down to its step and disks by `collide explain`."""
    conserved = any(c["check"] == "energy_drift" and c["status"] != "left_out" and c.get("scene") == scene
                    for c in a.summary["checks"])
    jumps, notes = {}, []
    if not conserved:
        return jumps, ""
    for backend, case, result in chosen:
        if backend == a.summary["reference"] or backend in a.aliases:
            continue
        j = digest.energy_jumps(result)
        if not j:
            continue
        jumps[backend] = j
        detail = explain_jump(directory, case, j)
        notes.append(f"<li><b>{html.escape(backend)}</b> ({html.escape(case['id'])}): the energy changes by "
                     f"{100 * j['change']:+.2g} % of max K between t = {j['t0']:g} and t = {j['t1']:g}, one output "
                     f"interval; the median interval changes it by {100 * j['median']:.2g} %.{detail}</li>")
    if not notes:
        return jumps, ""
    box2d = any(digest.facts(a.summary, b).get("base") == "box2d" for b in jumps)
    return jumps, ("<p>Energy jumps in the cases shown:</p><ul>" + "".join(notes) + "</ul><p>Why the stepped rule "
                   "changes the energy in one step where several contacts meet (three disks in contact at once, a disk "
                   "touching a wall and a disk; `collide explain` reruns a case and names them): "
                   "docs/stepping-rules.md, section 7, “Energy at e = 1”. An isolated pair keeps its energy at e = 1 "
                   "in the stepped rules." + (" Where Box2D's isolated pair loses energy, look first at its "
                   "restitution threshold, below which it makes a collision inelastic (docs/box2d-baseline.md)."
                   if box2d else "") + "</p>")


def scene_sections(summary, directory, a=None):
    a = a or Analysis(summary)
    parts = []
    for scene in a.scenes:
        chosen = representative_cases(summary, directory, scene)
        parts.append(f"<h3 id='{anchor('scene', scene)}'>{html.escape(scene)}</h3>")
        if not chosen:
            parts.append("<p>No case of this scene finished; see the failures above.</p>")
            continue
        results = [(b, r) for b, _, r in chosen]
        shown = [(b, r) for b, r in results if b not in a.aliases]
        labels = {b: " = ".join([b] + [x for x, y in a.aliases.items() if y == b]) for b, _ in shown}
        parts.append(image(figures.work_precision(summary, scene, digest, a.aliases),
                           f"<b>Work against precision, {html.escape(scene)}.</b> Each point is one time step "
                           "(labelled dt) of one backend: horizontal, the wall-clock seconds it needs per unit of "
                           "simulated time (after a warm-up, mean over replicates); vertical, its error against the "
                           f"exact event-driven reference '{html.escape(summary['reference'])}' with ± 1 SE: the mean "
                           "over phase replicates for trajectories, the difference of replicate means for Z (hollow: "
                           "not resolved, below 2 SE; dashed: the exact solver's own cost). Down and to the left is "
                           "better. The order in the legend is fitted on the asymptotic range (§3).",
                           "work-precision diagram"))
        which = ", ".join(f"{b} at dt = {c['dt']:g}, seed {c['seed']}" for b, c, _ in chosen)
        jumps, notes = jump_notes(scene, chosen, a, directory)
        parts.append(image(figures.conservation(shown, scene, jumps, labels),
                           f"<b>Conservation, {html.escape(scene)}.</b> Left: change of the energy (total energy "
                           "under gravity, else kinetic) since t = 0, divided by the largest kinetic energy seen. "
                           "Right: change of the total momentum, divided by sqrt(2 M K(0)). Exact dynamics keeps both "
                           "at zero where the scene conserves them (the checks say where it does not). Backends are "
                           "drawn with different dashes and widths, so lines that coincide stay visible. "
                           f"Cases shown: {html.escape(which)}.", "conservation time series"))
        parts.append(notes)
        hist = figures.overlap_histogram(shown, scene, labels)
        if hist:
            parts.append(image(hist, f"<b>Overlaps, {html.escape(scene)}.</b> Histogram of how deep overlapping "
                               "pairs of disks intersect in the final state, relative to their contact distance "
                               "(0 = touching, 1 = concentric). Hard disks never overlap; stepped solvers detect "
                               "contacts only after they happen, so some overlap is part of their rule. "
                               f"Cases shown: {html.escape(which)}.", "overlap histogram"))
        else:
            parts.append("<p>No overlapping pairs in the final state of the cases shown.</p>")
        backend, case, result = chosen[0]
        box = scene_box(summary.get("scene_files", {}).get(scene, ""))
        parts.append(image(figures.configuration(result, box, scene, backend),
                           f"<b>Configuration, {html.escape(scene)}.</b> The disks (drawn to scale, coloured by "
                           f"speed) at the start and at the end of the case {html.escape(case['id'])}, inside the "
                           "scene's box.", "initial and final configuration"))
        parts.append(animations.section(summary, directory, scene, image))  # motion strips, if frames were stored
    return "\n".join(parts)


STYLE = """
body { font-family: sans-serif; max-width: 1380px; margin: 0.5em auto; color: #222; }
h1 { font-size: 20px; margin: 0.2em 0; }
table { border-collapse: collapse; margin: 0.4em 0 1.2em 0; font-size: 12px; }
th, td { border: 1px solid #ccc; padding: 2px 5px; text-align: left; vertical-align: top; }
td.pass, tr.pass td:nth-child(2) { background: #dff0d8; }
td.fail, tr.fail td { background: #f2dede; }
td.left_out { background: #eee; color: #777; }
td.subject { font-family: monospace; word-break: break-all; max-width: 260px; }
table.checks { font-size: 10.5px; } table.checks td { white-space: nowrap; }
table.digest { font-size: 12px; margin: 0.2em 0 0.4em 0; } table.digest tr.total td { background: #f6f6f6; }
.where { color: #666; font-size: 10.5px; }
.top { display: flex; gap: 14px; align-items: flex-start; }
.top .main { flex: 1 1 auto; min-width: 0; overflow-x: auto; }
nav#toc { flex: 0 0 290px; font-size: 12px; border: 1px solid #ddd; padding: 4px 8px; background: #fafafa; }
nav#toc ul { margin: 2px 0; padding-left: 16px; } nav#toc p { margin: 4px 0; }
div.physics-top { display: flex; gap: 12px; align-items: flex-start; } div.physics-top figure { margin: 0; }
table.physics { font-size: 11px; } table.physics td.pass { background: #dfd; } table.physics td.fail { background: #fdd; }
figure { margin: 0.6em 0 1.6em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figure#headline { margin-top: 0.2em; } figure#headline img { max-height: 440px; }
figcaption { font-size: 12px; color: #444; max-width: 1300px; }
p.verdict { font-size: 18px; font-weight: bold; margin: 0.2em 0; } .pass { color: #2a7a2a; } .failed { color: #b02020; }
p.identical { font-size: 12px; margin: 0.2em 0; }
details { margin: 0.2em 0 0.2em 0.5em; } details.backend { margin-left: 1.5em; }
pre { white-space: pre-wrap; margin: 0; font-size: 11px; }
"""


def write_html(summary, directory, path, a=None):
    a = a or Analysis(summary)
    verdict = verdict_text(a)
    stability_first = ""
    if a.stability:
        stability_first = ("<h2 id='stability-first'>First failure of each backend</h2><p class='where'>Each cell: the "
                           "first failure on that scene (smallest failing dt, then smallest swept value) and failed / "
                           "classified cases; hover for the measured value. Maps and the full table: "
                           "<a href='#stability'>Stability</a>.</p>" + stability.first_failure_matrix(summary))
    body = f"""<!DOCTYPE html><html><head><meta charset="utf-8">
<title>collide validation report: {html.escape(summary['suite'])}</title><style>{STYLE}</style></head><body>
<h1>Validation report: suite '{html.escape(summary['suite'])}'</h1>
<div class="top"><div class="main">
<p class="verdict {'pass' if a.passed else 'failed'}" id="verdict">{html.escape(verdict)}.</p>
{stability_first}
{'<h2>Digest</h2>' if a.stability else ''}{digest_table(a)}
{identical_line(a)}
</div>{toc(a)}</div>
{physics.section(summary, image)}
{headline_figure(a)}
<p>{html.escape(summary.get('description', ''))}</p>
{stability.section(summary, image) if a.stability else ''}
<h2 id="failures">1. Failures</h2>{failures(a)}
<h2 id="checks">2. Checks by scene and backend</h2>
<p>One row per case (statistical comparisons: per sweep group, over its replicates), one column per check, collapsed
by scene and backend and sorted by margin, failures and the closest calls first. A cell shows the measured value, how
it must compare with the tolerance, and the tolerance; green passes, red fails, grey is left out (hover for the reason).
The trajectory error here is the worst phase replicate; the figures show the mean ± SE. Every check in one list:
<a href="checks.html">checks.html</a>. Definitions and the derivation of every tolerance: docs/validation.md.</p>
{check_tables(a)}
<h3 id="left-out">Left-out checks and why</h3>{left_out_table(summary)}
<h2 id="orders">3. Orders, floors and resolution</h2>
<p>The observed order is the least-squares slope of log error against log dt on the asymptotic range: sorted from
coarse to fine, the range ends where the error stops falling (every later local slope below 0.3); the
points below it are the floor, named in the table (for a float backend, rounding accumulates there). Both are computed
by <code>collide validate</code> (summary.json, docs/validation.md).</p>
{orders_table(a)}
<h2 id="scenes">4. Scenes</h2>{scene_sections(summary, directory, a)}
<h2 id="timings">5. Timings</h2>
<p>Wall time is spent in the solver's advance_to() only (metrics and output excluded), measured after an untimed
warm-up run. Each case runs in its own process; timings on a shared machine are noisy.</p>
{timing_table(summary)}
<h2 id="provenance">6. Provenance</h2>{provenance_table(summary)}
<script>
// A link into a collapsed table opens the <details> around its target.
function openTarget() {{
  const t = location.hash && document.getElementById(decodeURIComponent(location.hash.slice(1)));
  for (let e = t; e; e = e.parentElement) if (e.tagName === "DETAILS") e.open = true;
  if (t) t.scrollIntoView();
}}
window.addEventListener("hashchange", openTarget);
openTarget();
</script>
</body></html>"""
    safe_output.write_text(path, body)


def write_checks_html(summary, path):
    out = [f"""<!DOCTYPE html><html><head><meta charset="utf-8"><title>Every check: {html.escape(summary['suite'])}</title>
<style>{STYLE}</style></head><body><h1>Every check of suite '{html.escape(summary['suite'])}'</h1>
<p><a href="index.html">Back to the report</a>. One row per check, in the order of the run. Margin: measured ÷
tolerance (tolerance ÷ measured for a lower bound), above 1 fails.</p>
<table class="checks"><tr><th>case or group</th><th>check</th><th>status</th><th>value</th><th>tolerance</th>
<th>margin</th><th>expected by the rule</th><th>detail</th></tr>"""]
    for c in summary["checks"]:
        lo = c["status"] == "left_out"
        pct = c["check"] == "energy_drift"
        out.append(f"<tr><td class='subject'>{html.escape(c['subject'])}</td><td>{html.escape(c['check'])}</td>"
                   f"<td class='{html.escape(c['status'])}'>{html.escape(c['status'])}</td>"
                   f"<td>{'' if lo else fmt(c.get('value'))}</td>"
                   f"<td>{'' if lo else html.escape(c.get('comparison', '')) + ' ' + fmt(c.get('tolerance'))}</td>"
                   f"<td>{fmt(digest.margin(c))}</td><td>{html.escape(predicted_text(c, pct))}</td>"
                   f"<td>{html.escape(c['detail'])}</td></tr>")
    out.append("</table></body></html>")
    safe_output.write_text(path, "\n".join(out))


def md(text):
    return str(text).replace("|", "/").replace("\n", " ")


def write_markdown(summary, path, a=None, full_name="summary-full.md"):
    """The digest, in at most about 80 lines: verdict, per-backend table, failures (the first
    20), orders and floors; every check is in summary-full.md."""
    a = a or Analysis(summary)
    lines = [f"# Validation report: suite '{summary['suite']}'", "", f"**{verdict_text(a)}.**", "",
             "| backend | cases | passed | failed | left out | worst margin | order: trajectory | order: Z | floor |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in a.rows:
        b = r["backend"] + (f" (= {a.aliases[r['backend']]})" if r["backend"] in a.aliases else "")
        lines.append(f"| {md(b)} | {r['cases']} | {r['pass']} | {r['fail']} | {r['left_out']} | "
                     f"{md(margin_text(r['worst'], link=False))} | {digest.order_summary(r['orders'].get('trajectory', []))} | "
                     f"{digest.order_summary(r['orders'].get('Z', []))} | {md(floor_text(r['floors'], 3))} |")
    for x, b, n in a.identical:
        lines += ["", f"{b} gives the same numbers as {x} bit for bit ({n} compared values)."]
    lines += [""] + physics.markdown(summary)
    lines += ["## Failures", ""]
    if a.stability:
        lines += [f"- UNEXPECTED {md(u)}" for u in a.unexpected[:20]] or \
                 ["Nothing unexpected (every case classified, the exact solver stable, no crash)."]
        lines += stability.markdown(summary)[:40]
    else:
        failed = [c for c in summary["checks"] if c["status"] == "fail"]
        lines += [f"- `{c['subject']}` {c['check']}: {md(c['detail'].splitlines()[0] if c['detail'] else '')}"
                  for c in failed[:20]] or ["None."]
        if len(failed) > 20:
            lines.append(f"- ... and {len(failed) - 20} more in [{full_name}]({full_name})")
    lines += ["", "## Orders and floors", "", "| scene | backend | order (asymptotic range) | floor |", "|---|---|---|---|"]
    for f in a.fits:
        if f["backend"] in a.aliases:
            continue
        lines.append(f"| {md(f['scene'])} | {md(f['backend'])} | {md(digest.describe_order(f))} | "
                     f"{md(digest.describe_floor(f))} |")
    lines += ["", f"Every check: [{full_name}]({full_name}); figures: index.html."]
    if len(lines) > 80:  # keep the digest a screen long whatever the suite
        lines = lines[:78] + ["", f"(cut at 80 lines; everything: [{full_name}]({full_name}))"]
    safe_output.write_text(path, "\n".join(lines) + "\n")


def write_markdown_full(summary, path, a=None):
    a = a or Analysis(summary)
    lines = [f"# Validation report: suite '{summary['suite']}' (every check)", "", f"**{verdict_text(a)}.**", "",
             "## Failures", ""]
    failed = [c for c in summary["checks"] if c["status"] == "fail"]
    lines += [f"- `{c['subject']}` {c['check']}: {md(c['detail'])}" for c in failed] or ["None."]
    lines += stability.markdown(summary)
    lines += ["", "## Checks", "", "| case | check | status | value | tolerance | margin | note |",
              "|---|---|---|---|---|---|---|"]
    for c in summary["checks"]:
        lo = c["status"] == "left_out"
        note = c["detail"].splitlines()[0] if c["detail"] else ""
        extra = predicted_text(c, c["check"] == "energy_drift")
        lines.append(f"| `{c['subject']}` | {c['check']} | {c['status']} | {'' if lo else fmt(c.get('value'))} "
                     f"| {'' if lo else c.get('comparison', '') + ' ' + fmt(c.get('tolerance'))} | {fmt(digest.margin(c))} "
                     f"| {md(note + ('; ' + extra if extra else ''))} |")
    lines += ["", "## Observed convergence order", "", "| scene | backend | order (asymptotic range) | floor |",
              "|---|---|---|---|"]
    for f in a.fits:
        lines.append(f"| {md(f['scene'])} | {md(f['backend'])} | {md(digest.describe_order(f))} | "
                     f"{md(digest.describe_floor(f))} |")
    safe_output.write_text(path, "\n".join(lines) + "\n")


REPORT_FILES = ("index.html", "checks.html", "summary.md", "summary-full.md")


def check_outputs(out):
    """Every file the report writes is checked before any figure is drawn (safe_output.py:
    a FIFO, a device or a link to nothing in the way is refused, not written into)."""
    safe_output.check_output_directory(out)
    if os.path.isdir(out):
        for name in REPORT_FILES:
            safe_output.check_output_path(os.path.join(out, name))


def render(directory):
    out = os.path.join(directory, "report")
    check_outputs(out)
    summary = digest.load_summary(directory)
    verify_cases(summary, directory)
    safe_output.make_output_directory(out)
    a = Analysis(summary)
    write_html(summary, directory, os.path.join(out, "index.html"), a)
    write_checks_html(summary, os.path.join(out, "checks.html"))
    write_markdown(summary, os.path.join(out, "summary.md"), a)
    write_markdown_full(summary, os.path.join(out, "summary-full.md"), a)
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_report.py RESULTS_DIR")
    directory = sys.argv[1]
    try:
        out = render(directory)
    except ReportInputError as e:
        print(f"report: {e}", file=sys.stderr)
        sys.exit(2)
    except safe_output.OutputPathError as e:  # an output path, not an input: a status of its own
        print(f"report: {e}", file=sys.stderr)
        sys.exit(3)
    except OSError as e:
        print(f"report: {e.filename or directory}: {e.strerror or e}", file=sys.stderr)
        sys.exit(2)
    print(f"report    {os.path.join(out, 'index.html')}")
    print(f"          {os.path.join(out, 'checks.html')}")
    print(f"          {os.path.join(out, 'summary.md')} (every check: summary-full.md)")


if __name__ == "__main__":
    main()
