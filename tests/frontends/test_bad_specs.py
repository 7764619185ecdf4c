"""One catalogue of bad curve specifications, fed to every front end.

tests/reference/bad_specs.json: each case is a curve file (docs/spec.md) that
does not describe a curve, with the words its error must carry in every
front end: the field's name, the index (as a number in the message) and
fragments of the core's message. Here the CLI (one line on stderr, exit
status 2) and Python (a ValueError; a TypeError where Python's idiom for a
wrong type is one). The web module gets the same file in
web/test/bad_specs.test.mjs.
"""
import json
import re

import crspline
import pytest

from frontend_support import cli, load_reference

CATALOGUE = load_reference("bad_specs.json")["cases"]


def carries(message, case):
    """What the message lacks of the case's words (empty: it has them all)."""
    missing = [w for w in case["words"] if w not in message]
    if case["index"] is not None and not re.search(rf"(?<![\d.]){case['index']}(?![\d.])", message):
        missing.append(f"index {case['index']}")
    return missing


def test_the_catalogue():
    # About twenty cases, each with words to check, and every field of the
    # specification that can be wrong on its own among them.
    assert len(CATALOGUE) == 25
    assert len({c["name"] for c in CATALOGUE}) == len(CATALOGUE)
    assert all(c["words"] for c in CATALOGUE)
    assert {c["field"] for c in CATALOGUE} >= {"points", "alpha", "grid", "tension", "start", "end", "kb.tension",
                                               "kb.bias", "dimension"}


@pytest.mark.parametrize("case", CATALOGUE, ids=[c["name"] for c in CATALOGUE])
def test_cli(case):
    # `bezier` reads the curve and nothing else.
    # An infinite number is 1e999 in JSON text (json.dumps would write Infinity).
    p = cli(["bezier", "-"], json.dumps(case["spec"]).replace("Infinity", "1e999"))
    assert p.returncode == 2 and p.stdout == "", (p.returncode, p.stdout[:200])
    lines = p.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("crspline: "), p.stderr
    assert carries(lines[0], case) == [], lines[0]


def python_call(spec):
    """The CatmullRom call for a curve file: every field as the keyword
    Python has for it, an unknown one passed on as it is."""
    kw = {}
    for key, value in spec.items():
        if key == "points":
            continue
        if key == "end":
            if isinstance(value, str):
                kw["endconditions"] = value
            else:
                kw["endconditions"] = {"start": value.get("start", "natural"), "end": value.get("end", "natural")}
        else:
            kw[key] = value
    return lambda: crspline.CatmullRom(spec["points"], **kw)


PYTHON_CASES = [c for c in CATALOGUE if "python" not in c.get("not_in", {})]


@pytest.mark.parametrize("case", PYTHON_CASES, ids=[c["name"] for c in PYTHON_CASES])
def test_python(case):
    with pytest.raises((ValueError, TypeError)) as e:
        python_call(case["spec"])()
    if isinstance(e.value, TypeError):
        # A wrong type, or a keyword Python does not have: TypeError is the
        # Python idiom. A bad value is always a ValueError.
        assert case["name"] in ("alpha_not_a_number", "unknown_field"), e.value
    assert carries(str(e.value), case) == [], str(e.value)


def test_python_leaves_out_only_what_it_cannot_be_given():
    left_out = [c["name"] for c in CATALOGUE if "python" in c.get("not_in", {})]
    assert left_out == ["kb_null_inside", "kb_wrong_length"]


def test_a_message_without_the_words_is_caught():
    case = next(c for c in CATALOGUE if c["name"] == "grid_not_finite")
    assert carries("crspline: grid[1]: expected a finite number, got 1e999", case) == []
    assert carries("crspline: grid[11]: expected a finite number", case) == ["index 1"]
    assert carries("crspline: grid: bad", case) == ["finite", "index 1"]


# The values of a curve are judged once, by the core: where the command line
# can be given the bad value (JSON text holds no infinity: 1e999 is refused
# by the JSON reader with its line and column, before any rule), its line is
# the file's name and the core's sentence, the very sentence Python raises.
# The names of the ends and the dimension are the core's to judge too
# (end_from_name, set_ends, validate).
SAME_SENTENCE = [c for c in PYTHON_CASES
                 if (c["core"] and "Infinity" not in json.dumps(c["spec"]))
                 or c["name"] in ("bad_end_name", "bad_start_name", "dimension_zero", "dimension_seventeen")]


def test_same_sentence_cases():
    # Every value rule of the catalogue Python can be given, but the three
    # infinities, plus the four above.
    assert len(SAME_SENTENCE) == 15, [c["name"] for c in SAME_SENTENCE]


@pytest.mark.parametrize("case", SAME_SENTENCE, ids=[c["name"] for c in SAME_SENTENCE])
def test_cli_speaks_the_cores_sentence(case):
    with pytest.raises((ValueError, TypeError)) as e:
        python_call(case["spec"])()
    p = cli(["bezier", "-"], json.dumps(case["spec"]))
    assert p.stderr == f"crspline: <stdin>: {e.value}\n", (p.stderr, str(e.value))
