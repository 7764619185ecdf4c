"""crspline.geo on lines and rings that cross the antimeridian: the
geographic frame unwraps them (longitudes continuous along the part),
smooths them so, and brings them back into [-180, 180], input vertices bit
for bit.

The reference for each case is the same geometry given with its longitudes
already continuous (past 180, a layer of its own): the smoothing there is
the plain path of the frame, so the unwrapped result, turned back by 360
degrees where it is past 180, must equal it exactly (the same frame, the
same core, the same arithmetic)."""
import numpy as np
import pytest

gpd = pytest.importorskip("geopandas")
shapely_geometry = pytest.importorskip("shapely.geometry")
Polygon, LineString = shapely_geometry.Polygon, shapely_geometry.LineString

import crspline.geo as cg  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")


def wrap(lon):
    lon = np.asarray(lon, dtype=float)
    return np.where(lon > 180, lon - 360, lon)


def vanua_levu():
    """Fiji's Vanua Levu as one ring across the antimeridian: Natural
    Earth (1:110m) splits it at +-180 into two polygons of Fiji's
    MultiPolygon; their vertices off the cut, in ring order."""
    world = gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))
    fiji = world[world["name"] == "Fiji"].geometry.iloc[0]
    east = [c for c in fiji.geoms if np.asarray(c.exterior.coords)[:, 0].max() >= 180]
    west = [c for c in fiji.geoms if np.asarray(c.exterior.coords)[:, 0].min() <= -180]
    assert len(east) == 1 and len(west) == 1  # the 1:110m data as shipped
    e = np.asarray(east[0].exterior.coords)[:-1]
    w = np.asarray(west[0].exterior.coords)[:-1]
    e = e[np.abs(e[:, 0]) < 180]
    w = w[np.abs(w[:, 0]) < 180]
    # East part: from the cut's south end westwards round to its north end;
    # west part: from the north end round to the south end.
    ring = np.vstack((e, w))
    assert len(ring) == 7, ring
    return ring


def smooth_both(geom_crossing, geom_continuous, **kw):
    a = cg.smooth(gpd.GeoSeries([geom_crossing], crs="EPSG:4326"), **kw)
    b = cg.smooth(gpd.GeoSeries([geom_continuous], crs="EPSG:4326"), **kw)
    return a, b


def test_fiji_ring_across_the_antimeridian():
    ring = vanua_levu()
    steps = np.abs(np.diff(np.vstack((ring, ring[:1]))[:, 0]))
    assert (steps > 180).sum() == 2  # it does cross, out and back
    continuous = ring.copy()
    continuous[:, 0] = np.where(ring[:, 0] < 0, ring[:, 0] + 360, ring[:, 0])
    a, b = smooth_both(Polygon(ring), Polygon(continuous), tolerance=50.0)
    assert list(a["status"]) == ["ok"] and list(b["status"]) == ["ok"]
    got = np.asarray(a.geometry.iloc[0].exterior.coords)
    ref = np.asarray(b.geometry.iloc[0].exterior.coords)
    assert got.shape == ref.shape and len(got) > 3 * len(ring)
    # In [-180, 180]; equal to the continuous layer's output turned back.
    assert got[:, 0].min() >= -180 and got[:, 0].max() <= 180
    assert np.array_equal(got[:, 0], wrap(ref[:, 0])) and np.array_equal(got[:, 1], ref[:, 1])
    # Every input vertex on the output, bit for bit (not 360 degrees away).
    kept = {tuple(p) for p in got.tolist()}
    assert all(tuple(p) in kept for p in ring.tolist())
    # The same measures. (Deviation: the island is about 170 km across;
    # without the unwrapping the curve went round the globe.)
    assert a["max_deviation"].iloc[0] == b["max_deviation"].iloc[0]
    assert 0 < a["max_deviation"].iloc[0] < 20_000
    # Lengths: geodesic along each output, whose segments are the same
    # (the crossing one is the short way across, as pyproj takes it);
    # 1e-9 relative: pyproj on the two spellings of one longitude.
    assert a["length"].iloc[0] == pytest.approx(b["length"].iloc[0], rel=1e-9)


def test_seeded_line_across_the_antimeridian(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(20, 60))
    lon = 178.0 + np.cumsum(rng.uniform(0.05, 0.2, n))       # eastwards, past 180
    lat = 60.0 + np.cumsum(rng.normal(0, 0.05, n))
    assert lon[0] < 180 < lon[-1], (seed, lon[0], lon[-1])
    line = np.column_stack((wrap(lon), lat))
    continuous = np.column_stack((lon, lat))
    a, b = smooth_both(LineString(line), LineString(continuous), tolerance=20.0)
    assert list(a["status"]) == ["ok"], seed
    got = np.asarray(a.geometry.iloc[0].coords)
    ref = np.asarray(b.geometry.iloc[0].coords)
    assert got.shape == ref.shape, seed
    assert np.array_equal(got[:, 0], wrap(ref[:, 0])) and np.array_equal(got[:, 1], ref[:, 1]), seed
    assert got[:, 0].min() >= -180 and got[:, 0].max() <= 180
    # Input vertices bit for bit, in order.
    rows = {tuple(p): k for k, p in enumerate(got.tolist())}
    where = [rows.get(tuple(p)) for p in line.tolist()]
    assert None not in where and where == sorted(where), seed
    # The output crosses once, the short way: unwrapped, it is continuous.
    steps = np.abs(np.diff(got[:, 0]))
    assert (steps > 180).sum() == 1, seed
    assert a["max_deviation"].iloc[0] == b["max_deviation"].iloc[0]
    assert a["max_deviation"].iloc[0] < 5_000, seed


def test_ring_round_the_pole_is_not_unwrapped():
    """A ring whose longitude steps add up to a whole turn (round the pole)
    has no continuous longitude: it is smoothed as given (kept within
    +-180), as before."""
    lon = np.array([-180.0, -90.0, 0.0, 90.0, 180.0, 180.0, -180.0])
    lat = np.array([-70.0, -72.0, -69.0, -71.0, -70.0, -89.0, -89.0])
    g = Polygon(np.column_stack((lon, lat)))
    out = cg.smooth(gpd.GeoSeries([g], crs="EPSG:4326"), tolerance=1000.0)
    c = np.asarray(out.geometry.iloc[0].exterior.coords)
    assert out["status"].iloc[0] == "ok"
    assert c[:, 0].min() >= -180 and c[:, 0].max() <= 180


def test_cli_unwraps_as_python(tmp_path):
    """crspline smooth (the command) unwraps the same way: the same
    coordinates as crspline.geo.smooth, to the bit, on Vanua Levu and a
    line across 180 degrees."""
    import json
    import os
    import subprocess

    binary = os.environ.get("CRSPLINE_BIN")
    if not binary:
        pytest.skip("CRSPLINE_BIN not set (the CLI is not built)")
    ring = vanua_levu()
    line = np.array([[179.2, -17.5], [179.8, -17.2], [-179.7, -17.4], [-179.1, -17.0], [-178.8, -17.3]])
    features = [{"type": "Feature", "properties": {"k": 0},
                 "geometry": {"type": "Polygon", "coordinates": [np.vstack((ring, ring[:1])).tolist()]}},
                {"type": "Feature", "properties": {"k": 1},
                 "geometry": {"type": "LineString", "coordinates": line.tolist()}}]
    src = tmp_path / "in.geojson"
    src.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    out = tmp_path / "out.geojson"
    r = subprocess.run([binary, "smooth", "--tolerance", "50", str(src), "-o", str(out)], capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    doc = json.loads(out.read_text())
    got = [np.asarray(doc["features"][0]["geometry"]["coordinates"][0]),
           np.asarray(doc["features"][1]["geometry"]["coordinates"])]
    py = cg.smooth(gpd.GeoSeries([Polygon(ring), LineString(line)], crs="EPSG:4326"), tolerance=50.0)
    want = [np.asarray(py.geometry.iloc[0].exterior.coords), np.asarray(py.geometry.iloc[1].coords)]
    for g, w in zip(got, want):
        assert g.shape == w.shape and np.array_equal(g, w)
        assert g[:, 0].min() >= -180 and g[:, 0].max() <= 180
        assert (np.abs(np.diff(g[:, 0])) > 180).sum() >= 1  # it crosses, the short way


def test_dask_path_unwraps_the_same():
    """crspline.geo.dask on a layer with Vanua Levu across 180 degrees, in
    two partitions (synchronous scheduler): the rows of one process."""
    dd = pytest.importorskip("dask.dataframe")
    dask = pytest.importorskip("dask")
    import pandas as pd

    import crspline.geo.dask as cgd

    world = gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))
    oceania = world[(world["continent"] == "Oceania") & (world["name"] != "Fiji")].geometry.tolist()
    layer = gpd.GeoSeries(oceania + [Polygon(vanua_levu())], crs="EPSG:4326")
    expected = cg.smooth(layer, tolerance=50.0)
    df = pd.DataFrame({"geometry": [g.wkb for g in layer]})
    with dask.config.set(scheduler="sync"):
        got = cgd.smooth(dd.from_pandas(df, npartitions=2), crs=layer.crs, tolerance=50.0).compute()
    assert len(got) == len(expected) == len(oceania) + 1 > 5
    for (_, a), (_, b) in zip(got.iterrows(), expected.iterrows()):
        assert a["geometry"] == b.geometry.wkb
        assert np.float64(a["length"]).tobytes() == np.float64(b["length"]).tobytes()
        assert np.float64(a["max_deviation"]).tobytes() == np.float64(b["max_deviation"]).tobytes()
        assert (a["verdict"], a["status"]) == (b["verdict"], b["status"])
