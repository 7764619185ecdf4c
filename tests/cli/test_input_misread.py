"""Input that is never misread (issue 20): a closed ring's repeated first
point, index and parameter columns, point errors with their file and line,
empty input, conflicting sample options, tolerances and accuracies below what
the coordinates resolve, typos in commands and options, and plot's optional
values. Each case failed (wrongly succeeded, hung or misreported) before."""
import json
import math

import pytest

from cli_support import run, run_json

SQUARE = [[0, 0], [1, 0], [1, 1], [0, 1]]


def ok(args, stdin=""):
    p = run(args, stdin)
    assert p.returncode == 0, p.stderr
    return p


def check(p, line):
    assert p.returncode == 2, (p.returncode, p.stdout, p.stderr)
    assert p.stdout == "", p.stdout
    assert p.stderr == f"crspline: {line}\n", p.stderr


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return path


# --- a closed ring that repeats its first point ---------------------------------------

def test_closed_ring_repeat_is_dropped_and_said(tmp_path):
    ring = write(tmp_path, "ring.csv", "x,y\n" + "".join(f"{x},{y}\n" for x, y in SQUARE + [SQUARE[0]]))
    p = ok(["length", "--closed", str(ring)])
    want = run_json("length", {"points": SQUARE, "end": "closed"})["total"]
    # The same curve as the square without the repeat, exactly (same arithmetic).
    assert json.loads(p.stdout)["total"] == want
    assert abs(want - 4.2040) < 5e-4  # not 4.142, the length with a duplicated corner point
    assert p.stderr == (f"crspline: note: {ring}: line 6 (point 5): repeats the first point; a closed curve joins its "
                        "last point to the first by itself, so the repeat is dropped\n")
    # An open curve keeps every point, and says nothing.
    p = ok(["length", str(ring)])
    assert p.stderr == ""
    assert len(json.loads(p.stdout)["segments"]) == 4


# --- three or more numeric columns ------------------------------------------------------

TRACK = [(0.0, 0.0), (3.0, 4.0), (6.0, 0.0), (9.0, 4.0)]


@pytest.mark.parametrize("header,first,why", [
    (",x,y", lambda i: i, "the first column has no name (an index column?)"),
    ("t,x,y", lambda i: 10 * i, "the first column, 't', looks like an index or a parameter, not a coordinate"),
    ("id,x,y", lambda i: 7 - i, "the first column, 'id', looks like an index or a parameter, not a coordinate"),
])
def test_index_or_parameter_column_needs_columns(tmp_path, header, first, why):
    path = write(tmp_path, "track.csv", header + "\n" + "".join(f"{first(i)},{x},{y}\n" for i, (x, y) in enumerate(TRACK)))
    names = ", ".join(n or "(unnamed)" for n in header.split(","))
    check(run(["length", str(path)]),
          f"{path}: line 1: 3 numeric columns ({names}) would make a 3-D curve, but {why}; choose the coordinates "
          "with --columns (e.g. --columns x,y)")
    # With --columns the track is the 2-D curve, as JSON gives it.
    got = json.loads(ok(["length", "--columns", "x,y", str(path)]).stdout)
    assert got == run_json("length", {"points": [list(p) for p in TRACK]})


def test_headerless_counting_column_needs_columns(tmp_path):
    path = write(tmp_path, "idx.csv", "".join(f"{i},{x},{y}\n" for i, (x, y) in enumerate(TRACK)))
    check(run(["length", str(path)]),
          f"{path}: line 1: 3 numeric columns (column 1, column 2, column 3) would make a 3-D curve, but the first "
          "column counts 0, 1, 2, ... like an index; choose the coordinates with --columns (e.g. --columns 2,3)")


def test_three_columns_are_named_on_stderr_unless_named_like_coordinates(tmp_path):
    pts = [(0, 0, 0), (1, 2, 0.5), (3, 1, 1), (4, 4, 2)]
    body = "".join(f"{x},{y},{z}\n" for x, y, z in pts)
    bare = write(tmp_path, "bare.csv", body)
    p = ok(["length", str(bare)])
    assert p.stderr == f"crspline: note: {bare}: 3 columns read as a 3-D curve (column 1, column 2, column 3); choose others with --columns\n"
    assert json.loads(p.stdout) == run_json("length", {"points": [list(q) for q in pts]})
    named = write(tmp_path, "xyz.csv", "x,y,z\n" + body)
    assert ok(["length", str(named)]).stderr == ""


# --- errors about points name the file and the line ---------------------------------------

def test_strict_error_names_file_line_and_point(tmp_path):
    path = write(tmp_path, "dup.csv", "# a track\nx,y\n0,0\n# a comment\n1,1\n1,1\n2,0\n")
    check(run(["length", "--strict", str(path)]),
          f"{path}: line 5 (point 2) and line 6 (point 3): coincident consecutive points (strict mode): 1 and 2 "
          "(counted from 0)")
    doc = {"points": [[0, 0], [1, 1], [1, 1], [2, 0]], "strict": True}
    jpath = write(tmp_path, "dup.json", json.dumps(doc))
    check(run(["length", str(jpath)]),
          f"{jpath}: points[1] and points[2]: coincident consecutive points (strict mode): 1 and 2")


# --- empty input -------------------------------------------------------------------------

@pytest.mark.parametrize("name", ["empty.json", "empty.csv", "empty"])
def test_empty_stdin_and_empty_file_agree(tmp_path, name):
    path = write(tmp_path, name, "")
    from_file = run(["length", str(path)])
    from_stdin = run(["length"], "")
    check(from_file, f"{path}: the input is empty (a curve needs at least 2 points, got 0)")
    check(from_stdin, "<stdin>: the input is empty (a curve needs at least 2 points, got 0)")


# --- sample: count and tolerance are exclusive, as in JSON --------------------------------

def test_sample_count_and_tolerance_rejected_like_json(tmp_path):
    path = write(tmp_path, "p.csv", "0,0\n1,1\n2,0\n")
    check(run(["sample", "--count", "50", "--tolerance", "0.1", str(path)]),
          "--tolerance: give --count (number of points) or --tolerance (largest distance to the curve), not both")
    check(run(["sample", "-"], json.dumps({"points": [[0, 0], [1, 1], [2, 0]], "count": 50, "tolerance": 0.1})),
          "give 'count' (number of points) or 'tolerance' (largest distance to the curve), exactly one of them")


# --- tolerances and accuracies the coordinates cannot resolve -------------------------------

def floor(coords):
    # include/crspline/resolution.hpp: 64 ulps of the largest coordinate magnitude.
    return 64 * math.ulp(max(abs(c) for p in coords for c in p))


@pytest.mark.parametrize("scale,tolerance", [(1.0, "1e-16"), (1.0, "1e-300"), (1e6, "1e-12"), (1e-3, "1e-20")])
def test_tolerance_below_resolution_is_rejected_at_once(tmp_path, scale, tolerance):
    pts = [[0, 0], [scale, scale], [2 * scale, 0]]
    path = write(tmp_path, "p.json", json.dumps({"points": pts}))
    f = floor(pts)
    spacing = math.ulp(2 * scale)
    # The run's own 60 s timeout (cli_support.run) fails the test if it hangs.
    check(run(["sample", "--tolerance", tolerance, str(path)]),
          f"--tolerance: {float(tolerance)!r} is below what the coordinates resolve (their largest magnitude is "
          f"spaced {spacing!r} apart); the smallest meaningful tolerance for this input is {f!r}")


def test_tolerance_just_above_the_floor_is_accepted():
    # Collinear points: a straight curve, one piece at any tolerance.
    pts = [[0, 0], [1, 1], [2, 2]]
    f = floor(pts)
    assert run_json("sample", {"points": pts, "tolerance": f})["tolerance"] == f
    p = run(["sample", "-"], json.dumps({"points": pts, "tolerance": math.nextafter(f, 0)}))
    assert p.returncode == 2 and "smallest meaningful tolerance" in p.stderr, p.stderr


def test_accuracy_below_double_resolution_is_rejected(tmp_path):
    path = write(tmp_path, "p.csv", "0,0\n1,1\n2,0\n")
    smallest = 8 * 2.0 ** -52  # resolution.hpp: min_relative_accuracy, arc_length's own floor
    for command, extra in [("length", []), ("sample", ["--count", "5", "--spacing", "arc_length"]),
                           ("eval", ["--s", "0,1"])]:
        check(run([command, "--accuracy", "1e-300"] + extra + [str(path)]),
              f"--accuracy: 1e-300 is below what double arithmetic resolves; the smallest meaningful relative "
              f"accuracy is {smallest!r}")
    ok(["length", "--accuracy", repr(smallest), str(path)])
    check(run(["length", "-"], json.dumps({"points": [[0, 0], [1, 1]], "accuracy": 1e-16})),
          f"accuracy: 1e-16 is below what double arithmetic resolves; the smallest meaningful relative accuracy is "
          f"{smallest!r}")


# --- typos ------------------------------------------------------------------------------------

COMMANDS = "eval, bezier, length, sample, analyze, plot, demo"


def test_command_typo_suggests_the_nearest():
    check(run(["lenght", "p.csv"]),
          f"unknown command 'lenght' (did you mean 'length'?); the commands are {COMMANDS} (see 'crspline --help')")
    check(run(["evl"]), f"unknown command 'evl' (did you mean 'eval'?); the commands are {COMMANDS} (see 'crspline --help')")
    check(run(["frobnicate"]), f"unknown command 'frobnicate'; the commands are {COMMANDS} (see 'crspline --help')")


def test_option_typo_suggests_the_nearest_and_does_not_blame_the_input(tmp_path):
    path = write(tmp_path, "p.csv", "0,0\n1,1\n2,0\n")
    check(run(["length", "--aplha", "0.5", str(path)]),
          "unknown option --aplha for 'crspline length' (did you mean --alpha?); see 'crspline length --help'")
    check(run(["sample", str(path), "--tolerence=0.1"]),
          "unknown option --tolerence for 'crspline sample' (did you mean --tolerance?); see 'crspline sample --help'")
    # An option of another command is unknown here, with no near miss.
    check(run(["length", "--count", "5", str(path)]),
          "unknown option --count for 'crspline length'; see 'crspline length --help'")


# --- plot: optional values do not swallow or refuse the input --------------------------------

@pytest.mark.parametrize("flag,explicit", [("--comb", "--comb-scale"), ("--ticks", "--tick-step")])
def test_plot_optional_value_and_positional(tmp_path, flag, explicit):
    path = write(tmp_path, "p.csv", "0,0\n1,1\n2,0\n3,1\n")
    with_value = tmp_path / "a.svg"
    ok(["plot", flag, "0.5", str(path), "-o", str(with_value)])
    same = tmp_path / "b.svg"
    ok(["plot", explicit, "0.5", str(path), "-o", str(same)])
    assert with_value.read_bytes() == same.read_bytes()
    bare = tmp_path / "c.svg"
    ok(["plot", flag, str(path), "-o", str(bare)])
    assert bare.stat().st_size > 0
