"""`collide compare DIR_A DIR_B`: two result directories of the same suite (before and after a
change, two machines, two compilers), side by side (docs/your-solver.md, "Did my change make it
worse?").

It reports
  - how many cases are bit-identical: the same final state and metric series, bit for bit
    (cases/<id>.toml; wall times and provenance are not compared);
  - every check whose status changed (pass -> fail is a regression);
  - lost coverage: a check that A judged (pass or fail) and B left out or does not have, and a
    case file (its record cases/<id>.toml, its run runs/<id>.h5) that B's summary.json lists and
    B's directory lacks; each is named, and each is a regression: a change that stops a check
    from running must not read as "no significant regression";
  - every observable with an error bar that moved by more than --sigma combined standard
    errors: the work-precision points (the error against the reference at each dt) and the
    rows of "Reference against physics".
Exit status: 0 no significant regression; 1 a regression (more than --allow checks newly
failing, lost coverage, or an error against the reference that grew beyond --sigma); 2 the
directories cannot be compared (named on stderr): not one summary.json, two suites, or no case
in common.
"""

import argparse
import math
import os
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import digest  # noqa: E402  (the standard library only)
from printable import terminal  # noqa: E402
from safe_files import safe_output  # noqa: E402  (the input guard: no FIFO waited on)
import record_toml  # noqa: E402  (a case record as tomllib reads it, faster)


class Unreadable(Exception):
    pass


def load_summary(directory):
    """summary.json, checked as the report checks it (digest.load_summary)."""
    try:
        return digest.load_summary(directory)
    except digest.ReportInputError as e:
        found = os.path.exists(os.path.join(directory, "summary.json"))
        hint = "" if found else "; expected the output directory of `collide validate`"
        raise Unreadable(f"{e}{hint}") from None


def case_numbers(directory, case):
    """The final state and metric series of a case record, or None where it has none (no
    record, or one whose checksum line is missing or does not match: digest.verified_record_text)."""
    path = os.path.join(directory, case.get("result_file") or "cases/%s.toml" % case["id"])
    try:
        with safe_output.open_input(path, "rb") as f:
            record = record_toml.loads(digest.verified_record_text(path, f.read()))
    except (OSError, digest.ReportInputError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return None
    # repr() keeps the bits (NaN equals NaN here, -0.0 differs from 0.0).
    return repr((record.get("status"), record.get("final"), record.get("series")))


def missing_case_files(directory, cases):
    """The files that summary.json lists for its cases and the directory lacks, as paths."""
    missing = []
    for case in cases.values():
        for name in (case.get("result_file") or "cases/%s.toml" % case["id"], case.get("hdf5_file")):
            if name and not os.path.isfile(os.path.join(directory, name)):
                missing.append(os.path.join(directory, name))
    return missing


JUDGED = ("pass", "fail")


def lost_checks(checks_a, checks_b):
    """(key, status in A, status in B or None) of every check that A judged and B did not."""
    lost = []
    for key, ca in sorted(checks_a.items()):
        cb = checks_b.get(key)
        if ca["status"] in JUDGED and (cb is None or cb["status"] not in JUDGED):
            lost.append((key, ca["status"], cb))
    return lost


def z_score(a, sa, b, sb):
    spread = math.hypot(sa or 0.0, sb or 0.0)
    if a is None or b is None:
        return None
    if spread == 0:
        return 0.0 if a == b else math.inf
    return (b - a) / spread


def work_precision_points(summary):
    out = {}
    for line in summary.get("work_precision", []):
        for p in line.get("points", []):
            key = "work-precision %s %s %s dt=%s substeps=%s iterations=%s" % (
                line["scene"], line["backend"], line["error_kind"], p["dt"], p["substeps"], p["iterations"])
            out[key] = (p.get("error"), p.get("error_standard_error"))
    return out


def physics_values(summary):
    out = {}
    for r in summary.get("physics", {}).get("rows", []):
        key = "physics %s %s %s %s=%s" % (r["row"], r["scene"], r["backend"], r["parameter_name"], r["parameter"])
        out[key] = (r.get("value"), r.get("standard_error"))
    return out


def compare(dir_a, dir_b, sigma, allow):
    a, b = load_summary(dir_a), load_summary(dir_b)
    if a.get("suite") != b.get("suite"):
        raise Unreadable("%s ran suite '%s' and %s suite '%s': compare two runs of the same suite"
                         % (dir_a, a.get("suite"), dir_b, b.get("suite")))
    lines, regressions = [], 0
    cases_a = {c["id"]: c for c in a.get("cases", [])}
    cases_b = {c["id"]: c for c in b.get("cases", [])}
    both = sorted(set(cases_a) & set(cases_b))
    if not both:
        raise Unreadable("%s (%d cases) and %s (%d cases) share no case: compare two runs of the same suite"
                         % (dir_a, len(cases_a), dir_b, len(cases_b)))
    identical = 0
    for k in both:
        numbers_a = case_numbers(dir_a, cases_a[k])
        identical += numbers_a is not None and numbers_a == case_numbers(dir_b, cases_b[k])
    lines.append("cases     %d in both, %d bit-identical (final state and metric series), %d differ, "
                 "%d only in A, %d only in B" % (len(both), identical, len(both) - identical,
                                                 len(set(cases_a) - set(cases_b)), len(set(cases_b) - set(cases_a))))

    checks_a = {(c["subject"], c["check"]): c for c in a.get("checks", [])}
    checks_b = {(c["subject"], c["check"]): c for c in b.get("checks", [])}
    changed = []
    for key in sorted(set(checks_a) & set(checks_b)):
        sa, sb = checks_a[key]["status"], checks_b[key]["status"]
        if sa != sb:
            changed.append((key, sa, sb))
    new_failures = sum(1 for _, sa, sb in changed if sb == "fail")
    lines.append("checks    %d changed status: %d newly failing, %d newly passing; %d only in A, %d only in B"
                 % (len(changed), new_failures, sum(1 for _, sa, sb in changed if sa == "fail"),
                    len(set(checks_a) - set(checks_b)), len(set(checks_b) - set(checks_a))))
    for (subject, check), sa, sb in changed:
        tag = "REGRESSED" if sb == "fail" else "IMPROVED " if sa == "fail" else "CHANGED  "
        vb = checks_b[(subject, check)]
        lines.append("%s %s: %s: %s -> %s (value %s, tolerance %s)" % (tag, subject, check, sa, sb,
                                                                     vb.get("value"), vb.get("tolerance")))
    if new_failures > allow:
        regressions += 1

    # Lost coverage: what A judged and B no longer does, and the files B lists but lacks.
    lost = lost_checks(checks_a, checks_b)
    missing_a, missing_b = missing_case_files(dir_a, cases_a), missing_case_files(dir_b, cases_b)
    lines.append("coverage  %d checks judged in A are not judged in B; %d files listed in B's summary.json are "
                 "missing (%d in A's)" % (len(lost), len(missing_b), len(missing_a)))
    for (subject, check), sa, cb in lost:
        now = "not in B" if cb is None else "%s in B (%s)" % (cb["status"], cb.get("detail") or "no reason given")
        lines.append("LOST      %s: %s: %s in A, %s" % (subject, check, sa, now))
    lines.extend("MISSING   %s" % path for path in missing_b + missing_a)
    if lost or missing_b:
        regressions += 1

    moved, worse = [], 0
    for kind, values_a, values_b in (("error", work_precision_points(a), work_precision_points(b)),
                                     ("value", physics_values(a), physics_values(b))):
        for key in sorted(set(values_a) & set(values_b)):
            (va, sea), (vb, seb) = values_a[key], values_b[key]
            z = z_score(va, sea, vb, seb)
            if z is None or abs(z) <= sigma:
                continue
            grew = kind == "error" and z > 0
            worse += grew
            moved.append("%s %s: %s %s +- %s -> %s +- %s (%.1f combined standard errors)" % (
                "WORSE    " if grew else "MOVED    ", key, kind, va, sea, vb, seb, z))
    lines.append("observables %d moved beyond %g combined standard errors (%d errors against the reference grew)"
                 % (len(moved), sigma, worse))
    lines.extend(moved)
    if worse:
        regressions += 1
    verdict = "regression" if regressions else "no significant regression"
    lines.append("verdict   %s (allowed newly failing checks: %d, observables: %g sigma)" % (verdict, allow, sigma))
    return lines, 1 if regressions else 0


def main(argv):
    parser = argparse.ArgumentParser(prog="collide compare", description=__doc__.split("\n\n")[0])
    parser.add_argument("dir_a")
    parser.add_argument("dir_b")
    parser.add_argument("--sigma", type=float, default=3.0,
                        help="an observable moved when it changed by more than this many combined standard errors")
    parser.add_argument("--allow", type=int, default=0, help="newly failing checks tolerated before exit status 1")
    args = parser.parse_args(argv)
    try:
        lines, status = compare(args.dir_a, args.dir_b, args.sigma, args.allow)
    except Unreadable as e:
        print("collide compare: %s" % terminal(e), file=sys.stderr)
        return 2
    # Names, details and paths come from the two directories: shown through the sanitiser.
    print(terminal("compare   suite: A = %s, B = %s" % (args.dir_a, args.dir_b)))
    print("\n".join(terminal(line) for line in lines))
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
