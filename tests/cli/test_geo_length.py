"""crspline length on GeoJSON (issue 29): WGS 84 longitude/latitude in,
geodesic metres on the ellipsoid out, with the unit and CRS named; other
inputs keep their unitless lengths and no "unit" key.

References are independent of the command: pyproj's Geod (Karney's
algorithm, accurate to rounding) for geodesics, and the closed form of a
parallel's length on the ellipsoid (N cos(phi) dlambda, with N from the
same a and f). Needs pyproj (python3-pyproj, which python3-geopandas
brings).
"""
import json
import math
import random

import pytest

from cli_support import run

pyproj = pytest.importorskip("pyproj")
GEOD = pyproj.Geod(ellps="WGS84")


def length_of(tmp_path, coordinates, name="line.geojson", geometry="LineString"):
    doc = {"type": "FeatureCollection",
           "features": [{"type": "Feature", "properties": {}, "geometry": {"type": geometry, "coordinates": coordinates}}]}
    path = tmp_path / name
    path.write_text(json.dumps(doc))
    p = run(["length", str(path)])
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


def single(out):
    """The one curve's answer, whether or not the output wraps it in a list."""
    if isinstance(out, dict) and "total" in out:
        return out
    if isinstance(out, dict) and "curves" in out:
        assert len(out["curves"]) == 1
        return single(out["curves"][0])
    if isinstance(out, list):
        assert len(out) == 1
        return single(out[0])
    for key in ("result", "length"):
        if isinstance(out, dict) and key in out:
            return single(out[key])
    raise AssertionError(f"no length in {json.dumps(out)[:300]}")


def test_meridian_arc_of_one_degree(tmp_path):
    # Collinear, evenly spaced points on a meridian: the curve is the
    # meridian arc itself, a geodesic. 1e-9 relative: the quadrature's
    # accuracy is 1e-12 and pyproj's geodesic is accurate to rounding.
    lats = [40.0, 40.25, 40.5, 40.75, 41.0]
    out = single(length_of(tmp_path, [[10.0, lat] for lat in lats]))
    assert out["unit"] == "m" and out["crs"] == "EPSG:4326"
    ref = GEOD.inv(10.0, 40.0, 10.0, 41.0)[2]
    assert out["total"] == pytest.approx(ref, rel=1e-9)
    assert len(out["segments"]) == 4
    for k, s in enumerate(out["segments"]):
        assert s == pytest.approx(GEOD.inv(10.0, lats[k], 10.0, lats[k + 1])[2], rel=1e-9)


def test_meridian_arcs_seeded(tmp_path, seed):
    rng = random.Random(seed)
    checked = 0
    for case in range(20):
        lon = rng.uniform(-180, 180)
        lat0 = rng.uniform(-85, 80)
        span = rng.uniform(0.01, 5)
        n = rng.randint(3, 9)
        lats = [lat0 + span * k / (n - 1) for k in range(n)]
        if rng.random() < 0.5:
            lats.reverse()
        out = single(length_of(tmp_path, [[lon, lat] for lat in lats], name=f"m{case}.geojson"))
        ref = GEOD.inv(lon, lats[0], lon, lats[-1])[2]
        assert out["total"] == pytest.approx(ref, rel=1e-9), (seed, case, lon, lats)
        checked += 1
    assert checked == 20


@pytest.mark.parametrize("lat", [0.0, 30.0, -52.5, 75.0])
def test_parallel(tmp_path, lat):
    # Evenly spaced points on a parallel: the curve is the parallel (not a
    # geodesic), whose length is N(phi) cos(phi) dlambda exactly.
    a, f = GEOD.a, GEOD.f
    e2 = f * (2 - f)
    phi = math.radians(lat)
    n_radius = a / math.sqrt(1 - e2 * math.sin(phi) ** 2)
    lons = [-3.0 + 0.5 * k for k in range(9)]  # 4 degrees
    out = single(length_of(tmp_path, [[lon, lat] for lon in lons]))
    closed = n_radius * math.cos(phi) * math.radians(lons[-1] - lons[0])
    assert out["total"] == pytest.approx(closed, rel=1e-9)
    # pyproj on 4001 points of the parallel: each geodesic chord differs
    # from its arc by about (dlambda cos(phi))^2 / 24 relative, below 1e-11.
    dense = [lons[0] + (lons[-1] - lons[0]) * k / 4000 for k in range(4001)]
    assert out["total"] == pytest.approx(GEOD.line_length(dense, [lat] * len(dense)), rel=1e-9)


def test_curved_line_against_dense_polyline(tmp_path, seed):
    # A curved line: its length is the limit of geodesic polylines through
    # dense points of the curve. The points come from `crspline sample` on
    # the same file; 20001 points over 5 segments leave a chord error of
    # about (h kappa)^2 / 24, far below the 1e-7 asserted.
    rng = random.Random(seed)
    pts = [[rng.uniform(-2, 2) + 20, rng.uniform(-2, 2) + 45] for _ in range(6)]
    out = single(length_of(tmp_path, pts))
    path = tmp_path / "line.geojson"
    p = run(["sample", "--count", "20001", "--format", "json", str(path)])
    if p.returncode != 0:
        p = run(["sample", "--count", "20001", str(path)])
    assert p.returncode == 0, p.stderr
    sampled = json.loads(p.stdout)

    def points_of(x):
        if isinstance(x, dict):
            for key in ("points", "samples", "curves", "result"):
                if key in x:
                    return points_of(x[key])
        if isinstance(x, list) and len(x) == 1 and isinstance(x[0], (dict, list)) and not isinstance(x[0][0] if isinstance(x[0], list) else None, (int, float)):
            return points_of(x[0])
        return x

    dense = points_of(sampled)
    assert len(dense) == 20001, (seed, str(sampled)[:200])
    ref = GEOD.line_length([q[0] for q in dense], [q[1] for q in dense])
    assert out["total"] == pytest.approx(ref, rel=1e-7), seed
    # And never shorter than the geodesic between its ends.
    assert out["total"] >= GEOD.inv(pts[0][0], pts[0][1], pts[-1][0], pts[-1][1])[2]


def test_polygon_ring_and_plain_json_keep_units_apart(tmp_path):
    # A ring (closed curve) from GeoJSON is in metres; the same points as a
    # plain JSON curve are unitless (degrees as numbers) and say no unit.
    ring = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]]
    geo = single(length_of(tmp_path, [ring], geometry="Polygon"))
    assert geo["unit"] == "m" and geo["crs"] == "EPSG:4326"
    assert 4.0e5 < geo["total"] < 5.0e5  # about 4 x 111 km
    plain = tmp_path / "plain.json"
    plain.write_text(json.dumps({"points": ring[:-1], "closed": True}))
    p = run(["length", str(plain)])
    assert p.returncode == 0, p.stderr
    flat = json.loads(p.stdout)
    assert "unit" not in flat and "crs" not in flat
    assert 3.5 < flat["total"] < 5.0


def test_latitude_out_of_range_is_refused(tmp_path):
    doc = {"type": "LineString", "coordinates": [[0, 0], [1, 95.5], [2, 0]]}
    path = tmp_path / "bad.geojson"
    path.write_text(json.dumps(doc))
    p = run(["length", str(path)])
    assert p.returncode == 2
    assert p.stdout == ""
    assert "point 1: latitude 95.5 is outside [-90, 90]" in p.stderr
    assert len(p.stderr.strip().splitlines()) == 1
