"""Calls one public callable of the collide package with hostile values (test_public_callables_fuzz.py).

    python3 hostile_calls.py TARGET PROGRESS_FILE      (in a scratch directory: calls write files)

TARGET is a name from public_callables(): "collide.run", "collide.Scene" (the constructor),
"collide.Scene.with_overrides" (a method or property). Each call is written to PROGRESS_FILE
before it is made, so a child that dies says which call killed it. Exceptions are expected and
ignored; the process must reach the end and exit 0.
"""

import importlib
import inspect
import sys

import collide
import collide.gsd_export
import collide.solver_runner

MODULES = ["collide", "collide.solver_runner", "collide.gsd_export"]

# A class's attributes that are the machinery of every Python object, not collide's API.
OBJECT_MACHINERY = {"__dict__", "__doc__", "__module__", "__weakref__", "__new__", "__init__", "__qualname__",
                    "__annotations__", "__slotnames__"}

TINY_SCENE = """description = "2 disks"
seed = 1

[world]
box = [0.0, 0.0, 4.0, 4.0]
boundary = "reflect"

[run]
duration = 0.01
output_interval = 0.005
dt = 1e-3

[[particles]]
kind = "gas"
count = 2
radius = 0.5
mass = 1.0
velocity = { maxwell = 1.0 }
"""


def is_callable_attribute(value):
    return callable(value) or isinstance(value, (property, staticmethod, classmethod)) or hasattr(value, "__get__")


def public_callables():
    """Module-level functions and classes of each module in MODULES (names without a leading '_',
    defined in the package), and each class's own methods and properties (dunders included)."""
    targets = []
    for module_name in MODULES:
        module = importlib.import_module(module_name)
        for name in sorted(vars(module)):
            value = getattr(module, name)
            if name.startswith("_") or inspect.ismodule(value) or not callable(value):
                continue
            if not getattr(value, "__module__", "").startswith("collide"):
                continue  # imported from elsewhere (os, numpy, json ...)
            targets.append(module_name + "." + name)
            if isinstance(value, type):
                targets += [module_name + "." + name + "." + attr for attr in sorted(vars(value))
                            if attr not in OBJECT_MACHINERY and is_callable_attribute(vars(value)[attr])]
    return targets


def hostile_values():
    """(label, value) pairs: the label is what the progress file shows (a repr of some of these
    would itself be 10^5 characters, or recurse 10^5 levels)."""
    deep = {}
    for _ in range(100000):
        deep = {"a": deep}
    dotted = ".".join(["a"] * 150000)
    return [
        ("'x' * 10**5", "x" * 100000),
        ("'a\\0b'", "a\0b"),
        ("a dotted key 150,000 parts deep", dotted),
        ("{that key: 1}", {dotted: 1}),
        ("a dict 10**5 deep", deep),
        ("a lone surrogate", "\udcff"), ("''", ""), ("bytes not UTF-8", b"\xff\xfe"),
        ("10**100", 10 ** 100), ("-2**63", -2 ** 63), ("2**64", 2 ** 64), ("-1", -1),
        ("nan", float("nan")), ("inf", float("inf")),
        ("None", None), ("object()", object()), ("[]", []), ("{'': None}", {"": None}),
        ("Scene.__new__(Scene)", collide.Scene.__new__(collide.Scene)),
        ("Simulation.__new__(Simulation)", collide.Simulation.__new__(collide.Simulation)),
    ]


def argument_lists(plausible, hostile):
    """(labels, arguments): no argument, one or two hostile ones, and a hostile one after
    plausible leading arguments (so that the check of a later argument, e.g. run's `out`, is
    reached)."""
    lists = [((), ())]
    pairs = [(plausible[0], plausible[1]), (plausible[3], ("'out.xyz'", "out.xyz"))]
    for label, v in hostile:
        lists += [((label,), (v,)), ((label, label), (v, v))]
        lists += [((p_label, label), (p, v)) for p_label, p in plausible]
        lists += [((p_label, q_label, label), (p, q, v)) for (p_label, p), (q_label, q) in pairs]
    return lists


def resolve(target):
    """(the class or None, the attribute name or None, the object the target names)."""
    parts = target.split(".")
    for split in range(len(parts), 0, -1):
        try:
            module = importlib.import_module(".".join(parts[:split]))
        except ImportError:
            continue
        value, owner = module, None
        for part in parts[split:]:
            owner, value = value, getattr(value, part) if not isinstance(value, type) else vars(value)[part]
        name = parts[-1] if isinstance(owner, type) else None
        return (owner if name else None), name, value
    raise SystemExit("no such target " + target)


def callables_of(target, valid):
    """What to call for `target`: the function or class; for a class's attribute, the attribute
    read from an uninitialised and a valid object (a property is read there) and the unbound
    function or property getter, whose first argument is then hostile too."""
    cls, name, value = resolve(target)
    if cls is None:
        return [(target, value)]
    out = []
    for label, obj in (("uninitialised", cls.__new__(cls)), ("valid", valid.get(cls))):
        if obj is None:
            continue
        out.append(("getattr(%s %s, %r)" % (label, cls.__name__, name), lambda obj=obj: getattr(obj, name)))
    unbound = value.fget if isinstance(value, property) else getattr(cls, name)
    if callable(unbound):
        out.append((target + " (unbound)", unbound))
    return out


def main(target, progress_path):
    progress = open(progress_path, "w", encoding="utf-8")

    def note(text):
        progress.write(text + "\n")
        progress.flush()

    note("setting up")
    scene = collide.Scene.from_toml(TINY_SCENE, "tiny")
    collide.run(scene, "event", out="frames.h5", frames=True, progress=False)
    valid = {collide.Scene: scene, collide.Simulation: collide.Simulation(scene, "event"),
             collide.RunResult: collide.RunResult({"metrics": {}})}
    hostile = hostile_values()
    plausible = [("a valid Scene", scene), ("'event'", "event"), ("'out.h5'", "out.h5"), ("'frames.h5'", "frames.h5")]
    calls = argument_lists(plausible, hostile)
    for label, fn in callables_of(target, valid):
        if label.startswith("getattr("):
            note(label)
            try:
                fn = fn()
            except BaseException:  # noqa: BLE001  (any exception is a refusal; only a signal fails)
                continue
            if not callable(fn):
                continue
        for labels, args in calls:
            note("%s(%s)" % (label, ", ".join(labels)))
            try:
                fn(*args)
            except KeyboardInterrupt:
                raise
            except BaseException:  # noqa: BLE001
                pass
    note("done")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
