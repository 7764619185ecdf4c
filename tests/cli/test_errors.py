"""Bad input and usage: exit status 2, exactly one line on stderr naming the
field, index and value, and nothing on stdout. Also stdin handling, --help
and --version."""
import json
import os
import tempfile

import pytest

from cli_support import run, run_json

P4 = [[0, 0], [1, 2], [3, 3], [4, 1]]  # a valid open curve (uniform grid [0, 1, 2, 3])


def doc(**fields):
    d = {"points": P4}
    d.update(fields)
    return json.dumps(d)


# (name, command, stdin text, the exact stderr line after "crspline: "). The
# shape of the JSON is the command line's to check (its words, the field's
# path); the values are the core's (its words, the same in Python and the web
# module: tests/frontends/test_bad_specs.py), after the file's name.
CASES = [
    ("missing points", "eval", '{"t": [0]}', "missing field 'points'"),
    # A list is a list of curves (docs/cli.md, MANY CURVES).
    ("list of non-objects", "eval", "[1, 2]", '<stdin>: [0]: expected a curve object {"points": ...}, got 1'),
    ("points not an array", "bezier", '{"points": 3}', "points: expected an array of points, got 3"),
    ("wrong number of coordinates", "eval", '{"points": [[0, 0], [1, 1], [2, 2, 2]], "t": [0]}',
     "points[2]: expected 2 coordinates like points[0], got 3"),
    ("seventeen coordinates", "bezier", '{"points": [[' + ", ".join(["0"] * 17) + '], [' + ", ".join(["1"] * 17) + ']]}',
     "<stdin>: dimension must be 1 to 16, got 17"),
    ("string coordinate", "eval", '{"points": [[0, 0], [1, 1], [2, 2], [3, "abc"]], "t": [0]}',
     'points[3][1]: expected a finite number, got "abc"'),
    ("null coordinate", "bezier", '{"points": [[0, 0], [1, null]]}', "points[1][1]: expected a finite number, got null"),
    ("bool coordinate", "bezier", '{"points": [[0, true], [1, 1]]}', "points[0][1]: expected a finite number, got true"),
    ("1e999", "eval", '{"points": [[0, 0], [1, 1e999]], "t": [0]}', "points[1][1]: expected a finite number, got 1e999"),
    ("-1e999 in grid", "bezier", '{"points": [[0], [1]], "grid": [-1e999, 1]}',
     "grid[0]: expected a finite number, got -1e999"),
    ("one point", "eval", '{"points": [[1, 2]], "t": [0]}', "<stdin>: a curve needs at least 2 points, got 1"),
    ("closed with one point", "bezier", '{"points": [[1, 2]], "end": "closed"}',
     "<stdin>: a closed curve needs at least 2 points, got 1"),
    ("alpha 1.5", "eval", doc(alpha=1.5, t=[0]), "<stdin>: alpha must be in [0, 1], got 1.5"),
    ("alpha string", "bezier", doc(alpha="0.5"), 'alpha: expected a finite number, got "0.5"'),
    ("alpha and grid", "bezier", doc(alpha=0.5, grid=[0, 1, 2, 3]), "<stdin>: give alpha or grid, not both"),
    ("grid wrong length", "bezier", doc(grid=[0, 1, 2]), "<stdin>: grid has 3 values, expected 4 (one per point)"),
    ("closed grid wrong length", "bezier", doc(grid=[0, 1, 2, 3], end="closed"),
     "<stdin>: grid has 4 values, expected 5 (one per point plus one: a closed curve repeats the first knot)"),
    ("grid not increasing", "bezier", doc(grid=[0, 1, 1, 2]), "<stdin>: grid must be strictly increasing: grid[2] = 1 is not greater than grid[1] = 1"),
    ("unknown end condition", "bezier", doc(end="clamped"),
     "<stdin>: end conditions must be 'natural', 'reflect', 'closed' or one for each end, got 'clamped'"),
    ("closed per end", "bezier", doc(end={"start": "closed"}),
     "<stdin>: start condition must be 'natural', 'reflect' or a tangent, got 'closed'"),
    ("tangent of wrong length", "bezier", doc(end={"start": [1, 0], "end": [1, 0, 0]}),
     "<stdin>: end tangent has 3 coordinates, expected 2 like the points"),
    ("tangent with a string", "bezier", doc(end={"start": [1, "x"]}), 'end.start[1]: expected a finite number, got "x"'),
    ("unknown end field", "bezier", doc(end={"begin": "natural"}),
     "end: unknown field 'begin' (expected \"start\" and \"end\")"),
    ("tension 2", "bezier", doc(tension=2), "<stdin>: tension must be in [0, 1], got 2"),
    ("t out of domain", "eval", doc(alpha=0, t=[0, 1, 2, 3, 9]), "t[4]: t = 9 is outside the domain [0, 3]"),
    ("derivative 4", "eval", doc(t=[0], derivatives=[0, 4]), "derivatives[1]: expected 0, 1, 2 or 3, got 4"),
    ("derivative 1.5", "eval", doc(t=[0], derivatives=[1.5]), "derivatives[0]: expected 0, 1, 2 or 3, got 1.5"),
    ("duplicate derivatives", "eval", doc(t=[0], derivatives=[0, 1, 1]),
     "derivatives[2]: order 1 is already requested by derivatives[1]"),
    ("no derivatives", "eval", doc(t=[0], derivatives=[]),
     "derivatives: expected at least one order (0, 1, 2 or 3), got []"),
    ("t missing", "eval", doc(), "missing field 't' (the parameter values to evaluate at) or 's' (arc lengths)"),
    ("t not numbers", "eval", doc(t=[0, "1"]), 't[1]: expected a finite number, got "1"'),
    ("unknown field", "eval", doc(t=[0], foo=1), "unknown field 'foo'"),
    ("t given to bezier", "bezier", doc(t=[0]), "t: only 'crspline eval' takes this field, not 'crspline bezier'"),
    ("derivatives given to bezier", "bezier", doc(derivatives=[0]),
     "derivatives: only 'crspline eval' takes this field, not 'crspline bezier'"),
    ("duplicate key", "bezier", '{"points": [[0], [1]], "alpha": 0, "alpha": 1}', "<stdin>: duplicate field 'alpha'"),
    ("strict with coincident points", "bezier",
     '{"points": [[0, 0], [1, 1], [1, 1], [2, 0]], "alpha": 0.5, "strict": true}',
     "<stdin>: points[1] and points[2]: coincident consecutive points (strict mode): 1 and 2"),
    ("strict not a bool", "bezier", doc(strict="yes"), 'strict: expected true or false, got "yes"'),
    ("kb array of wrong length", "bezier", doc(kb={"tension": [0, 0.5, 0.5]}),
     "<stdin>: kb tension has 3 values, expected one per point (4)"),
    ("kb null inside", "bezier", doc(kb={"bias": [None, None, 0, None]}),
     "<stdin>: kb bias[1] is not finite (nan) (null is allowed only at the two end vertices of an open curve)"),
    ("kb null on a closed curve", "bezier", doc(end="closed", kb={"continuity": [None, 0, 0, 0]}),
     "<stdin>: kb continuity[0] is not finite (nan) (null is allowed only at the two end vertices of an open curve)"),
    ("kb unknown field", "bezier", doc(kb={"tensions": [0, 0, 0, 0]}),
     "kb: unknown field 'tensions' (expected \"tension\", \"continuity\", \"bias\")"),
    # Issue 31 point 3: a difference that overflows is refused at construction.
    ("overflow", "eval", '{"points": [[1e308], [-1e308]], "alpha": 0, "t": [0.5]}',
     "<stdin>: points[0]: points 0 and 1: the chord between them overflows (|P1 - P0| is not finite)"),
    # The same words as an empty file (test_input_errors.py: test_empty_inputs_agree).
    ("empty input", "eval", "", "<stdin>: the input is empty (a curve needs at least 2 points, got 0)"),
    ("NaN literal", "eval", '{"points": [[0], [NaN]]}',
     "<stdin>: line 1, column 19: syntax error while parsing value - invalid literal; last read: '0], [N'"),
]

def check_error(p, line):
    assert p.returncode == 2, (p.returncode, p.stdout, p.stderr)
    assert p.stdout == "", p.stdout
    assert p.stderr == f"crspline: {line}\n", p.stderr


@pytest.mark.parametrize("name,command,text,line", CASES, ids=[c[0] for c in CASES])
def test_error_line(name, command, text, line):
    check_error(run([command, "-"], text), line)


def test_error_names_are_unique():
    # Each case names one error class; a copied name would hide a missing one.
    assert len({c[0] for c in CASES}) == len(CASES)


def test_t_outside_a_centripetal_domain():
    # Non-round domain ends are printed so that they read back to the same double.
    out = run_json("eval", {"points": P4, "t": [], "knots": True})
    hi = out["grid"][-1]
    p = run(["eval"], doc(t=[0, hi, -0.25]))
    check_error(p, f"t[2]: t = -0.25 is outside the domain [0, {hi!r}]")
    assert float(p.stderr.split(", ")[1].rstrip("]\n")) == hi


@pytest.fixture
def tmpdir_path():
    with tempfile.TemporaryDirectory() as d:
        yield d


def test_malformed_json_file_names_line_and_column(tmpdir_path):
    path = os.path.join(tmpdir_path, "input.json")
    with open(path, "w") as f:
        f.write('{\n  "points": [[0, 0], [1, 1]],\n  "t": [0, 0.5,, 1]\n}\n')
    p = run(["eval", path])
    check_error(p, f"{path}: line 3, column 16: syntax error while parsing value - unexpected ','; "
                   "expected '[', '{', or a literal")


def test_malformed_json_position_after_multibyte_text(tmpdir_path):
    # Columns count bytes, as nlohmann's own position does.
    path = os.path.join(tmpdir_path, "b.json")
    with open(path, "w", encoding="utf-8") as f:
        f.write('{"points": [[0], [1]],\n"t": [], "é": x}')
    p = run(["bezier", path])
    check_error(p, f"{path}: line 2, column 16: syntax error while parsing value - invalid literal; last read: '\"é\": x'")


def test_missing_file(tmpdir_path):
    path = os.path.join(tmpdir_path, "missing.json")
    check_error(run(["eval", path]), f"{path}: cannot open: No such file or directory")


def test_directory_as_input(tmpdir_path):
    check_error(run(["bezier", tmpdir_path]), f"{tmpdir_path}: cannot read: Is a directory")


def test_usage_errors():
    for args, line in [
        ([], "A subcommand is required (see 'crspline --help')"),
        (["eval", "a.json", "b.json"], "The following argument was not expected: b.json (see 'crspline --help')"),
        (["bezier", "--frobnicate"], "unknown option --frobnicate for 'crspline bezier'; see 'crspline bezier --help'"),
    ]:
        check_error(run(args), line)


def test_stdin_dash_absent_and_file_agree(tmpdir_path):
    text = doc(t=[0, 0.5, 1.25], derivatives=[2, 0])
    path = os.path.join(tmpdir_path, "curve.json")
    with open(path, "w") as f:
        f.write(text)
    outputs = [run(["eval", "-"], text), run(["eval"], text), run(["eval", path])]
    for p in outputs:
        assert p.returncode == 0 and p.stderr == "", p.stderr
    assert outputs[0].stdout == outputs[1].stdout == outputs[2].stdout
    out = json.loads(outputs[0].stdout)
    assert list(out) == ["values"]  # the knot grid only with "knots": true
    assert list(out["values"]) == ["2", "0"]  # in the order requested
    assert out["values"]["0"][0] == P4[0]


def test_bezier_from_stdin_without_argument():
    p = run(["bezier"], json.dumps({"points": P4, "alpha": 0}))
    assert p.returncode == 0 and p.stderr == ""
    out = json.loads(p.stdout)
    assert list(out) == ["grid", "segments"]
    assert out["grid"] == [0, 1, 2, 3]
    assert len(out["segments"]) == 3
    for i, seg in enumerate(out["segments"]):
        assert seg[0] == P4[i] and seg[3] == P4[i + 1]  # the segment's ends, exactly


@pytest.mark.parametrize("args", [["--help"], ["eval", "--help"], ["bezier", "--help"], ["-h"]])
def test_help(args):
    p = run(args)
    assert p.returncode == 0, p.stderr
    assert p.stderr == ""
    assert "Example" in p.stdout and '"points"' in p.stdout
    if args[0] in ("eval", "bezier"):
        assert "crspline " + args[0] in p.stdout


def test_help_examples_are_true():
    """The example in each subcommand's help prints what the help says."""
    for command in ("eval", "bezier"):
        text = run([command, "--help"]).stdout
        lines = text[text.index("Example:"):].splitlines()[1:]
        example = " ".join(l.strip() for l in lines[:lines.index("")])
        cmd, printed = example.split(f"| crspline {command}")
        stdin = cmd.strip()[len("echo '"):-1]
        p = run([command], stdin)
        assert p.returncode == 0, p.stderr
        assert p.stdout.strip() == printed.replace(" ", ""), (p.stdout, printed)


def test_version():
    p = run(["--version"])
    assert p.returncode == 0
    assert p.stdout.strip() == "crspline 0.1.0"


def test_mutated_inputs_never_crash():
    """Seeded byte mutations of a valid input: every run exits 0 with JSON on
    stdout, or 2 with one 'crspline: ' line on stderr and nothing on stdout."""
    import random
    seed = int(os.environ.get("CRSPLINE_CLI_SEED", "20240611"))
    rng = random.Random(seed)
    base = json.dumps({"points": [[0, 0.5], [1, 2e3], [3, -3], [4, 1]], "alpha": 0.5,
                       "end": {"start": [1, 0], "end": "reflect"}, "tension": 0.25,
                       "kb": {"bias": [None, 0.5, -0.5, None]}, "t": [0, 1.5, 2], "derivatives": [0, 1, 2, 3]})
    alphabet = '0123456789.eE+-[]{},:" natrulfsNI\\\x00\xff'
    counts = {0: 0, 2: 0}
    for k in range(300):
        text = list(base)
        for _ in range(rng.randint(1, 4)):
            i = rng.randrange(len(text))
            op = rng.randrange(3)
            if op == 0:
                text[i] = rng.choice(alphabet)
            elif op == 1:
                del text[i]
            else:
                text.insert(i, rng.choice(alphabet))
        text = "".join(text)
        p = run(["eval"], text)
        where = f"seed {seed}, mutation {k}: {text!r}"
        assert p.returncode in (0, 2), f"exit status {p.returncode}: {where}"
        counts[p.returncode] += 1
        if p.returncode == 0:
            assert p.stderr == "", where
            json.loads(p.stdout, parse_constant=lambda c: pytest.fail(f"{c} in output: {where}"))
        else:
            assert p.stdout == "", where
            assert p.stderr.startswith("crspline: ") and p.stderr.count("\n") == 1, f"{p.stderr!r}: {where}"
    assert sum(counts.values()) == 300 and counts[2] > 0, counts
