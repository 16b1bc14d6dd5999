"""Random dicts for Scene.from_dict (tests/python/test_from_dict_fuzz.py).

A case is a valid scene dict with a few values replaced, or keys added, by random Python
objects: numbers at and beyond 64 bits, NaN, strings with lone surrogates and NULs, NumPy
scalars and arrays, containers nested deep or holding themselves, and objects whose
__index__ or __float__ raise or lie. Run as a script, it checks one batch of cases and prints
one JSON line per case, flushed, so that a crash names the case it happened in.
"""

import decimal
import fractions
import json
import random
import re
import sys

import numpy as np


class RaisingIndex:
    def __index__(self):
        raise ZeroDivisionError("__index__ fails")


class RaisingFloat:
    def __float__(self):
        raise OverflowError("__float__ fails")


class LyingFloat:
    def __float__(self):
        return "not a float"


class LyingIndex:
    def __index__(self):
        return 2.5


class RaisingStr:
    def __str__(self):
        raise RuntimeError("__str__ fails")

    def __repr__(self):
        raise RuntimeError("__repr__ fails")


def base_scene():
    return {
        "description": "fuzzed scene", "seed": 3,
        "world": {"box": [0.0, 0.0, 20.0, 20.0], "boundary": "reflect"},
        "physics": {"restitution": 1.0},
        "run": {"duration": 0.1, "output_interval": 0.05, "dt": 1e-3},
        "particles": [
            {"kind": "gas", "count": 20, "radius": 0.5, "mass": 1.0, "velocity": {"maxwell": 1.0}},
            {"kind": "list", "disks": [{"x": 2.0, "y": 2.0, "vx": 0.0, "vy": 0.0, "radius": 0.5, "mass": 1.0}]},
        ],
        "backend": {"event": {"tc": 1e-3}},
    }


def deep(depth, inner):
    for _ in range(depth):
        inner = [inner] if depth % 2 else {"a": inner}
    return inner


def self_holding(rng):
    if rng.random() < 0.5:
        d = {"x": 1}
        d["self"] = d
        return d
    x = [1]
    x.append(x)
    return x


def random_key(rng):
    alphabet = "abcxyz_- .\n\t\"'\\[]=#é\u2603\x00"
    return "".join(rng.choice(alphabet) for _ in range(rng.randint(0, 8)))


def random_value(rng, depth=0):
    kind = rng.randrange(24)
    if kind == 0: return rng.choice([0, 1, -1, 2**63 - 1, -2**63, 2**63, -2**63 - 1, 2**64, 2**70, 10**400])
    if kind == 1: return rng.choice([0.0, -0.0, 1e-300, 1e300, 1.7e308, float("nan"), float("inf"), -float("inf")])
    if kind == 2: return rng.choice([True, False, None])
    if kind == 3: return rng.choice(["", "gas", "list", "periodic", "\ud800", "a\x00b", "x" * 1000, "é\u2603"])
    if kind == 4: return rng.choice([np.int64(5), np.uint64(2**64 - 1), np.float32(0.5), np.float64("nan"),
                                     np.bool_(True), np.int8(-3), np.str_("gas"), np.datetime64("2020-01-01")])
    if kind == 5: return rng.choice([np.arange(4), np.zeros((2, 2)), np.array([]), np.array(["a", "b"]),
                                     np.array([1.5, np.nan]), np.zeros((1,) * 20), np.array(5)])
    if kind == 6: return rng.choice([RaisingIndex(), RaisingFloat(), LyingFloat(), LyingIndex(), RaisingStr()])
    if kind == 7: return rng.choice([1 + 2j, b"bytes", {1, 2}, frozenset(), range(3), object(), type,
                                     decimal.Decimal("1.5"), fractions.Fraction(1, 3), decimal.Decimal("nan")])
    if kind == 8: return deep(rng.choice([5, 9, 63, 64, 65, 200, 5000]), rng.choice([1, [], {}]))
    if kind == 9: return self_holding(rng)
    if kind == 10: return {1: "int key"} if rng.random() < 0.5 else {("a",): 1}
    if kind == 11: return {random_key(rng): 1.0}
    if kind == 12:
        bad = np.empty(1, dtype=object)
        bad[0] = bad
        return bad
    if depth > 3: return rng.random()
    if kind < 17: return [random_value(rng, depth + 1) for _ in range(rng.randint(0, 4))]
    if kind < 20: return tuple(random_value(rng, depth + 1) for _ in range(rng.randint(0, 3)))
    return {random_key(rng): random_value(rng, depth + 1) for _ in range(rng.randint(0, 3))}


def mutate(rng, scene):
    """Replaces a random value (or adds a key) somewhere in the scene dict."""
    for _ in range(rng.randint(1, 3)):
        node = scene
        while True:
            keys = list(node.keys()) if isinstance(node, dict) else list(range(len(node)))
            if not keys:
                break
            k = rng.choice(keys)
            child = node[k]
            if isinstance(child, (dict, list)) and child and rng.random() < 0.7:
                node = child
                continue
            if isinstance(node, dict) and rng.random() < 0.2:
                k = random_key(rng)
            node[k] = random_value(rng)
            break
    return scene


def case(seed, index):
    rng = random.Random(seed * 1000003 + index)
    return mutate(rng, base_scene())


def key_text(key):
    """A key as from_dict's messages write it: bare, or quoted with escapes (the keys made
    here are too short for its cut at 60 characters)."""
    if re.fullmatch(r"[A-Za-z0-9_-]+", key):
        return key
    escaped = "".join("\\" + c if c in '"\\' else "\\u%04x" % ord(c) if ord(c) < 0x20 or ord(c) == 0x7f else c
                      for c in key)
    return '"' + escaped + '"'


def paths(value, prefix, seen):
    """Every key path Scene.from_dict names a value by (its messages' first word), down to a
    little below the depth at which it stops."""
    out = {prefix or "the dict"}
    if id(value) in seen or len(seen) > 70:
        return out
    seen = seen | {id(value)}
    if isinstance(value, dict):
        for k, v in list(value.items()):
            if isinstance(k, str):
                name = key_text(k)
                out |= paths(v, prefix + "." + name if prefix else name, seen)
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            out |= paths(v, "%s[%d]" % (prefix, i), seen)
    return out


def check(seed, index):
    import collide

    d = case(seed, index)
    try:
        collide.Scene.from_dict(d)
        return {"case": index, "outcome": "built"}
    except collide.SceneError as e:  # the scene reader's refusal: file, line, key and what was expected
        return {"case": index, "outcome": "SceneError", "named": True, "message": str(e)[:300]}
    except (ValueError, TypeError) as e:
        message = str(e)
        where = message.split(": ", 1)[0]
        while where.endswith("]") and where not in paths(d, "", frozenset()):
            where = where[:where.rindex("[")]  # inside a NumPy array: named by the array's path
        named = where in paths(d, "", frozenset())
        return {"case": index, "outcome": type(e).__name__, "named": named, "message": message[:300]}
    except BaseException as e:  # noqa: B902 - anything else is a finding
        return {"case": index, "outcome": "other", "type": type(e).__name__, "message": str(e)[:300]}


if __name__ == "__main__":
    seed, first, count = (int(a) for a in sys.argv[1:4])
    for i in range(first, first + count):
        print(json.dumps({"start": i}), flush=True)
        print(json.dumps(check(seed, i)), flush=True)
