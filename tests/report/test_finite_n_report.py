"""The physics section's published finite-N rows (validation/report/finite_n.py and
templates/finite_n.html.j2) render from a synthesized summary: every cell is a number of the
summary (N, box, estimator, equilibration cut, correlation time, error bar, z), a row that has not
mixed reads "not mixed", and the figure of beta P d^2 against eta is drawn per N."""
import os
import sys
import unittest

REPORT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "validation", "report")
sys.path.insert(0, REPORT)

import finite_n  # noqa: E402
import physics  # noqa: E402
import templating  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_report_data  # noqa: E402  (recompute_every_z)


def published_row(**changes):
    row = {"row": "published_finite_n", "scene": "n72_crystal_0670", "backend": "event", "group": "g",
           "parameter_name": "area fraction", "parameter": 0.67, "measured": "pressure beta P d^2 at N = 72",
           "estimator": "collision virial in the rest frame", "value": 7.823051, "standard_error": 0.00061,
           "replicates": 2, "reference": 7.82314, "reference_uncertainty": 0.00025, "reference_name": "Li et al. (2022)",
           "citation": "J. Chem. Phys. 157, 234111 (2022)", "second_reference": None, "second_reference_name": "",
           "statistic": "z", "score": 0.1349, "resolved": True, "verdict": "pass", "detail": "pooled over 2 replicates",
           "published": "li_2022:N72_crystal_0.670", "box": "9 : 8 sqrt(3)/2 periodic",
           "facts": {"disks": 72, "equilibration": 21.5, "correlation_time": 0.45, "batches": 64,
                     "relative_error": 7.8e-5, "psi6_traversals": 9, "mixed": 1, "replicate_chi2": 0.3}}
    row.update(changes)
    return row


def summary():
    big = published_row(scene="n870", parameter=0.69, value=8.9702, reference=8.969476, published="li_2022:N870_crystal_0.690",
                        box="29 : 30 sqrt(3)/2 periodic", verdict="shown", score=0.4,
                        facts=dict(published_row()["facts"], disks=870, mixed=0, psi6_traversals=1))
    return {"physics": {"rows": [published_row(), big], "curves": [], "z_max": 3}}


class FiniteNRowsRenderFromTheSummary(unittest.TestCase):
    def test_the_table_shows_each_rows_facts(self):
        html = templating.render("physics.html.j2", physics=physics.section(summary()))
        for text in ("li_2022:N72_crystal_0.670", "9 : 8 sqrt(3)/2 periodic", "collision virial in the rest frame",
                     "21.5", "0.45", "7.823051 ± 0.00061", "7.82314 ± 0.00025", "0.135", "7.8e-05",
                     "29 : 30 sqrt(3)/2 periodic", "870", "not mixed", 'id="physics-finite-n"'):
            self.assertIn(text, html)

    def test_only_published_rows_are_laid_out(self):
        other = {"row": "equation_of_state"}
        self.assertEqual(len(finite_n.rows({"physics": {"rows": [other] + summary()["physics"]["rows"]}})), 2)
        self.assertIsNone(finite_n.section({"physics": {"rows": [other]}}))

    def test_the_figure_is_drawn_with_a_panel_per_n(self):
        png = finite_n.figure(summary())
        self.assertTrue(png.startswith(b"\x89PNG"))

    def test_a_row_without_a_value_is_left_out_of_the_figure_but_kept_in_the_table(self):
        s = {"physics": {"rows": [published_row(value=None, standard_error=None, score=None, verdict="fail")]}}
        self.assertIsNone(finite_n.figure(s))
        self.assertEqual(finite_n.table(s)[0]["value"], "n/a ± n/a")
        html = templating.render("physics.html.j2", physics=physics.section(s))  # the whole section renders
        self.assertIn("n/a", html)


def routes_summary(ecmc_value, verdict):
    """event and ecmc at one point, and the routes row between them (z on the difference)."""
    import math
    event = published_row(score_from={"value": 7.823051, "standard_error": 0.00061, "reference": 7.82314,
                                      "reference_uncertainty": 0.00025, "estimator": "virial", "z": (7.823051 - 7.82314) / math.hypot(0.00061, 0.00025)})
    ecmc = published_row(backend="ecmc", value=ecmc_value, standard_error=0.0021,
                         score_from={"value": ecmc_value, "standard_error": 0.0021, "reference": 7.82314,
                                     "reference_uncertainty": 0.00025, "estimator": "lifts", "z": (ecmc_value - 7.82314) / math.hypot(0.0021, 0.00025)})
    z = (ecmc_value - 7.823051) / math.hypot(0.0021, 0.00061)
    routes = dict(ecmc, row="routes_agree", reference=7.823051, reference_uncertainty=0.00061,
                  reference_name="event (collision virial in the rest frame)", verdict=verdict, score=abs(z),
                  score_from={"value": ecmc_value, "standard_error": 0.0021, "reference": 7.823051,
                              "reference_uncertainty": 0.00061, "z": z, "estimator": "difference"})
    return {"physics": {"rows": [event, ecmc, routes], "curves": [], "z_max": 3}}


class TheRoutesStandSideBySide(unittest.TestCase):
    def test_one_line_per_point_with_every_route_and_its_agreement_with_event(self):
        points = finite_n.routes(routes_summary(7.8262, "pass"))
        self.assertEqual(len(points), 1)
        self.assertEqual([r["backend"] for r in points[0]["routes"]], ["event", "ecmc"])
        self.assertEqual(points[0]["agreement"][0]["pair"], "ecmc − event")
        # (7.8262 - 7.823051) / hypot(0.0021, 0.00061), with the numbers it came from
        self.assertEqual(points[0]["agreement"][0]["z"], "z = +1.44 from 7.8262 ± 0.0021 against 7.82305 ± 0.00061")
        html = templating.render("physics.html.j2", physics=physics.section(routes_summary(7.8262, "pass")))
        for text in ('id="physics-routes"', "ecmc: z = +1.45 from 7.8262 ± 0.0021 against 7.82314 ± 0.00025",
                     "ecmc − event: z = +1.44 from", "(pass)", "(≤ "):
            self.assertIn(text, html)
        self.assertGreaterEqual(test_report_data.recompute_every_z(self, html), 4)

    def test_a_route_that_disagrees_reads_fail(self):
        html = templating.render("physics.html.j2", physics=physics.section(routes_summary(7.8450, "fail")))
        self.assertIn("ecmc − event: z = +10.04 from 7.845 ± 0.0021 against 7.82305 ± 0.00061 (FAIL)", html)

    def test_the_figure_has_no_text_over_text_or_cut(self):
        # The legends sat over the points and the frame cut the top ones; now under the panels.
        import figure_text
        self.assertEqual(figure_text.faults(finite_n.figure(summary())), [])
        self.assertEqual(figure_text.faults(finite_n.figure(routes_summary(7.8262, "pass"))), [])

    def test_every_route_has_its_own_marker(self):
        self.assertEqual(len(set(finite_n.ROUTE_MARKERS.values())), len(finite_n.ROUTE_MARKERS))
        self.assertTrue(finite_n.figure(routes_summary(7.8262, "pass")).startswith(b"\x89PNG"))


if __name__ == "__main__":
    unittest.main()
