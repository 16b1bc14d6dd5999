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
_HEADER = re.compile(r"^[ \t]*(\[\[?)([^\]]*)(\]\]?)[ \t]*$", re.MULTILINE)  # toml++ indents a sub-table's
_DOTTED_NAME = re.compile(r"[A-Za-z0-9_-]+(?:\.[A-Za-z0-9_-]+)*")
_ANY_HEADER = re.compile(r"^[ \t]*\[", re.MULTILINE)  # a line a header could be (or part of a nested array)


def _numbers(body):
    """The array's elements as tomllib gives them (an int where written as one: no '.', no
    exponent, not inf or nan), or None where one of them is not a number of the plain forms
    collide writes."""
    if not _NUMBER_LIST.fullmatch(body):
        return None
    return [float(t) if ("." in t or "e" in t or "E" in t or "n" in t) else int(t) for t in _TOKEN.findall(body)]


def _headers(text):
    """[(offset, [names of its dotted path], is_array_of_tables)] of the record's table headers,
    or None where one is not a `[a.b]` or `[[a.b]]` line of plain names (a quoted name: tomllib
    reads such a record alone)."""
    headers = []
    for m in _HEADER.finditer(text):
        if len(m.group(1)) != len(m.group(3)) or not _DOTTED_NAME.fullmatch(m.group(2)):
            return None
        headers.append((m.start(), m.group(2).split("."), m.group(1) == "[["))
    # A header this does not recognise (a comment after it, a CR before its line's end) would put the arrays after it in the table before it: tomllib reads such a record.
    return headers if len(headers) == len(_ANY_HEADER.findall(text)) and "\r" not in text else None


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
    tables = {}  # each array of tables' entries so far, by dotted path: an array after its header
    h = 0        # belongs to the entry that header opened, not to the array's last one
    table = result
    for start, key, values in arrays:
        while h < len(headers) and headers[h][0] < start:
            _, names, is_array = headers[h]
            if is_array:
                tables[tuple(names)] = tables.get(tuple(names), 0) + 1
            table = result
            for k in range(len(names)):
                table = table[names[k]]
                if isinstance(table, list):  # an array of tables: the entry its latest header opened
                    table = table[tables[tuple(names[:k + 1])] - 1]
            h += 1
        table[key] = values
    return result
