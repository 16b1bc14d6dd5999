#!/usr/bin/env python3
"""Tests of the report's numbers and drawing (validation/report/), on a real run of
tests/report/mini.toml and on synthetic data.

usage: test_report_data.py RESULTS_DIR
"""
import copy
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPORT = os.path.join(HERE, "..", "..", "validation", "report")
sys.path.insert(0, REPORT)

import digest  # noqa: E402
import figures  # noqa: E402
import make_report  # noqa: E402
import physics  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

RESULTS = None


def render(directory):
    return subprocess.run([sys.executable, os.path.join(REPORT, "make_report.py"), directory],
                          capture_output=True, text=True)


class DigestMatchesSummary(unittest.TestCase):
    def setUp(self):
        with open(os.path.join(RESULTS, "summary.json"), encoding="utf-8") as f:
            self.summary = json.load(f)
        self.rows = digest.digest(self.summary, digest.all_orders(self.summary))

    def test_totals_equal_counts(self):
        for key in ("pass", "fail", "left_out"):
            self.assertEqual(sum(r[key] for r in self.rows), self.summary["counts"][key], key)
        self.assertEqual(sum(r["cases"] for r in self.rows), len(self.summary["cases"]))

    def test_each_backend_counted(self):
        for r in self.rows:
            checks = [c for c in self.summary["checks"] if c["backend"] == r["backend"]]
            for key in ("pass", "fail", "left_out"):
                self.assertEqual(r[key], sum(1 for c in checks if c["status"] == key), (r["backend"], key))
            self.assertEqual(r["cases"], sum(1 for c in self.summary["cases"] if c["backend"] == r["backend"]))

    def test_worst_margin_is_the_largest(self):
        for r in self.rows:
            margins = [digest.margin(c) for c in self.summary["checks"] if c["backend"] == r["backend"]]
            margins = [m for m in margins if m is not None]
            if margins:
                self.assertEqual(r["worst"][0], max(margins))

    def test_rendered_digest_and_summary(self):
        html = open(os.path.join(RESULTS, "report", "index.html"), encoding="utf-8").read()
        self.assertIn('id="digest"', html)
        self.assertIn('id="headline"', html)
        summary_md = open(os.path.join(RESULTS, "report", "summary.md"), encoding="utf-8").read().splitlines()
        self.assertLessEqual(len(summary_md), 80)
        for b in digest.backends_in_order(self.summary):
            self.assertTrue(any(line.startswith(f"| {b}") for line in summary_md), f"{b} not in summary.md's digest")
        for name in ("checks.html", "summary-full.md"):
            self.assertTrue(os.path.exists(os.path.join(RESULTS, "report", name)), name)


class OrderFit(unittest.TestCase):
    def test_float_floor_excluded(self):
        # First order down to dt = 1e-3, then rounding: the error rises again.
        errors = {8e-3: 8e-3, 4e-3: 4e-3, 2e-3: 2e-3, 1e-3: 1e-3, 5e-4: 1.3e-3, 2.5e-4: 2.4e-3}
        fit = digest.fit_order([{"dt": dt, "error": e} for dt, e in errors.items()], "cpu")
        self.assertAlmostEqual(fit["order"], 1.0, places=6)
        self.assertEqual(fit["used"], 4)
        self.assertEqual(fit["floor"]["dt"], 1e-3)
        self.assertEqual(fit["floor"]["excluded"], 2)
        self.assertEqual(fit["floor"]["kind"], "float floor")
        self.assertIn("float floor from dt ≈ 0.001", digest.describe_floor(fit["floor"]))

    def test_flattening_is_a_floor(self):
        errors = {8e-3: 8e-3, 4e-3: 4e-3, 2e-3: 2e-3, 1e-3: 1.9e-3, 5e-4: 1.85e-3}
        fit = digest.fit_order([{"dt": dt, "error": e} for dt, e in errors.items()], "step")
        self.assertAlmostEqual(fit["order"], 1.0, places=6)
        self.assertEqual(fit["floor"]["kind"], "error floor")

    def test_no_floor_in_a_clean_line(self):
        fit = digest.fit_order([{"dt": 2.0 ** -k, "error": 3 * 4.0 ** -k} for k in range(5)], "step")
        self.assertAlmostEqual(fit["order"], 2.0, places=6)
        self.assertIsNone(fit["floor"])

    def test_statistical_noise_is_no_floor(self):
        # Z errors of a first-order bias over a narrow dt range: the finest point lies above the
        # coarser one, but well within its error bars, so the descent still explains it.
        pts = [{"dt": 6e-3, "error": 0.0100, "se": 0.0019}, {"dt": 4.8e-3, "error": 0.0080, "se": 0.0020},
               {"dt": 4e-3, "error": 0.0086, "se": 0.0022}]
        fit = digest.fit_order(pts, "step")
        self.assertIsNone(fit["floor"])
        self.assertEqual(fit["used"], 3)
        self.assertTrue(fit["statistical"])
        # Without the error bars the same numbers would be read as a floor.
        bare = digest.fit_order([{"dt": p["dt"], "error": p["error"]} for p in pts], "step")
        self.assertIsNotNone(bare["floor"])

    def test_significant_statistical_rise_is_a_floor(self):
        pts = [{"dt": 8e-3, "error": 0.016, "se": 0.001}, {"dt": 4e-3, "error": 0.008, "se": 0.001},
               {"dt": 2e-3, "error": 0.004, "se": 0.0005}, {"dt": 1e-3, "error": 0.012, "se": 0.001}]
        fit = digest.fit_order(pts, "cpu")
        self.assertEqual(fit["floor"]["dt"], 2e-3)
        self.assertAlmostEqual(fit["order"], 1.0, places=6)

    def test_order_error_bar_from_the_points(self):
        # Exact first-order points with 10 % log-space error bars at h = 1, 1/2, 1/4: the weighted
        # slope's standard error is 0.1 / sqrt(sum (x - mean x)^2) = 0.1 / (ln 2 * sqrt(2)).
        pts = [{"dt": 2.0 ** -k, "error": 2.0 ** -k, "se": 0.1 * 2.0 ** -k} for k in range(3)]
        fit = digest.fit_order(pts, "step")
        self.assertAlmostEqual(fit["order"], 1.0, places=9)
        self.assertAlmostEqual(fit["order_se"], 0.1 / (math.log(2) * math.sqrt(2)), places=9)
        self.assertIn("1.00 ± 0.10", digest.describe_order(fit))

    def test_box2d_floor_is_its_tolerances_not_rounding(self):
        errors = {4e-3: 1.6, 2e-3: 1.6, 1e-3: 1.61, 5e-4: 1.6}
        fit = digest.fit_order([{"dt": dt, "error": e} for dt, e in errors.items()], "box2d[shipped]")
        self.assertEqual(fit["floor"]["kind"], "solver floor")
        text = digest.describe_floor(fit["floor"])
        self.assertIn("Box2D's tolerances", text)
        self.assertNotIn("rounding", text)

    def test_too_few_points(self):
        fit = digest.fit_order([{"dt": 1e-3, "error": 1e-3}, {"dt": 5e-4, "error": 5e-4}])
        self.assertIsNone(fit["order"])
        self.assertIn("2 points", fit["note"])


class JumpExplained(unittest.TestCase):
    """An energy jump is named down to its step, disks and kind of contact by `collide explain`;
    a failing program is reported in the note, never silently dropped."""

    def stepped_case(self):
        with open(os.path.join(RESULTS, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
        return next(c for c in summary["cases"] if c["backend"] == "step" and c["scene"] == "periodic_gas")

    def test_named_by_collide_explain(self):
        case = self.stepped_case()
        jump = {"t0": 0.0, "t1": case["duration"], "change": -0.01, "scale": 1000.0}
        note = make_report.explain_jump(RESULTS, case, jump)
        self.assertIn("In detail: the step ending at t = ", note)
        # a 1000-disk gas in a periodic box: the largest change comes from disks in contact
        self.assertRegex(note, r"(an isolated pair|\d+ disks in contact at once) \(disk \d+ touches \d+")
        self.assertEqual(jump["explained"]["case"], case["id"])
        self.assertRegex(note, r"That step is -?\d+ % of the interval's change\.")

    def test_failure_is_reported(self):
        saved = os.environ.get("COLLIDE_EXECUTABLE")
        os.environ["COLLIDE_EXECUTABLE"] = "/bin/false"
        try:
            note = make_report.explain_jump(RESULTS, self.stepped_case(), {"t0": 0.0, "t1": 0.1})
        finally:
            if saved is None:
                del os.environ["COLLIDE_EXECUTABLE"]
            else:
                os.environ["COLLIDE_EXECUTABLE"] = saved
        self.assertIn("The step could not be named", note)


class Resolution(unittest.TestCase):
    def check(self, mean, se, ref, ref_se):
        return {"status": "pass", "check": "pressure",
                "detail": f"Z = P/(rho kT) {mean} +- {se} vs reference {ref} +- {ref_se}"}

    def test_unresolved_and_resolved(self):
        d = digest.statistical_difference(self.check(1.66, 0.02, 1.64, 0.018))
        self.assertFalse(d["resolved"])
        self.assertAlmostEqual(d["error"], 0.02 / 1.64)
        d = digest.statistical_difference(self.check(1.70, 0.005, 1.64, 0.005))
        self.assertTrue(d["resolved"])
        self.assertGreater(d["sigmas"], 8)

    def test_unresolved_point_drawn_hollow(self):
        fig, ax = plt.subplots()
        figures.draw_points(ax, [{"x": 1.0, "y": 0.05, "se": 0.01, "resolved": True, "label": "dt=0.002"},
                                 {"x": 2.0, "y": 0.01, "se": 0.02, "resolved": False, "label": "dt=0.001"}],
                            "tab:blue", "step")
        hollow = [l for l in ax.lines if l.get_markerfacecolor() == "none"]
        filled = [l for l in ax.lines if l.get_markerfacecolor() != "none" and l.get_marker() == "o"]
        self.assertEqual(len(hollow), 1)
        self.assertEqual(list(hollow[0].get_xdata()), [2.0])
        self.assertAlmostEqual(hollow[0].get_ydata()[0], 0.04)  # at its 2 SE bound
        self.assertEqual([list(l.get_xdata()) for l in filled], [[1.0]])
        self.assertIn("not resolved", [t.get_text() for t in ax.texts])
        plt.close(fig)


class PredictedDrift(unittest.TestCase):
    def test_prediction_shown_beside_the_measurement(self):
        c = {"subject": "g__step__dt0.001__seed1", "check": "energy_drift", "status": "pass", "value": 0.029,
             "tolerance": 0.05, "comparison": "<=", "detail": "", "predicted": 0.025, "predicted_uncertainty": 0.008}
        self.assertEqual(make_report.predicted_text(c, percent=True),
                         "drifts 2.9 % where the rule is expected to drift 2.5 ± 0.8 %")
        self.assertIn("expected 0.025 ± 0.008", make_report.cell(c, "energy_drift"))
        del c["predicted"]
        self.assertEqual(make_report.predicted_text(c, percent=True), "")


class IdenticalBackends(unittest.TestCase):
    def test_detected(self):
        checks = []
        for b in ("cpu", "opencl", "step"):
            for i in range(3):
                checks.append({"subject": f"s__{b}__dt0.001__seed{i}", "backend": b, "check": "energy_drift",
                               "status": "pass", "value": 0.1 * i + (0.01 if b == "step" else 0)})
        summary = {"checks": checks, "work_precision": []}
        self.assertEqual(digest.identical_backends(summary), [("cpu", "opencl", 3)])


class HostileInputs(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        shutil.copytree(RESULTS, os.path.join(self.dir, "r"), ignore=shutil.ignore_patterns("report", "runs"))
        self.results = os.path.join(self.dir, "r")
        self.summary_path = os.path.join(self.results, "summary.json")
        with open(self.summary_path, encoding="utf-8") as f:
            self.summary = json.load(f)

    def tearDown(self):
        shutil.rmtree(self.dir)

    def write(self, summary):
        with open(self.summary_path, "w", encoding="utf-8") as f:
            json.dump(summary, f)

    def test_invalid_json_names_the_file(self):
        with open(self.summary_path, "w") as f:
            f.write('{"suite": "x", ')
        r = render(self.results)
        self.assertEqual(r.returncode, 2)
        self.assertIn(self.summary_path, r.stderr)
        self.assertIn("not valid JSON", r.stderr)
        self.assertNotIn("Traceback", r.stderr)

    def test_missing_key_named(self):
        s = copy.deepcopy(self.summary)
        del s["checks"][3]["status"]
        self.write(s)
        r = render(self.results)
        self.assertEqual(r.returncode, 2)
        self.assertIn("checks[3]: missing key 'status'", r.stderr)
        self.assertNotIn("Traceback", r.stderr)

    def test_truncated_case_file_named(self):
        case = next(c for c in self.summary["cases"] if c["status"] == "completed")
        path = os.path.join(self.results, case["result_file"])
        text = open(path, encoding="utf-8").read()
        with open(path, "w", encoding="utf-8") as f:
            f.write(text[: len(text) // 2])
        r = render(self.results)
        self.assertEqual(r.returncode, 2)
        self.assertIn(path, r.stderr)
        self.assertNotIn("Traceback", r.stderr)

    def test_dollar_scene_and_bracket_backend(self):
        def rename(text):
            return text.replace("periodic_gas", "$x$ gas").replace('"cpu"', '"box2d[shipped]"').replace(
                "__cpu__", "__box2d[shipped]__")
        renamed = json.loads(rename(json.dumps(self.summary)))
        for old, new in zip(self.summary["cases"], renamed["cases"]):
            if old.get("result_file") and old["result_file"] != new["result_file"]:
                os.rename(os.path.join(self.results, old["result_file"]), os.path.join(self.results, new["result_file"]))
        self.write(renamed)
        r = render(self.results)
        self.assertEqual(r.returncode, 0, r.stderr)
        html = open(os.path.join(self.results, "report", "index.html"), encoding="utf-8").read()
        self.assertIn("box2d[shipped]", html)
        self.assertIn("$x$ gas", html)
        self.assertIn(f'id="{digest.anchor("scene", "$x$ gas")}"'.replace('"', "'"), html)



class PhysicsSectionDrawsTheSummary(unittest.TestCase):
    """The "Reference against physics" section lays out summary.json's physics rows and
    computes nothing: every number it shows is a number of the summary."""

    def summary(self):
        row = {"row": "equation_of_state", "scene": "fluid", "backend": "event", "group": "g",
               "parameter_name": "area fraction", "parameter": 0.65, "measured": "Z", "estimator": "collision virial",
               "value": 8.4031, "standard_error": 0.0082, "replicates": 4, "reference": 8.4080,
               "reference_uncertainty": 0.0017, "reference_name": "Kolafa & Rottner (2006)", "citation": "Mol. Phys. 104",
               "second_reference": 8.5944, "second_reference_name": "Henderson (1975)", "statistic": "z",
               "score": 0.55, "resolved": True, "verdict": "pass", "detail": ""}
        failed = dict(row, parameter=0.6, value=6.55, verdict="fail", score=9.1, reference=6.4553)
        shown = dict(row, backend="step", estimator="contact shell", verdict="shown", resolved=False)
        curve = {"name": "Kolafa & Rottner (2006)", "citation": "c", "eta": [0.0, 0.5, 0.65], "z": [1.0, 4.106, 8.408]}
        henderson = {"name": "Henderson (1975)", "citation": "c", "eta": [0.0, 0.5, 0.65], "z": [1.0, 4.125, 8.594]}
        return {"physics": {"rows": [row, failed, shown], "curves": [curve, henderson], "z_max": 3}}

    def test_counts_only_judged_rows_and_names_the_reference(self):
        lines = physics.summary_lines(self.summary())
        self.assertEqual(lines, [("Equation of state", 1, 2, "event", "Kolafa & Rottner (2006)")])

    def test_table_shows_the_summary_numbers_and_verdicts(self):
        html = physics.section(self.summary(), make_report.image)
        self.assertIn("8.4031 ± 0.0082", html)
        self.assertIn("Henderson (1975): 8.5944", html)
        self.assertIn("FAIL", html)
        self.assertIn("shown, not judged", html)
        self.assertIn("not resolved", html)  # the contact-shell row cannot tell the curves apart
        self.assertIn("id='physics'", html)

    def test_figure_is_drawn_and_markdown_lists_the_failure(self):
        self.assertIsNotNone(physics.eos_figure(self.summary()))
        md = "\n".join(physics.markdown(self.summary()))
        self.assertIn("| Equation of state | 1 of 2 pass |", md)
        self.assertIn("FAIL equation_of_state event area fraction 0.6", md)

    def test_a_suite_without_physics_rows_has_no_section(self):
        self.assertEqual(physics.section({"physics": {"rows": [], "curves": []}}, make_report.image), "")
        self.assertEqual(physics.markdown({}), [])

if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    RESULTS = sys.argv[1]
    unittest.main(argv=sys.argv[:1], verbosity=2)
