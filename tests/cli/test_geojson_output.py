"""`--format geojson` on inputs that hold many curves (issue 31, point 1),
and a figure of a many-curve input that holds one (point 2).

Many curves in give one FeatureCollection out: a GeoJSON input comes back
as itself, each curve's positions replaced by its polyline where they were
(ids, properties and the structure: a Polygon stays a Polygon with its
holes, Multi* geometries keep their parts); a JSON list, SVG paths or CSV
blocks give one Feature (a LineString) per curve. The output is parsed with
json, its features, geometries and rings counted against the input's, and
each polyline compared with the one-curve run on the same curve. Before the
fix the output was a CSV header glued to the first Feature, exit 0."""
import json
import math
import random

import pytest

from cli_support import run

TOLERANCE = "0.05"


def ok(args, stdin=""):
    p = run(args, stdin)
    assert p.returncode == 0, p.stderr
    return p


def ring(rng, cx, cy, r, n):
    """A closed GeoJSON ring: n star-shaped vertices, the first repeated at the end."""
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    pts = [[cx + r * rng.uniform(0.6, 1.0) * math.cos(a), cy + r * rng.uniform(0.6, 1.0) * math.sin(a)]
           for a in angles]
    return pts + [list(pts[0])]


def line(rng, n, x0=0.0):
    return [[x0 + i + rng.uniform(-0.3, 0.3), rng.uniform(-2, 2)] for i in range(n)]


def collection(rng):
    """A FeatureCollection of every geometry that holds curves, with ids of
    both kinds, properties, a bbox (which the output drops: it no longer
    bounds the polylines) and a foreign member (kept)."""
    features = [
        {"type": "Feature", "id": "road", "properties": {"name": "A1", "lanes": 2},
         "bbox": [0, -2, 5, 2], "geometry": {"type": "LineString", "coordinates": line(rng, 6)}},
        {"type": "Feature", "id": 7, "properties": {"name": "lake"},
         "geometry": {"type": "Polygon", "coordinates": [ring(rng, 0, 0, 10, 9), ring(rng, 1, 1, 2, 6)]}},
        {"type": "Feature", "properties": None,
         "geometry": {"type": "MultiLineString", "coordinates": [line(rng, 4), line(rng, 5, 10.0)]}},
        {"type": "Feature", "id": "islands", "properties": {"count": 2},
         "geometry": {"type": "MultiPolygon", "coordinates": [
             [ring(rng, 30, 0, 5, 7), ring(rng, 30, 0, 1, 5)],
             [ring(rng, 50, 0, 4, 8)]]}},
        {"type": "Feature", "id": "mixed", "properties": {"k": "v"},
         "geometry": {"type": "GeometryCollection", "geometries": [
             {"type": "LineString", "coordinates": line(rng, 3, 70.0)},
             {"type": "Polygon", "coordinates": [ring(rng, 80, 0, 3, 6)]}]}},
    ]
    return {"type": "FeatureCollection", "name": "test layer", "features": features}


def curves_of(geometry):
    """(positions, is_ring) of every curve of a geometry, in input order."""
    t, c = geometry["type"], geometry.get("coordinates")
    if t == "LineString":
        return [(c, False)]
    if t == "MultiLineString":
        return [(p, False) for p in c]
    if t == "Polygon":
        return [(r, True) for r in c]
    if t == "MultiPolygon":
        return [(r, True) for poly in c for r in poly]
    assert t == "GeometryCollection", t
    return [x for g in geometry["geometries"] for x in curves_of(g)]


def shape_of(geometry):
    """The geometry's structure without coordinates: types and part/ring counts."""
    t = geometry["type"]
    if t == "GeometryCollection":
        return [t, [shape_of(g) for g in geometry["geometries"]]]
    c = geometry["coordinates"]
    if t == "Polygon" or t == "MultiLineString":
        return [t, len(c)]
    if t == "MultiPolygon":
        return [t, [len(p) for p in c]]
    return [t]


def one_curve_sample(positions, is_ring):
    """The polyline of the one-curve run: the ring without its repeat, closed."""
    doc = {"points": positions[:-1] if is_ring else positions, "tolerance": float(TOLERANCE)}
    if is_ring:
        doc["closed"] = True
    return json.loads(ok(["sample", "-"], json.dumps(doc)).stdout)["points"]


def test_feature_collection_comes_back_whole(tmp_path, seed):
    rng = random.Random(seed)
    fc = collection(rng)
    path = tmp_path / "map.geojson"
    path.write_text(json.dumps(fc))
    p = ok(["sample", "--tolerance", TOLERANCE, "--format", "geojson", str(path)])
    out = json.loads(p.stdout)
    assert out["type"] == "FeatureCollection" and out["name"] == "test layer"
    assert len(out["features"]) == len(fc["features"]) == 5
    checked = 0
    for f_in, f_out in zip(fc["features"], out["features"]):
        assert f_out["type"] == "Feature"
        assert f_out.get("id") == f_in.get("id") and type(f_out.get("id")) is type(f_in.get("id"))
        assert f_out["properties"] == f_in["properties"]
        assert "bbox" not in f_out
        assert shape_of(f_out["geometry"]) == shape_of(f_in["geometry"])
        for (pos_in, is_ring), (pos_out, _) in zip(curves_of(f_in["geometry"]), curves_of(f_out["geometry"])):
            want = one_curve_sample(pos_in, is_ring)
            if is_ring:
                # RFC 7946: a ring's last position is its first, exactly.
                assert pos_out[-1] == pos_out[0] and len(pos_out) >= 4
                # The one-curve run ends on the first point to rounding
                # (it evaluates the closed curve at t_max); 1e-12 of the
                # coordinates' size (at most 100 here) is far above that
                # rounding and far below the sampling tolerance.
                assert max(abs(a - b) for a, b in zip(want[-1], pos_out[-1])) <= 1e-10
                assert pos_out[:-1] == want[:-1]
            else:
                assert pos_out == want
            checked += 1
    # 1 + 2 + 2 + 3 + 2 curves: none lost.
    assert checked == 10
    # -o FILE writes the same text, and it is valid JSON.
    target = tmp_path / "out.geojson"
    ok(["sample", "--tolerance", TOLERANCE, str(path), "-o", str(target)])
    assert target.read_text() == p.stdout
    assert json.loads(target.read_text()) == out


def test_one_feature_and_a_bare_polygon_become_a_collection(seed):
    rng = random.Random(seed)
    polygon = {"type": "Polygon", "coordinates": [ring(rng, 0, 0, 5, 7), ring(rng, 0, 0, 1, 5)]}
    feature = {"type": "Feature", "id": "only", "properties": {"a": 1}, "geometry": polygon}
    for given in (feature, polygon):
        out = json.loads(ok(["sample", "--count", "9", "--format", "geojson", "-"], json.dumps(given)).stdout)
        assert out["type"] == "FeatureCollection" and len(out["features"]) == 1
        f = out["features"][0]
        assert f["geometry"]["type"] == "Polygon" and len(f["geometry"]["coordinates"]) == 2
        assert all(len(r) == 9 and r[0] == r[-1] for r in f["geometry"]["coordinates"])
        assert f["properties"] == (given.get("properties"))
        assert f.get("id") == given.get("id")


def test_a_json_list_gives_a_feature_per_curve(seed):
    rng = random.Random(seed)
    items = [{"id": "a", "points": line(rng, 5), "properties": {"n": 1}},
             {"id": 3, "points": line(rng, 4)},
             {"points": ring(rng, 0, 0, 3, 6)[:-1], "closed": True}]
    out = json.loads(ok(["sample", "--count", "7", "--format", "geojson", "-"], json.dumps(items)).stdout)
    assert out["type"] == "FeatureCollection" and len(out["features"]) == len(items) == 3
    for item, f in zip(items, out["features"]):
        assert f["geometry"]["type"] == "LineString"
        want = json.loads(ok(["sample", "--count", "7", "-"],
                             json.dumps({k: v for k, v in item.items() if k not in ("id", "properties")})).stdout)
        coords = f["geometry"]["coordinates"]
        assert len(coords) == 7
        if item.get("closed"):
            assert coords[-1] == coords[0] and coords[:-1] == want["points"][:-1]
        else:
            assert coords == want["points"]
        assert f["properties"] == item.get("properties")
    assert [f["id"] for f in out["features"]] == ["a", 3, "[2]"]


def test_csv_blocks_and_svg_paths_give_collections():
    csv = "0,0\n1,1\n2,0\n\n5,5\n6,7\n7,5\n8,6\n"
    out = json.loads(ok(["sample", "--count", "4", "--format", "geojson", "--input-format", "csv", "-"], csv).stdout)
    assert [len(f["geometry"]["coordinates"]) for f in out["features"]] == [4, 4]
    svg = '<svg><path id="p" d="M 0 0 L 4 0 L 4 3 Z M 10 10 L 12 11 L 13 15"/></svg>'
    out = json.loads(ok(["sample", "--count", "5", "--format", "geojson", "--input-format", "svg", "-"], svg).stdout)
    assert len(out["features"]) == 2
    first = out["features"][0]["geometry"]["coordinates"]
    assert first[0] == first[-1]  # the Z subpath is a closed curve


def test_geojson_refuses_other_dimensions_naming_the_curve():
    items = [{"id": "flat", "points": [[0, 0], [1, 1], [2, 0]]}, {"id": "wide", "points": [[0, 0, 0, 0], [1, 1, 1, 1]]}]
    p = run(["sample", "--count", "3", "--format", "geojson", "-"], json.dumps(items))
    assert p.returncode == 2 and p.stdout == ""
    assert p.stderr == ("crspline: <stdin>: curve wide: --format geojson: needs 2-D or 3-D points, got 4-D "
                        "(use json or csv)\n")


@pytest.mark.parametrize("command", ["eval", "bezier", "length", "analyze", "plot"])
def test_no_other_subcommand_offers_geojson(command):
    # Only sample writes GeoJSON; the others refuse it by name rather than
    # writing something else.
    p = run([command, "--format", "geojson", "-"], json.dumps({"points": [[0, 0], [1, 1], [2, 0]], "t": [0]}))
    assert p.returncode == 2 and p.stdout == ""
    assert "geojson" in p.stderr and p.stderr.count("\n") == 1


# --- a figure of a many-curve input that holds one curve (point 2) -------------------------

def test_bezier_svg_of_a_geojson_file_with_one_curve(tmp_path):
    ls = tmp_path / "ls.json"
    pts = [[0, 0], [1, 2], [3, 3], [4, 0]]
    ls.write_text(json.dumps({"type": "Feature", "properties": {}, "geometry": {"type": "LineString", "coordinates": pts}}))
    figure = ok(["bezier", "--format", "svg", str(ls)]).stdout
    same = ok(["bezier", "--format", "svg", "-"], json.dumps({"points": pts})).stdout
    assert figure == same and figure.startswith("<?xml")


def test_svg_of_several_curves_is_refused_in_plain_words(tmp_path):
    two = tmp_path / "two.json"
    two.write_text(json.dumps([{"points": [[0, 0], [1, 1]]}, {"points": [[0, 1], [1, 0]]}]))
    p = run(["bezier", "--format", "svg", str(two)])
    assert p.returncode == 2 and p.stdout == ""
    assert p.stderr == (f"crspline: --format svg: one curve per figure, and {two} holds 2 curves "
                        "(use json, csv or svg-path)\n")
