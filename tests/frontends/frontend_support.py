"""Helpers of the cross-front-end tests: the CLI binary (CRSPLINE_BIN), the
reference folder (CRSPLINE_REFERENCE_DIR) and the Python package (on
PYTHONPATH); CTest sets all three (tests/frontends/CMakeLists.txt). By hand:

    CRSPLINE_BIN=build/rel/cli/crspline PYTHONPATH=build/rel/python \\
        /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/frontends
"""
import json
import os
import pathlib
import subprocess

REFERENCE_DIR = pathlib.Path(os.environ.get("CRSPLINE_REFERENCE_DIR")
                             or pathlib.Path(__file__).resolve().parents[1] / "reference")


def load_reference(name):
    return json.loads((REFERENCE_DIR / name).read_text(encoding="utf-8"))


def cli(args, stdin):
    path = os.environ.get("CRSPLINE_BIN")
    if not path:
        raise RuntimeError("set CRSPLINE_BIN to the crspline executable (CTest does this)")
    return subprocess.run([path] + list(args), input=stdin, capture_output=True, text=True, encoding="utf-8",
                          timeout=60)
