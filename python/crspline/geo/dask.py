"""crspline.geo on a Dask DataFrame whose geometry column holds WKB bytes.

``smooth(ddf, crs=..., tolerance=...)`` gives the rows that
``crspline.geo.smooth`` gives on the same layer in one process, byte for
byte (geometry as WKB out), with the same options and columns.

How the work is spread (and what is not yet): decoding the WKB of each
partition and encoding the results run on the workers, partition by
partition; the smoothing itself (topology, arcs, proof) runs as ONE task
over the whole layer, so a boundary shared by features in different
partitions is still one arc, smoothed once, and the rows match the
single-process path exactly. That task needs the layer's vertices in one
worker's memory: the arc-keyed shuffle that would smooth arcs on many
workers (group arcs by their end vertices) is not implemented yet.

``write_partitions(result, directory, crs=...)`` writes one file per
partition (GeoJSON by default; any fiona driver), each on a worker.
"""
from __future__ import annotations

import os

__all__ = ["smooth", "write_partitions"]

_OUT_COLUMNS = ("length", "max_deviation", "verdict", "status")


def _decode(df, geometry):
    """A partition's WKB column as Shapely geometries (None stays None)."""
    from shapely import wkb

    return [None if b is None else wkb.loads(bytes(b)) for b in df[geometry]]


def _smooth_all(decoded, crs, options):
    """The whole layer in one call of crspline.geo.smooth: per partition,
    the columns to add (geometry WKB and the four measures)."""
    import geopandas as gpd

    from . import smooth as smooth_series

    sizes = [len(d) for d in decoded]
    geoms = [g for d in decoded for g in d]
    series = gpd.GeoSeries(geoms, crs=crs)
    out = smooth_series(series, **options)
    results, k = [], 0
    for n in sizes:
        part = out.iloc[k:k + n]
        results.append({
            "geometry": [None if g is None else g.wkb for g in part.geometry],
            "length": part["length"].to_numpy(),
            "max_deviation": part["max_deviation"].to_numpy(),
            "verdict": part["verdict"].to_list(),
            "status": part["status"].to_list(),
        })
        k += n
    return results


def _assemble(df, result, geometry):
    out = df.copy()
    out[geometry] = result["geometry"]
    for c in _OUT_COLUMNS:
        out[c] = result[c]
    return out


def smooth(ddf, *, crs, geometry="geometry", alpha=0.5, tolerance=None, max_deviation=None, topology="preserve"):
    """Smooth a Dask DataFrame's WKB geometry column (see crspline.geo.smooth
    for the options and columns). `crs`: the layer's CRS (anything pyproj
    takes). Returns a lazy Dask DataFrame with the same partitions, index
    and columns, the geometry smoothed (WKB) and the four measure columns."""
    import dask
    import dask.dataframe as dd
    import pandas as pd

    for c in _OUT_COLUMNS:
        if c in ddf.columns:
            raise ValueError(f"the input already has a column named {c!r}; rename it first")
    if geometry not in ddf.columns:
        raise ValueError(f"no geometry column {geometry!r} in the Dask DataFrame (columns: {list(ddf.columns)})")
    if tolerance is None:
        raise ValueError("tolerance is required (a distance in the layer's units, metres on a geographic CRS)")
    options = dict(alpha=alpha, tolerance=tolerance, max_deviation=max_deviation, topology=topology)
    parts = ddf.to_delayed()
    decoded = [dask.delayed(_decode)(p, geometry) for p in parts]
    whole = dask.delayed(_smooth_all)(decoded, crs, options)
    meta = ddf._meta.copy()
    for c, dtype in zip(_OUT_COLUMNS, ("f8", "f8", "object", "object")):
        meta[c] = pd.Series([], dtype=dtype)
    outs = [dask.delayed(_assemble)(p, whole[i], geometry) for i, p in enumerate(parts)]
    return dd.from_delayed(outs, meta=meta, divisions=ddf.divisions)


def _write(df, path, crs, geometry, driver):
    import geopandas as gpd
    from shapely import wkb

    geoms = [None if b is None else wkb.loads(bytes(b)) for b in df[geometry]]
    gdf = gpd.GeoDataFrame(df.drop(columns=[geometry]), geometry=gpd.GeoSeries(geoms, index=df.index, crs=crs),
                           crs=crs)
    gdf.to_file(path, driver=driver)
    return path


def write_partitions(ddf, directory, *, crs, geometry="geometry", driver="GeoJSON", extension=None):
    """Write one file per partition (part-00000.geojson, ...) into
    `directory`, each by a task on a worker; returns the paths."""
    import dask

    ext = extension or {"GeoJSON": "geojson", "GPKG": "gpkg", "ESRI Shapefile": "shp"}.get(driver, "dat")
    os.makedirs(directory, exist_ok=True)
    tasks = [dask.delayed(_write)(p, os.path.join(directory, f"part-{i:05d}.{ext}"), crs, geometry, driver)
             for i, p in enumerate(ddf.to_delayed())]
    return list(dask.compute(*tasks))
