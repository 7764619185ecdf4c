#!/usr/bin/python3
"""The figure and the numbers of docs/fit.md: one DEM contour (traced by
marching squares, tests/reference/fit/dem_jacksboro.txt) at a tolerance of
half a grid cell, four ways: the input, Ramer-Douglas-Peucker (as
simplify-js's high-quality mode), paper.js' Path.simplify (Schneider's
fitting, run in node from bench/js/fit; skipped when node or the package is
missing) and crspline.fit (subset and free). Each output's deviation both
ways is measured by dense sampling; crspline's is also proved.

    PYTHONPATH=build/rel/python /usr/bin/python3 examples/python/plot_fit.py [OUT.png]

Without an argument it writes docs/fit.png. It prints the table docs/fit.md shows.
"""
import json
import pathlib
import shutil
import subprocess
import sys

import numpy as np

import crspline

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "reference" / "fit" / "dem_jacksboro.txt"
LINE = "jacksboro_500_73"  # an open contour of 295 points with bends at every scale
TOL = 0.5


def read_line(name):
    words = CORPUS.read_text().split()
    i = 0
    while i < len(words):
        _, label, closed, tol, n = words[i:i + 5]
        n = int(n)
        pts = np.array(words[i + 5:i + 5 + 2 * n], dtype=float).reshape(n, 2)
        if label == name:
            return pts, closed == "1"
        i += 5 + 2 * n
    raise SystemExit(f"{name} not in {CORPUS}")


def rdp(pts, tol):
    """Ramer-Douglas-Peucker, distance to the segment (simplify-js, high quality)."""
    keep = np.zeros(len(pts), bool)
    keep[0] = keep[-1] = True
    stack = [(0, len(pts) - 1)]
    while stack:
        a, b = stack.pop()
        if b <= a + 1:
            continue
        d = seg_dist(pts[a + 1:b], pts[a][None], pts[b][None])[:, 0]
        k = int(np.argmax(d))
        if d[k] > tol:
            keep[a + 1 + k] = True
            stack += [(a, a + 1 + k), (a + 1 + k, b)]
    return pts[keep]


def seg_dist(p, a, b):
    """Distances of points p (M, 2) to segments a -> b (K, 2): (M, K)."""
    d = b - a
    w = p[:, None, :] - a[None]
    l2 = np.maximum((d * d).sum(-1), 1e-300)
    f = np.clip((w * d[None]).sum(-1) / l2, 0, 1)
    return np.linalg.norm(w - f[..., None] * d[None], axis=-1)


def both_ways(samples, pts):
    """Largest distance of the samples to the input polyline and of the input points to the samples' polyline."""
    c2i = seg_dist(samples, pts[:-1], pts[1:]).min(axis=1).max()
    i2c = seg_dist(pts, samples[:-1], samples[1:]).min(axis=1).max()
    return max(c2i, i2c)


def paper_cubics(pts, closed, tol):
    node = shutil.which("node")
    script = ROOT / "bench" / "js" / "fit_peers.mjs"
    if not node or not (ROOT / "bench" / "js" / "fit" / "node_modules" / "paper-jsdom").exists():
        return None
    doc = json.dumps({"points": pts.tolist(), "closed": closed, "tolerance": tol})
    out = subprocess.run([node, str(script), "--cubics"], input=doc, capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def bezier(cubics, per=64):
    t = np.linspace(0, 1, per, endpoint=False)[:, None]
    out = []
    for v in cubics:
        b = np.array(v).reshape(4, 2)
        out.append((1 - t) ** 3 * b[0] + 3 * (1 - t) ** 2 * t * b[1] + 3 * (1 - t) * t ** 2 * b[2] + t ** 3 * b[3])
    out.append(np.array(cubics[-1][6:8])[None])
    return np.vstack(out)


def main():
    out_path = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "fit.png"
    pts, closed = read_line(LINE)
    assert not closed
    rows = [("input (marching squares)", len(pts), "points", "—")]
    r_rdp = rdp(pts, TOL)
    rows.append(("Ramer–Douglas–Peucker", len(r_rdp), "vertices", f"{both_ways(r_rdp, pts):.3f}"))
    paper = paper_cubics(pts, closed, TOL)
    if paper:
        ps = bezier(paper["cubics"])
        rows.append(("paper.js Path.simplify", len(paper["cubics"]), "cubics (3 points each)",
                     f"{both_ways(ps, pts):.3f}"))
    fits = {}
    for mode in ("subset", "free"):
        r = crspline.fit(pts, tolerance=TOL, mode=mode)
        s = r.curve.evaluate(np.linspace(r.curve.grid[0], r.curve.grid[-1], 200 * r.count))
        fits[mode] = (r, s)
        rows.append((f"crspline.fit, {mode}", r.count, "control points",
                     f"{both_ways(s, pts):.3f} (proved ≤ {r.deviation:.3f})"))
    print(f"Contour {LINE} of dem_jacksboro.txt, tolerance {TOL} (half a grid cell)\n")
    print("| method | count | of | deviation both ways, measured |")
    print("| --- | --- | --- | --- |")
    for name, n, what, dev in rows:
        print(f"| {name} | {n} | {what} | {dev} |")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), sharex=True, sharey=True)
    panels = [("input: %d points" % len(pts), None, None),
              ("Ramer–Douglas–Peucker: %d vertices" % len(r_rdp), r_rdp, r_rdp),
              (("paper.js simplify: %d cubics" % len(paper["cubics"])) if paper else "paper.js: not available",
               bezier(paper["cubics"]) if paper else None, None),
              ("crspline.fit (subset): %d control points, proved ≤ %.3f" % (fits["subset"][0].count,
                                                                          fits["subset"][0].deviation),
               fits["subset"][1], fits["subset"][0].curve.points)]
    for ax, (title, line, marks) in zip(axes.flat, panels):
        ax.plot(pts[:, 0], pts[:, 1], color="0.75", lw=2.5, zorder=1)
        ax.plot(pts[:, 0], pts[:, 1], ".", color="0.45", ms=2.5, zorder=2)
        if line is not None:
            ax.plot(line[:, 0], line[:, 1], color="C3", lw=1.1, zorder=3)
        if marks is not None:
            ax.plot(marks[:, 0], marks[:, 1], "o", color="C0", ms=3, zorder=4)
        ax.set_title(title, fontsize=10)
        ax.set_aspect("equal")
    fig.suptitle(f"One DEM contour (grid units), tolerance {TOL} cell: grey the input, red the output", fontsize=11)
    fig.tight_layout()
    fig.savefig(out_path, dpi=90)
    print(f"\nwrote {out_path}")


if __name__ == "__main__":
    main()
