"""Many curves in one run (issue 20): a JSON list of curve objects, GeoJSON
(LineString, Polygon rings, Multi*, FeatureCollection with properties),
SVG path data with several subpaths, CSV with a curve-id column or
blank-line-separated blocks. Results come per curve in input order, each the
same as the one-curve run gives; errors name the curve. The corpus test runs
a few hundred generated closed polygons through one process."""
import json
import math
import random

import pytest

from cli_support import run, run_json

SEED = 20261124


def ok(args, stdin=""):
    p = run(args, stdin)
    assert p.returncode == 0, p.stderr
    return p


def check(p, line):
    assert p.returncode == 2, (p.returncode, p.stdout, p.stderr)
    assert p.stdout == "", p.stdout
    assert p.stderr == f"crspline: {line}\n", p.stderr


def polygon(rng, n):
    """A star-shaped closed polygon: n vertices at increasing angles."""
    # Latitudes (y) within +-80: GeoJSON is WGS 84, and `length` refuses |lat| > 90 (issue 29).
    cx, cy, r = rng.uniform(-100, 100), rng.uniform(-60, 60), rng.uniform(1, 20)
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    return [[cx + r * rng.uniform(0.5, 1.0) * math.cos(a), cy + r * rng.uniform(0.5, 1.0) * math.sin(a)] for a in angles]


def test_geojson_polygon_corpus_matches_one_curve_runs(tmp_path):
    """300 generated polygons as a FeatureCollection through one `length` and
    one `bezier` process: every result equals the one-curve run on the ring
    without its repeated first point, exactly (the same arithmetic)."""
    rng = random.Random(SEED)
    rings = [polygon(rng, rng.randint(3, 12)) for _ in range(300)]
    features = [{"type": "Feature", "id": f"p{i}", "properties": {"name": f"polygon {i}", "n": len(r)},
                 "geometry": {"type": "Polygon", "coordinates": [r + [r[0]]]}} for i, r in enumerate(rings)]
    path = tmp_path / "polygons.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    for command in ["length", "bezier"]:
        got = json.loads(ok([command, str(path)]).stdout)
        assert len(got) == len(rings), f"seed {SEED}"
        for i, (item, ring) in enumerate(zip(got, rings)):
            assert item["id"] == f"p{i}" and item["properties"] == {"name": f"polygon {i}", "n": len(ring)}
            want = run_json(command, {"points": ring, "end": "closed"})
            if command == "length":  # issue 29: GeoJSON lengths are metres; the ring alone as GeoJSON
                want = run_json(command, {"type": "Polygon", "coordinates": [ring + [ring[0]]]})[0]["result"]
                assert want["unit"] == "m"
            assert item["result"] == want, f"seed {SEED}, polygon {i}"


def test_geojson_multi_forms_and_holes(tmp_path):
    a = [[0, 0], [4, 0], [4, 4], [0, 4]]
    hole = [[1, 1], [2, 1], [2, 2], [1, 2]]
    line = [[0, 0], [1, 2], [3, 1]]
    geo = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"k": 1},
         "geometry": {"type": "MultiPolygon", "coordinates": [[a + [a[0]], hole + [hole[0]]], [a + [a[0]]]]}},
        {"type": "Feature", "properties": None, "geometry": {"type": "MultiLineString", "coordinates": [line, line[::-1]]}},
        {"type": "Feature", "properties": {}, "geometry": {"type": "LineString", "coordinates": line}},
    ]}
    got = json.loads(ok(["length", "-"], json.dumps(geo)).stdout)
    assert [g["id"] for g in got] == ["features[0] polygon 0 ring 0", "features[0] polygon 0 ring 1",
                                      "features[0] polygon 1", "features[1] part 0", "features[1] part 1", "features[2]"]
    closed = [{"points": a, "end": "closed"}, {"points": hole, "end": "closed"}, {"points": a, "end": "closed"}]
    opened = [{"points": line}, {"points": line[::-1]}, {"points": line}]
    for item, doc in zip(got, closed + opened):
        # Issue 29: GeoJSON lengths are geodesic metres: the same curve alone as GeoJSON.
        pts = doc["points"]
        alone = ({"type": "Polygon", "coordinates": [pts + [pts[0]]]} if doc.get("end") == "closed"
                 else {"type": "LineString", "coordinates": pts})
        assert item["result"]["unit"] == "m"
        assert item["result"] == run_json("length", alone)[0]["result"]
    assert got[0]["properties"] == {"k": 1} and "properties" not in got[3]


def test_json_list_of_curves_with_ids_and_options():
    curves = [{"id": "a", "points": [[0, 0], [1, 1], [2, 0]], "alpha": 0},
              {"points": [[0, 0], [3, 4], [6, 0], [9, 4]], "end": "closed", "properties": {"colour": "red"}},
              {"id": 7, "points": [[0], [1], [3]]}]
    got = json.loads(ok(["length", "-"], json.dumps(curves)).stdout)
    assert [g["id"] for g in got] == ["a", "[1]", "7"]
    assert got[1]["properties"] == {"colour": "red"}
    for item, c in zip(got, curves):
        c = {k: v for k, v in c.items() if k not in ("id", "properties")}
        assert item["result"] == run_json("length", c)
    # A flag applies to every curve.
    got = json.loads(ok(["length", "--chordal", "-"], json.dumps(curves)).stdout)
    for item, c in zip(got, curves):
        c = {k: v for k, v in c.items() if k not in ("id", "properties")}
        assert item["result"] == run_json("length", dict(c, alpha=1))


def test_errors_name_the_curve(tmp_path):
    curves = [{"id": "good", "points": [[0, 0], [1, 1]]}, {"id": "bad", "points": [[0, 0], [1, 1]], "alpha": 3}]
    check(run(["length", "-"], json.dumps(curves)), "<stdin>: curve bad: alpha must be in [0, 1], got 3")
    path = tmp_path / "dup.csv"
    path.write_text("id,x,y\nA,0,0\nA,1,1\nB,0,0\nB,1,1\nB,1,1\nB,2,0\n")
    check(run(["length", "--strict", "--curve-column", "id", str(path)]),
          f"{path}: curve B: line 5 (point 2) and line 6 (point 3): coincident consecutive points (strict mode): "
          "1 and 2 (counted from 0)")
    path.write_text("id,x,y\nA,0,0\nA,1,1\nB,0,0\nB,1,1\nA,2,0\n")
    check(run(["length", "--curve-column", "id", str(path)]),
          f"{path}: line 6, column 1: curve 'A' again after other curves (the rows of a curve must be consecutive)")


def test_csv_blocks_and_curve_column(tmp_path):
    a = [[0, 0], [1, 2], [3, 1]]
    b = [[5, 5], [6, 7], [8, 5], [9, 9]]
    blocks = tmp_path / "blocks.csv"
    blocks.write_text("x,y\n" + "".join(f"{x},{y}\n" for x, y in a) + "\n\n" + "".join(f"{x},{y}\n" for x, y in b) + "\n")
    got = json.loads(ok(["bezier", str(blocks)]).stdout)
    assert [g["id"] for g in got] == ["block 1 (line 2)", "block 2 (line 7)"]
    assert [g["result"] for g in got] == [run_json("bezier", {"points": a}), run_json("bezier", {"points": b})]
    ids = tmp_path / "ids.csv"
    ids.write_text("name,x,y\n" + "".join(f"first,{x},{y}\n" for x, y in a) + "".join(f"second,{x},{y}\n" for x, y in b))
    table = ok(["length", "--curve-column", "name", "--format", "csv", str(ids)]).stdout.splitlines()
    one_a = ok(["length", "--format", "csv", "-"], json.dumps({"points": a})).stdout.splitlines()
    one_b = ok(["length", "--format", "csv", "-"], json.dumps({"points": b})).stdout.splitlines()
    assert table == (["curve," + one_a[0]] + ["first," + r for r in one_a[1:]] + ["second," + r for r in one_b[1:]])


def test_svg_path_subpaths(tmp_path):
    svg = tmp_path / "shapes.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg">\n'
                   '  <path id="square" d="M 0 0 L 1 0 L 1 1 L 0 1 Z"/>\n'
                   '  <path d="M10,10 l 1,2 c 0,1 1,1 2,0 h 1 v -2 M 20 20 Q 21 21 22 20 T 24 20 z"/>\n'
                   '</svg>\n')
    got = json.loads(ok(["length", str(svg)]).stdout)
    assert [g["id"] for g in got] == ["square", "path 2 subpath 1", "path 2 subpath 2"]
    want = [{"points": [[0, 0], [1, 0], [1, 1], [0, 1]], "end": "closed"},
            {"points": [[10, 10], [11, 12], [13, 12], [14, 12], [14, 10]]},
            {"points": [[20, 20], [22, 20], [24, 20]], "end": "closed"}]
    assert [g["result"] for g in got] == [run_json("length", w) for w in want]
    # The square's length is the closed curve's 4.204, not 4.142 with the repeat.
    assert abs(got[0]["result"]["total"] - 4.2040) < 5e-4
    # Bare path data from stdin; svg-path output: one line per curve.
    out = ok(["bezier", "--format", "svg-path", "-"], "M 0 0 L 1 1 L 2 0 M 5 5 L 6 6 L 7 5").stdout.splitlines()
    assert out == [ok(["bezier", "--format", "svg-path", "-"], json.dumps({"points": p})).stdout.strip()
                   for p in ([[0, 0], [1, 1], [2, 0]], [[5, 5], [6, 6], [7, 5]])]
    check(run(["length", "-"], "M 0 0 L 1 x"), "<stdin>: line 1: path data: expected a finite number")
