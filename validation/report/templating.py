"""The report's pages come from the jinja2 templates in templates/ (Debian: python3-jinja2); the
Python side hands them plain data. Every *.html.j2 template escapes what it shows, so a scene's
name or an outside solver's message reaches the page as text, never as markup; the only bytes
let through are the figures' PNG data, base64-encoded here.
"""
import base64
import os
import sys

try:
    import jinja2
except ImportError:  # named, rather than a traceback: the report cannot be laid out without it
    sys.exit("report: the Python package jinja2 is missing: the report's pages are jinja2 templates "
             "(Debian: apt-get install python3-jinja2; scripts/install-deps.sh installs it)")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import printable  # noqa: E402

TEMPLATE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "templates")


def md(text):
    """Text for a Markdown page (printable.markdown, the one sanitiser): no HTML, no '|' to end a
    table cell, no line break to end a row, no escape byte."""
    return printable.markdown(text)


def png_data(png):
    """A figure's PNG bytes as the base64 text of a data: URL."""
    return base64.b64encode(png).decode("ascii")


ENVIRONMENT = jinja2.Environment(loader=jinja2.FileSystemLoader(TEMPLATE_DIR),
                                 autoescape=jinja2.select_autoescape(["html.j2"], default_for_string=True),
                                 undefined=jinja2.StrictUndefined)
ENVIRONMENT.filters["md"] = md
ENVIRONMENT.filters["png"] = png_data


def render(name, **context):
    """templates/NAME filled in with `context`."""
    return ENVIRONMENT.get_template(name).render(**context)
