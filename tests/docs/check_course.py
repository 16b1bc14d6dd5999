#!/usr/bin/env python3
"""Keeps the course honest: its exercises, figures and links against today's programs.

    check_course.py exercises COLLIDE   run every exercise's commands; each answer's
                                        <!-- expect: TEXT --> line must appear in the output
    check_course.py links               every image and relative link of docs/ resolves, and every
                                        quoted line range (<!-- quote PATH:A-B -->) matches its file
    check_course.py figures COLLIDE     docs/figures/make_figures.py runs on the library scenes

An exercise is a "### Exercise" section of a chapter (docs/course/*.md): its first ```sh block
is the command a student runs, with `collide` meaning the built program, in a scratch folder
that sees the repository's data/ and docs/.
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
COURSE = ROOT / "docs" / "course"
MIN_EXERCISES = 3


def chapters():
    pages = sorted(COURSE.glob("[0-9]-*.md"))
    if len(pages) != 5:
        sys.exit(f"expected five chapter pages in {COURSE}, found {[p.name for p in pages]}")
    return pages


def exercises(page):
    """(title, commands, expected lines) of every exercise on a chapter page."""
    found = []
    for section in re.split(r"(?m)^### ", page.read_text())[1:]:
        if not section.startswith("Exercise"):
            continue
        title = section.splitlines()[0]
        block = re.search(r"```sh\n(.*?)```", section, re.S)
        expects = re.findall(r"<!-- expect: (.*?) -->", section)
        if not block or not expects:
            sys.exit(f"{page.name}: '{title}' needs a ```sh block and at least one <!-- expect: --> line")
        found.append((title, block.group(1), expects))
    return found


def scratch_environment(collide, scratch):
    bin_dir = scratch / "bin"
    bin_dir.mkdir()
    (bin_dir / "collide").symlink_to(pathlib.Path(collide).resolve())
    (bin_dir / "python3").symlink_to("/usr/bin/python3")  # Debian's numpy/h5py live there
    for name in ("data", "docs"):
        (scratch / name).symlink_to(ROOT / name)
    env = dict(os.environ)
    env["PATH"] = f"{bin_dir}:{env['PATH']}"
    return env


def check_exercises(collide):
    failures, count = [], 0
    for page in chapters():
        items = exercises(page)
        if len(items) < MIN_EXERCISES:
            failures.append(f"{page.name}: {len(items)} exercises, at least {MIN_EXERCISES} wanted")
        for title, commands, expects in items:
            count += 1
            with tempfile.TemporaryDirectory(prefix="collide-exercise-") as scratch:
                scratch = pathlib.Path(scratch)
                env = scratch_environment(collide, scratch)
                done = subprocess.run(["bash", "-euo", "pipefail", "-c", commands], cwd=scratch, env=env,
                                      capture_output=True, text=True, timeout=600)
            if done.returncode != 0:
                failures.append(f"{page.name}: '{title}' exited {done.returncode}:\n{done.stderr[-2000:]}")
                continue
            missing = [e for e in expects if e not in done.stdout]
            if missing:
                failures.append(f"{page.name}: '{title}': the docs' answer {missing} is not what the "
                                f"command prints today:\n{done.stdout[-3000:]}")
    print(f"{count} exercises checked")
    return failures


def check_links():
    failures, images = [], 0
    for page in sorted((ROOT / "docs").rglob("*.md")):
        text = page.read_text()
        for is_image, target in re.findall(r"(!?)\[[^\]]*\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+://|#|mailto:", target):
                continue
            path = (page.parent / target.split("#")[0]).resolve()
            images += bool(is_image)
            if not path.exists():
                failures.append(f"{page.relative_to(ROOT)}: link to {target} does not resolve")
    for page in chapters():
        if "![" not in page.read_text():
            failures.append(f"{page.name}: a chapter without a figure")
    print(f"{images} image links checked")
    return failures


def check_quotes():
    """Code quoted on a page as <!-- quote PATH:A-B --> followed by a fenced block must be lines
    A to B of PATH, exactly: a quote that drifts from the source fails here."""
    failures, quoted = [], 0
    pattern = re.compile(r"<!-- quote ([^ :]+):(\d+)-(\d+) -->\n```[a-z]*\n(.*?)\n```", re.S)
    for page in sorted((ROOT / "docs").rglob("*.md")):
        for path, first, last, body in pattern.findall(page.read_text()):
            quoted += 1
            source = ROOT / path
            if not source.exists():
                failures.append(f"{page.relative_to(ROOT)}: quotes {path}, which does not exist")
                continue
            lines = source.read_text().split("\n")[int(first) - 1:int(last)]
            if "\n".join(lines) != body:
                failures.append(f"{page.relative_to(ROOT)}: the quote of {path}:{first}-{last} differs from the file")
    print(f"{quoted} code quotes checked")
    return failures


def check_figures(collide):
    with tempfile.TemporaryDirectory(prefix="collide-figures-out-") as out:
        done = subprocess.run(["/usr/bin/python3", str(ROOT / "docs/figures/make_figures.py"),
                               "--collide", collide, "--out", out], capture_output=True, text=True)
        made = sorted(p.name for p in pathlib.Path(out).glob("*.png"))
    if done.returncode != 0:
        return [f"make_figures.py exited {done.returncode}:\n{done.stderr[-3000:]}"]
    linked = set()
    for page in chapters():
        linked |= set(re.findall(r"\(\.\./figures/([^)]+\.png)\)", page.read_text()))
    missing = sorted(linked - set(made))
    print(f"{len(made)} figures made")
    return [f"figures linked by the course but not made by make_figures.py: {missing}"] if missing else []


def main():
    what = sys.argv[1] if len(sys.argv) > 1 else ""
    if what == "exercises" and len(sys.argv) == 3:
        failures = check_exercises(sys.argv[2])
    elif what == "links":
        failures = check_links() + check_quotes()
    elif what == "figures" and len(sys.argv) == 3:
        failures = check_figures(sys.argv[2])
    else:
        sys.exit(__doc__)
    for failure in failures:
        print(f"FAIL {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
