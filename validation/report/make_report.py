#!/usr/bin/env python3
"""Renders the report of a validation run from DIR/summary.json and DIR/cases/*.toml as
written by `collide validate`:

  DIR/report/index.html       self-contained (figures embedded as palette PNGs); its first screen
                              holds the verdict, one verdict per backend with its cost, the
                              per-backend digest, the table of contents and the headline
                              work-precision figure
  DIR/report/checks.html      every check of every case, one row each (filterable), and every
                              case's timing
  DIR/report/checks.csv       every check, one row each
  DIR/report/summary.md       the digest in at most about 80 lines (CI logs, pull requests)
  DIR/report/summary-full.md  every check, as Markdown

Called by `collide report DIR`; docs/reading-a-report.md is a guided tour of the result. A
malformed input file ends the renderer with exit status 2 and a message naming the file.
"""
import base64
import csv
import html
import io
import json
import math
import os
import sys
import tomllib
from collections import OrderedDict
import multiprocessing
from concurrent.futures import ProcessPoolExecutor, as_completed

import jinja2
from markupsafe import Markup

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import animations  # noqa: E402
import digest  # noqa: E402
import figures  # noqa: E402
import physics  # noqa: E402
import progress  # noqa: E402
import safe_output  # noqa: E402
import stability  # noqa: E402
import verdicts  # noqa: E402
from digest import ReportInputError  # noqa: E402


def md(text):
    """Text for a Markdown table cell: no '|' to end the cell, no line break to end the row."""
    return str(text).replace("|", "/").replace("\n", " ")


TEMPLATES = jinja2.Environment(loader=jinja2.FileSystemLoader(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                           "templates")),
                               autoescape=jinja2.select_autoescape(["html.j2"]), trim_blocks=False)
TEMPLATES.filters["md"] = md


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
    first seed, so the time series and pictures show each backend at its best setting. Only
    these records are read (`collide report` has checked every listed record before the
    renderer starts: core/run_reader, validation/case_result)."""
    chosen = OrderedDict()
    for case in summary["cases"]:
        if case["scene"] != scene or case["status"] != "completed" or not case.get("result_file"):
            continue
        best = chosen.get(case["backend"])
        if best is None or case["dt"] < best["dt"] or (case["dt"] == best["dt"] and case["seed"] < best["seed"]):
            chosen[case["backend"]] = case
    return [(backend, case, digest.load_case(directory, case)) for backend, case in chosen.items()]


# ---------------------------------------------------------------------------------------------
# The analysis every part of the report shares, read once

class Analysis:
    def __init__(self, summary):
        self.summary = summary
        self.fits = digest.orders(summary)
        self.fit = {(f["scene"], f["backend"]): f for f in self.fits}
        self.rows = digest.digest(summary)
        self.combinations = digest.combinations(summary)
        self.identical = digest.identical_backends(summary)
        self.aliases = {b: a for a, b, _ in self.identical}
        self.scenes = digest.scenes_in_order(summary)
        self.backends = digest.backends_in_order(summary)
        self.stability = stability.has_outcomes(summary)
        self.unexpected = stability.unexpected(summary) if self.stability else []
        self.verdicts = [] if self.stability else verdicts.all_verdicts(summary, self.rows, self.aliases,
                                                                         self.combinations)

    @property
    def passed(self):
        """A stability suite passes when every case was classified and nothing unexpected
        happened (its failed checks are the map's findings); any other suite when no check failed."""
        return not self.unexpected if self.stability else self.summary["passed"]


def verdict_text(a):
    s, counts = a.summary, a.summary["counts"]
    commit = s["provenance"].get("git_commit", "?")[:12] + (" dirty" if s["provenance"].get("git_dirty") == "true" else "")
    word = "PASSED" if a.passed else "FAILED"
    ran = sum(r["cases"] for r in a.rows)
    cannot = sum(r["cases_cannot_run"] for r in a.rows)
    if a.stability:
        classified = sum(1 for c in s["cases"] if "outcome" in c)
        tail = (f"{classified} of {len(s['cases'])} cases classified, {len(a.unexpected)} unexpected "
                f"({counts['fail']} failed checks are the map's findings)")
    else:
        t = digest.combination_totals(a.combinations)
        tail = (f"{t['pass']} (scene, backend, check) combinations pass, {t['fail']} fail, {t['left_out']} do not "
                f"apply, {t['cannot_run']} cannot run ({counts['pass']} checks passed, {counts['fail']} failed)")
        judged = [r for r in physics.rows(s) if r["verdict"] != "shown"]
        if judged:
            tail += (f"; reference against physics: {sum(r['verdict'] == 'pass' for r in judged)} of "
                     f"{len(judged)} rows pass")
    cases = f"{ran} cases ran" + (f", {cannot} could not (the backend cannot run the scene)" if cannot else "")
    return f"{word}: {tail}; {cases}; {s['wall_seconds']:.1f} s (commit {commit})"


def margin_text(row, link=True):
    worst = row["worst"]
    if worst is None:
        return "n/a"
    m, subject, check = worst
    text = "∞" if m == math.inf else f"{m:.2f}" if 0.01 <= m < 1e4 else fmt(m)
    ties = f", one of {row['ties']} checks at this value" if row["ties"] > 1 else ""
    where = f"{check.replace('_', ' ')}{ties}" if link else f"{subject}: {check.replace('_', ' ')}{ties}"
    return (f"{text} <span class='where' title='{html.escape(subject, quote=True)}'>({html.escape(where)})</span>"
            if link else f"{text} ({where})")


def floor_text(fits, limit=1):
    if not fits:
        return ""
    parts = [f"{f['scene']}: from h ≈ {f['floor']['h']:g} at ≈ {f['floor']['error']:.2g}" if f["floor"] else
             f"{f['scene']}: floor-contaminated order" for f in fits[:limit]]
    if len(fits) > limit:
        parts.append(f"+{len(fits) - limit} more")
    return "; ".join(parts)


def digest_rows(a, link=True):
    out = []
    for r in a.rows:
        c = r["combinations"]
        out.append({"backend": r["backend"], "name": r["backend"] + (f" (= {a.aliases[r['backend']]})" if r["backend"] in a.aliases else ""),
                    "anchor": digest.anchor("backend", r["backend"]), "cases": r["cases"],
                    "cases_cannot_run": r["cases_cannot_run"], "pass": r["pass"], "fail": r["fail"],
                    "left_out": r["left_out"], "c_pass": c["pass"], "c_fail": c["fail"], "c_left_out": c["left_out"],
                    "c_cannot_run": c["cannot_run"], "worst": margin_text(r, link),
                    "order_trajectory": digest.order_summary(r["orders"].get("trajectory", [])),
                    "order_z": digest.order_summary(r["orders"].get("Z", [])),
                    "floor": floor_text(r["floors"], 1 if link else 3)})
    return out


DIGEST = jinja2.Template("""<table id="digest" class="digest"><tr><th>backend</th><th>verdict</th><th>trusted for</th>
<th>not for</th><th>cost ÷ exact solver's</th><th>cases run (cannot)</th><th>(scene, check) pass / fail / n.a. / cannot run</th>
<th>worst margin</th><th>order: traj.</th><th>order: Z</th></tr>
{% for r in rows %}<tr id="verdict-{{ r.anchor }}"><td><a href="#{{ r.anchor }}">{{ r.name }}</a></td>
<td class="{{ 'fail' if r.failed else 'pass' }}">{{ r.verdict }}</td><td>{{ r.trusted }}</td><td>{{ r.not_for }}</td><td>{{ r.cost }}</td>
<td>{{ r.cases }}{% if r.cases_cannot_run %} ({{ r.cases_cannot_run }}){% endif %}</td>
<td class="{{ 'fail' if r.c_fail else 'pass' }}">{{ r.c_pass }} / {{ r.c_fail }} / {{ r.c_left_out }} / {{ r.c_cannot_run }}</td>
<td>{{ r.worst|safe }}</td><td>{{ r.order_trajectory }}</td><td>{{ r.order_z }}</td></tr>
{% endfor %}<tr class="total"><td colspan="10">Cost: wall seconds per simulated time unit at the backend's cheapest sweep
point, over the exact solver's, per scene (<a href="#timings">§5</a>). Counts are (scene, check) combinations, one per check
of a scene whatever its sweep points and seeds (the checks behind them: {{ checks }}). Worst margin: measured ÷ tolerance,
quantised counts left out (<a href="#checks">§2</a>). Orders: fitted by <code>collide validate</code> on the asymptotic
range; * marks a floor-contaminated one; floors in <a href="#orders">§3</a>.</td></tr></table>""", autoescape=True)


def digest_table(a):
    c = a.summary["counts"]
    verdict_of = {v["backend"]: v for v in a.verdicts}
    empty = {"verdict": "", "trusted": "", "not_for": "", "cost": "", "failed": False}
    rows = [dict(r, **{k: v for k, v in verdict_of.get(r["backend"], empty).items() if k in empty})
            for r in digest_rows(a)]
    return DIGEST.render(rows=rows, checks=f"{c['pass']} passed, {c['fail']} failed, {c['left_out']} left out")


def identical_line(a):
    if not a.identical:
        return ""
    parts = [f"<b>{html.escape(b)}</b> gives the same numbers as <b>{html.escape(x)}</b> bit for bit ({n} compared "
             "values: every check value and work-precision point); its errors are drawn once, its costs at its own "
             "measured cost" for x, b, n in a.identical]
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
              "<li><a href='#orders'>3. Orders, floors, resolution and power</a></li>",
              "<li><a href='#scenes'>4. Scenes</a>: " + ", ".join(
                  f"<a href='#{digest.anchor('scene', sc)}'>{html.escape(sc)}</a>" for sc in a.scenes) + "</li>",
              "<li><a href='#timings'>5. Timings and the machine</a></li>", "<li><a href='#provenance'>6. Provenance</a></li>"]
    return (f"<nav id='toc'><b>Contents</b><ul>{''.join(items)}</ul>"
            "<p class='where'>Margin: measured ÷ tolerance (above 1 fails). Cost: wall seconds per simulated time "
            "unit at the backend's cheapest sweep point, over the exact solver's. A statistical difference below 2 "
            "standard errors is drawn hollow at its 95 % upper limit |Δ| + 1.96 SE: not resolved.</p></nav>")


def headline_figure(a):
    png = figures.headline(a.summary, digest, a.aliases)
    if png is None and a.stability:
        return "<p id='headline'>A stability suite draws maps instead of work-precision figures.</p>"
    if png is None:
        return (f"<p id='headline'>No work-precision data: it needs the reference backend "
                f"'{html.escape(a.summary['reference'])}' and a scene compared by trajectory or statistics.</p>")
    return image(png, "<b>Work against precision, every backend at its own cost.</b> Horizontal: wall-clock seconds "
                 "per unit of simulated time (after a warm-up, mean over replicates). Vertical: left, the trajectory "
                 "error against the exact solver (mean over phase replicates ± 1 SE, one marker shape per scene); "
                 "middle and right, the relative difference between the replicate means of pressure Z and collision "
                 "rate and the exact solver's (± 1 combined SE); thin dashes: the stepped rule's predicted bias. A "
                 "hollow point is not resolved (below 2 SE) and sits at its 95 % upper limit |Δ| + 1.96 SE. The "
                 f"vertical dashed lines are the exact solver '{html.escape(a.summary['reference'])}' own cost per "
                 "time unit on each scene. Down and to the left is better.", "headline work-precision figure", "headline")


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
    for c in failed[:200]:
        out.append(f"<tr class='fail'><td>{html.escape(c['subject'])}</td><td>{html.escape(c['check'])}</td>"
                   f"<td><pre>{html.escape(c['detail'])}</pre></td></tr>")
    out.append("</table>")
    if len(failed) > 200:
        out.append(f"<p>... and {len(failed) - 200} more on <a href='checks.html'>checks.html</a>.</p>")
    return "\n".join(out)


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
        unc = f" ± {u:.2g}" if isinstance(u, (int, float)) else ""
        what = "Z" if c["check"] == "pressure" else "the rate"
        return f"the rule is expected to shift {what} by {p:+.3g}{unc} from the reference"
    return f"expected {fmt(p)}" + (f" ± {fmt(u)}" if isinstance(u, (int, float)) else "")


def check_matrix(a):
    """One table per scene: a row per backend, a column per check; each cell the counts of its
    cases or groups and the worst margin."""
    worst = {}
    for c in a.summary["checks"]:
        m = digest.margin(c)
        key = (c["scene"], c["backend"], c["check"])
        if m is not None and (key not in worst or m > worst[key][0]):
            worst[key] = (m, c.get("quantised", False))
    names = digest.check_order(a.summary)
    out, anchored = [], set()
    for scene in a.scenes:
        keys = [k for k in a.combinations if k[0] == scene]
        present = [n for n in names if any(k[2] == n for k in keys)]
        backends = list(OrderedDict.fromkeys(k[1] for k in keys))
        fails = sum(a.combinations[k]["fail"] for k in keys)
        out.append(f"<details class='scene' id='{digest.anchor('checks', scene)}'{' open' if fails else ''}>"
                   f"<summary><b>{html.escape(scene)}</b>: {len(keys)} (backend, check) combinations, {fails} failed "
                   "checks</summary><table class='checks'><tr><th>backend</th>"
                   + "".join(f"<th>{html.escape(n.replace('_', ' '))}</th>" for n in present) + "</tr>")
        for b in backends:
            ident = "" if b in anchored else f" id='{digest.anchor('backend', b)}'"  # the digest's links land here
            anchored.add(b)
            out.append(f"<tr{ident}><td>{html.escape(b)}</td>")
            for n in present:
                counts = a.combinations.get((scene, b, n))
                if not counts:
                    out.append("<td></td>")
                    continue
                status = digest.combination_status(counts)
                text = {"pass": f"{counts['pass']} ✓", "fail": f"{counts['fail']} ✗ of {counts['pass'] + counts['fail']}",
                        "left_out": "n/a", "cannot_run": "cannot run"}[status]
                if status == "pass" and counts["left_out"]:
                    text += f", {counts['left_out']} n/a"
                m = worst.get((scene, b, n))
                if m and status in ("pass", "fail"):
                    text += f" · {'≡' if m[1] else ''}{fmt(m[0])}"
                out.append(f"<td class='{status}'>{text}</td>")
            out.append("</tr>")
        out.append("</table></details>")
    for b in a.backends:  # a backend without checks still gets its anchor
        if b not in anchored:
            out.append(f"<p id='{digest.anchor('backend', b)}'>{html.escape(b)}: no checks.</p>")
    return "\n".join(out)


def left_out_table(a):
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
    if not reasons:
        return "<p>No check was left out.</p>"
    out = ["<table><tr><th>kind</th><th>check</th><th>reason</th><th>(scene, backend) combinations</th><th>checks</th>"
           "<th>scenes</th></tr>"]
    for (kind, check, reason), e in reasons.items():
        out.append(f"<tr><td>{kind}</td><td>{html.escape(check)}</td><td>{html.escape(reason)}</td><td>{len(e['combos'])}</td>"
                   f"<td>{e['checks']}</td><td>{html.escape(', '.join(sorted(e['scenes'])))}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def statistical_point_text(p):
    if p["resolved"]:
        text = f"{p['dt']:g}: {p['relative']:+.3g} ± {p['se']:.2g} ({p['sigmas']:.1f} SE)"
    else:
        text = f"{p['dt']:g}: {p['relative']:+.3g} ± {p['se']:.2g} (not resolved; |Δ| ≤ {p['upper']:.2g} at 95 %)"
    if p["predicted"] is not None:
        text += f", predicted {p['predicted']:+.3g}"
    return text + f"; detectable ≥ {p['detectable']:.2g}; {fmt(p['seconds'])} s"


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
            measure = "(Z − Z_ref) / Z_ref, means ± combined SE"
            pts = "<br>".join(html.escape(statistical_point_text(p))
                              for p in digest.statistical_points(s, line["scene"], "pressure").get(b, []))
        same = f" (= {html.escape(a.aliases[b])})" if b in a.aliases else ""
        out.append(f"<tr><td>{html.escape(line['scene'])}</td><td>{html.escape(b)}{same}</td><td>{measure}</td>"
                   f"<td>{pts}</td><td>{html.escape(digest.describe_order(fit))}</td>"
                   f"<td>{html.escape(digest.describe_floor(fit))}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


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


BIAS_FITS = jinja2.Template("""{% if rows %}<h3 id="bias-fits">The stepped rules' bias, fitted over the whole run</h3>
<p>Each statistical check above judges one sweep point. Fitted jointly over every point of a backend, the bias constant
(docs/validation.md, “The stepped rules' statistics bias”) says whether the points agree with the model together:
χ² of the fitted constant on n − 1 degrees of freedom, and of the model's own constant on n.</p>
<table id="bias-fit-table"><tr><th>backend</th><th>constant</th><th>fitted (this run)</th><th>model</th>
<th>(fitted − model) / SE</th><th>χ² fitted</th><th>χ² model</th></tr>
{% for r in rows %}<tr><td>{{ r.backend }}</td><td>{{ r.name }}</td><td>{{ r.fitted }}</td><td>{{ r.model }}</td><td>{{ r.z }}</td>
<td>{{ r.chi2 }}</td><td>{{ r.chi2_model }}</td></tr>{% endfor %}</table>{% endif %}""", autoescape=True)


def load_energy_jumps(directory):
    """The energy jumps `collide report` found in the cases drawn and explained before the
    renderer started (validation/explain/report_jumps.h): DIR/report/energy_jumps.json's list,
    or none where the renderer runs without it (a test that calls it directly)."""
    path = os.path.join(directory, "report", "energy_jumps.json")
    if not os.path.exists(path):
        return []
    with open(path, encoding="utf-8") as f:
        return json.load(f)["jumps"]


def jumps_by_scene(a, jumps):
    """{scene: {backend: (case, jump)}} for the backends drawn (an alias is drawn as its twin)."""
    cases = {c["id"]: c for c in a.summary["cases"]}
    out = {}
    for j in jumps:
        if j["backend"] not in a.aliases and j["case"] in cases:
            out.setdefault(j["scene"], {})[j["backend"]] = (cases[j["case"]], j)
    return out


def explanation_text(jump):
    """The step, the disks and the kind of contact behind a jump, as `collide explain` words
    them (C++ wrote them into energy_jumps.json), as HTML; or why they could not be named."""
    if jump.get("problem") or not jump.get("explained"):
        return f" The step could not be named: {html.escape(jump.get('problem') or 'no explanation recorded')}."
    found = jump["explained"]
    share = ""
    interval = jump["change"] * jump["scale"]  # the output interval's change
    if interval and math.isfinite(found["energy_change"]):
        share = f" That step is {100 * found['energy_change'] / interval:.0f} % of the interval's change."
    return f" In detail: {html.escape(found['description'])}.{share}"


def jump_notes(a, jumps):
    notes = []
    for backend, (case, j) in jumps.items():
        if "change" not in j:  # its record could not be read back for the search
            notes.append(f"<li><b>{html.escape(backend)}</b> ({html.escape(case['id'])}):{explanation_text(j)}</li>")
            continue
        notes.append(f"<li><b>{html.escape(backend)}</b> ({html.escape(case['id'])}): the energy changes by "
                     f"{100 * j['change']:+.2g} % of max K between t = {j['t0']:g} and t = {j['t1']:g}, one output "
                     f"interval; the median interval changes it by {100 * j['median']:.2g} %.{explanation_text(j)}</li>")
    if not notes:
        return ""
    box2d = any(digest.facts(a.summary, b).get("base") == "box2d" for b in jumps)
    return ("<p>Energy jumps in the cases shown:</p><ul>" + "".join(notes) + "</ul><p>Why the stepped rule "
            "changes the energy in one step where several contacts meet (three disks in contact at once, a disk "
            "touching a wall and a disk; `collide explain` reruns a case and names them): "
            "docs/stepping-rules.md, section 7, “Energy at e = 1”. An isolated pair keeps its energy at e = 1 "
            "in the stepped rules." + (" Where Box2D's isolated pair loses energy, look first at its "
            "restitution threshold, below which it makes a collision inelastic (docs/box2d-baseline.md)."
            if box2d else "") + "</p>")


def scene_section(summary, directory, a, scene, chosen, jumps):
    """One scene's figures and notes, as a list of HTML parts; the energy-jump notes are a
    placeholder ("JUMPS", scene, jumps) filled in by the process that lays the page out."""
    parts = [f"<h3 id='{digest.anchor('scene', scene)}'>{html.escape(scene)}</h3>"]
    if not chosen:
        return parts + ["<p>No case of this scene finished; see the failures above.</p>"]
    shown = [(b, r) for b, _, r in chosen if b not in a.aliases]
    labels = {b: " = ".join([b] + [x for x, y in a.aliases.items() if y == b]) for b, _ in shown}
    parts.append(image(figures.work_precision(summary, scene, digest, a.aliases, a.fit),
                       f"<b>Work against precision, {html.escape(scene)}.</b> Each point is one time step "
                       "(labelled dt) of one backend at its own cost: horizontal, the wall-clock seconds it needs "
                       "per unit of simulated time (after a warm-up, mean over replicates); vertical, its error "
                       f"against the exact event-driven reference '{html.escape(summary['reference'])}' with ± 1 "
                       "SE (hollow: not resolved, drawn at the 95 % upper limit |Δ| + 1.96 SE; the vertical "
                       "dashed line: the exact solver's own cost). Down and to the left is better. The order in "
                       "the legend is the one validate fitted on the asymptotic range (§3).",
                       "work-precision diagram"))
    which = ", ".join(f"{b} at dt = {c['dt']:g}, seed {c['seed']}" for b, c, _ in chosen)
    drift = figures.conservation(shown, scene, {b: j for b, (_, j) in jumps.items()}, labels)
    parts.append(image(drift, f"<b>Conservation, {html.escape(scene)}.</b> Change of the energy (total energy under "
                       "gravity, else kinetic) since t = 0, divided by the largest kinetic energy seen, and of "
                       "the total momentum, divided by sqrt(2 M K(0)); a panel where every backend stays below "
                       f"{figures.QUIET:g} is not drawn (the figure says which). Backends are drawn with different "
                       "dashes and widths, so lines that coincide stay visible. "
                       f"Cases shown: {html.escape(which)}.", "conservation time series")
                 if drift else f"<p>Energy and momentum stay within {figures.QUIET:g} of their start in every "
                               f"case shown ({html.escape(which)}): no conservation figure.</p>")
    parts.append(("JUMPS", scene, jumps))
    hist = figures.overlap_histogram(shown, scene, labels)
    if hist:
        parts.append(image(hist, f"<b>Overlaps, {html.escape(scene)}.</b> How deep overlapping pairs of disks "
                           "intersect in the final state, relative to their contact distance (0 = touching, 1 = "
                           f"concentric); a backend with fewer than {figures.FEW_PAIRS} pairs is drawn as one marker "
                           "per pair. Hard disks never overlap; stepped solvers detect contacts only after they "
                           f"happen, so some overlap is part of their rule. Cases shown: {html.escape(which)}.",
                           "overlap histogram"))
    else:
        parts.append("<p>No overlapping pairs in the final state of the cases shown.</p>")
    backend, case, result = chosen[0]
    box = scene_box(summary.get("scene_files", {}).get(scene, ""))
    parts.append(image(figures.configuration(result, box, scene, backend),
                       f"<b>Configuration, {html.escape(scene)}.</b> The disks (drawn to scale, coloured by "
                       f"speed) at the start and at the end of the case {html.escape(case['id'])}, inside the "
                       "scene's box.", "initial and final configuration"))
    parts.append(animations.section(summary, directory, scene, image))  # motion strips, if frames were stored
    return parts


_SHARED = {}  # what the drawing processes inherit when forked (nothing is pickled but a scene name)


def _scene_section_worker(scene):
    s = _SHARED
    return scene_section(s["summary"], s["directory"], s["a"], scene, s["chosen"][scene], s["requests"].get(scene, {}))


def _with_progress(pool, scenes):
    """Each scene's section from the pool, in scene order, with a progress line on the way
    (progress.py: in place on a terminal, quiet in short logs)."""
    futures = [pool.submit(_scene_section_worker, scene) for scene in scenes]
    line = progress.ProgressLine()
    done = 0
    for _ in as_completed(futures):
        done += 1
        line.update(done / len(futures), f"report: {done} of {len(futures)} scenes drawn")
    line.finish()
    return [f.result() for f in futures]


def scene_sections(summary, directory, a=None):
    """Every scene's section. The figures are drawn by forked processes, one scene each, as many
    at a time as there are cores; the energy jumps come explained from `collide report`."""
    a = a or Analysis(summary)
    chosen_by_scene = OrderedDict((scene, representative_cases(summary, directory, scene)) for scene in a.scenes)
    requests = jumps_by_scene(a, load_energy_jumps(directory))
    cores = max(1, os.cpu_count() or 1)
    _SHARED.update(summary=summary, directory=directory, a=a, chosen=chosen_by_scene, requests=requests)
    try:
        with ProcessPoolExecutor(max_workers=cores, mp_context=multiprocessing.get_context("fork")) as pool:
            sections = _with_progress(pool, a.scenes)
    finally:
        _SHARED.clear()
    return "\n".join(jump_notes(a, p[2]) if isinstance(p, tuple) else p for parts in sections for p in parts)


def machine_text(summary):
    """The machine the timings come from: processor, cores, load, and how many threads each
    case ran with times the cases run at once (summary.json's machine, execution, provenance),
    as HTML sentences for the caller's paragraph."""
    m = summary.get("machine") or {}
    jobs = (summary.get("execution") or {}).get("jobs", "?")
    threads = OrderedDict()
    for c in summary["cases"]:
        for k, v in (c.get("provenance") or {}).items():
            if k.endswith(".threads"):
                threads.setdefault(c["backend"], set()).add(v)
    cores = m.get("cores")
    parts = [f"Processor: {html.escape(m.get('cpu_model', '?'))}, {cores} cores; load average when the run ended "
             f"{fmt(m.get('load_1min'))} (1 min), {fmt(m.get('load_5min'))} (5 min), {fmt(m.get('load_15min'))} (15 min); "
             f"{html.escape(str(jobs))} cases at a time (--jobs)."]
    for b, values in threads.items():
        t = max(int(v) for v in values if str(v).isdigit()) if any(str(v).isdigit() for v in values) else None
        if t is None:
            continue
        busy = t * int(jobs) if str(jobs).isdigit() else None
        over = f", oversubscribing the {cores} cores" if busy and cores and busy > cores else ""
        parts.append(f"{html.escape(b)}: {t} threads per case × {jobs} cases at a time = {busy} threads{over}.")
    return " ".join(parts)


COSTS = jinja2.Template("""<table id="costs"><tr><th>scene</th><th>backend</th><th>cheapest sweep point</th>
<th>s per time unit (mean)</th><th>fastest – slowest replicate</th><th>÷ exact solver's</th></tr>
{% for c in costs %}<tr><td>{{ c.scene }}</td><td>{{ c.backend }}</td><td>{{ c.group }}</td><td>{{ c.mean }}</td>
<td>{{ c.spread }}</td><td>{{ c.ratio }}</td></tr>{% endfor %}</table>""", autoescape=True)


def timings(summary):
    rows = [{"scene": c["scene"], "backend": c["backend"], "group": c["group"], "mean": fmt(c["seconds_per_time_unit"]),
             "spread": f"{fmt(c['fastest_replicate'])} – {fmt(c['slowest_replicate'])} ({c['replicates']})",
             "ratio": fmt(c.get("relative_to_reference"))} for c in summary.get("costs", [])]
    return ("<p>Wall time is spent in the solver's advance_to() only (metrics and output excluded), measured after an "
            "untimed warm-up run, each case in its own process. " + machine_text(summary) + "</p>" +
            COSTS.render(costs=rows) + "<p>Every case's timing: <a href='checks.html#timings'>checks.html</a>.</p>")


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


STYLE = """
body { font-family: sans-serif; max-width: 1380px; margin: 0.5em auto; color: #222; }
h1 { font-size: 20px; margin: 0.2em 0; }
table { border-collapse: collapse; margin: 0.4em 0 1.2em 0; font-size: 12px; }
th, td { border: 1px solid #ccc; padding: 2px 5px; text-align: left; vertical-align: top; }
td.pass, tr.pass td:nth-child(2) { background: #dff0d8; }
td.fail, tr.fail td { background: #f2dede; }
td.left_out, td.cannot_run { background: #eee; color: #777; }
td.subject { font-family: monospace; word-break: break-all; max-width: 260px; }
table.checks { font-size: 10.5px; } table.checks td { white-space: nowrap; }
table.digest { font-size: 11.5px; margin: 0.2em 0 0.4em 0; } table.digest tr.total td { background: #f6f6f6; }
table#verdicts td:nth-child(2) { max-width: 420px; }
.where { color: #666; font-size: 10.5px; }
.top { display: flex; gap: 14px; align-items: flex-start; }
.top .main { flex: 1 1 auto; min-width: 0; overflow-x: auto; }
nav#toc { flex: 0 0 260px; font-size: 12px; border: 1px solid #ddd; padding: 4px 8px; background: #fafafa; }
nav#toc ul { margin: 2px 0; padding-left: 16px; } nav#toc p { margin: 4px 0; }
div.physics-top { display: flex; gap: 12px; align-items: flex-start; } div.physics-top figure { margin: 0; }
table.physics { font-size: 11px; } table.physics td.pass { background: #dfd; } table.physics td.fail { background: #fdd; }
figure { margin: 0.6em 0 1.6em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figure#headline { margin-top: 0.2em; } figure#headline img { max-height: 440px; }
figcaption { font-size: 12px; color: #444; max-width: 1300px; }
p.verdict { font-size: 16px; font-weight: bold; margin: 0.2em 0; } .pass { color: #2a7a2a; } .failed { color: #b02020; }
p.identical { font-size: 12px; margin: 0.2em 0; }
details { margin: 0.2em 0 0.2em 0.5em; }
pre { white-space: pre-wrap; margin: 0; font-size: 11px; }
"""


def write_html(summary, directory, path, a=None):
    a = a or Analysis(summary)
    stability_first = ""
    if a.stability:
        stability_first = ("<h2 id='stability-first'>First failure of each backend</h2><p class='where'>Each cell: the "
                           "first failure on that scene (smallest failing dt, then smallest swept value) and failed / "
                           "classified cases; hover for the measured value. Maps and the full table: "
                           "<a href='#stability'>Stability</a>.</p>" + stability.first_failure_matrix(summary))
    page = TEMPLATES.get_template("index.html.j2").render(
        suite=summary["suite"], style=Markup(STYLE), passed=a.passed, verdict=verdict_text(a),
        stability_first=Markup(stability_first), verdicts=a.verdicts, digest_table=Markup(digest_table(a)),
        identical=Markup(identical_line(a)), toc=Markup(toc(a)), physics=Markup(physics.section(summary, image)),
        headline=Markup(headline_figure(a)), description=summary.get("description", ""),
        stability_section=Markup(stability.section(summary, image) if a.stability else ""),
        failures=Markup(failures(a)), check_matrix=Markup(check_matrix(a)), left_out=Markup(left_out_table(a)),
        orders_table=Markup(orders_table(a)), bias_fits=Markup(BIAS_FITS.render(rows=bias_fit_rows(summary))),
        scenes=Markup(scene_sections(summary, directory, a)), timings=Markup(timings(summary)),
        provenance=Markup(provenance_table(summary)))
    safe_output.write_text(path, page)


def check_rows(summary):
    for c in summary["checks"]:
        lo = c["status"] == "left_out"
        yield {"subject": c["subject"], "check": c["check"], "status": c["status"],
               "value": "" if lo else fmt(c.get("value")),
               "tolerance": "" if lo else c.get("comparison", "") + " " + fmt(c.get("tolerance")),
               "margin": fmt(digest.margin(c)) + (" (quantised)" if c.get("quantised") else ""),
               "predicted": predicted_text(c, c["check"] == "energy_drift"), "detail": c["detail"]}


def write_checks_html(summary, path):
    cases = [{"id": c["id"], "status": c["status"], "disks": c["disks"], "duration": fmt(c["duration"]),
              "wall": fmt(c["wall_seconds"]), "per_unit": fmt(c.get("seconds_per_time_unit")),
              "steps": c.get("steps", ""), "contacts": c.get("contacts", ""), "warmup": fmt(c.get("warmup_seconds")),
              "cls": "pass" if c["status"] == "completed" else "left_out" if c["status"] == "left_out" else "fail"}
             for c in summary["cases"]]
    safe_output.write_text(path, TEMPLATES.get_template("checks.html.j2").render(
        suite=summary["suite"], style=Markup(STYLE), rows=check_rows(summary), cases=cases))


CSV_FIELDS = ("subject", "scene", "backend", "check", "status", "value", "comparison", "tolerance", "margin",
              "quantised", "predicted", "predicted_uncertainty", "detail")


def write_checks_csv(summary, path):
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=CSV_FIELDS, extrasaction="ignore", lineterminator="\n")
    writer.writeheader()
    for c in summary["checks"]:
        writer.writerow({k: c.get(k, "") for k in CSV_FIELDS})
    safe_output.write_text(path, buffer.getvalue())


def write_markdown(summary, path, a=None, full_name="summary-full.md"):
    """The digest, in at most about 80 lines: verdict, per-backend verdicts and table, failures
    (the first 20), orders and floors; every check is in summary-full.md."""
    a = a or Analysis(summary)
    if a.stability:
        failures_ = [f"- UNEXPECTED {md(u)}" for u in a.unexpected[:20]] or \
                    ["Nothing unexpected (every case classified, the exact solver stable, no crash)."]
        failures_ += stability.markdown(summary)[:40]
    else:
        failed = [c for c in summary["checks"] if c["status"] == "fail"]
        failures_ = [f"- `{c['subject']}` {c['check']}: {md(c['detail'].splitlines()[0] if c['detail'] else '')}"
                     for c in failed[:20]] or ["None."]
        if len(failed) > 20:
            failures_.append(f"- ... and {len(failed) - 20} more in [{full_name}]({full_name})")
    text = TEMPLATES.get_template("summary.md.j2").render(
        suite=summary["suite"], verdict=verdict_text(a), verdicts=a.verdicts,
        rows=digest_rows(a, link=False),
        identical=[f"{b} gives the same numbers as {x} bit for bit ({n} compared values)." for x, b, n in a.identical],
        physics=physics.markdown(summary), failures=failures_,
        fits=[{"scene": f["scene"], "backend": f["backend"], "order": digest.describe_order(f),
               "floor": digest.describe_floor(f)} for f in a.fits if f["backend"] not in a.aliases],
        full_name=full_name)
    lines = text.splitlines()
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
    for r, c in zip(check_rows(summary), summary["checks"]):
        note = c["detail"].splitlines()[0] if c["detail"] else ""
        lines.append(f"| `{r['subject']}` | {r['check']} | {r['status']} | {r['value']} | {r['tolerance']} | {r['margin']} "
                     f"| {md(note + ('; ' + r['predicted'] if r['predicted'] else ''))} |")
    lines += ["", "## Observed convergence order", "", "| scene | backend | order (asymptotic range) | floor |",
              "|---|---|---|---|"]
    for f in a.fits:
        lines.append(f"| {md(f['scene'])} | {md(f['backend'])} | {md(digest.describe_order(f))} | "
                     f"{md(digest.describe_floor(f))} |")
    safe_output.write_text(path, "\n".join(lines) + "\n")


REPORT_FILES = ("index.html", "checks.html", "checks.csv", "summary.md", "summary-full.md")


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
    safe_output.make_output_directory(out)
    a = Analysis(summary)
    write_html(summary, directory, os.path.join(out, "index.html"), a)
    write_checks_html(summary, os.path.join(out, "checks.html"))
    write_checks_csv(summary, os.path.join(out, "checks.csv"))
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
