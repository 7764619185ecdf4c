"""An error about a field of a JSON curve file names the file (issue 31,
point 7): the README promises "the file, line and column or the field and
index", and a list file and the core's errors already named it. A shape
error (`points[1][1]: expected a finite number`), an unknown field and a
number beyond the double range now start with the file's name too. On stdin
the field's path stays the whole address (tests/cli/test_errors.py), and a
flag's message names the flag, not the file."""
import json

import pytest

from cli_support import run

P3 = [[0, 0], [1, 1], [2, 0]]

# (name, command, the file's text, the line after "crspline: FILE: ").
CASES = [
    ("shape error", "bezier", '{"points": [[0, 0], [1, "x"], [2, 0]]}', 'points[1][1]: expected a finite number, got "x"'),
    ("null coordinate", "length", '{"points": [[0, 0], [1, null]]}', "points[1][1]: expected a finite number, got null"),
    ("unknown field", "bezier", '{"points": [[0, 0], [1, 1]], "foo": 1}', "unknown field 'foo'"),
    ("number beyond double", "bezier", '{"points": [[0, 0], [1, 1e999]]}', "points[1][1]: expected a finite number, got 1e999"),
    ("missing points", "length", '{"alpha": 0.5}', "missing field 'points'"),
    ("another command's field", "length", '{"points": [[0, 0], [1, 1]], "t": [0]}',
     "t: only 'crspline eval' takes this field, not 'crspline length'"),
    ("eval parameters", "eval", '{"points": [[0, 0], [1, 1]], "t": [0, "1"]}', 't[1]: expected a finite number, got "1"'),
    ("sample count", "sample", '{"points": [[0, 0], [1, 1]], "count": 1}', "count: expected an integer >= 2, got 1"),
    ("end object", "bezier", '{"points": [[0, 0], [1, 1]], "end": {"begin": "natural"}}',
     "end: unknown field 'begin' (expected \"start\" and \"end\")"),
    # The core's words were already after the file's name; not twice.
    ("core error", "bezier", '{"points": [[0, 0], [1, 1]], "alpha": 2}', "alpha must be in [0, 1], got 2"),
]


@pytest.mark.parametrize("name,command,text,line", CASES, ids=[c[0] for c in CASES])
def test_a_field_error_in_a_file_names_the_file(tmp_path, name, command, text, line):
    path = tmp_path / "curve.json"
    path.write_text(text)
    p = run([command, str(path)])
    assert p.returncode == 2 and p.stdout == "", (p.returncode, p.stdout)
    assert p.stderr == f"crspline: {path}: {line}\n"


def test_the_cases_are_distinct():
    assert len({c[0] for c in CASES}) == len(CASES) == 10


def test_a_flag_error_names_the_flag_not_the_file(tmp_path):
    path = tmp_path / "curve.json"
    path.write_text(json.dumps({"points": P3}))
    p = run(["bezier", "--alpha", "abc", str(path)])
    assert p.returncode == 2 and p.stderr == 'crspline: --alpha: expected a finite number, got "abc"\n'


def test_stdin_keeps_the_field_path_alone():
    p = run(["bezier", "-"], '{"points": [[0, 0], [1, "x"]]}')
    assert p.returncode == 2 and p.stderr == 'crspline: points[1][1]: expected a finite number, got "x"\n'


def test_a_list_file_names_the_file_and_the_curve(tmp_path):
    path = tmp_path / "list.json"
    path.write_text(json.dumps([{"id": "a", "points": P3}, {"id": "b", "points": P3, "foo": 1}]))
    p = run(["length", str(path)])
    assert p.returncode == 2 and p.stderr == f"crspline: {path}: curve b: unknown field 'foo'\n"
