#!/usr/bin/env python3
"""Opens a rendered report the way a reader does: chromium, headless, at 1400 x 900, and checks
that the first screen holds the verdict and the per-backend digest with a verdict and a cost
for each backend (each low-power pass marked with the bias it could have detected), that the
headline work-precision figure follows it at once, that no two pieces of text on the first
screen overlap, that no two labels inside any figure overlap and none is cut by its edge (each
PNG's record of its text boxes, tests/report/figure_text.py), and that every in-page link
(table of contents, digest) resolves.

usage: test_browser.py RESULTS_DIR [SCREENSHOT.png]

Needs the Debian packages chromium, chromium-driver and python3-selenium
(scripts/install-deps.sh). A missing browser is a failure, not a skip: CI must run this.
"""
import os
import re
import shutil
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # figure_text.py beside this file
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "validation", "report"))
import digest  # noqa: E402  (the report's anchors: a row's id from its backend's name)

RESULTS = None
SCREENSHOT = None
WIDTH, HEIGHT = 1400, 900


def find(program, *candidates):
    for c in (shutil.which(program),) + candidates:
        if c and os.path.exists(c):
            return c
    return None


class FirstScreen(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        try:
            from selenium import webdriver
            from selenium.webdriver.chrome.service import Service
        except ImportError as e:
            raise AssertionError(f"python3-selenium is missing ({e}); run scripts/install-deps.sh") from None
        browser = find("chromium", "/usr/bin/chromium")
        driver = find("chromedriver", "/usr/bin/chromedriver")
        if not browser or not driver:
            raise AssertionError("chromium and chromium-driver are needed for this test; run scripts/install-deps.sh")
        options = webdriver.ChromeOptions()
        options.binary_location = browser
        for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                    f"--window-size={WIDTH},{HEIGHT}", "--hide-scrollbars"):
            options.add_argument(arg)
        cls.driver = webdriver.Chrome(service=Service(driver), options=options)
        cls.driver.set_window_size(WIDTH, HEIGHT)
        # The window size includes no browser chrome in headless mode; make the viewport exact.
        inner = cls.driver.execute_script("return [window.innerWidth, window.innerHeight]")
        cls.driver.set_window_size(WIDTH + (WIDTH - inner[0]), HEIGHT + (HEIGHT - inner[1]))
        cls.index = os.path.abspath(os.path.join(RESULTS, "report", "index.html"))
        cls.driver.get("file://" + cls.index)
        cls.driver.execute_script("return document.readyState")
        if SCREENSHOT:
            cls.driver.save_screenshot(SCREENSHOT)

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()

    def rect(self, css):
        from selenium.webdriver.common.by import By
        elements = self.driver.find_elements(By.CSS_SELECTOR, css)
        self.assertTrue(elements, f"{css} is not on the page")
        return self.driver.execute_script(
            "const r = arguments[0].getBoundingClientRect(); return [r.top, r.bottom, r.left, r.right];", elements[0])

    def test_viewport(self):
        inner = self.driver.execute_script("return [window.innerWidth, window.innerHeight]")
        self.assertEqual(inner, [WIDTH, HEIGHT])

    def stability_suite(self):
        return self.driver.execute_script("return document.getElementById('stability-first') !== null;")

    def test_verdict_and_digest_on_first_screen(self):
        # A stability suite's first screen is its first-failure table; the digest follows it.
        for css in ("#verdict", "#first-failures") if self.stability_suite() else ("#verdict", "#digest"):
            top, bottom, left, right = self.rect(css)
            self.assertGreaterEqual(top, 0, css)
            self.assertLessEqual(bottom, HEIGHT, f"{css} ends at {bottom} px, below the first screen")
            self.assertLessEqual(right, WIDTH, f"{css} is wider than the screen")

    def test_backend_verdicts_with_cost_on_first_screen(self):
        if self.stability_suite():
            self.skipTest("a stability suite opens with its first failures")
        from selenium.webdriver.common.by import By
        top, bottom, left, right = self.rect("#digest")
        self.assertGreaterEqual(top, 0)
        self.assertLessEqual(bottom, HEIGHT, f"the backend verdicts end at {bottom} px, below the first screen")
        rows = self.driver.find_elements(By.CSS_SELECTOR, "#digest tr[id^='verdict-']")
        self.assertGreater(len(rows), 1)
        for row in rows:
            cells = [c.text for c in row.find_elements(By.TAG_NAME, "td")]
            self.assertTrue(cells[1], f"no verdict for {cells[0]}")
            self.assertRegex(cells[5], r"×|s per time unit", f"no cost for {cells[0]}")
            self.assertTrue(row.is_displayed())

    def digest_row(self, backend):
        """The cells of the backend's digest row (its name cell may add a note: 'opencl (= cpu)')."""
        from selenium.webdriver.common.by import By
        rows = self.driver.find_elements(By.ID, "verdict-" + digest.anchor("backend", backend))
        self.assertTrue(rows, f"no digest row for {backend}")
        return rows[0].find_elements(By.TAG_NAME, "td")

    def test_not_for_names_a_measured_bias_for_step(self):
        """Issue 48: the stepped rules' measured error is on the first screen, with its SE."""
        if self.stability_suite():
            self.skipTest("a stability suite opens with its first failures")
        not_for = self.digest_row("step")[3]
        self.assertRegex(not_for.text, r"(Z [-+]\d[\d.e-]* % ± [\d.e-]+ %|[\d.e-]+ ± [\d.e-]+ r_min)",
                         "step's 'not for' names no measured error with its SE")
        self.assertLessEqual(self.driver.execute_script("return arguments[0].getBoundingClientRect().top;", not_for),
                             HEIGHT, "step's 'not for' is below the first screen")

    def test_a_shipped_preset_is_not_shown_passing_elastic_physics(self):
        from selenium.webdriver.common.by import By
        names = [r.find_elements(By.TAG_NAME, "td")[0].text.split("\n")[0]
                 for r in self.driver.find_elements(By.CSS_SELECTOR, "#digest tr[id^='verdict-']")]
        variants = [n for n in names if "[" in n]
        if not variants:
            self.skipTest("no preset variant in this suite")
        for name in variants:
            verdict = self.digest_row(name)[1]
            self.assertIn("fail", verdict.get_attribute("class"), f"{name} is shown green")
            self.assertRegex(verdict.text, r"FAILS the physical model: \d+ of its \d+ checks fail under the limits of")

    def test_low_power_passes_marked_on_first_screen(self):
        """Issue 48, item 5: every backend whose summary.json lists a low-power pass (a Z check that
        passed but could not have seen a bias of the stated accuracy) carries, in its verdict on the
        first screen, the bias each such pass could have detected."""
        import json
        from selenium.webdriver.common.by import By
        with open(os.path.join(RESULTS, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
        low = {b: (v.get("accuracy") or {}).get("low_power") for b, v in summary["verdicts"].items()}
        low = {b: l for b, l in low.items() if l}
        if not low:
            self.skipTest("no low-power pass in this suite")
        for backend, passes in low.items():
            cells = self.digest_row(backend)
            marks = cells[1].find_elements(By.CSS_SELECTOR, "span.low-power")
            self.assertEqual(len(marks), 1, f"{backend}'s low-power passes are not marked")
            same = re.search(r"\(= (.+)\)", cells[0].text.split("\n")[0])  # 'opencl (= cpu)': its entries are cpu's
            for p in passes:
                self.assertRegex(marks[0].text, rf"as {re.escape(same.group(1))}$" if same else
                                 rf"≥ [\d.]+ % \({re.escape(p['scene'])}, {p['replicates']} rep\.\)")
            bottom = self.driver.execute_script("return arguments[0].getBoundingClientRect().bottom;", marks[0])
            self.assertLessEqual(bottom, HEIGHT, f"{backend}'s low-power mark is below the first screen")

    def test_cost_at_accuracy_column_on_first_screen(self):
        if self.stability_suite():
            self.skipTest("a stability suite opens with its first failures")
        top, bottom, left, right = self.rect("#cost-at-accuracy")
        self.assertLessEqual(bottom, HEIGHT)
        self.assertLessEqual(right, WIDTH)
        self.assertRegex(self.digest_row("step")[6].text, r"×|not reached")

    def test_headline_text_at_least_10_px(self):
        """The headline PNG records its smallest text in PNG pixels (figures.smallest_text_px);
        scaled by the displayed width over the natural width it must reach 10 px."""
        if self.stability_suite():
            self.skipTest("a stability suite has no work-precision figure")
        import base64
        import io
        from PIL import Image
        src, shown, natural = self.driver.execute_script(
            "const i = document.querySelector('figure#headline img'); return [i.src, i.clientWidth, i.naturalWidth];")
        with Image.open(io.BytesIO(base64.b64decode(src.split(",", 1)[1]))) as png:
            smallest = float(png.info["smallest-text-px"])
        self.assertGreaterEqual(smallest * shown / natural, 10, f"headline text {smallest:.1f} px in the PNG, "
                                f"shown at {shown} of {natural} px")

    def test_no_figure_label_overlaps_or_is_cut(self):
        """Every figure of the page records the box of each text it draws (figures.png: tick
        labels, axis labels, legends, annotations such as "dt=..."); no two may overlap and none
        may be cut by the figure's edge. The motion strips are drawn by `collide render`, not
        by the report's figures, and carry no record."""
        import base64
        import figure_text
        images = self.driver.execute_script(
            "return Array.from(document.querySelectorAll('img')).map(i => [i.alt, i.src]);")
        checked = 0
        for alt, src in images:
            if not src.startswith("data:image/png;base64,") or alt == "motion strip":
                continue
            faults = figure_text.faults(base64.b64decode(src.split(",", 1)[1]))
            self.assertEqual(faults, [], f"figure '{alt}' (number {checked + 1} on the page)")
            checked += 1
        self.assertGreater(checked, 3, "too few figures with a text record on the page")

    def test_no_text_overlaps_on_first_screen(self):
        overlaps = self.driver.execute_script("""
            const boxes = [];
            const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
            for (let n = walker.nextNode(); n; n = walker.nextNode()) {
              if (!n.textContent.trim()) continue;
              const range = document.createRange(); range.selectNodeContents(n);
              for (const r of range.getClientRects())
                if (r.width > 1 && r.height > 1 && r.bottom > 0 && r.top < window.innerHeight)
                  boxes.push([r.left, r.top, r.right, r.bottom, n.textContent.trim().slice(0, 30)]);
            }
            const out = [];
            for (let i = 0; i < boxes.length; ++i)
              for (let j = i + 1; j < boxes.length; ++j) {
                const a = boxes[i], b = boxes[j];
                const w = Math.min(a[2], b[2]) - Math.max(a[0], b[0]), h = Math.min(a[3], b[3]) - Math.max(a[1], b[1]);
                if (w > 2 && h > 2) out.push(a[4] + " / " + b[4]);
              }
            return out;""")
        self.assertEqual(overlaps, [], "text overlaps on the first screen")

    def test_headline_figure_on_first_screen(self):
        if self.stability_suite():
            self.skipTest("a stability suite has no work-precision figure")
        top, bottom, left, right = self.rect("figure#headline img")
        self.assertTrue(self.driver.execute_script(
            "return document.querySelector('figure#headline img').complete"), "the figure did not load")
        # The first screen holds the verdicts with their costs; the figure follows the digest at once.
        digest_bottom = self.rect("#digest")[1]
        self.assertLess(top - digest_bottom, 80, "something stands between the digest and the headline figure")
        self.assertGreater(bottom - top, 200, "the headline figure is too small to read")

    def test_contents_on_first_screen(self):
        top, bottom, _, _ = self.rect("nav#toc")
        self.assertLessEqual(bottom, HEIGHT)

    def test_every_in_page_link_resolves(self):
        links = self.driver.execute_script(
            "return Array.from(document.querySelectorAll('a[href]')).map(a => a.getAttribute('href'));")
        internal = [h for h in links if h.startswith("#")]
        self.assertGreater(len(internal), 5, "the table of contents has too few links")
        for href in internal:
            target = self.driver.execute_script("return document.getElementById(arguments[0]) !== null;",
                                                href[1:])
            self.assertTrue(target, f"link {href} points nowhere")
        for href in links:
            if not href.startswith(("#", "http")):
                self.assertTrue(os.path.exists(os.path.join(os.path.dirname(self.index), href.split("#")[0])),
                                f"link {href} names a file that does not exist")

    def test_digest_link_opens_its_table(self):
        from selenium.webdriver.common.by import By
        links = self.driver.find_elements(By.CSS_SELECTOR, "#digest a[href^='#backend-']")
        if not links:
            self.skipTest("no backend links in the digest")
        target = links[-1].get_attribute("href").split("#", 1)[1]
        links[-1].click()
        element = self.driver.find_element(By.ID, target)
        self.assertTrue(element.is_displayed(), f"#{target} stays hidden in a collapsed table after its link")
        self.driver.get("file://" + self.index)  # back to the first screen for the other tests

    def test_ids_unique(self):
        ids = self.driver.execute_script("return Array.from(document.querySelectorAll('[id]')).map(e => e.id);")
        self.assertEqual(len(ids), len(set(ids)), "duplicate ids: " + str(sorted({i for i in ids if ids.count(i) > 1})))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    RESULTS = sys.argv[1]
    SCREENSHOT = sys.argv[2] if len(sys.argv) > 2 else None
    unittest.main(argv=sys.argv[:1], verbosity=2)
