"""Writes report_cases.json: a few curves and the analysis report `crspline
analyze` prints for each (the schema of docs/report.md). The CLI, Python and
web tests check that their front end reports the same keys and values.

    CRSPLINE_BIN=build/rel/cli/crspline /usr/bin/python3 tests/reference/make_report_cases.py

Each case's `curve` has `points` (nested lists), `alpha`, and optionally
`closed` and `tension`; each front end takes them in its own words (the
CLI's "end": "closed", Python's endconditions="closed", the web's closed:
true): cli_input() here and in the tests.
"""
import json
import math
import os
import pathlib
import subprocess

HERE = pathlib.Path(__file__).resolve().parent

ARC = [[math.cos(a / 10), math.sin(a / 10)] for a in range(0, 12)]
HELIX = [[math.cos(a / 2), math.sin(a / 2), a / 4] for a in range(0, 8)]
CASES = [
    # A short edge between two long ones: the uniform curve loops inside
    # segment 1 (the paper's Figure 2); the certificate fails rule 1.
    ("uniform_loop", {"points": [[0, 0], [1, 1], [1.1, 1], [2, 0]], "alpha": 0}),
    # An exact cusp at u = 1/2 of segment 1 (SOURCES.md).
    ("uniform_cusp", {"points": [[-5, 1], [0, 0], [1, 0], [6, 1]], "alpha": 0}),
    # A closed figure eight: crossings between segments.
    ("closed_figure_eight", {"points": [[1, 1], [2, 0], [1, -1], [-1, 1], [-2, 0], [-1, -1]], "alpha": 0.5,
                             "closed": True}),
    # A gentle centripetal arc: certified.
    ("certified_arc", {"points": ARC, "alpha": 0.5}),
    # Segments 0 and 2 cross; chordal knots.
    ("chordal_crossing", {"points": [[0, 0], [2, 2], [2, 0], [0, 2]], "alpha": 1}),
    # Tension: no paper bounds (distance_bound null).
    ("tension", {"points": [[0, 0], [1, 2], [3, 3], [4, 0], [6, 1]], "alpha": 0.5, "tension": 0.3}),
    # A 3-D helix: closest approaches, not crossings.
    ("helix_3d", {"points": HELIX, "alpha": 0.5}),
    # 1-D, increasing: no fold (a 1-D curve that reverses overlaps itself in a
    # continuum, thousands of meetings: not a fixture).
    ("line_1d", {"points": [[0], [1], [3], [4.5]], "alpha": 0.5}),
    # 7-D: the wide (zero-padded) curve reports 7 coordinates.
    ("seven_d", {"points": [[k * (j + 1) % 5 + 0.25 * j for j in range(7)] for k in range(5)], "alpha": 0.5}),
]


def cli_input(curve):
    """The curve as `crspline analyze` reads it."""
    doc = {k: v for k, v in curve.items() if k != "closed"}
    if curve.get("closed"):
        doc["end"] = "closed"
    return doc


def main():
    binary = os.environ.get("CRSPLINE_BIN", "build/rel/cli/crspline")
    out = []
    for name, curve in CASES:
        p = subprocess.run([binary, "analyze"], input=json.dumps(cli_input(curve)), capture_output=True, text=True, check=True)
        out.append({"name": name, "curve": curve, "report": json.loads(p.stdout)})
    doc = {"about": "crspline analyze's report of each curve (docs/report.md); written by make_report_cases.py",
           "cases": out}
    (HERE / "report_cases.json").write_text(json.dumps(doc, indent=1) + "\n")


if __name__ == "__main__":
    main()
