"""Text that collide did not write (a solver's output, a scene's or a check's name read from
summary.json), made safe to show: the Python twin of core/text/printable.h, the one sanitiser
of the C++ side.

  terminal(text)  every control character (C0, DEL, C1) shown as \\xNN, line breaks included,
                  so that no escape reaches the terminal and no line break forges a line of
                  collide's own output; letters of any script pass;
  markdown(text)  terminal(), then what Markdown would read as markup written as text: HTML
                  (& < >) as entities, so a tag a solver prints (script, b) is shown as text,
                  not run or drawn; '|' (a table cell's end), '`' (a code span) and '](' (a link)
                  escaped with a backslash, and a backslash itself.
"""


import re

# What terminal() rewrites: the C0 and C1 control characters, DEL, and the surrogates (a byte
# that was not UTF-8, a lone surrogate). Text without any (nearly every name and message) is
# returned as it is, without the walk one character at a time: the report shows ~40,000 texts.
_REWRITTEN = re.compile("[\x00-\x1f\x7f-\x9f\ud800-\udfff]")
_MARKUP = re.compile(r"[&<>\\|`]|\]\(")


def _is_control(ch):
    code = ord(ch)
    return code < 0x20 or 0x7f <= code <= 0x9f  # layout: the C0 and C1 control characters


def terminal(text):
    text = str(text)
    if not _REWRITTEN.search(text):
        return text
    out = []
    for ch in text:
        code = ord(ch)
        if 0xdc80 <= code <= 0xdcff:  # layout: a byte that was not UTF-8 (surrogateescape)
            out.append("\\x%02x" % (code - 0xdc00))
        elif _is_control(ch) or 0xd800 <= code <= 0xdfff:  # layout: a lone surrogate
            out.append("\\x%02x" % code if code <= 0xff else "\\u%04x" % code)  # layout: two hex digits for a byte
        else:
            out.append(ch)
    return "".join(out)


_MARKDOWN = {"&": "&amp;", "<": "&lt;", ">": "&gt;", "\\": "\\\\", "|": "\\|", "`": "\\`"}


def markdown(text):
    text = terminal(text)
    if not _MARKUP.search(text):
        return text
    escaped = "".join(_MARKDOWN.get(ch, ch) for ch in text)
    return escaped.replace("](", "]\\(")
