"""crspline.geo.dask on a LocalCluster of two worker processes: the rows are
those of the single-process crspline.geo.smooth, byte for byte, with more
than one partition and both workers used; one file per partition written."""
import numpy as np
import pytest

gpd = pytest.importorskip("geopandas")
dd = pytest.importorskip("dask.dataframe")
distributed = pytest.importorskip("distributed")

import pandas as pd  # noqa: E402

import crspline.geo as cg  # noqa: E402
import crspline.geo.dask as cgd  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(scope="module")
def world():
    return gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))


def wkb_frame(gdf):
    df = pd.DataFrame(gdf.drop(columns=gdf.geometry.name))
    df["geometry"] = [g.wkb for g in gdf.geometry]
    return df


def test_dask_rows_match_single_process(client, world, tmp_path):
    expected = cg.smooth(world, tolerance=50.0)
    ddf = dd.from_pandas(wkb_frame(world), npartitions=6)
    assert ddf.npartitions == 6
    result = cgd.smooth(ddf, crs=world.crs, tolerance=50.0)
    with distributed.get_task_stream(client) as ts:
        got = result.compute()
    workers = {t["worker"] for t in ts.data}
    assert len(workers) == 2, workers
    assert len(got) == len(expected) == 177
    assert (got.index == expected.index).all()
    assert list(got.columns) == list(expected.columns)
    same = 0
    for (_, a), (_, b) in zip(got.iterrows(), expected.iterrows()):
        assert a["geometry"] == b.geometry.wkb, a["name"]
        for c in ("length", "max_deviation"):
            assert np.float64(a[c]).tobytes() == np.float64(b[c]).tobytes(), (a["name"], c)
        for c in ("verdict", "status", "name", "iso_a3", "pop_est"):
            assert a[c] == b[c]
        same += 1
    assert same == 177
    # One file per partition, 177 rows back.
    paths = cgd.write_partitions(result, str(tmp_path / "out"), crs=world.crs)
    assert len(paths) == 6
    back = pd.concat([gpd.read_file(p) for p in paths])
    assert len(back) == 177
    assert sorted(back["name"]) == sorted(world["name"])


def rows_equal(got, expected):
    """Every row byte for byte (geometry WKB, float bits, strings); returns
    the number of rows compared."""
    assert len(got) == len(expected)
    assert (got.index == expected.index).all()
    same = 0
    for (_, a), (_, b) in zip(got.iterrows(), expected.iterrows()):
        assert a["geometry"] == (None if b.geometry is None else b.geometry.wkb), same
        for c in ("length", "max_deviation"):
            assert np.float64(a[c]).tobytes() == np.float64(b[c]).tobytes(), (same, c, a[c], b[c])
        assert (a["verdict"], a["status"]) == (b["verdict"], b["status"]), same
        same += 1
    return same


def test_arcs_are_shuffled_and_smoothed_once(client, world):
    """The arc stages: as many distinct arcs over all buckets as the single
    process smooths (each shared border once, though its two countries sit
    in different partitions), spread over every bucket; more than one group
    of arcs that may meet (islands apart from the continents)."""
    expected = cg.smooth(world, tolerance=50.0)
    ddf = dd.from_pandas(wkb_frame(world), npartitions=6)
    counts = cgd.arc_counts(ddf, crs=world.crs, tolerance=50.0, buckets=4)
    assert counts["arcs"] == expected.attrs["crspline_stats"]["arcs"]
    assert len(counts["arcs_per_bucket"]) == 4 and min(counts["arcs_per_bucket"]) > 0
    assert counts["groups"] > 10  # islands, Americas, Australia, ... apart
    # Partitions of consecutive rows: borders between partitions exist.
    part = np.repeat(np.arange(6), np.diff(np.asarray(ddf.divisions[:-1] + (len(world),))))
    assert len(part) == 177
    idx = world.sindex
    crossing = sum(1 for i, j in zip(*idx.query_bulk(world.geometry, predicate="touches")) if part[i] != part[j])
    assert crossing > 20, crossing


def contour_layer(seed):
    """Seeded contour lines of a random field (nested, near each other: the
    proof raises tension between lines), dealt round-robin to partitions so
    that neighbours sit in different partitions."""
    from test_geo import random_field_contours

    lines = random_field_contours(seed)
    gdf = gpd.GeoDataFrame({"level": np.arange(len(lines))}, geometry=lines.values, crs=lines.crs)
    return gdf


def test_contours_across_partitions(client, seed):
    gdf = contour_layer(seed)
    assert len(gdf) >= 10
    expected = cg.smooth(gdf, tolerance=1e-3)
    stats = expected.attrs["crspline_stats"]
    df = wkb_frame(gdf)
    df = df.iloc[np.argsort(np.arange(len(df)) % 3, kind="stable")]  # round robin, then in 3 partitions
    ddf = dd.from_pandas(df, npartitions=3, sort=False)
    assert ddf.npartitions == 3
    got = cgd.smooth(ddf, crs=gdf.crs, tolerance=1e-3, buckets=2).compute().sort_index()
    assert rows_equal(got, expected) == len(gdf)
    # The proof did work here: tension was raised somewhere (so a wrong
    # grouping of arcs would have shown), and the groups were several.
    assert stats["tensioned_vertices"] > 0, seed
    counts = cgd.arc_counts(ddf, crs=gdf.crs, tolerance=1e-3, buckets=2)
    assert counts["arcs"] == stats["arcs"]


def test_options_and_projected_layer(client, world):
    """max_deviation, topology="none", and a projected layer in feet (nybb,
    76k vertices) with Z added to some features: the same rows."""
    from shapely.geometry import LineString

    sub = world[world["continent"].isin(["South America", "Africa"])]
    for kw in (dict(tolerance=50.0, max_deviation=3000.0), dict(tolerance=50.0, topology="none")):
        expected = cg.smooth(sub, **kw)
        got = cgd.smooth(dd.from_pandas(wkb_frame(sub), npartitions=3), crs=sub.crs, **kw).compute()
        assert rows_equal(got, expected) == len(sub), kw
    nybb = gpd.read_file(gpd.datasets.get_path("nybb"))
    expected = cg.smooth(nybb, tolerance=10.0)
    got = cgd.smooth(dd.from_pandas(wkb_frame(nybb), npartitions=2), crs=nybb.crs, tolerance=10.0).compute()
    assert rows_equal(got, expected) == 5
    # Z in the first partition only: every row gets Z (0 where none was given),
    # as in one process.
    lines = gpd.GeoDataFrame({"k": range(4)}, geometry=[
        LineString([(0, 0, 1), (1, 1, 2), (2, 0, 3), (3, 1, 4)]), LineString([(0, 2), (1, 3), (2, 2)]),
        LineString([(0, 4), (1, 5), (2, 4), (3, 5)]), LineString([(3, 1), (4, 0), (5, 1)])], crs="EPSG:3857")
    expected = cg.smooth(lines, tolerance=0.01)
    got = cgd.smooth(dd.from_pandas(wkb_frame(lines), npartitions=2), crs=lines.crs, tolerance=0.01).compute()
    assert rows_equal(got, expected) == 4


def test_dask_errors(world):
    ddf = dd.from_pandas(wkb_frame(world), npartitions=2)
    with pytest.raises(ValueError, match="no geometry column 'geom'"):
        cgd.smooth(ddf, crs=world.crs, geometry="geom", tolerance=1.0)
    with pytest.raises(ValueError, match="tolerance is required"):
        cgd.smooth(ddf, crs=world.crs)
