"""Hypothesis properties, mirroring the C++ suite (tests/property):
interpolation at the knots, C1 at the knots, reversal, affine invariance,
and the arc-length round trip. Tolerances are k * eps * scale with the
reason for k next to each."""
import numpy as np
from hypothesis import assume, given, strategies as st

import crspline
from conftest import EPS, magnitude_of, scale_of

coordinate = st.floats(min_value=-100, max_value=100, allow_nan=False, allow_infinity=False)
alphas = st.sampled_from([0.0, 0.25, 0.5, 0.75, 1.0])
dims = st.integers(min_value=1, max_value=4)


@st.composite
def polygons(draw, min_points=2, max_points=9, dim=None, distinct=True):
    """Random points; consecutive ones distinct and not nearly coincident
    (relative to the polygon's size) unless distinct=False."""
    d = draw(dims) if dim is None else dim
    n = draw(st.integers(min_value=min_points, max_value=max_points))
    p = np.array(draw(st.lists(st.lists(coordinate, min_size=d, max_size=d), min_size=n, max_size=n)))
    if distinct:
        size = scale_of(p)
        assume(size > 1e-3)
        chords = np.linalg.norm(np.diff(p, axis=0), axis=1)
        assume(np.all(chords > 1e-3 * size))
    return p


@given(polygons(dim=None, distinct=False), alphas, st.booleans())
def test_interpolates_its_points_at_the_knots(p, alpha, closed):
    assume(not closed or len(p) >= 3)
    c = crspline.CatmullRom(p, alpha=alpha, endconditions="closed" if closed else "natural")
    g = c.grid
    x = c.evaluate(g[:len(p)])
    # Exact: every segment is stored relative to its first point, so u = 0
    # gives that point bit for bit; the last knot returns the last point.
    # Where knots coincide (points equal up to the 8-ulp coincidence test of
    # the core) the later segment owns the knot: within 8 eps of the scale.
    unique = np.array([np.sum(g == v) == 1 for v in g[:len(p)]])
    assert np.array_equal(x[unique], p[unique])
    assert np.all(np.abs(x - p) <= 8 * EPS * magnitude_of(p))
    if not closed:
        assert np.array_equal(c.evaluate(c.grid[-1]), p[-1])
    else:
        assert np.array_equal(c.evaluate(c.grid[-1]), p[0])


@given(polygons(min_points=3), alphas)
def test_c1_at_the_knots(p, alpha):
    c = crspline.CatmullRom(p, alpha=alpha)
    g = c.grid
    h = np.diff(g)
    for i in range(1, len(g) - 1):
        # Left limit: the previous segment's cubic at its end (the knot
        # itself belongs to the right segment). delta = 1e-7 of the shorter
        # interval: the derivative moves by delta * |x''| at most, and the
        # rounding of t (eps * t / delta relative) stays far below that.
        delta = 1e-7 * min(h[i - 1], h[i])
        left = c.evaluate(g[i] - delta, 1)
        right = c.evaluate(g[i], 1)
        acc = max(np.abs(c.evaluate(g[i] - delta, 2)).max(), np.abs(c.evaluate(g[i], 2)).max())
        speed = np.abs(right).max() + np.abs(left).max()
        tol = 2 * delta * acc + 1e4 * EPS * g[i] / delta * speed * h[i - 1] + 64 * EPS * speed
        assert np.max(np.abs(left - right)) <= tol, (i, left, right, tol)


def test_second_derivative_jumps_at_a_knot():
    # C1, not C2: a generic polygon has a jump in x'' at interior knots.
    c = crspline.CatmullRom([[0, 0], [1, 2], [3, 1], [4, 3]])
    g = c.grid
    left = c.evaluate_unchecked(g[1] - 1e-12, 2)  # still the previous cubic up to 1e-12 * x'''
    seg0 = c.to_bezier()[0]
    h0 = g[1] - g[0]
    exact_left = 6 * (seg0[3] - 2 * seg0[2] + seg0[1]) / h0**2  # x'' at the end of segment 0
    assert np.allclose(left, exact_left, rtol=1e-9)
    assert np.linalg.norm(exact_left - c.evaluate(g[1], 2)) > 0.1


@given(polygons(), alphas)
def test_reversal_traces_the_same_curve_backwards(p, alpha):
    c = crspline.CatmullRom(p, alpha=alpha)
    r = crspline.CatmullRom(p[::-1], alpha=alpha)
    T = c.domain[1]
    # Same knot intervals in reverse order (summed the other way: a few ulps
    # of T apart).
    assert abs(r.domain[1] - T) <= 8 * EPS * T
    t = np.linspace(0, T, 25)
    tr = np.clip(r.domain[1] - t, 0, r.domain[1])
    scale = magnitude_of(p)
    # Both are the same cubics evaluated from the other end: rounding of the
    # coefficients and of t (times the speed) only.
    speed = np.abs(c.evaluate(t, 1)).max()
    tol = 1e-12 * scale + 64 * EPS * T * speed
    assert np.max(np.abs(c.evaluate(t) - r.evaluate(tr))) <= tol


@given(polygons(dim=2), alphas, st.floats(-3, 3), st.floats(-3, 3), st.floats(-50, 50), st.floats(-50, 50),
       st.lists(st.floats(-2, 2), min_size=4, max_size=4))
def test_affine_invariance(p, alpha, log_scale, angle, bx, by, m):
    # Uniform knots: any affine map commutes with the curve. alpha > 0: a
    # similarity s R x + b scales the knots by s^alpha.
    b = np.array([bx, by])
    if alpha == 0:
        A = np.array(m).reshape(2, 2)
        tscale = 1.0
    else:
        s = np.exp(log_scale)
        A = s * np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
        tscale = s**alpha
    q = p @ A.T + b
    assume(alpha == 0 or np.all(np.linalg.norm(np.diff(q, axis=0), axis=1) > 1e-3 * scale_of(q)))
    c = crspline.CatmullRom(p, alpha=alpha)
    d = crspline.CatmullRom(q, alpha=alpha)
    t = np.linspace(*c.domain, 21)
    td = np.minimum(t * tscale, d.domain[1])  # the product can round past t_max
    size = magnitude_of(q) + magnitude_of(p) * np.abs(A).max() + np.abs(b).max()
    # 1e-12 as the C++ test: the maps' own rounding plus that of the knots.
    assert np.max(np.abs(c.evaluate(t) @ A.T + b - d.evaluate(td))) <= 1e-12 * size


@given(polygons(), alphas, st.booleans())
def test_arc_length_round_trip(p, alpha, closed):
    assume(not closed or len(p) >= 3)
    if closed:
        assume(np.linalg.norm(p[0] - p[-1]) > 1e-3 * scale_of(p))
    c = crspline.CatmullRom(p, alpha=alpha, endconditions="closed" if closed else "natural")
    L = c.arc_length()
    # The length is at least the polygon's (chords) and at most the Bézier
    # control polygons' (convex hull property, per segment).
    b = c.to_bezier()
    chords = np.linalg.norm(b[:, 3] - b[:, 0], axis=1).sum()
    hull = np.linalg.norm(np.diff(b, axis=1), axis=2).sum()
    assert chords * (1 - 1e-12) <= L <= hull * (1 + 1e-12)
    s = np.linspace(0, L, 40)
    t = c.t_at_arc_length(s)
    assert np.all(np.diff(t) >= 0) and t[0] == c.domain[0]
    # Round trip in arc length: the inverse meets the accuracy promise
    # (1e-12 relative; 2e-12 as the C++ geometry test).
    assert np.max(np.abs(c.arc_length_at(t) - s)) <= 2e-12 * L + 1e-300
    # Knot lengths add up the segments.
    k = c.knot_arc_lengths()
    assert k[0] == 0 and abs(k[-1] - L) <= 1e-12 * L
    assert abs(c.arc_length(c.grid[1], c.grid[-1]) - (L - k[1])) <= 1e-11 * L


@given(polygons(dim=2), alphas)
def test_sample_by_arc_length_is_evenly_spaced(p, alpha):
    c = crspline.CatmullRom(p, alpha=alpha)
    r = c.sample(11)
    L = c.arc_length()
    assert np.allclose(r["s"], np.linspace(0, L, 11), rtol=0, atol=1e-14 * L)
    assert np.max(np.abs(c.arc_length_at(r["t"]) - r["s"])) <= 2e-12 * L
    assert np.array_equal(r["points"], c.evaluate(r["t"]))


@given(polygons(), alphas, st.integers(0, 3))
def test_float32_agrees_with_double(p, alpha, order):
    p32 = p.astype(np.float32)
    c32 = crspline.CatmullRom(p32, alpha=alpha)
    c64 = crspline.CatmullRom(p32.astype(np.float64), alpha=alpha)
    t = np.linspace(*c64.domain, 17)
    t32 = np.minimum(t.astype(np.float32), c32.domain[1])
    x32 = c32.evaluate(t32, order)
    x64 = c64.evaluate(np.minimum(t32.astype(np.float64), c64.domain[1]), order)
    assert x32.dtype == np.float32
    # Same inputs to float rounding; knots and coefficients carry relative
    # error ~ a few float eps amplified by the polygon's conditioning.
    ref = np.abs(x64).max() + magnitude_of(p) / max(np.diff(c64.grid).min(), 1e-30) ** order
    assume(np.isfinite(ref))
    assert np.max(np.abs(x32 - x64)) <= 1e-3 * ref
