"""pytest set-up of the CLI tests: the shared `seed` fixture."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "support"))
from seed_fixture import pytest_runtest_makereport, seed  # noqa: E402,F401  (the seed fixture)
