#!/usr/bin/python3
"""Frames along a pose curve, and the angular-acceleration jumps of SciPy's
RotationSpline as shipped beside crspline's converged one.

    PYTHONPATH=build-py/python MPLCONFIGDIR=$(mktemp -d) \
        /usr/bin/python3 examples/python/plot_rotation.py [out.png]

Writes docs/rotation.png by default (the figure in docs/rotation.md). Needs
SciPy (apt python3-scipy) for the right panel.
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
from scipy.spatial.transform import Rotation, RotationSpline  # noqa: E402

from crspline import rotation  # noqa: E402


def walk(rng, n, lo_deg, hi_deg):
    """Keys [w, x, y, z], each turned from the last by lo..hi degrees about a random axis."""
    r = [Rotation.random(random_state=rng.integers(2**31))]
    for _ in range(n - 1):
        axis = rng.normal(size=3)
        r.append(Rotation.from_rotvec(axis / np.linalg.norm(axis) * np.radians(rng.uniform(lo_deg, hi_deg))) * r[-1])
    return Rotation.concatenate(r)


def frames(ax, rng):
    # A camera path: a rising helix of 8 positions, orientations 30-60 degrees apart.
    n = 8
    a = np.linspace(0, 1.5 * np.pi, n)
    pos = np.column_stack([3 * np.cos(a), 3 * np.sin(a), np.linspace(0, 3, n)])
    keys = walk(rng, n, 30, 60).as_quat()[:, [3, 0, 1, 2]]
    pose = rotation.PoseCurve(pos, keys)
    t = pose.constant_speed_times(40)  # equal steps of path length
    p, q, _, _ = pose.evaluate(t)
    m = rotation.as_matrix(q)
    ax.plot(*pose.evaluate(np.linspace(pose.grid[0], pose.grid[-1], 400))[0].T, color="0.4", lw=1)
    for axis, color in enumerate(("#d62728", "#2ca02c", "#1f77b4")):
        d = m[:, :, axis] * 0.45
        ax.quiver(*p.T, *d.T, color=color, lw=1, arrow_length_ratio=0.2)
    ax.scatter(*pos.T, color="k", s=12, depthshade=False)
    ax.set_title("body frames along a pose curve\n(x red, y green, z blue; equal path steps)", fontsize=9)
    ax.set_box_aspect((1, 1, 0.5))
    for f in (ax.set_xticklabels, ax.set_yticklabels, ax.set_zticklabels):
        f([])


def jumps(ax, rng):
    # 20 keys, 160-170 degree steps, uneven times: SciPy's 10 rounds stop short.
    n = 20
    keys = walk(rng, n, 160, 170)
    times = np.cumsum(rng.uniform(0.5, 1.5, n))
    theirs, ours = RotationSpline(times, keys), rotation.RotationSpline(times, keys)
    k = times[1:-1]
    # SciPy's jump seen 1e-9 of the span either side of the key: the
    # measurement's own floor, 2e-9 span |jerk|, is near 1e-6 here.
    d = 1e-9 * (times[-1] - times[0])
    scipy_jump = np.linalg.norm(theirs(k + d, 2) - theirs(k - d, 2), axis=1)
    seg = np.arange(1, n - 1)
    left = ours._c.evaluate_on(seg - 1, k, 2, "body")[2]
    right = ours._c.evaluate_on(seg, k, 2, "body")[2]
    ours_jump = np.maximum(np.linalg.norm(left - right, axis=1), 1e-17)  # exact zeros drawn at the floor
    x = np.arange(1, n - 1)
    ax.bar(x - 0.2, scipy_jump, 0.4, color="#ff7f0e", label="SciPy 1.10 RotationSpline (as shipped)")
    ax.bar(x + 0.2, ours_jump, 0.4, color="#1f77b4", label="crspline (Newton, converged)")
    ax.set_yscale("log")
    ax.set_ylim(1e-17, 10)
    ax.set_xticks(x[::2])
    ax.set_xlabel("interior key")
    ax.set_ylabel("|angular-acceleration jump| (rad/s²)")
    ax.set_title("C² in name and in fact: the jump at each key\n(20 keys, 160–170° steps)", fontsize=9)
    ax.legend(fontsize=8, loc="center right")


def main(out):
    rng = np.random.default_rng(28)
    fig = plt.figure(figsize=(10, 4.4), dpi=120)
    frames(fig.add_subplot(1, 2, 1, projection="3d"), rng)
    jumps(fig.add_subplot(1, 2, 2), rng)
    fig.subplots_adjust(left=0.02, right=0.98, bottom=0.12, top=0.88, wspace=0.15)
    fig.savefig(out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "docs" / "rotation.png")
