"""Input formats (JSON, CSV, TSV, stdin, columns by name or number), options
that set every curve parameter, and output formats (JSON, CSV, TSV, SVG,
SVG path data, chosen by --format or by the extension of -o). An SVG is
parsed back: its path's segments equal `crspline bezier`."""
import csv
import io
import json
import os
import re
import xml.etree.ElementTree as ET

import pytest

from cli_support import run, run_json

P5 = [[0, 0], [1, 2], [3, 2.5], [4, 0.5], [6, 1]]
CSV = "x,y\n" + "".join(f"{x},{y}\n" for x, y in P5)


def ok(args, stdin=""):
    p = run(args, stdin)
    assert p.returncode == 0, p.stderr
    assert p.stderr == ""
    return p.stdout


@pytest.fixture
def files(tmp_path):
    (tmp_path / "p.csv").write_text(CSV)
    (tmp_path / "p.tsv").write_text(CSV.replace(",", "\t"))
    (tmp_path / "p.json").write_text(json.dumps({"points": P5}))
    (tmp_path / "wide.txt").write_text("# id t x y\n" + "".join(f"{i} {i * 0.5} {x} {y}\n" for i, (x, y) in enumerate(P5)))
    (tmp_path / "semi.dat").write_text("\n".join(f"{x};{y}" for x, y in P5) + "\n")
    return tmp_path


def test_every_input_format_gives_the_same_curve(files):
    want = run_json("bezier", {"points": P5})
    outs = [ok(["bezier", str(files / "p.csv")]), ok(["bezier", str(files / "p.tsv")]),
            ok(["bezier", str(files / "p.json")]), ok(["bezier", "--columns", "3,4", str(files / "wide.txt")]),
            ok(["bezier", str(files / "semi.dat")]), ok(["bezier", "-"], CSV), ok(["bezier"], CSV),
            ok(["bezier", "--input-format", "csv", "--delimiter", "tab", "-"], CSV.replace(",", "\t"))]
    for out in outs:
        assert json.loads(out) == want


def test_columns_by_name_and_comments(files):
    path = files / "named.csv"
    path.write_text("# a comment\n\nid,b,a\n# another\n" + "".join(f"{i},{y},{x}\n" for i, (x, y) in enumerate(P5)))
    assert json.loads(ok(["bezier", "--columns", "a,b", str(path)])) == run_json("bezier", {"points": P5})
    # One column: a 1-D curve; four columns: 4-D.
    one = json.loads(ok(["bezier", "--columns", "a", str(path)]))
    assert one["segments"][0][0] == [P5[0][0]]
    four = json.loads(ok(["bezier", "--columns", "a,b,id,a", str(path)]))
    assert len(four["segments"][0][0]) == 4


def test_options_match_json_fields(files):
    """Each curve option gives what the JSON field gives."""
    cases = [
        (["--alpha", "0.25"], {"alpha": 0.25}),
        (["--uniform"], {"alpha": 0}),
        (["--centripetal"], {"alpha": 0.5}),
        (["--chordal"], {"alpha": 1}),
        (["--grid", "0,1,3,4,7"], {"grid": [0, 1, 3, 4, 7]}),
        (["--closed"], {"end": "closed"}),
        (["--start", "reflect", "--end", "1,-1"], {"end": {"start": "reflect", "end": [1, -1]}}),
        (["--start=-1,0.5"], {"end": {"start": [-1, 0.5]}}),
        (["--tension", "0.3"], {"tension": 0.3}),
        (["--kb-tension", "null,0.5,0,-0.5,null", "--kb-bias", "0,0.2,0.2,0.2,0", "--kb-continuity", "0,1,0,0,0"],
         {"kb": {"tension": [None, 0.5, 0, -0.5, None], "bias": [0, 0.2, 0.2, 0.2, 0], "continuity": [0, 1, 0, 0, 0]}}),
        (["--strict"], {"strict": True}),
    ]
    for args, fields in cases:
        got = json.loads(ok(["bezier"] + args + [str(files / "p.csv")]))
        assert got == run_json("bezier", dict({"points": P5}, **fields)), args


def test_options_override_json_fields(files):
    path = files / "c.json"
    path.write_text(json.dumps({"points": P5, "alpha": 1, "end": "reflect", "t": [0, 1]}))
    got = json.loads(ok(["eval", "--uniform", "--start", "natural", "--t", "0.5,2", str(path)]))
    path.write_text(json.dumps({"points": P5, "alpha": 1, "end": "reflect"}))
    want = run_json("eval", {"points": P5, "alpha": 0, "end": {"start": "natural", "end": "reflect"}, "t": [0.5, 2]})
    assert got == want
    want_b = run_json("bezier", {"points": P5, "alpha": 1, "end": {"start": "natural", "end": "reflect"}})
    assert json.loads(ok(["bezier", "--start", "natural", str(path)])) == want_b
    # --grid replaces the JSON alpha; a grid file works like a list.
    (files / "grid.txt").write_text("# knots\n0\n1\n2.5\n3\n4\n")
    got = json.loads(ok(["bezier", "--grid", str(files / "grid.txt"), str(path)]))
    assert got["grid"] == [0, 1, 2.5, 3, 4]


def test_subcommand_options(files):
    src = str(files / "p.csv")
    e = json.loads(ok(["eval", "--t", "0,1.5", "--derivatives", "1,0", src]))
    assert e == run_json("eval", {"points": P5, "t": [0, 1.5], "derivatives": [1, 0]})
    e = json.loads(ok(["eval", "--s", "0,1", "--accuracy", "1e-9", src]))
    assert e == run_json("eval", {"points": P5, "s": [0, 1], "accuracy": 1e-9})
    s = json.loads(ok(["sample", "--count", "7", "--spacing", "arc_length", src]))
    assert s == run_json("sample", {"points": P5, "count": 7, "spacing": "arc_length"})
    s = json.loads(ok(["sample", "--tolerance", "0.01", src]))
    assert s == run_json("sample", {"points": P5, "tolerance": 0.01})
    l = json.loads(ok(["length", "--accuracy", "1e-6", src]))
    assert l == run_json("length", {"points": P5, "accuracy": 1e-6})


def rows(text, delimiter=","):
    return list(csv.reader(io.StringIO(text), delimiter=delimiter))


def test_csv_and_tsv_outputs(files):
    src = str(files / "p.csv")
    e = run_json("eval", {"points": P5, "t": [0, 0.7, 2], "derivatives": [0, 2]})
    r = rows(ok(["eval", "--t", "0,0.7,2", "--derivatives", "0,2", "--format", "csv", src]))
    assert r[0] == ["t", "x", "y", "d2x", "d2y"]
    assert [[float(x) for x in row] for row in r[1:]] == [[t] + p + d for t, p, d in
                                                        zip([0, 0.7, 2], e["values"]["0"], e["values"]["2"])]
    b = run_json("bezier", {"points": P5})
    r = rows(ok(["bezier", "--format", "tsv", src]), "\t")
    assert r[0][:5] == ["segment", "t0", "t1", "b0_x", "b0_y"] and len(r) == 1 + len(b["segments"])
    assert [float(x) for x in r[2][3:]] == [c for p in b["segments"][1] for c in p]
    l = run_json("length", {"points": P5})
    r = rows(ok(["length", "--format", "csv", src]))
    assert r[-1] == ["total", repr(l["total"])] and [float(row[1]) for row in r[1:-1]] == l["segments"]
    s = run_json("sample", {"points": P5, "count": 4, "spacing": "arc_length"})
    r = rows(ok(["sample", "--count", "4", "--spacing", "arc_length", "--format", "csv", src]))
    assert r[0] == ["t", "s", "x", "y"] and [float(x) for x in r[2]] == [s["t"][1], s["s"][1]] + s["points"][1]


def test_format_from_extension_and_atomic_write(files):
    src = str(files / "p.csv")
    for ext, check in [(".json", json.loads), (".csv", rows), (".tsv", rows), (".svg", ET.fromstring)]:
        out = files / ("out" + ext)
        assert ok(["bezier", src, "-o", str(out)]) == ""
        check(out.read_text())
    # No temporary file is left behind next to the outputs.
    assert sorted(os.listdir(files)) == sorted(["p.csv", "p.tsv", "p.json", "wide.txt", "semi.dat",
                                                "out.json", "out.csv", "out.tsv", "out.svg"])


NUM = r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?"


def parse_path(d):
    """Segments [[B0, B1, B2, B3], ...] of an 'M x y C ... C ...' path."""
    tokens = re.findall(r"[MC]|" + NUM, d)
    assert tokens[0] == "M"
    start = [float(tokens[1]), float(tokens[2])]
    segs, i = [], 3
    while i < len(tokens):
        assert tokens[i] == "C", tokens[i]
        pts = [[float(tokens[i + 1 + 2 * k]), float(tokens[i + 2 + 2 * k])] for k in range(3)]
        segs.append([start] + pts)
        start = pts[2]
        i += 7
    return segs


@pytest.mark.parametrize("fields", [{}, {"alpha": 0}, {"alpha": 1, "end": "closed"}, {"tension": 0.5}])
def test_svg_path_equals_bezier(files, fields):
    doc = dict({"points": [[1e-3, 7], [1.25, -3e5], [123.456, 0.1], [2, 2]]}, **fields)
    b = run_json("bezier", doc)["segments"]
    svg = ok(["bezier", "--format", "svg"], json.dumps(doc))
    root = ET.fromstring(svg)
    ns = {"s": "http://www.w3.org/2000/svg"}
    paths = root.findall(".//s:path[@id='curve']", ns)
    assert len(paths) == 1
    assert parse_path(paths[0].get("d")) == b  # exactly: shortest round-trip numbers
    assert parse_path(ok(["bezier", "--format", "svg-path"], json.dumps(doc)).strip()) == b
    poly = root.find(".//s:polyline[@id='control-polygon']", ns).get("points").split()
    assert len(poly) == len(b) + 1


def test_svg_of_eval_and_sample_marks_the_points(files):
    src = str(files / "p.csv")
    svg = ET.fromstring(ok(["sample", "--count", "9", "--format", "svg", src]))
    circles = svg.findall(".//{http://www.w3.org/2000/svg}circle")
    assert len(circles) == 9
    svg = ET.fromstring(ok(["eval", "--t", "0,1", "-o", "-", "--format", "svg", src]))
    assert len(svg.findall(".//{http://www.w3.org/2000/svg}circle")) == 2


def test_ten_to_the_six_csv_points_load(tmp_path):
    """10^6 points load and give a curve (time is measured, never asserted)."""
    n = 10 ** 6
    path = tmp_path / "big.csv"
    with open(path, "w") as f:
        f.write("x,y\n")
        f.writelines(f"{i * 0.001},{(i * 7919) % 1000 * 0.001}\n" for i in range(n))
    out = json.loads(ok(["length", "--uniform", str(path)]))
    assert len(out["segments"]) == n - 1 and out["total"] > 0
    out = json.loads(ok(["eval", "--uniform", "--t", f"0,{n - 1}", str(path)]))
    assert out["values"]["0"] == [[0, 0], [(n - 1) * 0.001, ((n - 1) * 7919) % 1000 * 0.001]]


def test_big_json_points_fast_path_agrees_with_tree():
    # The flat reader and the tree agree (well-formed points, then a bad one at the end).
    pts = [[i, (i * 37) % 11] for i in range(2000)]
    assert run_json("length", {"points": pts})["segments"][5] > 0
    p = run(["bezier"], json.dumps({"points": pts + [[1, "x"]]}))
    assert p.returncode == 2 and p.stderr == 'crspline: points[2000][1]: expected a finite number, got "x"\n'
    p = run(["bezier"], json.dumps({"points": pts + [[1, 2, 3]]}))
    assert p.stderr == "crspline: points[2000]: expected 2 coordinates like points[0], got 3\n"
