"""The file guards of collide (python/collide/safe_output.py: the output guard and atomic write,
the input guard) for the report's modules. They live with the Python package, whose GSD writer
uses them too, and are found from here in the source tree and under an install prefix alike
(share/collide/validation/report beside share/collide/python/collide)."""
import os
import sys

_SHARED = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "collide"))
if _SHARED not in sys.path:
    sys.path.insert(1, _SHARED)

import safe_output  # noqa: E402,F401  (re-exported)
