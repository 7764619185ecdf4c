#!/usr/bin/python3
"""The figures of docs/sweep.md: a closed knot tube with and without the
seam fix, a banked road, a stroked glyph.

    PYTHONPATH=build/sweep/python /usr/bin/python3 examples/python/plot_sweep.py [OUT_DIR]

Writes sweep_knot.png, sweep_road.png and sweep_stroke.png into OUT_DIR
(default docs/).
"""
import os
import pathlib
import sys
import tempfile

os.environ.setdefault("MPLCONFIGDIR", tempfile.mkdtemp(prefix="mpl-"))
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import PathPatch  # noqa: E402
from matplotlib.path import Path  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import crspline  # noqa: E402

OUT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "docs")


def triangles(mesh):
    return mesh["positions"][mesh["indices"]]


def stripes(mesh, faces, light=(0.3, -0.5, 0.8)):
    """Face colours: 8 stripes around the tube by the quad's profile vertex
    (texture u), shaded by the normals."""
    idx = mesh["indices"][faces]
    m = mesh["ring_size"]
    j = (idx % m).min(axis=1)
    band = np.floor(8 * j / (m - 1)).astype(int) % 2
    n = mesh["normals"][idx].mean(axis=1)
    shade = 0.45 + 0.55 * np.clip(n @ (np.array(light) / np.linalg.norm(light)), 0, 1)
    base = np.where(band[:, None] == 0, [[0.85, 0.35, 0.1]], [[0.95, 0.9, 0.8]])
    return np.clip(base * shade[:, None], 0, 1)


def knot_points(n=12):
    a = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.c_[(2 + np.cos(3 * a)) * np.cos(2 * a), (2 + np.cos(3 * a)) * np.sin(2 * a), np.sin(3 * a)]


def knot_figure():
    c = crspline.CatmullRom(knot_points(), endconditions="closed")
    fig = plt.figure(figsize=(11, 5.2))
    for i, seamless in enumerate([False, True]):
        m = crspline.sweep(c, radius=0.35, tubular_segments=240, radial_segments=24, seamless=seamless)
        # The stretch of tube where the loop closes: the last rings and the first.
        rings, size = m["rings"], m["ring_size"]
        k = m["indices"][:, 0] // size
        faces = np.flatnonzero((k < 14) | (k >= rings - 15))
        ax = fig.add_subplot(1, 2, i + 1, projection="3d")
        tri = triangles(m)[faces]
        ax.add_collection3d(Poly3DCollection(tri, facecolors=stripes(m, faces), edgecolors="none"))
        lo, hi = tri.reshape(-1, 3).min(axis=0), tri.reshape(-1, 3).max(axis=0)
        mid, half = (lo + hi) / 2, (hi - lo).max() / 2
        ax.set_xlim(mid[0] - half, mid[0] + half), ax.set_ylim(mid[1] - half, mid[1] + half)
        ax.set_zlim(mid[2] - half, mid[2] + half)
        ax.view_init(elev=20, azim=-30)
        ax.set_axis_off()
        r = m["report"]
        title = ("holonomy spread evenly: the stripes run on (no seam)" if seamless
                 else f"frame carried once around, {np.degrees(abs(r['holonomy'])):.0f} deg off: a seam")
        ax.set_title(title, fontsize=10)
    fig.suptitle("Where a (2, 3) torus knot tube closes: 8 texture stripes around it", fontsize=12)
    fig.tight_layout()
    fig.savefig(OUT / "sweep_knot.png", dpi=90)
    plt.close(fig)


def road_figure():
    # A road over a hill with two bends; banked into each bend by roll keys at arc lengths.
    pts = np.array([[0, 0, 0], [6, 0, 0.5], [10, 3, 1.5], [10, 8, 2.0], [6, 11, 2.2], [1, 11, 1.6], [-3, 14, 1.0],
                    [-3, 19, 0.5]], dtype=float)
    c = crspline.CatmullRom(pts)
    L = c.arc_length()
    # The deck, 2.4 wide and 0.3 deep, counterclockwise in the (normal, binormal)
    # plane: the normal follows "up", so the deck's width lies along the binormal.
    deck = np.array([[-0.3, -1.2], [0.0, -1.2], [0.0, 1.2], [-0.3, 1.2]])
    road = crspline.sweep(c, profile=deck, profile_closed=True, up=[0, 0, 1],
                          roll=([0, 0.25 * L, 0.42 * L, 0.58 * L, 0.78 * L, L], [0, 0, -0.35, 0, 0.35, 0]),
                          tolerance=2e-3)
    fig = plt.figure(figsize=(8, 6))
    ax = fig.add_subplot(projection="3d")
    idx = road["indices"]
    n = road["normals"][idx].mean(axis=1)
    top = n[:, 2] > 0.5
    shade = 0.35 + 0.65 * np.clip(n @ np.array([0.4, -0.3, 0.87]), 0, 1)
    colour = np.where(top[:, None], [[0.35, 0.35, 0.4]], [[0.75, 0.45, 0.2]]) * shade[:, None]
    ax.add_collection3d(Poly3DCollection(triangles(road), facecolors=np.clip(colour, 0, 1), edgecolors="none"))
    centre = c.evaluate(np.linspace(*c.domain, 400))
    ax.plot(*centre.T, color="gold", lw=1.2)
    ax.set_xlim(-5, 12), ax.set_ylim(-1, 20), ax.set_zlim(-1, 4)
    ax.set_box_aspect((17, 21, 7), zoom=1.1)
    ax.view_init(elev=14, azim=-115)
    ax.set_axis_off()
    ax.set_title("A banked road: up = +z, roll keys at arc lengths (rotation splines)", fontsize=10)
    fig.tight_layout()
    fig.savefig(OUT / "sweep_road.png", dpi=90)
    plt.close(fig)


def glyph_figure():
    # An ampersand-like glyph: one stroke that crosses itself twice.
    pts = np.array([[6, 0], [4.5, 1.5], [2.5, 4], [1.5, 6], [2.5, 7.5], [4, 7], [4, 5.5], [1, 3], [0.3, 1.2],
                    [1.5, 0], [3.5, 0.3], [6, 3]], dtype=float)
    c = crspline.CatmullRom(pts)
    fig, axes = plt.subplots(1, 3, figsize=(12, 5))
    for ax, (join, cap, w) in zip(axes, [("round", "round", 0.9), ("round", "butt", 0.5), ("round", "square", 1.4)]):
        polys = crspline.stroke(c, w, join=join, cap=cap)
        verts, codes = [], []
        for rings in polys:
            for r in rings:
                verts += list(r) + [r[0]]
                codes += [Path.MOVETO] + [Path.LINETO] * (len(r) - 1) + [Path.CLOSEPOLY]
        ax.add_patch(PathPatch(Path(verts, codes), facecolor="#2b4c7e", edgecolor="#0b1c3e", lw=0.6))
        line = c.tessellate()["points"]
        ax.plot(*line.T, color="w", lw=0.7)
        holes = sum(len(p) - 1 for p in polys)
        nv = sum(len(r) for p in polys for r in p)
        ax.set_title(f"width {w}, {cap} caps: {len(polys)} polygon, {holes} holes, {nv} vertices", fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlim(-1.5, 7.5), ax.set_ylim(-1.5, 9)
        ax.set_axis_off()
    fig.suptitle("crspline.stroke: the union, simple polygons with holes (no self-overlapping outline)", fontsize=11)
    fig.tight_layout()
    fig.savefig(OUT / "sweep_stroke.png", dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    OUT.mkdir(parents=True, exist_ok=True)
    knot_figure()
    road_figure()
    glyph_figure()
    print("wrote", ", ".join(str(OUT / n) for n in ("sweep_knot.png", "sweep_road.png", "sweep_stroke.png")))
