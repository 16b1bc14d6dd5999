"""What every part of the report shares, read once from summary.json (digest.py's numbers), and
the words and numbers it shows them with, as plain text: the templates escape and lay them out.
"""
import math

import digest
import physics
import stability
import verdicts


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


def fmt(value):
    if value is None or isinstance(value, str):
        return "n/a" if value is None else value
    if value == 0:
        return "0"
    return f"{value:.3g}"


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


def margin_parts(row):
    """A digest row's worst margin as {'text', 'subject', 'where'} (the number, the check's
    subject, the check with its ties), or None where it has none."""
    worst = row["worst"]
    if worst is None:
        return None
    m, subject, check = worst
    text = "∞" if m == math.inf else f"{m:.2f}" if 0.01 <= m < 1e4 else fmt(m)  # layout: fixed point where it reads
    ties = f", one of {row['ties']} checks at this value" if row["ties"] > 1 else ""
    at_limit = row.get("quantised_at_limit", 0)
    quantised = f"; {at_limit} quantised count{'s' if at_limit > 1 else ''} at the limit" if at_limit else ""
    return {"text": text, "subject": subject, "where": f"{check.replace('_', ' ')}{ties}{quantised}"}


def margin_text(row):
    """The worst margin in one line of text (summary.md)."""
    parts = margin_parts(row)
    return "n/a" if parts is None else f"{parts['text']} ({parts['subject']}: {parts['where']})"


def floor_text(fits, limit=1):
    if not fits:
        return ""
    parts = [f"{f['scene']}: from h ≈ {f['floor']['h']:g} at ≈ {f['floor']['error']:.2g}" if f["floor"] else
             f"{f['scene']}: floor-contaminated order" for f in fits[:limit]]
    if len(fits) > limit:
        parts.append(f"+{len(fits) - limit} more")
    return "; ".join(parts)


def digest_rows(a, link=True):
    """The per-backend digest; `link`: for the page (the worst margin in parts, one floor),
    else for summary.md (the worst margin in words, three floors)."""
    out = []
    for r in a.rows:
        c = r["combinations"]
        out.append({"backend": r["backend"], "name": r["backend"] + (f" (= {a.aliases[r['backend']]})" if r["backend"] in a.aliases else ""),
                    "anchor": digest.anchor("backend", r["backend"]), "cases": r["cases"],
                    "cases_cannot_run": r["cases_cannot_run"], "pass": r["pass"], "fail": r["fail"],
                    "left_out": r["left_out"], "c_pass": c["pass"], "c_fail": c["fail"], "c_left_out": c["left_out"],
                    "c_cannot_run": c["cannot_run"], "worst": margin_parts(r) if link else margin_text(r),
                    "order_trajectory": digest.order_summary(r["orders"].get("trajectory", [])),
                    "order_z": digest.order_summary(r["orders"].get("Z", [])),
                    "floor": floor_text(r["floors"], 1 if link else 3)})
    return out


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
