#!/usr/bin/python3
"""Uniform, centripetal and chordal Catmull-Rom curves through one polygon.

    PYTHONPATH=build-py/python MPLCONFIGDIR=$(mktemp -d) \
        /usr/bin/python3 examples/python/plot_parameterizations.py [out.png]

Writes docs/python_parameterizations.png by default (the figure in
docs/python.md). Uniform knots give a cusp and a loop where the chords are
uneven; centripetal ones never do within a segment (and the analysis
certifies it); chordal ones hug long chords.
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

import crspline  # noqa: E402

# Short chords between long ones: where the three differ most (uniform
# knots loop at the small zigzag).
POINTS = np.array([[0.0, 0.0], [0.5, 3.0], [3.5, 3.2], [3.6, 3.0], [3.7, 3.2], [6.5, 3.0], [7.0, 0.0]])


def main(out):
    fig, ax = plt.subplots(figsize=(7.5, 5.2), dpi=120)
    # A zoom on the zigzag, in the empty middle of the figure.
    zoom = ax.inset_axes([0.3, 0.08, 0.4, 0.5])
    for a_ in (ax, zoom):
        a_.plot(*POINTS.T, color="0.6", lw=1, ls="--", marker="o", ms=5, mfc="white", label="control polygon",
                zorder=1)
    styles = [("uniform", crspline.uniform, "#d62728"), ("centripetal", crspline.centripetal, "#1f77b4"),
              ("chordal", crspline.chordal, "#2ca02c")]
    for name, alpha, color in styles:
        c = crspline.CatmullRom(POINTS, alpha=alpha)
        x = c.sample(600, by="t")["points"]  # one vectorized evaluate call
        a = c.analyze()
        notes = []
        if a["has_cusp"]:
            notes.append("cusp")
        if a["has_self_intersection"]:
            notes.append("loop (x)")
        label = f"{name} (alpha = {alpha:g})" + (f": {', '.join(notes)}" if notes else "")
        for a_ in (ax, zoom):
            a_.plot(*x.T, color=color, lw=2, label=label, zorder=2)
            # Mark where the curve meets itself (loops inside segments and
            # crossings between them).
            for meeting in a["intersections"]:  # docs/report.md
                a_.plot(*meeting["point"], marker="x", color=color, ms=9, mew=2, zorder=3)
    zoom.set_xlim(3.35, 3.85)
    zoom.set_ylim(2.9, 3.3)
    zoom.set_aspect("equal")
    zoom.set_xticks([])
    zoom.set_yticks([])
    ax.indicate_inset_zoom(zoom, edgecolor="0.4")
    ax.set_aspect("equal")
    ax.set_title("crspline: Catmull-Rom parameterizations (Python, natural ends)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=2, fontsize=9, frameon=False)
    ax.grid(alpha=0.25)
    ax.margins(0.05)
    fig.tight_layout()
    fig.savefig(out)
    print(f"wrote {out}")


if __name__ == "__main__":
    default = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python_parameterizations.png"
    main(sys.argv[1] if len(sys.argv) > 1 else default)
