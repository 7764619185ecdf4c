#!/usr/bin/python3
"""Builds the fit corpus (tests/reference/fit/*.txt) from real data shipped
by Debian packages; see README.md beside it. Run with Debian's python3:

    /usr/bin/python3 tests/reference/fit/make_corpus.py

Output format, one block per line (plain text, read by tests/fit and
bench/fit_bench.cpp):

    line <name> <closed 0|1> <tolerance> <count>
    x y            (count rows)
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SAMPLE = "/usr/share/matplotlib/mpl-data/sample_data"  # Debian: python3-matplotlib (matplotlib-data)


def contours(z, levels, min_points):
    """Marching-squares contours (contourpy, matplotlib's own) in grid units: x = column, y = row."""
    import contourpy
    gen = contourpy.contour_generator(z=np.asarray(z, dtype=np.float64), name="serial", line_type="Separate")
    out = []
    for lev in levels:
        for line in gen.lines(lev):
            if len(line) >= min_points:
                closed = bool(np.all(line[0] == line[-1]))
                pts = line[:-1] if closed else line
                out.append((f"{lev:g}", closed, pts))
    return out


def write(name, lines, tolerance_of):
    path = os.path.join(HERE, name)
    total = 0
    with open(path, "w") as f:
        for label, closed, pts in lines:
            tol = tolerance_of(pts)
            f.write(f"line {label} {int(closed)} {tol:.17g} {len(pts)}\n")
            for x, y in pts:
                f.write(f"{x:.10g} {y:.10g}\n")
            total += len(pts)
    print(f"{name}: {len(lines)} lines, {total} points", file=sys.stderr)


def main():
    # 1. DEM contours at half a grid cell: the Jacksboro fault DEM (USGS,
    #    344 x 403, 10 m cells) every 50 m, and the ETOPO topobathy sample
    #    (91 x 120) every 250 m; marching squares steps at the grid's scale.
    dem = np.load(os.path.join(SAMPLE, "jacksboro_fault_dem.npz"))["elevation"].astype(np.float64)
    lines = contours(dem, np.arange(300, 800, 50), 30)
    write("dem_jacksboro.txt", [(f"jacksboro_{l}_{i}", c, p) for i, (l, c, p) in enumerate(lines)], lambda p: 0.5)
    topo = np.load(os.path.join(SAMPLE, "topobathy.npz"))["topo"].astype(np.float64)
    lines = contours(topo, np.arange(-4000, 2000, 250), 20)
    write("dem_topobathy.txt", [(f"topobathy_{l}_{i}", c, p) for i, (l, c, p) in enumerate(lines)], lambda p: 0.5)
    # 2. Digitized outlines: New York City's borough boundaries (geopandas'
    #    nybb, NYC Department of City Planning, feet), rings of 200 to 4000
    #    points, at half their median vertex spacing (the digitizing's own
    #    detail), relative to the ring's first point.
    import geopandas as gpd
    import geopandas.datasets
    g = gpd.read_file(geopandas.datasets.get_path("nybb"))
    rings = []
    for name, geom in zip(g["BoroName"], g.geometry):
        for k, poly in enumerate(geom.geoms):
            c = np.asarray(poly.exterior.coords)[:-1]
            if 200 <= len(c) <= 4000:
                rings.append((f"nybb_{name.replace(' ', '_')}_{k}", True, c - c[0]))
    half_spacing = lambda p: 0.5 * float(np.median(np.linalg.norm(np.diff(p, axis=0), axis=1)))
    write("outlines_nybb.txt", rings, half_spacing)


if __name__ == "__main__":
    main()
