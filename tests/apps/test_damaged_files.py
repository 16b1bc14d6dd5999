#!/usr/bin/env python3
"""Every file collide reads back is checked before it is used (docs/refusals.md, "Files read
back"): `collide render` on damaged run files, `collide validate --resume` and `collide report`
on damaged case records and run files, stray files in cases/, and a seeded fuzz test that
damages a run file at random (truncation, bit flips, shapes, types and datasets changed with
h5py) and requires every reader to refuse it with the file's name, or, for a harmless change,
to give exactly the output of the intact file. Never a crash, never exit 0 with other output.

usage: test_damaged_files.py COLLIDE SCENE_DIR
"""
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import zlib

import h5py
import numpy as np

COLLIDE = None
SCENES = None
CASE = "head_on_equal__step__dt0.004__seed1"  # the case whose files are damaged

SUITE = """name = "damaged-files"
description = "A tiny suite whose files the test damages"
scene_dir = "{scenes}"
backends = ["event", "step"]
reference = "event"
seeds = [1]
time_limit = 60
warmup_fraction = 0

[output]
hdf5 = true
frames = true

[[scene]]
name = "head_on_equal"
compare = "trajectory"
dt = [4e-3]
"""


def collide(*args, cwd=None):
    return subprocess.run([COLLIDE, *args], capture_output=True, text=True, cwd=cwd, timeout=120)


def rewrite_dataset(f, name, data, checksum=True):
    """Replaces dataset `name` by `data` (any shape or type), as another program would."""
    del f[name]
    if checksum:
        f.create_dataset(name, data=data, chunks=True, fletcher32=True)
    else:
        f.create_dataset(name, data=data)


def with_fresh_checksum(record_text):
    """A record edited with its checksum line recomputed, as an older collide or a careful
    hand edit would leave it: only the field checks can find what is wrong."""
    body = record_text.split("\n", 1)[1]
    return f'checksum = "crc32:{zlib.crc32(body.encode()):08x}"\n' + body


class Fixture(unittest.TestCase):
    """One validated suite and one run file with frames, made once; each test works on copies."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="damaged-")
        suite = os.path.join(cls.tmp, "suite.toml")
        with open(suite, "w") as f:
            f.write(SUITE.format(scenes=SCENES))
        cls.suite = suite
        cls.results = os.path.join(cls.tmp, "results")
        r = collide("validate", suite, "--out", cls.results, "--jobs", "1")
        assert r.returncode == 0, r.stdout + r.stderr
        cls.run_file = os.path.join(cls.results, "runs", CASE + ".h5")
        cls.baseline = cls.render_bytes(cls.run_file)
        assert cls.baseline is not None and cls.baseline == cls.render_bytes(cls.run_file), "render is not repeatable"

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    @classmethod
    def render_bytes(cls, path, out_name="strip.png"):
        out = os.path.join(cls.tmp, out_name)
        if os.path.exists(out):
            os.remove(out)
        r = collide("render", path, "--out", out, "--frames", "4", "--size", "64x48")
        if r.returncode != 0:
            return None
        with open(out, "rb") as f:
            return f.read()

    def copy_results(self):
        target = tempfile.mkdtemp(dir=self.tmp)
        shutil.copytree(self.results, os.path.join(target, "r"))
        return os.path.join(target, "r")

    def copy_run(self):
        path = os.path.join(tempfile.mkdtemp(dir=self.tmp), "run.h5")
        shutil.copy(self.run_file, path)
        return path

    def assert_refused(self, result, path, *words):
        """Refused with exit status 1 (not a signal, not a Python traceback), the file named."""
        text = result.stdout + result.stderr
        self.assertEqual(result.returncode, 1, text)
        self.assertIn(path, text)
        for word in words:
            self.assertIn(word, text)
        self.assertNotIn("Traceback", text)


class RenderChecksTheRunFile(Fixture):
    """Item 2: a shorter mass array read out of bounds, a shorter radius array dropped disks,
    NaN positions drew blank frames and exited 0."""

    def render(self, path):
        return collide("render", path, "--out", os.path.join(os.path.dirname(path), "out.png"))

    def test_mass_shorter_than_radius(self):
        path = self.copy_run()
        with h5py.File(path, "r+") as f:
            rewrite_dataset(f, "particles/mass", f["particles/mass"][:-1])
        self.assert_refused(self.render(path), path, "/particles/mass", "shape")

    def test_radius_shorter_than_mass(self):
        path = self.copy_run()
        with h5py.File(path, "r+") as f:
            rewrite_dataset(f, "particles/radius", f["particles/radius"][:-1])
        self.assert_refused(self.render(path), path, "/particles/")

    def test_nan_positions(self):
        path = self.copy_run()
        with h5py.File(path, "r+") as f:
            f["frames/position"][0, 0, 0] = np.nan  # h5py recomputes the chunk's checksum
        self.assert_refused(self.render(path), path, "NaN")

    def test_older_format_named(self):
        path = self.copy_run()
        with h5py.File(path, "r+") as f:
            f.attrs["format_version"] = "1"
        self.assert_refused(self.render(path), path, "older collide")


class ResumeAndReportCheckWhatTheyRead(Fixture):
    """Item 3: damaged records and run files are run again by --resume and named by report."""

    record = os.path.join("cases", CASE + ".toml")

    def resume(self, results):
        return collide("validate", self.suite, "--out", results, "--resume")

    def assert_rerun(self, results, *words):
        r = self.resume(results)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        line = next((l for l in r.stderr.splitlines() if l.startswith(f"resume: running {CASE} again")), None)
        self.assertIsNotNone(line, r.stderr)
        for word in words:
            self.assertIn(word, line)
        self.assertIn("1 run, 1 resumed", r.stdout)
        with open(os.path.join(results, self.record)) as f:
            self.assertTrue(re.search(r"\nstatus = [\"']completed[\"']\n", f.read()), "rerun record without status")

    def edit_record(self, results, edit, fresh_checksum=True):
        path = os.path.join(results, self.record)
        with open(path) as f:
            text = edit(f.read())
        with open(path, "w") as f:
            f.write(with_fresh_checksum(text) if fresh_checksum else text)

    def test_record_without_status_is_rerun(self):
        results = self.copy_results()
        self.edit_record(results, lambda t: re.sub(r"\nstatus = .*\n", "\n", t))
        self.assert_rerun(results, "no field 'status'")

    def test_wrongly_typed_field_is_rerun(self):
        results = self.copy_results()
        self.edit_record(results, lambda t: re.sub(r"\nsteps = .*\n", '\nsteps = "many"\n', t))
        self.assert_rerun(results, "'steps' is not an integer")

    def test_record_changed_after_writing_is_rerun(self):
        results = self.copy_results()
        self.edit_record(results, lambda t: t.replace("\ncontacts = 1\n", "\ncontacts = 7\n"), fresh_checksum=False)
        self.assert_rerun(results, "checksum does not match")

    def test_negative_kinetic_energy_is_rerun(self):
        results = self.copy_results()
        with h5py.File(os.path.join(results, "runs", CASE + ".h5"), "r+") as f:
            f["metrics/kinetic_energy"][1] = -4.0
        self.assert_rerun(results, "/metrics/kinetic_energy")

    def test_report_names_a_negative_radius(self):
        results = self.copy_results()
        run = os.path.join(results, "runs", CASE + ".h5")
        with h5py.File(run, "r+") as f:
            f["particles/radius"][0] = -8.0
        r = collide("report", results)
        self.assert_refused(r, run, "/particles/radius", "--resume")
        self.assertFalse(os.path.exists(os.path.join(results, "report", "index.html")))

    def test_report_names_a_damaged_record(self):
        results = self.copy_results()
        self.edit_record(results, lambda t: re.sub(r"\nstatus = .*\n", "\n", t))
        r = collide("report", results)
        self.assert_refused(r, os.path.join(results, self.record), "damaged case record")


class ReportReadsWhatTheSummaryLists(Fixture):
    """Item 4: a stray file in cases/ is named in a warning, not a reason to refuse."""

    def test_stray_files_are_named_and_left_alone(self):
        results = self.copy_results()
        # A case of an earlier suite in the same directory, whose run file is gone.
        with open(os.path.join(results, "cases", CASE + ".toml")) as f:
            stale = f.read().replace(f"runs/{CASE}.h5", "runs/old_suite_case.h5")
        with open(os.path.join(results, "cases", "old_suite_case.toml"), "w") as f:
            f.write(with_fresh_checksum(stale))
        with open(os.path.join(results, "cases", CASE + ".toml~"), "w") as f:
            f.write("an editor's backup\n")
        r = collide("report", results)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        warning = next((l for l in r.stderr.splitlines() if "does not list" in l), "")
        self.assertIn("old_suite_case.toml", warning)
        self.assertIn(CASE + ".toml~", warning)
        self.assertTrue(os.path.exists(os.path.join(results, "report", "index.html")))


# ---------------------------------------------------------------------------------------------
# Fuzz: random damage, fixed seed.

def damage(path, rng):
    """One random kind of damage to the run file at `path`; returns its description."""
    kind = rng.choice(["truncate", "flip", "flip", "shape", "type", "delete", "attribute"])
    if kind == "truncate":
        size = os.path.getsize(path)
        keep = rng.randrange(size)
        os.truncate(path, keep)
        return f"truncated to {keep} of {size} bytes"
    if kind == "flip":
        data = bytearray(open(path, "rb").read())
        spots = [(rng.randrange(len(data)), rng.randrange(8)) for _ in range(rng.randint(1, 4))]
        for at, bit in spots:
            data[at] ^= 1 << bit
        open(path, "wb").write(data)
        return f"bits flipped at {spots}"
    with h5py.File(path, "r+") as f:
        names = []
        f.visititems(lambda name, obj: names.append(name) if isinstance(obj, h5py.Dataset) else None)
        name = rng.choice(names)
        data = f[name][()]
        if kind == "shape":
            cut = data[: max(0, len(data) - rng.randint(1, 2))] if rng.random() < 0.5 else np.concatenate([data, data[:1]])
            rewrite_dataset(f, name, cut, checksum=rng.random() < 0.8)
            return f"{name}: shape {data.shape} -> {cut.shape}"
        if kind == "type":
            kind_to = rng.choice(["f4", "i8", "f8", "i4"])
            rewrite_dataset(f, name, data.astype(kind_to), checksum=rng.random() < 0.8)
            return f"{name}: type {data.dtype} -> {kind_to}"
        if kind == "delete":
            del f[name]
            return f"{name}: deleted"
        attribute = rng.choice(list(f.attrs))
        del f.attrs[attribute]
        return f"root attribute {attribute}: deleted"


class FuzzRunFileReaders(Fixture):
    RENDER_ROUNDS = 36
    RESUME_ROUNDS = 8

    def check_render(self, path, what):
        out = os.path.join(os.path.dirname(path), "out.png")
        r = collide("render", path, "--out", out, "--frames", "4", "--size", "64x48")
        text = r.stdout + r.stderr
        if r.returncode == 0:
            with open(out, "rb") as f:
                self.assertEqual(f.read(), self.baseline, f"{what}: exit 0 with a different picture")
            self.outcomes["identical"] += 1
        else:
            self.outcomes["refused"] += 1
            self.assertEqual(r.returncode, 1, f"{what}: {text}")
            self.assertIn(path, text, what)

    def test_render(self):
        self.outcomes = {"refused": 0, "identical": 0}
        rng = random.Random(20261124)
        for round_ in range(self.RENDER_ROUNDS):
            path = self.copy_run()
            what = f"round {round_}: " + damage(path, rng)
            with self.subTest(what):
                self.check_render(path, what)
        print(f"\n  render: {self.outcomes['refused']} damaged files refused, {self.outcomes['identical']} harmless "
              "ones drawn identically", file=sys.stderr)

    def test_resume(self):
        rng = random.Random(31)
        for round_ in range(self.RESUME_ROUNDS):
            results = self.copy_results()
            run = os.path.join(results, "runs", CASE + ".h5")
            what = f"round {round_}: " + damage(run, rng)
            with self.subTest(what):
                r = collide("validate", self.suite, "--out", results, "--resume")
                self.assertEqual(r.returncode, 0, f"{what}: {r.stdout}{r.stderr}")
                rerun = f"resume: running {CASE} again: {run}" in r.stderr
                if not rerun:  # kept: then it must read exactly as the intact file does
                    self.assertEqual(self.render_bytes(run), self.baseline, f"{what}: kept, but reads differently")
                self.assertIsNotNone(self.render_bytes(run), f"{what}: unreadable after --resume")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    COLLIDE, SCENES = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    unittest.main(argv=sys.argv[:1], verbosity=2)
