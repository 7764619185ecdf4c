"""GIS smoothing at scale (issue 29): lines of 10-50 vertices smoothed,
measured and decided by crspline.geo, in one process and through Dask.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/geo_bench.py \
        [--sizes 10000,100000[,1000000]] [--reps R] [--dask-lines N] [--out FILE.json] [--smoke]

What is timed, per size n (lines per second per core: the core runs on one
thread, so the rate is per core):
  * smooth:  crspline.geo.smooth(series, tolerance=...): arcs, smoothing,
             the crossing proof ("decided"), lengths and deviations;
  * measure: crspline.geo.measure(series, tolerance=...): length, deviation
             and verdict of the curves through the vertices (no smoothing);
  * time per line at each n: flat from 10^4 to 10^6 means linear.
The Dask path (crspline.geo.dask.smooth on a LocalCluster of 2 one-thread
workers, 4 partitions) is timed against the single-process smooth on the
same --dask-lines lines; its overhead is the ratio.

The lines are seeded random walks (10-50 vertices, steps 0.5-1.5 units,
turns within +-60 degrees), one per cell of a grid with 100-unit spacing,
so they do not cross (the proof still checks every nearby pair); CRS
EPSG:3857 (projected, metres): no geodesic step. Timings on a loaded
machine are not figures: BENCHMARKS.md records the run that made them.
"""
import argparse
import json
import math
import statistics
import sys
import time

import numpy as np


def random_lines(n, seed=29):
    """n LineStrings of 10-50 vertices, one per 100x100 cell (seeded)."""
    from shapely.geometry import LineString

    rng = np.random.default_rng(seed)
    side = max(1, math.ceil(math.sqrt(n)))
    lines = []
    for i in range(n):
        m = int(rng.integers(10, 51))
        turns = rng.uniform(-math.pi / 3, math.pi / 3, m - 1)
        heading = rng.uniform(0, 2 * math.pi) + np.cumsum(turns)
        steps = rng.uniform(0.5, 1.5, m - 1)
        xy = np.zeros((m, 2))
        xy[1:, 0] = np.cumsum(steps * np.cos(heading))
        xy[1:, 1] = np.cumsum(steps * np.sin(heading))
        xy -= xy.mean(axis=0)  # a walk of 50 steps of <= 1.5 stays within 75 of its mean
        xy += [100.0 * (i % side), 100.0 * (i // side)]
        lines.append(LineString(xy))
    return lines


def best_of(reps, fn):
    times = []
    result = None
    for _ in range(reps):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return min(times), statistics.median(times), result


def bench_single(n, reps, tolerance):
    import geopandas as gpd

    import crspline.geo

    series = gpd.GeoSeries(random_lines(n), crs="EPSG:3857")
    vertices = int(sum(len(g.coords) for g in series))
    rows = {}
    for name, fn in (("smooth", lambda: crspline.geo.smooth(series, tolerance=tolerance)),
                     ("measure", lambda: crspline.geo.measure(series, tolerance=tolerance))):
        best, median, out = best_of(reps, fn)
        # What was timed did the work: one row per line, every status ok.
        assert len(out) == n, (name, len(out), n)
        bad = int((out["status"] != "ok").sum())
        assert bad == 0, f"{name}: {bad} lines not ok at n={n}"
        rows[name] = {"best_s": best, "median_s": median, "lines_per_s": n / best, "us_per_line": 1e6 * best / n}
    return {"lines": n, "vertices": vertices, **rows}


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
    single_best, _, single = best_of(reps, lambda: crspline.geo.smooth(series, tolerance=tolerance))
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster):
        dask_best, _, out = best_of(
            reps, lambda: crspline.geo.dask.smooth(ddf, crs="EPSG:3857", tolerance=tolerance).compute())
    # The Dask rows are the single-process rows (checked, not assumed).
    assert len(out) == n
    assert list(out["geometry"]) == [g.wkb for g in single.geometry]
    return {"lines": n, "single_s": single_best, "dask_s": dask_best, "overhead": dask_best / single_best}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="10000,100000")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--tolerance", type=float, default=0.01)
    ap.add_argument("--dask-lines", type=int, default=10000)
    ap.add_argument("--out")
    ap.add_argument("--smoke", action="store_true", help="tiny sizes, one rep: checks the script runs")
    args = ap.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    reps, dask_lines = args.reps, args.dask_lines
    if args.smoke:
        sizes, reps, dask_lines = [200, 400], 1, 200

    results = {"single": [bench_single(n, reps, args.tolerance) for n in sizes]}
    print(f"{'lines':>9} {'vertices':>10} {'smooth lines/s':>15} {'us/line':>9} {'measure lines/s':>16} {'us/line':>9}")
    for r in results["single"]:
        print(f"{r['lines']:>9} {r['vertices']:>10} {r['smooth']['lines_per_s']:>15.0f} "
              f"{r['smooth']['us_per_line']:>9.2f} {r['measure']['lines_per_s']:>16.0f} "
              f"{r['measure']['us_per_line']:>9.2f}")
    if dask_lines > 0:
        d = bench_dask(dask_lines, reps, args.tolerance)
        results["dask"] = d
        print(f"Dask (LocalCluster 2x1, 4 partitions), {d['lines']} lines: {d['dask_s']:.3f} s against "
              f"{d['single_s']:.3f} s in one process: overhead x{d['overhead']:.2f}")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump(results, f, indent=2)
    return 0


if __name__ == "__main__":  # the Dask workers import this file: no cluster at import
    sys.exit(main())
