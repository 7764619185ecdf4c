"""Seeded random round trip: for 200 random curves (dimension 1-4, random
alpha or grid, end condition, tension, sometimes Kochanek-Bartels values),
`crspline eval` at the knots the CLI reports returns the points.

Why 1e-12: at a knot t(i) the owning segment starts there (u = 0 exactly,
the point is its origin), and at the last knot the segment's cubic is summed
at u = 1: a few roundings of coefficients of the size of the coordinates.
Scale = the largest |coordinate|, so 1e-12 leaves a factor of ~1000 over eps.

Set CRSPLINE_CLI_SEED to replay a run; the seed is in every failure message.
"""
import math
import os
import random

from cli_support import max_abs, run_json

CURVES = 200
SEED = int(os.environ.get("CRSPLINE_CLI_SEED", "20240611"))


def random_curve(rng):
    dim = rng.randint(1, 4)
    closed = rng.random() < 0.25
    n = rng.randint(3 if closed else 2, 9)
    size = 10 ** rng.uniform(-3, 3)
    offset = [rng.choice([0.0, 0.0, 10 ** rng.uniform(0, 6)]) for _ in range(dim)]
    points = [[offset[d] + size * rng.uniform(-1, 1) for d in range(dim)] for _ in range(n)]
    doc = {"points": points}
    kind = rng.choice(["alpha", "alpha", "named", "grid", "default"])
    if kind == "alpha":
        doc["alpha"] = rng.random()
    elif kind == "named":
        doc["alpha"] = rng.choice([0, 0.5, 1])
    elif kind == "grid":
        t, grid = rng.uniform(-5, 5), []
        for _ in range(n + 1 if closed else n):
            grid.append(t)
            t += rng.uniform(0.01, 3)
        doc["grid"] = grid
    if closed:
        doc["end"] = "closed"
    else:
        def one_end():
            return rng.choice(["natural", "reflect", [rng.uniform(-5, 5) * size for _ in range(dim)]])
        doc["end"] = rng.choice(["natural", "reflect", {"start": one_end(), "end": one_end()}])
    if rng.random() < 0.5:
        doc["tension"] = rng.random()
    if rng.random() < 0.2:
        doc["kb"] = {k: [rng.uniform(-1, 1) for _ in range(n)] for k in rng.sample(["tension", "continuity", "bias"], 2)}
    return doc


def test_eval_at_the_knots_returns_the_points():
    rng = random.Random(SEED)
    checked, dims = 0, set()
    for k in range(CURVES):
        doc = random_curve(rng)
        where = f"seed {SEED}, curve {k}: {doc}"
        grid = run_json("eval", dict(doc, t=[], knots=True))["grid"]
        pts = doc["points"]
        closed = doc.get("end") == "closed"
        assert len(grid) == len(pts) + (1 if closed else 0), where
        assert all(b > a for a, b in zip(grid, grid[1:])), where
        out = run_json("eval", dict(doc, t=grid, derivatives=[0, 1]))
        got = out["values"]["0"]
        expected = pts + [pts[0]] if closed else pts  # a closed curve returns to points[0]
        scale = max_abs(pts)
        for i, (g, e) in enumerate(zip(got, expected)):
            err = max(abs(a - b) for a, b in zip(g, e))
            assert err <= 1e-12 * scale, f"knot {i}: {g} vs {e}, error {err:.3g} > {1e-12 * scale:.3g}; {where}"
        assert all(math.isfinite(x) for v in out["values"]["1"] for x in v), where
        checked += 1
        dims.add(len(pts[0]))
    assert checked == CURVES, f"seed {SEED}"
    assert dims == {1, 2, 3, 4}, f"seed {SEED}: dimensions {dims}"
