"""Issue 13, item 4, through the command line: knot intervals keep their precision.

The curve through [0,-1e6], [0,0], [1,0], [1+1e-9,1e-9] with alpha 1 has a
chord of 1.4e-9 after knots near 1e6. `crspline bezier`, `analyze` and `eval`
must give segment 1 as computed from the intervals themselves; the reference
is that curve in 50-digit decimal arithmetic from the same binary64 inputs
(no running sums). Tolerances: the library's own test
(tests/analysis/test_knot_intervals.cpp) bounds the double Bezier points of
segment 1 (coordinates at most 1.5) by 32 eps; the printed numbers are
shortest round-trip decimals, so they add nothing. 1e-14 leaves room; the
old code was off by 3e-3.
"""
import json
from decimal import Decimal, getcontext

from cli_support import run, run_json

getcontext().prec = 50

POINTS = [[0, -1000000], [0, 0], [1, 0], [1.000000001, 0.000000001]]
DOC = {"points": POINTS, "alpha": 1}
TOL = 1e-14


def reference():
    """Intervals, vertex tangents at P1 and P2, and segment 1's Bezier points, in Decimal."""
    p = [[Decimal(float(x)) for x in q] for q in POINTS]
    h = [((p[k + 1][0] - p[k][0]) ** 2 + (p[k + 1][1] - p[k][1]) ** 2).sqrt() for k in range(3)]

    def tangent(k):  # [h1^2 (Pk - Pk-1) + h0^2 (Pk+1 - Pk)] / [h0 h1 (h0 + h1)]
        h0, h1 = h[k - 1], h[k]
        return [(h1 * h1 * (p[k][c] - p[k - 1][c]) + h0 * h0 * (p[k + 1][c] - p[k][c])) / (h0 * h1 * (h0 + h1))
                for c in range(2)]

    m1, m2 = tangent(1), tangent(2)
    b1 = [p[1][c] + h[1] / 3 * m1[c] for c in range(2)]
    b2 = [p[2][c] - h[1] / 3 * m2[c] for c in range(2)]
    return p, h, b1, b2


def bezier_at(b, u):
    v = 1 - u
    return [v ** 3 * b[0][c] + 3 * u * v * v * b[1][c] + 3 * u * u * v * b[2][c] + u ** 3 * b[3][c] for c in range(2)]


def max_distance_to_chord(p, b1, b2):
    """Segment 1's chord is (0,0)-(1,0) and its Bezier x coordinates lie in [0, 1]:
    the distance is |y(u)|, largest where y'(u) = 0."""
    assert all(0 <= x <= 1 for x in (b1[0], b2[0]))
    y1, y2 = b1[1], b2[1]
    a, b, c = 3 * (y1 - y2), 2 * y2 - 4 * y1, y1
    disc = b * b - 4 * a * c
    roots = [(-b + s * disc.sqrt()) / (2 * a) for s in (-1, 1)]
    inside = [u for u in roots if 0 <= u <= 1]
    assert inside
    return max(abs(bezier_at([p[1], b1, b2, p[2]], u)[1]) for u in inside)


def test_bezier_points_of_the_short_interval_curve():
    p, h, b1, b2 = reference()
    assert abs(float(b2[0]) - 0.764298) < 1e-6 and abs(float(b2[1]) + 0.235702) < 1e-6  # the figures
    out = run_json("bezier", DOC)
    seg = out["segments"][1]
    for got, want in zip(seg[1] + seg[2], b1 + b2):
        assert abs(got - float(want)) <= TOL, (seg, [float(x) for x in b1 + b2])
    # The knots are the rounded running sums: the last is 1e6 + 1 + 1.4e-9 to
    # the grid's precision (ulp(1e6) = 1.2e-10).
    assert abs(out["grid"][3] - float(h[0] + h[1] + h[2])) <= 2.5e-10


def test_analyze_distance_and_bound():
    p, h, b1, b2 = reference()
    want = max_distance_to_chord(p, b1, b2)
    assert abs(float(want) - 0.104756) < 1e-6  # the figure
    seg = run_json("analyze", DOC)["segments"][1]
    assert abs(seg["max_chord_distance"] - float(want)) <= TOL, seg["max_chord_distance"]
    # Eq. 6 two-sided for alpha 1: d2 / (4 (1 + d3/d2)) with d2 = 1: at most d2 / 4
    # (the old code printed 0.25308).
    assert seg["distance_bound"] <= 0.25
    assert abs(seg["distance_bound"] - float(Decimal("0.25") / (1 + h[2]))) <= TOL
    assert seg["max_chord_distance"] <= seg["distance_bound"]


def test_eval_in_segment_1():
    p, h, b1, b2 = reference()
    us = [k / 16 for k in range(16)]  # t = 1e6 + u is exact for these u
    r = run(["eval", "-", "--t", ",".join(repr(1e6 + u) for u in us)], json.dumps(DOC))
    assert r.returncode == 0, r.stderr
    values = json.loads(r.stdout)["values"]["0"]
    assert len(values) == len(us)
    for u, got in zip(us, values):
        want = bezier_at([p[1], b1, b2, p[2]], Decimal(u))
        assert max(abs(got[c] - float(want[c])) for c in range(2)) <= 4 * TOL, (u, got)
