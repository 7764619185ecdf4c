"""GIS smoothing at scale (issue 29): lines of 10-50 vertices smoothed,
measured and decided by crspline.geo, in one process and through Dask.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/geo_bench.py \
        [--sizes 10000,100000[,1000000]] [--frame-sizes 10000,100000] [--reps R] \
        [--dask-lines N] [--out FILE.json] [--smoke]

What is timed, per size n:
  * core (flat coordinate arrays through the binding, one call for the
    whole layer: what crspline.geo hands the C++ core, without the
    GeoPandas objects):
      - smooth:  arcs, smoothing, the crossing proof ("decided"), lengths,
                 deviations and the output polylines;
      - measure: the same curves and proof, lengths, deviations and
                 verdicts, no output polylines (smooth_options::polylines
                 false: "measured and decided");
      - length:  lengths and deviations of the curves through the
                 vertices, each line alone, no proof ("length only");
  * frame (--frame-sizes): crspline.geo.smooth and crspline.geo.measure on
    a GeoSeries, the Shapely objects in and out included;
  * time per line at each n: flat from 10^4 to 10^6 means linear.
Rates are lines per second per core: the core runs on the calling thread,
and the rate is taken from the process's CPU time (time.process_time), so
other processes on a shared machine slow the wall clock but not the rate
as much; wall-clock rates are printed beside them.
The Dask path (crspline.geo.dask.smooth on a LocalCluster of 2 one-thread
workers, 4 partitions) is timed against the single-process smooth on the
same --dask-lines lines; its overhead is the ratio.

The lines are seeded random walks (10-50 vertices, steps 0.5-1.5 units,
turns within +-60 degrees, so some cross themselves and the proof has
crossings to find), one per cell of a grid with 100-unit spacing, so no
two lines meet (the proof still looks for every nearby pair); CRS
EPSG:3857 (projected, metres): no geodesic step. Timings on a loaded
machine are not figures: BENCHMARKS.md records the run that made them.
"""
import argparse
import json
import math
import resource
import statistics
import sys
import time

import numpy as np


def random_layer(n, seed=29):
    """n seeded walks as flat arrays: xy (V, 2), part offsets (n + 1)."""
    rng = np.random.default_rng(seed)
    m = rng.integers(10, 51, n)
    offsets = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(m, out=offsets[1:])
    total = int(offsets[-1])
    line = np.repeat(np.arange(n), m)
    first = offsets[:-1]
    # Headings: a start per line, then turns within +-60 degrees, summed per line.
    turn = rng.uniform(-math.pi / 3, math.pi / 3, total)
    turn[first] = rng.uniform(0, 2 * math.pi, n)
    heading = np.cumsum(turn)
    heading -= np.repeat(heading[first] - turn[first], m)
    step = rng.uniform(0.5, 1.5, total)
    step[first] = 0.0  # the first vertex is the walk's start
    xy = np.column_stack((np.cumsum(step * np.cos(heading)), np.cumsum(step * np.sin(heading))))
    xy -= np.repeat(xy[first], m, axis=0)
    # Centred in its cell: a walk of 49 steps of <= 1.5 stays within 74 of its mean.
    sums = np.add.reduceat(xy, first, axis=0)
    xy -= np.repeat(sums / m[:, None], m, axis=0)
    side = max(1, math.ceil(math.sqrt(n)))
    cell = np.column_stack((100.0 * (np.arange(n) % side), 100.0 * (np.arange(n) // side)))
    xy += np.repeat(cell, m, axis=0)
    return np.ascontiguousarray(xy), offsets


def random_lines(n, seed=29):
    """The same walks as Shapely LineStrings."""
    from shapely.geometry import LineString

    xy, offsets = random_layer(n, seed)
    return [LineString(xy[offsets[i]:offsets[i + 1]]) for i in range(n)]


def best_of(reps, fn):
    """(best CPU seconds, best wall seconds, last result)."""
    cpu, wall = [], []
    result = None
    for _ in range(reps):
        c0, w0 = time.process_time(), time.perf_counter()
        result = fn()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
    return min(cpu), min(wall), result


def rate(n, cpu, wall):
    return {"cpu_s": cpu, "wall_s": wall, "lines_per_s": n / cpu, "us_per_line": 1e6 * cpu / n,
            "wall_lines_per_s": n / wall}


CORE_ROWS = (("smooth", True, True), ("measure", True, False), ("length", False, False))


def bench_core(n, reps, tolerance, rows_wanted=("smooth", "measure", "length")):
    from crspline import _crspline

    xy, offsets = random_layer(n)
    z = np.zeros((len(xy), 0))
    kinds = np.zeros(n, dtype=np.uint8)
    features = np.arange(n, dtype=np.int64)
    ok = _crspline._geo_statuses.index("ok")
    rows = {}
    for name, preserve, polylines in CORE_ROWS:
        if name not in rows_wanted:
            continue

        def run():
            return _crspline._geo_smooth(xy, z, offsets, kinds, features, n, 0.5, tolerance, None, preserve, None,
                                         polylines=polylines)

        cpu, wall, r = best_of(reps, run)
        # What was timed did the work: one report per line, every status ok,
        # and the proof ran (it finds the walks that cross themselves).
        assert len(r["status"]) == n, (name, len(r["status"]), n)
        bad = int((np.asarray(r["status"]) != ok).sum())
        assert bad == 0, f"{name}: {bad} lines not ok at n={n}"
        assert np.all(np.asarray(r["length"]) > 0), name
        if preserve:
            assert r["stats"]["input_crossings"] > 0, (name, dict(r["stats"]))
        rows[name] = {**rate(n, cpu, wall), "stats": {k: int(v) for k, v in r["stats"].items()},
                      "output_vertices": int(len(r["xy"]))}
        del r
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return {"lines": n, "vertices": int(len(xy)), "peak_rss_mb": peak, **rows}


def bench_frame(n, reps, tolerance):
    import geopandas as gpd

    import crspline.geo

    series = gpd.GeoSeries(random_lines(n), crs="EPSG:3857")
    rows = {}
    for name, fn in (("smooth", lambda: crspline.geo.smooth(series, tolerance=tolerance)),
                     ("measure", lambda: crspline.geo.measure(series, tolerance=tolerance))):
        cpu, wall, out = best_of(reps, fn)
        assert len(out) == n, (name, len(out), n)
        bad = int((out["status"] != "ok").sum())
        assert bad == 0, f"{name}: {bad} lines not ok at n={n}"
        rows[name] = rate(n, cpu, wall)
    return {"lines": n, **rows}


def bench_dask(n, reps, tolerance):
    import dask.dataframe as dd
    import geopandas as gpd
    import pandas as pd
    from distributed import Client, LocalCluster

    import crspline.geo
    import crspline.geo.dask

    lines = random_lines(n)
    series = gpd.GeoSeries(lines, crs="EPSG:3857")
    df = pd.DataFrame({"name": [f"line {i}" for i in range(n)], "geometry": [g.wkb for g in lines]})
    ddf = dd.from_pandas(df, npartitions=4)
    _, single_best, single = best_of(reps, lambda: crspline.geo.smooth(series, tolerance=tolerance))
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster):
        _, dask_best, out = best_of(
            reps, lambda: crspline.geo.dask.smooth(ddf, crs="EPSG:3857", tolerance=tolerance).compute())
    # The Dask rows are the single-process rows (checked, not assumed).
    assert len(out) == n
    assert list(out["geometry"]) == [g.wkb for g in single.geometry]
    return {"lines": n, "single_s": single_best, "dask_s": dask_best, "overhead": dask_best / single_best}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="10000,100000")
    ap.add_argument("--frame-sizes", default="10000,100000")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--tolerance", type=float, default=0.01)
    ap.add_argument("--dask-lines", type=int, default=10000)
    ap.add_argument("--rows", default="smooth,measure,length",
                    help="core rows to time (10^6 lines: smooth peaks at about 5.7 GB, measure 2.7 GB, length 1.9 GB; BENCHMARKS.md)")
    ap.add_argument("--out")
    ap.add_argument("--smoke", action="store_true", help="tiny sizes, one rep: checks the script runs")
    args = ap.parse_args()
    sizes = [int(s) for s in args.sizes.split(",") if s]
    frame_sizes = [int(s) for s in args.frame_sizes.split(",") if s]
    reps, dask_lines = args.reps, args.dask_lines
    if args.smoke:
        sizes, frame_sizes, reps, dask_lines = [200, 400], [200], 1, 200

    results = {"tolerance": args.tolerance, "core": [], "frame": []}
    print(f"core, flat arrays (tolerance {args.tolerance}): lines per second per core (CPU time), us per line; "
          "wall-clock lines/s in brackets")
    print(f"{'lines':>9} {'vertices':>10} {'smooth':>22} {'measure':>22} {'length':>22} {'peak MB':>8}")
    for n in sizes:
        r = bench_core(n, reps, args.tolerance, args.rows.split(","))
        results["core"].append(r)
        cells = [f"{r[k]['lines_per_s']:>8.0f} {r[k]['us_per_line']:>6.1f} [{r[k]['wall_lines_per_s']:>6.0f}]"
                 if k in r else "-" for k in ("smooth", "measure", "length")]
        print(f"{n:>9} {r['vertices']:>10} {cells[0]:>22} {cells[1]:>22} {cells[2]:>22} {r['peak_rss_mb']:>8.0f}",
              flush=True)
    if len(results["core"]) > 1:
        for k in args.rows.split(","):
            us = [r[k]["us_per_line"] for r in results["core"]]
            print(f"  {k}: time per line from {sizes[0]} to {sizes[-1]} lines: x{us[-1] / us[0]:.2f}")
    if frame_sizes:
        print("GeoDataFrame front end (crspline.geo.smooth / measure, Shapely objects in and out)")
        print(f"{'lines':>9} {'smooth':>22} {'measure':>22}")
        for n in frame_sizes:
            r = bench_frame(n, reps, args.tolerance)
            results["frame"].append(r)
            cells = [f"{r[k]['lines_per_s']:>8.0f} {r[k]['us_per_line']:>6.1f} [{r[k]['wall_lines_per_s']:>6.0f}]"
                     for k in ("smooth", "measure")]
            print(f"{n:>9} {cells[0]:>22} {cells[1]:>22}", flush=True)
    if dask_lines > 0:
        d = bench_dask(dask_lines, reps, args.tolerance)
        results["dask"] = d
        print(f"Dask (LocalCluster 2x1, 4 partitions), {d['lines']} lines: {d['dask_s']:.3f} s against "
              f"{d['single_s']:.3f} s in one process (wall): overhead x{d['overhead']:.2f}")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump(results, f, indent=2)
    return 0


if __name__ == "__main__":  # the Dask workers import this file: no cluster at import
    sys.exit(main())
