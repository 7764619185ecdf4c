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
        for c in ("length", "curve_length", "max_deviation"):
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
        for c in ("length", "curve_length", "max_deviation"):
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
    # Groups placed largest first on the least loaded smoothing task: no task
    # holds more than the average plus the largest group (list scheduling's
    # bound); every arc vertex is in one task.
    load, largest = counts["task_vertices"], counts["largest_group"]
    assert len(load) == 4 and min(load) > 0
    assert 0 < largest["arcs"] < counts["arcs"]
    assert max(load) <= sum(load) / 4 + largest["vertices"], (load, largest)
    # Partitions of consecutive rows: borders between partitions exist.
    part = np.repeat(np.arange(6), np.diff(np.asarray(ddf.divisions[:-1] + (len(world),))))
    assert len(part) == 177
    idx = world.sindex
    crossing = sum(1 for i, j in zip(*idx.query_bulk(world.geometry, predicate="touches")) if part[i] != part[j])
    assert crossing > 20, crossing


def stacked_lines(seed, reps=6, lines=6, vertices=40):
    """Contour-like lines stacked 1 apart, each vertex jittered by up to
    0.49 across on a shared x grid of short (0.01-0.05) and long (0.3-0.6)
    steps, as tests/geo's ContourLinesNeverCross: the inputs never meet, the
    free curves overshoot into their neighbours in places, so the proof
    must raise tension between lines. `reps` stacks, 100 apart in x."""
    from shapely.geometry import LineString

    rng = np.random.default_rng(seed)
    geoms, stack = [], []
    for rep in range(reps):
        short = rng.uniform(size=vertices - 1) < 0.5
        steps = np.where(short, 0.01 + 0.04 * rng.uniform(size=vertices - 1), 0.3 + 0.3 * rng.uniform(size=vertices - 1))
        xs = 100.0 * rep + np.concatenate(([0.0], np.cumsum(steps)))
        for k in range(lines):
            geoms.append(LineString(np.column_stack((xs, k + rng.uniform(-0.49, 0.49, vertices)))))
            stack.append(rep)
    return gpd.GeoDataFrame({"stack": stack}, geometry=geoms, crs="EPSG:3857")


def test_tension_across_partitions(client, seed):
    """Neighbouring lines dealt to different partitions (round robin): the
    tension the proof raises between them is the single-process one."""
    gdf = stacked_lines(seed)
    assert len(gdf) == 36
    expected = cg.smooth(gdf, tolerance=1e-3)
    stats = expected.attrs["crspline_stats"]
    # Not vacuous: tension was raised between lines (a wrong grouping of
    # arcs would have left it out), and no input crossing or touch.
    assert stats["tensioned_vertices"] > 0, seed
    assert stats["input_crossings"] == 0 and (expected["verdict"] == "simple").all(), seed
    df = wkb_frame(gdf)
    df = df.iloc[np.argsort(np.arange(len(df)) % 3, kind="stable")]  # round robin, then in 3 partitions
    ddf = dd.from_pandas(df, npartitions=3, sort=False)
    assert ddf.npartitions == 3
    got = cgd.smooth(ddf, crs=gdf.crs, tolerance=1e-3, buckets=2).compute().sort_index()
    assert rows_equal(got, expected) == 36
    counts = cgd.arc_counts(ddf, crs=gdf.crs, tolerance=1e-3, buckets=2)
    assert counts["arcs"] == stats["arcs"] == 36
    assert counts["groups"] >= 6  # the stacks, 100 apart, are separate groups


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


def test_scheduler_and_workers_as_on_many_machines(world, tmp_path):
    """The docs' multi-machine recipe, on this machine: `dask scheduler` and
    two `dask worker` processes started from the command line (as on
    separate machines), a Client to the scheduler's address; the same
    rows as one process, both workers used."""
    import json
    import os
    import shutil
    import subprocess
    import time

    dask_cli = shutil.which("dask")
    if dask_cli is None:
        pytest.skip("the dask command (python3-distributed) is not installed")
    sched_file = tmp_path / "scheduler.json"
    procs = []
    try:
        common = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=dict(os.environ))
        procs.append(subprocess.Popen([dask_cli, "scheduler", "--host", "127.0.0.1", "--port", "0",
                                       "--no-dashboard", "--scheduler-file", str(sched_file)], **common))
        for _ in range(2):
            procs.append(subprocess.Popen([dask_cli, "worker", "--scheduler-file", str(sched_file), "--nthreads", "1",
                                           "--no-dashboard", "--host", "127.0.0.1"], **common))
        deadline = time.monotonic() + 120  # a start-up limit only, on a loaded machine
        while not sched_file.exists() and time.monotonic() < deadline:
            time.sleep(0.2)
        address = json.loads(sched_file.read_text())["address"]
        with distributed.Client(address) as c:
            c.wait_for_workers(2, timeout=120)
            sub = world[world["continent"] == "South America"]
            expected = cg.smooth(sub, tolerance=50.0)
            result = cgd.smooth(dd.from_pandas(wkb_frame(sub), npartitions=3), crs=sub.crs, tolerance=50.0)
            with distributed.get_task_stream(c) as ts:
                got = result.compute()
            assert len({t["worker"] for t in ts.data}) == 2
            assert rows_equal(got, expected) == len(sub) == 13
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in reversed(procs):
            try:
                p.wait(timeout=30)
            except subprocess.TimeoutExpired:
                p.kill()


def test_dask_errors(world):
    ddf = dd.from_pandas(wkb_frame(world), npartitions=2)
    with pytest.raises(ValueError, match="no geometry column 'geom'"):
        cgd.smooth(ddf, crs=world.crs, geometry="geom", tolerance=1.0)
    with pytest.raises(ValueError, match="tolerance is required"):
        cgd.smooth(ddf, crs=world.crs)


def test_containment_across_partitions(client, seed):
    """Issue 39 on the cluster: the reproduction's island and the seeded
    islands, holes and lines near a coast, as separate features dealt to
    different partitions (round robin): the swept regions' proof raises the
    same tension as in one process, so the rows are byte-equal, the
    relations kept and every output valid."""
    import test_geo_containment as tc
    from shapely.geometry import MultiPolygon

    land, islands, holes, lines = tc.island_layer(seed)
    geoms = [tc.BIG, tc.ISLAND, land, MultiPolygon([land] + islands)] + islands + lines
    gdf = gpd.GeoDataFrame({"k": np.arange(len(geoms))}, geometry=geoms, crs="EPSG:3857")
    expected = cg.smooth(gdf, tolerance=tc.REPRO_TOLERANCE)
    assert expected.attrs["crspline_stats"]["swept_vertices"] > 0, seed  # not vacuous
    df = wkb_frame(gdf)
    df = df.iloc[np.argsort(np.arange(len(df)) % 3, kind="stable")]
    got = cgd.smooth(dd.from_pandas(df, npartitions=3, sort=False), crs=gdf.crs,
                     tolerance=tc.REPRO_TOLERANCE, buckets=2).compute().sort_index()
    assert rows_equal(got, expected) == len(geoms)
    out = gpd.GeoSeries.from_wkb(got["geometry"])
    assert out.is_valid.all()
    assert tc.relation(out[0], out[1]) == "disjoint"
