"""Helpers shared by the crspline CLI tests (standard library only).

The binary comes from CRSPLINE_BIN and the reference data from
CRSPLINE_REFERENCE_DIR; CTest sets both (tests/cli/CMakeLists.txt). Run by
hand with, for example:

    CRSPLINE_BIN=build/cli/crspline /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/cli
"""
import json
import math
import os
import subprocess

_HERE = os.path.dirname(os.path.abspath(__file__))


def binary():
    path = os.environ.get("CRSPLINE_BIN")
    if not path:
        raise RuntimeError("set CRSPLINE_BIN to the crspline executable (CTest does this)")
    return path


def reference_dir():
    return os.environ.get("CRSPLINE_REFERENCE_DIR") or os.path.join(_HERE, os.pardir, "reference")


def load_reference(name):
    with open(os.path.join(reference_dir(), name), encoding="utf-8") as f:
        return json.load(f)


def run(args, stdin=""):
    """Runs crspline with the given arguments and stdin text; returns the CompletedProcess."""
    return subprocess.run([binary()] + list(args), input=stdin, capture_output=True, text=True,
                          encoding="utf-8", timeout=60)


def run_json(command, doc):
    """Runs `crspline COMMAND -` on the JSON document and returns the parsed output.
    Fails with the stderr line when the command does not succeed."""
    p = run([command, "-"], json.dumps(doc, allow_nan=False))
    assert p.returncode == 0, f"crspline {command} failed ({p.returncode}): {p.stderr.strip()}\ninput: {json.dumps(doc)[:400]}"
    assert p.stderr == "", p.stderr
    # The output must be strict JSON: no NaN or Infinity literals.
    return json.loads(p.stdout, parse_constant=_reject_constant)


def _reject_constant(name):
    raise AssertionError(f"crspline printed {name}, which is not JSON")


def max_abs(values):
    """Largest absolute value in a nested list of numbers (0 for an empty one)."""
    if isinstance(values, (int, float)):
        return abs(values)
    return max((max_abs(v) for v in values), default=0.0)


def max_diff(a, b):
    """Largest absolute difference between two nested lists of the same shape."""
    if isinstance(a, (int, float)):
        assert isinstance(b, (int, float)), (a, b)
        return abs(a - b)
    assert len(a) == len(b), f"shapes differ: {len(a)} vs {len(b)}"
    return max((max_diff(x, y) for x, y in zip(a, b)), default=0.0)


def ulp_of(values):
    """One unit in the last place of the largest magnitude in `values`."""
    return math.ulp(max_abs(values))
