"""A case record's TOML (cases/<id>.toml), read as tomllib reads it, faster.

tomllib, pure Python, spends nearly all its time on the long arrays of numbers a record holds
(the energy series, the disks' positions and velocities: 4.8 MB for the drawn cases of the default
suite, 0.7 s of a processor). Here each such array, `key = [ numbers ]` on lines of its own, is
read with Python's int() and float(), the functions tomllib itself applies to a number, and
the rest of the record, with those arrays emptied, by tomllib; the arrays are then put back in
the tables they were in. An array holding anything else (a string, a number written with '_',
0x, or a leading zero), a table header that is not a plain name, or a multi-line string (whose
lines could look like either) leaves the text to tomllib as it is, so the result is always tomllib's (tests/report/test_report_data.py, RecordToml).
"""
import re
import tomllib

_NUMBER = r"[+-]?(?:inf|nan|(?:0|[1-9][0-9]*)(?:\.[0-9]+)?(?:[eE][+-]?[0-9]+)?)"
# A whole line `key = [` ... `]` whose elements are numbers only (one line or several).
_ARRAY = re.compile(r"^([A-Za-z0-9_-]+) = \[([-+0-9.eEinfa,\s]*)\]$", re.MULTILINE)
# The elements, checked in one pass: numbers only, commas between, a trailing comma allowed.
_NUMBER_LIST = re.compile(rf"\s*(?:{_NUMBER}\s*,\s*)*(?:{_NUMBER}\s*)?")
_TOKEN = re.compile(r"[^\s,]+")
_HEADER = re.compile(r"^(\[\[?)([^\]]*)(\]\]?)$", re.MULTILINE)
_PLAIN_NAME = re.compile(r"[A-Za-z0-9_-]+")


def _numbers(body):
    """The array's elements as tomllib gives them (an int where written as one: no '.', no
    exponent, not inf or nan), or None where one of them is not a number of the plain forms
    collide writes."""
    if not _NUMBER_LIST.fullmatch(body):
        return None
    return [float(t) if ("." in t or "e" in t or "E" in t or "n" in t) else int(t) for t in _TOKEN.findall(body)]


def _headers(text):
    """[(offset, name, is_array_of_tables)] of the record's table headers, or None where one
    is not a plain name (quoted, dotted: tomllib reads such a record alone)."""
    headers = []
    for m in _HEADER.finditer(text):
        if len(m.group(1)) != len(m.group(3)) or not _PLAIN_NAME.fullmatch(m.group(2)):
            return None
        headers.append((m.start(), m.group(2), m.group(1) == "[["))
    return headers


def loads(text):
    """tomllib.loads(text) for a case record (raises tomllib.TOMLDecodeError as it does)."""
    headers = None if "'''" in text or '"""' in text else _headers(text)
    if headers is None:  # a multi-line string could hold a line that looks like an array or a header
        return tomllib.loads(text)
    arrays, pieces, end = [], [], 0
    for m in _ARRAY.finditer(text):
        values = _numbers(m.group(2))
        if values is None:
            continue
        arrays.append((m.start(), m.group(1), values))
        pieces += [text[end:m.start()], m.group(1), " = []"]
        end = m.end()
    result = tomllib.loads("".join(pieces) + text[end:])
    seen = {}  # an array of tables' entries so far, to find the one an array belongs to
    h = 0
    table = result
    for start, key, values in arrays:
        while h < len(headers) and headers[h][0] < start:
            _, name, is_array = headers[h]
            seen[name] = seen.get(name, 0) + 1
            table = result[name][seen[name] - 1] if is_array else result[name]
            h += 1
        table[key] = values
    return result
