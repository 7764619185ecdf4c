"""The `seed` fixture of the pytest suites (tests/python and tests/cli
import it in their conftest.py): a fresh random seed per test, or
CRSPLINE_SEED's when set, to rerun a failure. Every failure's report names
it, whatever was raised: a test's own messages only cover its assertions."""
import os
import random

import pytest


@pytest.fixture
def seed(request):
    value = int(os.environ["CRSPLINE_SEED"]) if "CRSPLINE_SEED" in os.environ else random.randrange(2**32)
    request.node.crspline_seed = value
    return value


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    report = (yield).get_result()
    value = getattr(item, "crspline_seed", None)
    if value is not None and report.failed:
        report.sections.append(("seed", f"seed {value} (rerun with CRSPLINE_SEED={value})"))
