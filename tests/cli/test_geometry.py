"""`crspline length`, `crspline sample` and `crspline eval` with arc lengths.

Lengths are checked against the oracle's 30-digit segment lengths (1e-12
relative, SOURCES.md) and closed forms; arc-length sampling by the spacing
of the printed points along the curve; tolerance sampling by dense
evaluation of the curve between consecutive vertices (the polyline must stay
within the tolerance); every error has its exact line.
"""
import json
import math
import random

from cli_support import load_reference, run, run_json


def test_length_of_oracle_segments():
    checked = 0
    for case in load_reference("oracle.json")["cases"]:
        out = run_json("length", {"points": case["points"], "alpha": case["alpha"], "tension": case["tension"]})
        assert len(out["segments"]) == 3
        exact = float(case["arc_length_hp"])
        assert abs(out["segments"][1] - exact) <= 1e-12 * exact + 1e-300, (case["name"], out["segments"][1], exact)
        assert abs(out["total"] - sum(out["segments"])) <= 1e-14 * out["total"] + 1e-300
        checked += 1
    # The data file's case count: guards against the file silently shrinking.
    assert checked == 38


def test_length_of_a_straight_line_at_each_accuracy():
    pts = [[0, 0, 0], [1, 2, 2], [1.5, 3, 3], [4, 8, 8]]  # collinear, uneven
    for acc in (1e-2, 1e-6, 1e-12):
        out = run_json("length", {"points": pts, "accuracy": acc})
        assert abs(out["total"] - 12.0) <= acc * 12.0, (acc, out["total"])
        assert out["accuracy"] == acc


def dist_point_segment(p, a, b):
    ab = [y - x for x, y in zip(a, b)]
    ap = [y - x for x, y in zip(a, p)]
    L = sum(x * x for x in ab)
    w = 0.0 if L == 0 else max(0.0, min(1.0, sum(x * y for x, y in zip(ap, ab)) / L))
    return math.dist(p, [x + w * y for x, y in zip(a, ab)])


def test_sample_by_tolerance_stays_within_it():
    seed = 7001
    rng = random.Random(seed)
    for rep in range(12):
        pts = [[rng.uniform(-5, 5), rng.uniform(-5, 5)] for _ in range(6)]
        closed = rep % 3 == 0
        tol = 10.0 ** -rng.randint(1, 5)
        doc = {"points": pts, "alpha": rng.choice([0, 0.5, 1]), "tolerance": tol}
        if closed:
            doc["end"] = "closed"
        out = run_json("sample", doc)
        t, v = out["t"], out["points"]
        assert out["tolerance"] == tol
        assert t == sorted(t) and len(t) == len(v) >= 2
        # Dense evaluation of each polyline piece's stretch of curve.
        dense = []
        for k in range(len(t) - 1):
            dense += [t[k] + (t[k + 1] - t[k]) * j / 16 for j in range(17)]
        base = {key: doc[key] for key in doc if key != "tolerance"}
        pos = run_json("eval", dict(base, t=dense))["values"]["0"]
        for k in range(len(t) - 1):
            for j in range(17):
                d = dist_point_segment(pos[17 * k + j], v[k], v[k + 1])
                # 1e-9 relative slack: rounding of the printed vertices.
                assert d <= tol * (1 + 1e-9) + 1e-12, f"seed {seed} rep {rep}: {d} > {tol}"
        if closed:
            assert v[0] == v[-1]


def test_sample_by_count_in_t_and_in_arc_length():
    pts = [[0, 0], [1, 2], [3, 1], [4, 4], [6, 0]]
    by_t = run_json("sample", {"points": pts, "count": 9})
    grid = run_json("bezier", {"points": pts})["grid"]
    assert by_t["t"][0] == grid[0] and by_t["t"][-1] == grid[-1]
    steps = [b - a for a, b in zip(by_t["t"], by_t["t"][1:])]
    assert max(steps) - min(steps) <= 1e-14 * grid[-1]
    assert by_t["points"][0] == pts[0] and by_t["points"][-1] == pts[-1]
    by_s = run_json("sample", {"points": pts, "count": 9, "spacing": "arc_length"})
    total = run_json("length", {"points": pts})["total"]
    assert by_s["s"][-1] == total
    # Each consecutive pair is total / 8 apart along the curve, measured by an
    # independent length: Gauss-Legendre on the speed |c'(t)| from `eval`
    # (derivative 1 at given t, no arc-length table), 3 points on 64 panels
    # per smooth stretch (pieces are split at the knots, where the speed's
    # derivative jumps). The speed is bounded away from 0 here, so the rule's
    # O(h^6) error is far below the accuracy.
    t = by_s["t"]
    assert len(t) == 9
    nodes = [(-math.sqrt(0.6), 5 / 9), (0.0, 8 / 9), (math.sqrt(0.6), 5 / 9)]
    panels = 64
    ts, ws, owner = [], [], []
    for k in range(8):
        cuts = [t[k]] + [g for g in grid if t[k] < g < t[k + 1]] + [t[k + 1]]
        for a, b in zip(cuts, cuts[1:]):
            h = (b - a) / panels
            for j in range(panels):
                mid = a + (j + 0.5) * h
                for x, w in nodes:
                    ts.append(mid + 0.5 * h * x)
                    ws.append(0.5 * h * w)
                    owner.append(k)
    speed = [math.hypot(*d) for d in run_json("eval", {"points": pts, "t": ts, "derivatives": [1]})["values"]["1"]]
    pieces = [0.0] * 8
    for k, w, v in zip(owner, ws, speed):
        pieces[k] += w * v
    for k in range(8):
        # The default accuracy is 1e-12 relative ('crspline sample --help');
        # the s -> t inversion and the printed t add a few of it.
        assert abs(pieces[k] - total / 8) <= 4e-12 * total, (k, pieces[k], total / 8)
    # The pieces add up to the total, and the total to the oracle-checked
    # length command's (the same table: consistency only).
    ev = run_json("eval", {"points": pts, "s": by_s["s"]})
    assert ev["t_of_s"] == by_s["t"]
    assert ev["values"]["0"] == by_s["points"]


def test_eval_with_arc_lengths_round_trips():
    pts = [[0, 0, 0], [1, 2, 0], [3, 1, 1], [4, 4, 2], [6, 0, 0]]
    total = run_json("length", {"points": pts})["total"]
    s = [0, total / 3, total / 2, total]
    out = run_json("eval", {"points": pts, "s": s, "derivatives": [0, 1], "knots": True})
    assert len(out["t_of_s"]) == 4 and out["t_of_s"][0] == 0 and out["t_of_s"][-1] == out["grid"][-1]
    assert out["values"]["0"][0] == pts[0] and out["values"]["0"][-1] == pts[-1]
    # s(t_of_s) via the length of the prefix curve: the prefix through a knot
    # has the same segments, so compare at the knots' arc lengths instead.
    lengths = run_json("length", {"points": pts})["segments"]
    knots_s = [sum(lengths[:i]) for i in range(len(pts))]
    back = run_json("eval", {"points": pts, "s": knots_s})["t_of_s"]
    for a, b in zip(back, out["grid"]):
        assert abs(a - b) <= 1e-11 * out["grid"][-1]


def check_error(args, text, line):
    p = run(args, text)
    assert p.returncode == 2, (p.returncode, p.stderr)
    assert p.stdout == ""
    assert p.stderr == f"crspline: {line}\n", p.stderr


ERRORS = [
    (["length", "-"], '{"points": [[0, 0], [1, 1]], "accuracy": 0}',
     "accuracy: expected a relative accuracy in (0, 1), got 0"),
    (["length", "-"], '{"points": [[0, 0], [1, 1]], "t": [0]}',
     "t: only 'crspline eval' takes this field, not 'crspline length'"),
    (["eval", "-"], '{"points": [[0, 0], [1, 1]], "t": [0], "s": [0]}',
     "give 't' (parameter values) or 's' (arc lengths), not both"),
    (["eval", "-"], '{"points": [[0, 0], [3, 4]], "s": [0, 6]}',
     "s[1]: s = 6 is outside the arc-length range [0, 5]"),
    (["eval", "-"], '{"points": [[0, 0], [3, 4]], "t": [0], "accuracy": 1e-6}',
     "accuracy: only used with 's' (arc lengths)"),
    (["sample", "-"], '{"points": [[0, 0], [1, 1]]}',
     "give 'count' (number of points) or 'tolerance' (largest distance to the curve), exactly one of them"),
    (["sample", "-"], '{"points": [[0, 0], [1, 1]], "count": 2.5}', "count: expected an integer >= 2, got 2.5"),
    (["sample", "-"], '{"points": [[0, 0], [1, 1]], "count": 3, "spacing": "u"}',
     'spacing: expected "t" or "arc_length", got "u"'),
    (["sample", "-"], '{"points": [[0, 0], [1, 1]], "tolerance": -1}', "tolerance: expected a distance > 0, got -1"),
    (["sample", "-"], '{"points": [[0, 0], [1, 1]], "tolerance": 1, "spacing": "t"}',
     "spacing: only used with 'count'"),
]


def test_geometry_errors():
    for args, text, line in ERRORS:
        check_error(args, text, line)
