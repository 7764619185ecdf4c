"""`"tangents"` in the JSON curve description: a cubic Hermite curve with the
given dx/dt at each point (catmull_rom::hermite). Expected values are closed
forms: a cubic polynomial is reproduced from its own points and derivatives.
"""
import random

from cli_support import max_abs, run, run_json

SEED = 1515


def cubic(a, b, c, d):
    def f(t):
        return [ak + bk * t + ck * t * t + dk * t**3 for ak, bk, ck, dk in zip(a, b, c, d)]

    def df(t):
        return [bk + 2 * ck * t + 3 * dk * t * t for bk, ck, dk in zip(b, c, d)]
    return f, df


def test_a_cubic_is_reproduced_from_its_tangents():
    # Points and exact derivatives of one cubic on an uneven grid: the
    # Hermite curve is that cubic. Tolerance 1e-12 of the values' size: a
    # few roundings of terms that size on each side.
    rng = random.Random(SEED)
    checked = 0
    for dim in (1, 2, 3, 4):
        coef = [[rng.uniform(-2, 2) for _ in range(dim)] for _ in range(4)]
        f, df = cubic(*coef)
        grid = [0.0]
        for _ in range(4):
            grid.append(grid[-1] + rng.uniform(0.2, 1.5))
        doc = {"points": [f(t) for t in grid], "grid": grid, "tangents": [df(t) for t in grid]}
        ts = [grid[0] + (grid[-1] - grid[0]) * k / 20 for k in range(21)]
        out = run_json("eval", dict(doc, t=ts, derivatives=[0, 1]))
        scale = max(1.0, max_abs([f(t) for t in ts]), max_abs([df(t) for t in ts]))
        for t, p, v in zip(ts, out["values"]["0"], out["values"]["1"]):
            assert max(abs(x - y) for x, y in zip(p, f(t))) <= 1e-12 * scale, f"seed {SEED}, dim {dim}, t {t}"
            assert max(abs(x - y) for x, y in zip(v, df(t))) <= 1e-12 * scale, f"seed {SEED}, dim {dim}, t {t}"
            checked += 1
    assert checked == 4 * 21


def test_incoming_and_outgoing_tangents():
    # Vertex 1 arrives with (1, 1) and leaves with (1, -1): at the knot (owned
    # by the segment on its right) dx/dt is the outgoing one; segment 0 is
    # the Hermite cubic with m0 = (1, 0), m1 = (1, 1): y(1/2) = -1/8.
    doc = {"points": [[0, 0], [1, 0], [2, 0]], "grid": [0, 1, 2],
           "tangents": {"in": [[0, 0], [1, 1], [1, 0]], "out": [[1, 0], [1, -1], [0, 0]]}}
    out = run_json("eval", dict(doc, t=[0.5, 1], derivatives=[0, 1]))
    assert max(abs(a - b) for a, b in zip(out["values"]["0"][0], [0.5, -0.125])) <= 1e-15
    assert max(abs(a - b) for a, b in zip(out["values"]["1"][1], [1, -1])) <= 1e-15


def test_closed_with_tangents_and_alpha_knots():
    # Closed square, centripetal knots (each side 1: intervals 1), tangents
    # (0, 0): every side is P_i + (3u^2 - 2u^3)(P_{i+1} - P_i).
    doc = {"points": [[0, 0], [1, 0], [1, 1], [0, 1]], "end": "closed", "alpha": 0.5,
           "tangents": [[0, 0]] * 4}
    out = run_json("eval", dict(doc, t=[0.25, 3.5, 4]))
    w = 3 * 0.25**2 - 2 * 0.25**3
    expected = [[w, 0], [0, 0.5], [0, 0]]
    for got, e in zip(out["values"]["0"], expected):
        assert max(abs(a - b) for a, b in zip(got, e)) <= 1e-15


def error_line(doc):
    import json
    p = run(["eval", "-"], json.dumps(dict(doc, t=[0])))
    assert p.returncode == 2, p
    return p.stderr.strip()


def test_tangent_errors_name_the_field_and_index():
    base = {"points": [[0, 0], [1, 0], [2, 1]]}
    assert error_line(dict(base, tangents=[[1, 0], [1, 0]])) == \
        "crspline: tangents: expected 3 tangents (one per point), got 2"
    assert error_line(dict(base, tangents=[[1, 0], [1, 0, 0], [1, 0]])) == \
        "crspline: tangents[1]: expected 2 coordinates like points[0], got 3"
    assert error_line(dict(base, tangents=[[1, 0], [1, "x"], [1, 0]])).startswith("crspline: tangents[1][1]: ")
    assert error_line(dict(base, tangents=[[1, 0]] * 3, tension=0.5)) == \
        "crspline: tangents: given tangents take no 'tension'"
    assert error_line(dict(base, tangents=[[1, 0]] * 3, end="reflect")) == \
        "crspline: tangents: given tangents take no end conditions (only \"closed\": true or \"end\": \"closed\")"
    assert error_line(dict(base, tangents={"in": [[1, 0]] * 3})).startswith(
        "crspline: tangents: expected {\"in\": [...], \"out\": [...]}")
