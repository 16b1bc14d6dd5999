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
import csv
import io
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import templating  # noqa: E402  (first: it names a missing jinja2 rather than failing later)
import digest  # noqa: E402
from safe_files import safe_output  # noqa: E402  (python/collide/safe_output.py)
import scenes  # noqa: E402
import sections  # noqa: E402
import stability  # noqa: E402
import figures  # noqa: E402
import physics  # noqa: E402
import engines_page  # noqa: E402
from analysis import Analysis, digest_rows, fmt, predicted_text, verdict_text  # noqa: E402
from digest import ReportInputError  # noqa: E402
from templating import md  # noqa: E402


def write_html(summary, directory, path, a=None, meanwhile=None):
    """index.html; `meanwhile` runs while its figures are drawn (scenes.sections)."""
    a = a or Analysis(summary)
    page = sections.page(a, scenes.sections(summary, directory, a, meanwhile))
    safe_output.write_text(path, templating.render("index.html.j2", **page, quiet=f"{figures.QUIET:g}",
                                                   few_pairs=figures.FEW_PAIRS))


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
    safe_output.write_text(path, templating.render("checks.html.j2", suite=summary["suite"], rows=check_rows(summary),
                                                   cases=cases))


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
        failures_ = [f"- {md(c['subject'])} {md(c['check'])}: {md(c['detail'].splitlines()[0] if c['detail'] else '')}"
                     for c in failed[:20]] or ["None."]
        if len(failed) > 20:
            failures_.append(f"- ... and {len(failed) - 20} more in [{full_name}]({full_name})")
    text = templating.render(
        "summary.md.j2", suite=summary["suite"], verdict=verdict_text(a), verdicts=a.verdicts,
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
    lines += [f"- {md(c['subject'])} {md(c['check'])}: {md(c['detail'])}" for c in failed] or ["None."]
    lines += stability.markdown(summary)
    lines += ["", "## Checks", "", "| case | check | status | value | tolerance | margin | note |",
              "|---|---|---|---|---|---|---|"]
    for r, c in zip(check_rows(summary), summary["checks"]):
        note = c["detail"].splitlines()[0] if c["detail"] else ""
        lines.append(f"| {md(r['subject'])} | {md(r['check'])} | {r['status']} | {r['value']} | {r['tolerance']} | {r['margin']} "
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
    figures.assign_styles(list(summary.get("backends", {})))  # one colour and marker per backend, every figure
    a = Analysis(summary)

    def pages_without_figures():  # written while the figures are drawn: this process would wait idle
        write_checks_html(summary, os.path.join(out, "checks.html"))
        write_checks_csv(summary, os.path.join(out, "checks.csv"))
        write_markdown(summary, os.path.join(out, "summary.md"), a)
        write_markdown_full(summary, os.path.join(out, "summary-full.md"), a)
    write_html(summary, directory, os.path.join(out, "index.html"), a, meanwhile=pages_without_figures)
    engines_page.write(directory, summary, out)  # "Engines side by side", where two or more engines ran
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
