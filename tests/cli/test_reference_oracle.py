"""`crspline eval` and `crspline bezier` against the 50-digit oracle of one
segment (tests/reference/oracle.json).

Each case is one segment from P1 to P2 with neighbours P0 and P3. Given the
four points, the middle segment (index 1) of the open curve through them is
that segment: its tangents at P1 and P2 use only P0..P3, so the end
conditions ("reflect" here) change only segments 0 and 2.

Scale: the tolerance is relative to the segment's own size,
scale = max |P - P1| over the four points, not to the coordinates' magnitude.
SOURCES.md: "the plain pyramid loses 3e-8 at a 1e8 offset, while 6e-16 * scale
is reachable": crspline evaluates relative to a nearby control point, so its
error follows the size of the segment, and a tolerance relative to 1e8 would
let a 3e-8 loss through. One more term: the oracle's values are binary64
roundings of the 50-digit values, and so are crspline's, so two correct
answers may differ by one ulp of the coordinates' magnitude (1.5e-8 at 1e8,
1e-15 near 5): that ulp is added to every tolerance.
"""
import math

from cli_support import load_reference, max_abs, max_diff, run_json, ulp_of

REL = 1e-13  # SOURCES.md: positions and Bezier points to 1e-13 * scale


def segment_scale(points):
    p1 = points[1]
    return max(abs(x - o) for p in points for x, o in zip(p, p1))


def check_case(case):
    pts, alpha, tension = case["points"], case["alpha"], case["tension"]
    curve = {"points": pts, "alpha": alpha, "tension": tension, "end": "reflect"}
    bez = run_json("bezier", curve)
    grid = bez["grid"]
    # The knots: the CLI's grid is the oracle's, up to rounding of the chord powers.
    assert max_diff(grid, case["knots"]) <= 4e-16 * max(1.0, max_abs(case["knots"])), (grid, case["knots"])
    scale = segment_scale(pts)
    tol = REL * scale + ulp_of(pts)

    # Bezier control points of segment 1.
    assert len(bez["segments"]) == 3
    err = max_diff(bez["segments"][1], case["bezier"])
    assert err <= tol, f"bezier: error {err:.3g} > {tol:.3g}: {bez['segments'][1]} vs {case['bezier']}"

    # Positions (and dx/dt) at the oracle's u values, mapped onto the CLI's grid.
    t1, t2 = grid[1], grid[2]
    t = [t1 + u * (t2 - t1) for u in case["u"]]
    constant = case["knots"][2] == case["knots"][1]
    orders = [0] if constant else [0, 1]
    out = run_json("eval", dict(curve, t=t, derivatives=orders))
    err = max_diff(out["values"]["0"], case["position"])
    assert err <= tol, f"position: error {err:.3g} > {tol:.3g}"
    if constant:
        # A zero knot interval between identical points: a constant segment; the
        # oracle gives no d/dt there (d_dt is null).
        assert case["d_dt"] is None or any(v is None for v in case["d_dt"])
        return "position"
    # The derivative to the same relative tolerance, relative to its own scale
    # (the largest |dx/dt| the oracle gives on the segment); rounding of the
    # positions enters through 1/h, hence the ulp / h term.
    dscale = max_abs(case["d_dt"])
    dtol = REL * max(dscale, scale / (t2 - t1)) + ulp_of(pts) / (t2 - t1)
    err = max_diff(out["values"]["1"], case["d_dt"])
    assert err <= dtol, f"d_dt: error {err:.3g} > {dtol:.3g}: {out['values']['1']} vs {case['d_dt']}"
    return "position+d_dt"


def test_every_oracle_case():
    data = load_reference("oracle.json")
    cases = data["cases"]
    failures, kinds = {}, {"position": 0, "position+d_dt": 0}
    for case in cases:
        try:
            kinds[check_case(case)] += 1
        except AssertionError as e:
            failures[case["name"]] = str(e).splitlines()[0]
    assert not failures, "\n".join(f"{name}: {msg}" for name, msg in failures.items())
    # Every case checked; only the constant segments (P1 == P2) without d/dt.
    assert sum(kinds.values()) == len(cases) == 38
    constant = sum(c["knots"][2] == c["knots"][1] for c in cases)
    assert kinds["position"] == constant == 2, kinds
