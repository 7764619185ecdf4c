"""crspline.geo.fit (issue 40, GIS): each arc of a coverage fitted once with
few control points (a subset of its vertices), proved within the tolerance
of the input both ways, with the smoothing's proof on the fitted curves: no
new crossings, no changed containment, shared borders still shared.

What is checked, each time counted: the proved deviation is within the
tolerance and bounds a measured Hausdorff distance (Shapely) between input
and output; far fewer control points than input vertices; neighbours share
their fitted borders (areas add up to their union's); every pairwise
relation kept and every output valid (Natural Earth, nybb, contours);
seeded contour lines at one level spacing never cross after fitting; the
Dask path gives the same rows byte for byte; the command's --fit agrees.
"""
import json
import os
import subprocess

import numpy as np
import pytest

gpd = pytest.importorskip("geopandas")
shapely = pytest.importorskip("shapely")

from shapely.geometry import Point  # noqa: E402
from shapely.ops import unary_union  # noqa: E402

import crspline.geo as cg  # noqa: E402

pytestmark = [pytest.mark.filterwarnings("ignore:Geometry is in a geographic CRS"),
              pytest.mark.filterwarnings("ignore:STRtree will be changed"),
              pytest.mark.filterwarnings("ignore::DeprecationWarning")]


def vertices(g):
    from test_geo import coords_of

    return len(coords_of(g))


@pytest.fixture(scope="module")
def nybb():
    return gpd.read_file(gpd.datasets.get_path("nybb"))


@pytest.fixture(scope="module")
def nybb_fitted(nybb):
    return cg.fit(nybb, tolerance=20.0)  # feet


def test_nybb_fit_is_proved_and_small(nybb, nybb_fitted):
    out = nybb_fitted
    assert list(out.columns) == list(nybb.columns) + ["length", "control_points", "deviation", "verdict", "status"]
    assert (out.status == "ok").all()
    total_in = sum(vertices(g) for g in nybb.geometry)
    total_cp = int(out.control_points.sum())
    # nybb's boroughs are dense (about 4 ft a segment) and a 20 ft band
    # leaves most of it out (measured: 11,739 of 76,063, 0.15).
    assert total_cp < 0.25 * total_in, (total_cp, total_in)
    for g_in, g_out, dev in zip(nybb.geometry, out.geometry, out.deviation):
        assert 0 < dev <= 20.0
        # The output polyline's vertices are on the curve and its chords
        # within tolerance / 10 of it; the curve is within dev of the input
        # both ways: an output vertex within dev of the input boundary, an
        # input vertex within dev + tolerance / 10 of the output (Shapely's
        # distances; every 7th output and 31st input vertex: all of them
        # cost minutes).
        from test_geo import coords_of

        b_in, b_out = g_in.boundary, g_out.boundary
        worst_out = max(b_in.distance(Point(p)) for p in coords_of(g_out)[::7])
        worst_in = max(b_out.distance(Point(p)) for p in coords_of(g_in)[::31])
        assert worst_out <= dev * (1 + 1e-9) and worst_in <= dev + 2.0 + 1e-6, (worst_out, worst_in, dev)
    assert out.is_valid.all()


def test_nybb_fit_keeps_borders_and_relations(nybb, nybb_fitted):
    from test_geo_containment import changed_relations, parts

    out = nybb_fitted
    # Neighbours share their fitted borders: no overlap (areas add up).
    total = float(out.area.sum())
    assert abs(total - unary_union(list(out.geometry)).area) <= 1e-9 * total
    changed, compared = changed_relations(list(nybb.geometry), list(out.geometry))
    assert not changed and compared >= 4, (changed, compared)
    for g0, g1 in zip(nybb.geometry, out.geometry):
        c, _ = changed_relations(parts(g0), parts(g1))
        assert not c, c[:5]


def test_world_fit_relations_validity(seed):
    from test_geo_containment import changed_relations, parts

    world = gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))
    out = cg.fit(world, tolerance=5000.0)  # metres
    assert (out.deviation <= 5000.0).all()
    before, after = list(world.geometry), list(out.geometry)
    assert not [i for i in range(len(before)) if before[i].is_valid and not after[i].is_valid]
    changed, compared = changed_relations(before, after)
    assert not changed and compared >= 300, (changed[:5], compared)
    for g0, g1 in zip(before, after):
        if g0.geom_type == "MultiPolygon":
            c, _ = changed_relations(parts(g0), parts(g1))
            assert not c, c[:5]
    assert int(out.control_points.sum()) < sum(vertices(g) for g in before)


def test_contours_one_level_apart_never_cross(seed):
    """Contour lines at consecutive levels of a seeded field, traced on a
    60 x 60 grid (cell 10/59), fitted at half a cell: zero crossings
    between levels (and with themselves where the input had none)."""
    from test_geo import crossing_pairs, random_field_contours

    cell = 10 / 59
    checked = 0
    for k in range(3):
        lines = random_field_contours(seed + k, levels=20)
        if crossing_pairs(list(lines)) != 0:
            continue
        out = cg.fit(lines, tolerance=cell / 2)
        assert (out.deviation <= cell / 2).all()
        assert crossing_pairs(list(out.geometry)) == 0, seed + k
        simple_in = np.array([g.is_simple for g in lines])
        assert all(g.is_simple for g, ok in zip(out.geometry, simple_in) if ok)
        assert out.control_points.sum() < sum(len(g.coords) for g in lines)
        checked += len(lines)
    assert checked >= 20, checked


def test_island_smaller_than_the_tolerance_stays_a_ring():
    """An island (a 10 by 10 square) in a sea, fitted at tolerances up to six
    times its size: each ring keeps three control points at least (before,
    the fit took the island round in one point and failed), both outputs
    valid, the island still inside its hole, the two still sharing their
    border (areas add up to their union's)."""
    from shapely.geometry import Polygon

    island = Polygon([(0, 0), (10, 0), (10, 10), (0, 10)])
    sea = Polygon([(-100, -100), (100, -100), (100, 100), (-100, 100)],
                  [[(0, 0), (0, 10), (10, 10), (10, 0)]])
    layer = gpd.GeoDataFrame({"name": ["island", "sea"]}, geometry=[island, sea], crs="EPSG:3857")
    checked = 0
    for tol in (1.0, 5.0, 20.0, 60.0):
        out = cg.fit(layer, tolerance=tol)
        assert list(out["status"]) == ["ok", "ok"], (tol, list(out["status"]))
        assert min(out["control_points"]) >= 3, (tol, list(out["control_points"]))
        assert (out["deviation"] <= tol).all(), (tol, list(out["deviation"]))
        a, b = out.geometry.iloc[0], out.geometry.iloc[1]
        assert a.is_valid and b.is_valid and a.area > 0
        assert not a.overlaps(b)
        # Shared border: the areas add up to the union's (1e-9 relative:
        # Shapely's rounding of the union of two polygons with ~2,000 vertices).
        assert abs(a.area + b.area - unary_union([a, b]).area) <= 1e-9 * unary_union([a, b]).area
        checked += 1
    assert checked == 4


def test_fit_errors():
    g = gpd.GeoSeries.from_wkt(["LINESTRING (0 0, 1 1, 2 0)"])
    with pytest.raises(ValueError, match="tolerance must be a positive finite distance, got -1"):
        cg.fit(g, tolerance=-1)
    with pytest.raises(ValueError, match="tolerance must be a positive finite distance, got nan"):
        cg.fit(g, tolerance=float("nan"))
    with pytest.raises(ValueError, match="tolerance is required"):
        cg.fit(g)
    big = gpd.GeoSeries.from_wkt(["LINESTRING (1e12 0, 1.000001e12 1, 1.000002e12 0)"])
    with pytest.raises(ValueError, match="at or below the rounding floor"):
        cg.fit(big, tolerance=1e-6)


def test_dask_fit_rows_match_single_process():
    """Africa's countries (a coverage with islands) in three partitions."""
    dd = pytest.importorskip("dask.dataframe")
    distributed = pytest.importorskip("distributed")
    import pandas as pd

    import crspline.geo.dask as cgd

    world = gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))
    layer = world[world["continent"] == "Africa"]
    expected = cg.fit(layer, tolerance=5000.0)
    df = pd.DataFrame(layer.drop(columns=layer.geometry.name))
    df["geometry"] = [g.wkb for g in layer.geometry]
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster):
        got = cgd.fit(dd.from_pandas(df, npartitions=3), crs=layer.crs, tolerance=5000.0).compute()
    assert list(got.columns) == list(expected.columns)
    compared = 0
    for (_, a), (_, b) in zip(got.iterrows(), expected.iterrows()):
        assert a["geometry"] == b.geometry.wkb
        for c in ("length", "deviation"):
            assert np.float64(a[c]).tobytes() == np.float64(b[c]).tobytes(), c
        assert (a["control_points"], a["verdict"], a["status"]) == (b["control_points"], b["verdict"], b["status"])
        compared += 1
    assert compared == len(layer) >= 50


@pytest.mark.skipif(not os.environ.get("CRSPLINE_BIN"), reason="CRSPLINE_BIN not set (the CLI is not built)")
def test_cli_smooth_fit(tmp_path):
    world = gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))
    src = tmp_path / "world.geojson"
    src.write_text(world.to_json())
    out = tmp_path / "fit.geojson"
    r = subprocess.run([os.environ["CRSPLINE_BIN"], "smooth", "--fit", "5000", str(src), "-o", str(out)],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    doc = json.loads(out.read_text())
    expected = cg.fit(gpd.read_file(src), tolerance=5000.0)
    props = [f["properties"] for f in doc["features"]]
    assert [p["crspline_control_points"] for p in props] == list(expected.control_points)
    assert [p["crspline_max_deviation_m"] for p in props] == list(expected.deviation)
    assert [p["crspline_verdict"] for p in props] == list(expected.verdict)
