"""crspline smooth (the command) on Natural Earth's countries as GeoJSON:
the same geometry as crspline.geo.smooth on the same file, the measures as
properties in metres, and bad input as one line with status 2."""
import json
import os
import subprocess

import numpy as np
import pytest

gpd = pytest.importorskip("geopandas")

import crspline.geo as cg  # noqa: E402

BIN = os.environ.get("CRSPLINE_BIN")
pytestmark = [pytest.mark.skipif(not BIN, reason="CRSPLINE_BIN not set (the CLI is not built)"),
              pytest.mark.filterwarnings("ignore::DeprecationWarning")]


def rings(g):
    polys = [g] if g.geom_type == "Polygon" else list(g.geoms)
    for p in polys:
        yield np.asarray(p.exterior.coords)
        for h in p.interiors:
            yield np.asarray(h.coords)


def test_cli_smooth_matches_python(tmp_path):
    world = gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))
    src = tmp_path / "world.geojson"
    world.to_file(src, driver="GeoJSON")
    layer = gpd.read_file(src)  # what the command reads (GDAL's GeoJSON rounding included)
    out = tmp_path / "smooth.geojson"
    r = subprocess.run([BIN, "smooth", "--tolerance", "50", str(src), "-o", str(out)], capture_output=True,
                       text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    doc = json.loads(out.read_text())
    assert doc["crspline"]["units"].startswith("metre")
    assert len(doc["features"]) == 177
    got = gpd.GeoDataFrame.from_features(doc["features"], crs="EPSG:4326")
    expected = cg.smooth(layer, tolerance=50.0)
    compared = 0
    for a, b, (_, row), (_, erow) in zip(got.geometry, expected.geometry, got.iterrows(), expected.iterrows()):
        for ra, rb in zip(rings(a), rings(b)):
            # The same core on the same numbers through the same frame: equal
            # to the last bit (JSON writes doubles to round trip).
            assert ra.shape == rb.shape
            assert np.array_equal(ra, rb)
            compared += len(ra)
        assert row["crspline_status"] == erow["status"]
        assert row["crspline_verdict"] == erow["verdict"]
        assert row["crspline_max_deviation_m"] == erow["max_deviation"]
        # GeographicLib (the command) against pyproj's Geod: both Karney's
        # algorithm, accurate to rounding; sums over up to ~10^4 segments
        # in different orders stay far below 1e-9 relative.
        assert row["crspline_length_m"] == pytest.approx(erow["length"], rel=1e-9)
        assert row["crspline_curve_length_m"] == erow["curve_length"]  # the same core number
    assert compared > 50000


def test_cli_smooth_errors(tmp_path):
    bad = tmp_path / "bad.geojson"
    bad.write_text('{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, '
                   '"geometry": {"type": "LineString", "coordinates": [[0, 0], [1]]}}]}')
    r = subprocess.run([BIN, "smooth", "--tolerance", "5", str(bad)], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr == ("crspline smooth: features[0].geometry.coordinates[1]: "
                        "expected a position [x, y] or [x, y, z]\n")
    r = subprocess.run([BIN, "smooth", str(bad)], capture_output=True, text=True)
    assert r.returncode == 2 and "--tolerance is required" in r.stderr
    r = subprocess.run([BIN, "smooth", "--tolerance", "-1", str(bad)], capture_output=True, text=True,
                       input="")
    assert r.returncode == 2


def test_cli_keeps_islands_out_and_reports_nesting(tmp_path):
    """Issue 39 through the command: the reproduction's island (moved to
    WGS 84) stays outside the municipality, as in Python, and a
    multi-polygon with a shell inside another is reported `nested`."""
    from pyproj import Transformer
    from shapely.geometry import MultiPolygon, Polygon
    from shapely.ops import transform

    import test_geo_containment as tc

    to_wgs84 = Transformer.from_crs("EPSG:30166", "EPSG:4326", always_xy=True).transform
    big, island = transform(to_wgs84, tc.BIG), transform(to_wgs84, tc.ISLAND)
    outer = Polygon([(10, 10), (10.01, 10), (10.01, 10.01), (10, 10.01)])
    inner = Polygon([(10.004, 10.004), (10.006, 10.004), (10.005, 10.006)])
    layer = gpd.GeoDataFrame(geometry=[MultiPolygon([big, island]), big, island, MultiPolygon([outer, inner])],
                             crs="EPSG:4326")
    src = tmp_path / "in.geojson"
    src.write_text(layer.to_json())
    out = tmp_path / "out.geojson"
    r = subprocess.run([BIN, "smooth", "--tolerance", str(tc.REPRO_TOLERANCE), str(src), "-o", str(out)],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    doc = json.loads(out.read_text())
    got = gpd.GeoDataFrame.from_features(doc["features"], crs="EPSG:4326")
    assert got.is_valid[0] and got.is_valid[1] and got.is_valid[2]
    assert tc.relation(*got.geometry[0].geoms) == "disjoint"
    assert not got.geometry[1].intersects(got.geometry[2])
    props = [f["properties"] for f in doc["features"]]
    assert props[3]["crspline_verdict"] == "nested"
    assert props[3]["crspline_status"] == (
        "ok: part 1 (an outer ring) lies inside the polygon of part 0 (an outer ring) (nested shells)")
    expected = cg.smooth(gpd.read_file(src), tolerance=tc.REPRO_TOLERANCE)
    assert [p["crspline_verdict"] for p in props] == list(expected.verdict)
