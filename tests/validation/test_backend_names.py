"""No judgement tests a backend's name (docs/validation.md, "What a solver claims").

Every fact about a backend (exact, its stepping rule, precision, what it conserves, a limit of its
own) is declared once, in the registry (apps/all_backends.cpp), and read from there. This test
greps the C++ of validation/, core/ and apps/ for comparisons with the registry's own names
(`== "event"`, `rfind("opencl", 0)`, a list such as `{"event", "step", ...}`) and fails on any
outside the registry. A default value (`std::string backend = "step"`) is no comparison.

    python3 test_backend_names.py SOURCE_DIR
"""
import pathlib
import re
import sys

SOURCE = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
REGISTRY = SOURCE / "apps" / "all_backends.cpp"
SEARCHED = ["validation", "core", "apps"]

# The scene file's own schema, not a judgement: which [backend.NAME] tables a scene may hold and
# that [backend.step] holds no keys. The scene reader (core) is read before, and without, the
# registry (apps), so it keeps these two until the scene schema is declared by the backends.
SCENE_SCHEMA = {("core/scene/scene_loader.cpp", "allow_only"), ("core/scene/backend_table.cpp", "backend ==")}


def built_in_names():
    names = re.findall(r'\.name\s*=\s*"([^"]+)"', REGISTRY.read_text(encoding="utf-8"))
    assert len(names) >= 5, "the registry's names could not be read from %s" % REGISTRY
    return names


def comparison_patterns(names):
    quoted = "|".join(re.escape('"%s"' % n) for n in names)
    return [
        re.compile(r"[=!]=\s*(%s)" % quoted),                           # backend == "event"
        re.compile(r"(%s)\s*[=!]=" % quoted),                           # "event" == backend
        re.compile(r"\b(?:r?find|compare|starts_with)\(\s*(%s)" % quoted),  # b.rfind("opencl", 0)
        re.compile(r"\{[^{}]*(%s)[^{}]*,\s*(%s)" % (quoted, quoted)),      # {"event", "step"}
    ]


def code_lines(path):
    """(number, text) of each line with // comments removed."""
    for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
        yield number, line.split("//", 1)[0]


def name_tests():
    patterns = comparison_patterns(built_in_names())
    found = []
    for folder in SEARCHED:
        for path in sorted((SOURCE / folder).rglob("*")):
            if path.suffix not in (".cpp", ".h") or path == REGISTRY:
                continue
            relative = path.relative_to(SOURCE).as_posix()
            for number, text in code_lines(path):
                if any(p.search(text) for p in patterns):
                    if any(relative == f and key in text for f, key in SCENE_SCHEMA):
                        continue
                    found.append("%s:%d: %s" % (relative, number, text.strip()))
    return found


def self_test():
    """The patterns catch what they are meant to (a test that cannot fail proves nothing)."""
    patterns = comparison_patterns(["event", "opencl", "step"])
    for bad in ['if (backend == "event") {', 'd.backend.rfind("opencl", 0) == 0', 'return base == "step" ||',
                'allow_only({"event", "step"});']:
        assert any(p.search(bad) for p in patterns), bad
    for fine in ['std::string backend = "step";', '{"step", jump.step},', 'value_or("event")']:
        assert not any(p.search(fine) for p in patterns), fine


if __name__ == "__main__":
    self_test()
    problems = name_tests()
    for p in problems:
        print("a backend's name tested outside the registry:", p)
    sys.exit(1 if problems else 0)
