"""The report only lays out (docs/reading-a-report.md, "Where each verdict is decided"): no file of
validation/report/ compares a number against a threshold of its own. Every verdict, and every
threshold behind one, is decided by `collide validate` in C++ and written to summary.json.

The rule, applied to the syntax tree of every validation/report/*.py:

- A comparison (<, >, <=, >=) with a numeric literal on either side is a threshold, except
  - the literals 0 and 1 (signs, empty/non-empty, fractions in [0, 1], "more than one"), and
  - a comparison of a length or count, `len(...)` against a number (how many rows to lay out);
- unless the line ends with a comment `# layout: <why>`, which says the number chooses a
  format or a page size and never what the page says about a solver (e.g. print "2.3x" below
  10 and "23x" above). Such a line names its reason where a reader sees it.

== and != against a literal are not comparisons with a threshold (they test a value, e.g. an
exit status) and are not looked at.
"""
import ast
import pathlib

import pytest

REPORT = pathlib.Path(__file__).resolve().parents[2] / "validation" / "report"
ORDERING = (ast.Lt, ast.Gt, ast.LtE, ast.GtE)


def number(node):
    """The value of a numeric literal (with its sign), or None."""
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        value = number(node.operand)
        return None if value is None else (-value if isinstance(node.op, ast.USub) else value)
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
        return node.value
    return None


def is_length(node):
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "len"


def thresholds(source, name="<text>"):
    """[(line, text)] of the comparisons against a numeric threshold in `source`."""
    lines = source.splitlines()
    found = []
    for node in ast.walk(ast.parse(source, name)):
        if not isinstance(node, ast.Compare):
            continue
        operands = [node.left, *node.comparators]
        for k, op in enumerate(node.ops):
            if not isinstance(op, ORDERING):
                continue
            left, right = operands[k], operands[k + 1]
            literal = number(left) if number(left) is not None else number(right)
            other = right if number(left) is not None else left
            if literal is None or literal in (0, 1) or is_length(other):
                continue
            line = lines[node.lineno - 1]
            if "# layout:" not in line:
                found.append((node.lineno, line.strip()))
    return sorted(found)


@pytest.mark.parametrize("path", sorted(REPORT.glob("*.py")), ids=lambda p: p.name)
def test_no_comparison_against_a_numeric_threshold(path):
    found = thresholds(path.read_text(encoding="utf-8"), str(path))
    assert not found, f"{path.name}: a verdict decided in the report (decide it in C++, write it to " \
                      f"summary.json; or mark a format choice '# layout: why'): " + \
                      "; ".join(f"line {n}: {text}" for n, text in found)


def test_the_rule_finds_the_thresholds_it_is_meant_to_find():
    # The verdict thresholds the report held before they moved into `collide validate`.
    source = "if loose and loose[0] >= 5:\n    pass\nif drift and drift[0] >= 0.01:\n    pass\n" \
             "ok = sigmas >= 3\nbad = -2.5 > x\n"
    assert [n for n, _ in thresholds(source)] == [1, 3, 5, 6]


def test_the_rule_passes_what_is_not_a_threshold():
    source = "a = x > 0\nb = 0 < f < 1\nc = len(rows) > 20\nd = x == 3\n" \
             "e = f'{x:.2g}' if x < 10 else f'{x:.0f}'  # layout: two digits below 10\n"
    assert thresholds(source) == []
