"""Shared helpers of the Python tests.

Run with Debian's interpreter on the built package, e.g.
    PYTHONPATH=build-py/python /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/python
(CTest's python.pytest case sets this up.)
"""
import json
import os
import pathlib
import sys

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "support"))
from seed_fixture import pytest_runtest_makereport, seed  # noqa: E402,F401  (the seed fixture)

# Hypothesis: derandomized (the same examples every run, so a failure
# reproduces), no example database on disk, no deadline on a shared machine.
settings.register_profile("crspline", derandomize=True, database=None, deadline=None, max_examples=60,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("CRSPLINE_HYPOTHESIS_PROFILE", "crspline"))

REPO = pathlib.Path(__file__).resolve().parents[2]
REFERENCE_DIR = pathlib.Path(os.environ.get("CRSPLINE_REFERENCE_DIR", REPO / "tests" / "reference"))

EPS = np.finfo(np.float64).eps


def load_reference(name):
    with open(REFERENCE_DIR / name) as f:
        return json.load(f)


def scale_of(points):
    """Bounding-box diagonal of the points (at least 1e-300)."""
    p = np.asarray(points, dtype=float).reshape(len(points), -1)
    return max(float(np.linalg.norm(p.max(axis=0) - p.min(axis=0))), 1e-300)


def magnitude_of(points):
    """Largest absolute coordinate (for rounding of the coordinates themselves)."""
    return float(np.max(np.abs(np.asarray(points, dtype=float))))


@pytest.fixture(scope="session")
def crspline():
    import crspline as module
    return module


def assert_releases_the_gil(call, scale=1):
    """Runs call(scale) in a thread while this one keeps running Python,
    and asserts that it kept running: stamps taken all along the call, no
    gap of half the call's length (with the GIL held the loop would stall
    for the whole call). A call too short to tell (under 50 ms: a fast
    machine, an optimized build) runs again with twice the scale, up to 2^8
    times the first; the call must then last 20 ms at least."""
    import threading
    import time

    for _ in range(9):
        done = threading.Event()
        started = threading.Event()
        span = {}

        def work():
            started.set()
            t0 = time.perf_counter()
            call(scale)
            span["call"] = time.perf_counter() - t0
            done.set()

        th = threading.Thread(target=work)
        th.start()
        started.wait()
        stamps = []
        while not done.is_set():
            stamps.append(time.perf_counter())
        th.join()
        if span["call"] >= 0.05:
            break
        scale *= 2
    assert span["call"] > 0.02, ("the call was too short to tell", span["call"], scale)
    gaps = np.diff(stamps) if len(stamps) > 1 else np.array([span["call"]])
    assert len(stamps) > 100 and gaps.max() < 0.5 * span["call"], (len(stamps), gaps.max(), span["call"])
