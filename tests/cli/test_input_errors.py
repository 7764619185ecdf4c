"""Bad CSV, bad options, unreadable inputs and unwritable outputs: exit
status 2, one exact line on stderr naming the file, line and column (or the
option and index), nothing on stdout, and no file left behind."""
import os
import shutil
import stat
import subprocess

import pytest

from cli_support import binary, run

CSV = "x,y\n0,0\n1,2\n3,3\n4,1\n"


@pytest.fixture
def d(tmp_path):
    (tmp_path / "p.csv").write_text(CSV)
    return tmp_path


def check(p, line):
    assert p.returncode == 2, (p.returncode, p.stdout, p.stderr)
    assert p.stdout == "", p.stdout
    assert p.stderr == f"crspline: {line}\n", p.stderr


# (name, csv text, extra args, expected line with {f} for the file name)
CSV_CASES = [
    ("not a number", "x,y\n0,0\n1,abc\n", [], '{f}: line 3, column 3: expected a finite number, got "abc"'),
    ("nan", "0,0\n1,nan\n", [], '{f}: line 2, column 3: expected a finite number, got "nan"'),
    ("inf", "0,0\n-inf,1\n", [], '{f}: line 2, column 1: expected a finite number, got "-inf"'),
    ("overflow", "0,0\n1e999,1\n", [], '{f}: line 2, column 1: expected a finite number, got "1e999"'),
    ("empty field", "0,0\n1,\n", [], "{f}: line 2, column 3: expected a finite number, got an empty field"),
    ("too few fields", "x,y\n0,0\n1\n", [], "{f}: line 3, column 2: expected 2 fields like line 1, got 1"),
    ("too many fields", "0,0\n1,2,3\n", [], "{f}: line 2, column 5: expected 2 fields like line 1, got 3"),
    ("seventeen columns", ",".join(str(k) for k in range(17)) + "\n", [],
     "{f}: line 1, column 39: expected 1 to 16 columns, got 17 (choose some with --columns)"),
    ("one point", "# only one\n1,2\n", [], "{f}: a curve needs at least 2 points, got 1"),
    ("no points", "x,y\n", [], "{f}: a curve needs at least 2 points, got 0"),
    ("unknown column", CSV, ["--columns", "x,z"], "--columns: no column named 'z' in the header of {f} (columns: x, y)"),
    ("column number too big", CSV, ["--columns", "1,3"],
     "--columns: column 3 does not exist: line 1 of {f} has 2 fields (columns are numbered from 1)"),
    ("name without header", "0,0\n1,1\n", ["--columns", "x"],
     "--columns: 'x' is not a column number, and {f} has no header line to name columns"),
    # The first line reads as a header (no field is a number), the second fails.
    ("tab data, comma delimiter", "0\t0\n1\t1\n", ["--delimiter", ","],
     '{f}: line 2, column 1: expected a finite number, got "1\t1"'),
]


@pytest.mark.parametrize("name,text,args,line", CSV_CASES, ids=[c[0] for c in CSV_CASES])
def test_csv_errors(d, name, text, args, line):
    path = d / "in.csv"
    path.write_text(text)
    check(run(["bezier"] + args + [str(path)]), line.format(f=path))


OPTION_CASES = [
    (["bezier", "--alpha", "1.5"], "--alpha: alpha must be in [0, 1], got 1.5"),
    (["bezier", "--alpha", "abc"], '--alpha: expected a finite number, got "abc"'),
    (["bezier", "--uniform", "--chordal"],
     "--alpha: give one of --alpha, --uniform, --centripetal, --chordal (several are for 'crspline plot')"),
    (["bezier", "--grid", "0,1,2"], "--grid: grid has 3 values, expected 4 (one per point)"),
    (["bezier", "--grid", "0,1,1,2"], "--grid: grid must be strictly increasing: grid[2] = 1 is not greater than grid[1] = 1"),
    (["bezier", "--grid", "0,1,2,3", "--alpha", "0"],
     "--grid: give --grid or an alpha (--alpha, --uniform, --centripetal, --chordal), not both"),
    (["bezier", "--start", "clamped"], "--start: start condition must be 'natural', 'reflect' or a tangent, got 'clamped'"),
    (["bezier", "--end", "1,2,3"], "--end: end tangent has 3 coordinates, expected 2 like the points"),
    (["bezier", "--closed", "--start", "natural"], "--closed: a closed curve has no end conditions (--start, --end)"),
    (["bezier", "--tension", "2"], "--tension: tension must be in [0, 1], got 2"),
    (["bezier", "--kb-bias", "0,1"], "--kb-bias: kb bias has 2 values, expected one per point (4)"),
    (["bezier", "--kb-tension", "0,null,0,0"],
     "--kb-tension: kb tension[1] is not finite (nan) (null is allowed only at the two end vertices of an open curve)"),
    (["eval", "--uniform", "--t", "0,99"], "--t[1]: t = 99 is outside the domain [0, 3]"),
    (["eval", "--t", "0", "--derivatives", "0,5"], "--derivatives[1]: expected 0, 1, 2 or 3, got 5"),
    (["eval"], "missing option --t (the parameter values to evaluate at) or --s (arc lengths)"),
    (["sample", "--count", "1"], "--count: expected an integer >= 2, got 1"),
    (["sample", "--count", "5", "--spacing", "chord"], '--spacing: expected "t" or "arc_length", got "chord"'),
    (["length", "--accuracy", "2"], "--accuracy: expected a relative accuracy in (0, 1), got 2"),
    (["bezier", "--format", "png"], "--format: expected one of json, csv, tsv, svg, svg-path for 'crspline bezier', got 'png'"),
    (["length", "--format", "svg"], "--format: expected one of json, csv, tsv for 'crspline length', got 'svg'"),
    (["bezier", "--delimiter", "x"], "--delimiter: expected ',', ';', '|', ':', 'tab' or 'space', got 'x'"),
    (["bezier", "--input-format", "xml"], "--input-format: expected json, csv, tsv or svg, got 'xml'"),
    (["plot", "--size", "big"], "--size: expected WIDTHxHEIGHT in pixels, 200x150 to 10000x10000, got 'big'"),
    (["plot", "--alpha", "0,2"], "--alpha[1]: alpha must be in [0, 1], got 2"),
    (["plot", "--comb-scale", "-1"], "--comb-scale: expected a number > 0, got '-1'"),
    (["bezier", "--alpha"], "--alpha: 1 required TEXT missing (see 'crspline --help')"),
]


@pytest.mark.parametrize("args,line", OPTION_CASES, ids=[" ".join(c[0]) for c in OPTION_CASES])
def test_option_errors(d, args, line):
    check(run(args[:1] + [str(d / "p.csv")] + args[1:]), line)


def test_grid_file_errors(d):
    bad = d / "grid.txt"
    bad.write_text("0\n1\nx\n")
    check(run(["bezier", "--grid", str(bad), str(d / "p.csv")]),
          f'{bad}: line 3, column 1: expected a finite number, got "x"')
    missing = d / "nope.txt"
    check(run(["bezier", "--grid", str(missing), str(d / "p.csv")]),
          f"--grid: '{missing}' is neither a list of numbers (like 0,1,2.5) nor a readable file "
          "(cannot open: No such file or directory)")


def test_json_with_csv_options(d):
    path = d / "p.json"
    path.write_text('{"points": [[0, 0], [1, 1]]}')
    check(run(["bezier", "--columns", "1,2", str(path)]), f"--columns: only for CSV input, and {path} is read as JSON")


def test_missing_and_unreadable_input(d):
    check(run(["bezier", str(d / "missing.csv")]), f"{d / 'missing.csv'}: cannot open: No such file or directory")
    # A directory opens but cannot be read.
    check(run(["bezier", str(d)]), f"{d}: cannot read: Is a directory")
    # A file with mode 0. Root reads anything through CAP_DAC_OVERRIDE and
    # CAP_DAC_READ_SEARCH, and `./run test` runs as root: there the binary
    # runs under setpriv with those two capabilities dropped, so the check
    # runs either way.
    path = d / "secret.csv"
    path.write_text(CSV)
    path.chmod(0)
    prefix = []
    if os.getuid() == 0:
        assert shutil.which("setpriv"), "setpriv (util-linux) is needed to drop root's read capabilities"
        drop = "-dac_override,-dac_read_search"
        prefix = ["setpriv", "--bounding-set", drop, "--inh-caps", drop]
    p = subprocess.run(prefix + [binary(), "bezier", str(path)], capture_output=True, text=True, timeout=60)
    check(p, f"{path}: cannot open: Permission denied")


def test_unwritable_outputs_leave_nothing(d):
    src = str(d / "p.csv")
    check(run(["bezier", src, "-o", str(d / "no" / "such" / "dir.json")]),
          f"{d / 'no' / 'such' / 'dir.json'}: cannot write: No such file or directory")
    os.mkdir(d / "adir")
    check(run(["bezier", src, "-o", str(d / "adir")]), f"{d / 'adir'}: cannot write: Is a directory")
    check(run(["bezier", src, "-o", str(d / "out.xyz")]),
          f"--output: cannot tell the format from the extension '.xyz' of {d / 'out.xyz'} ('crspline bezier' writes "
          "json, csv, tsv, svg, svg-path; choose one with --format)")
    # A failure after parsing (strict mode) leaves no output file either.
    (d / "dup.csv").write_text("0,0\n1,1\n1,1\n2,0\n")
    check(run(["bezier", "--strict", str(d / "dup.csv"), "-o", str(d / "x.json")]),
          f"{d / 'dup.csv'}: line 2 (point 2) and line 3 (point 3): coincident consecutive points (strict mode): "
          "1 and 2 (counted from 0)")
    check(run(["bezier", "--format", "svg", "--columns", "1", src, "-o", str(d / "x.svg")]),
          "--format svg: needs 2-D points, got 1-D (use json or csv)")
    check(run(["plot", "--columns", "1", src, "-o", str(d / "x.png")]), "plot: needs 2 or more coordinates per point, got 1 (choose two with --columns)")
    check(run(["demo", "-o", str(d / "p.csv")]), f"{d / 'p.csv'}: cannot create the folder: Not a directory")
    assert sorted(os.listdir(d)) == ["adir", "dup.csv", "p.csv"]
    assert os.listdir(d / "adir") == []


@pytest.mark.parametrize("command", ["eval", "bezier", "length", "sample", "analyze", "plot", "demo"])
def test_help_of_every_subcommand(command):
    p = run([command, "--help"])
    assert p.returncode == 0 and p.stderr == ""
    assert "Example" in p.stdout and f"crspline {command}" in p.stdout
