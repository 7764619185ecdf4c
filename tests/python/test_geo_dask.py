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


def test_dask_errors(world):
    ddf = dd.from_pandas(wkb_frame(world), npartitions=2)
    with pytest.raises(ValueError, match="no geometry column 'geom'"):
        cgd.smooth(ddf, crs=world.crs, geometry="geom", tolerance=1.0)
    with pytest.raises(ValueError, match="tolerance is required"):
        cgd.smooth(ddf, crs=world.crs)
