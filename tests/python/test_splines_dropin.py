"""crspline.splines as a drop-in for the `splines` package.

1. Every probe of tests/reference/splines_dropin_probes.json (what `splines`
   0.3.3 itself returned: numbers, shapes, types, exceptions) run through
   crspline.splines with `import splines` bound to it.
2. The patterns of the `splines` documentation the probes do not cover
   (subclass tangent hooks, closed Kochanek-Bartels curves with per-vertex
   TCB, more than 4 dimensions with alpha != 0, CubicHermite), against the
   `splines` formulas re-derived here and a Hermite evaluator written here,
   never against crspline itself.
"""
import builtins
import sys

import numpy as np
import pytest

from conftest import load_reference

from crspline import splines as compat

PROBES = load_reference("splines_dropin_probes.json")


# ------------------------------------------------------------------ probes
def _run_probe(case):
    """Runs the cells as the probe file's README says; returns {label: value or exception}."""
    got = {}
    counts = {}
    namespace = {"np": np}
    saved = sys.modules.get("splines")
    sys.modules["splines"] = compat  # `import splines` in a cell gets crspline.splines
    try:
        for cell in case["cells"]:
            cid = cell["id"]

            def record(label, value, cid=cid):
                k = counts.get(cid, 0)
                counts[cid] = k + 1
                got[f"{cid}.{k:02d}:{label}"] = value

            namespace["record"] = record
            try:
                exec(compile(cell["src"], f"<{case['id']} {cid}>", "exec"), namespace)
            except Exception as e:  # noqa: BLE001 - the probe records what was raised
                got[f"{cid}:exception"] = e
        for key, exp in case["expected"].items():
            if not key.startswith("probe["):
                continue
            var, what = key[len("probe["):].split("]:", 1)
            s = namespace[var]
            if what == "grid":
                got[key] = s.grid
            elif what.startswith("evaluate(grid, "):
                got[key] = s.evaluate(s.grid, int(what[len("evaluate(grid, "):-1]))
            elif what.startswith("evaluate(t_inner, "):
                got[key] = s.evaluate(exp["t"], int(what[len("evaluate(t_inner, "):-1]))
            else:
                raise AssertionError(f"unknown probe {key}")
    finally:
        if saved is None:
            del sys.modules["splines"]
        else:
            sys.modules["splines"] = saved
    return got


def _check(key, exp, actual):
    if exp["kind"] == "error":
        assert isinstance(actual, BaseException), f"{key}: expected {exp['type']}, got {actual!r}"
        cls = getattr(builtins, exp["type"])
        assert isinstance(actual, cls), f"{key}: expected {exp['type']}, got {type(actual).__name__}: {actual}"
        assert str(actual) == exp["msg"], f"{key}: message {str(actual)!r} != {exp['msg']!r}"
        return
    assert not isinstance(actual, BaseException), f"{key}: raised {type(actual).__name__}: {actual}"
    if exp["kind"] == "value":
        assert actual == exp["value"] and type(actual) is type(exp["value"]), \
            f"{key}: {actual!r} != {exp['value']!r}"
        return
    a = np.asarray(actual)
    assert a.dtype.kind in "fiu", f"{key}: dtype {a.dtype}"
    assert list(a.shape) == exp["shape"], f"{key}: shape {a.shape} != {tuple(exp['shape'])}"
    e = np.asarray(exp["data"], dtype=np.float64)
    # The file's tolerance: max(1e-12 * max(1, max|expected|), 1e-9 * |expected|) per number.
    tol = np.maximum(1e-12 * max(1.0, float(np.abs(e).max(initial=0))), 1e-9 * np.abs(e))
    err = np.abs(a.astype(np.float64).ravel() - e)
    assert np.all(err <= tol), f"{key}: worst error {err.max()} at {int(err.argmax())} (tolerance {tol[err.argmax()]})"


def test_probe_file_has_every_case():
    # 76 probes: the count guards against a truncated copy.
    assert len(PROBES["cases"]) == 76
    assert PROBES["splines_version"] == "0.3.3"


@pytest.mark.parametrize("case", PROBES["cases"], ids=[c["id"] for c in PROBES["cases"]])
def test_probe(case):
    got = _run_probe(case)
    unexpected = [k for k in got if k.endswith(":exception") and k not in case["expected"]]
    assert not unexpected, f"unexpected exceptions: {[(k, got[k]) for k in unexpected]}"
    for key, exp in case["expected"].items():
        assert key in got, f"{key}: nothing recorded"
        _check(key, exp, got[key])


# ------------------------------------------------ an independent evaluator
def hermite_eval(x, outgoing, incoming, grid, t, n=0):
    """Cubic Hermite curve through the rows of x on grid, segment i with
    dx/dt outgoing[i] at its start and incoming[i] at its end, written with
    the four Hermite basis polynomials (and their derivatives) of u."""
    x = np.asarray(x, float)
    grid = np.asarray(grid, float)
    out = []
    for tt in np.atleast_1d(t):
        i = len(grid) - 2 if tt == grid[-1] else int(np.searchsorted(grid, tt, side="right")) - 1
        h = grid[i + 1] - grid[i]
        u = (tt - grid[i]) / h
        basis = [
            [2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u, -2 * u**3 + 3 * u**2, u**3 - u**2],
            [6 * u**2 - 6 * u, 3 * u**2 - 4 * u + 1, -6 * u**2 + 6 * u, 3 * u**2 - 2 * u],
            [12 * u - 6, 6 * u - 4, -12 * u + 6, 6 * u - 2],
        ][n]
        p = basis[0] * x[i] + basis[1] * h * outgoing[i] + basis[2] * x[i + 1] + basis[3] * h * incoming[i]
        out.append(p / h**n)
    return np.array(out)


def knots(x, alpha):
    d = np.linalg.norm(np.diff(x, axis=0), axis=1)
    return np.concatenate([[0.0], np.cumsum(d**alpha)])


def sample_t(grid, per=7):
    """Points inside every segment and the knots."""
    grid = np.asarray(grid, float)
    inner = [grid[i] + (grid[i + 1] - grid[i]) * k / per for i in range(len(grid) - 1) for k in range(per)]
    return np.array(inner + [grid[-1]])


def close(a, b, scale):
    # The compared quantities are short sums of products of inputs of size
    # `scale`; both sides round them differently: 1e-12 relative is ~4500 ulp.
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-12 * max(1.0, scale))


# ------------------------------------------- subclass hooks of the splines docs
POINTS = np.array([(-1, -0.5), (0, 2.3), (1, 1), (4, 1.3), (3.8, -0.2), (2.5, 0.1)])  # the splines docs' points1
TIMES = [0, 1, 2.2, 3, 4, 4.5]  # non-uniform: the tangent variants differ


def natural_ends(x, grid, in_first_interior, out_last_interior):
    """splines' natural end condition: zero second derivative at each end,
    (3 chord velocity - the tangent at the segment's other end) / 2."""
    d0, d1 = grid[1] - grid[0], grid[-1] - grid[-2]
    start = (3 * (x[1] - x[0]) / d0 - in_first_interior) / 2
    end = (3 * (x[-1] - x[-2]) / d1 - out_last_interior) / 2
    return start, end


def open_curve_reference(x, grid, tangent_pairs):
    """Hermite data of an open splines curve from (incoming, outgoing) at the
    interior vertices and natural ends."""
    n = len(x)
    inc = np.array([p[0] for p in tangent_pairs])
    out = np.array([p[1] for p in tangent_pairs])
    start, end = natural_ends(x, grid, inc[0], out[-1])
    seg_out = np.concatenate([[start], out])       # segment i starts at vertex i
    seg_in = np.concatenate([inc, [end]])          # and ends at vertex i + 1
    assert len(seg_out) == len(seg_in) == n - 1
    return seg_out, seg_in


def mean_velocity(points, times):
    x_1, x0, x1 = np.asarray(points)
    t_1, t0, t1 = times
    return ((x0 - x_1) / (t0 - t_1) + (x1 - x0) / (t1 - t0)) / 2


def wikipedia(points, times):
    x_1, _, x1 = np.asarray(points)
    t_1, _, t1 = times
    return (x1 - x_1) / (t1 - t_1)


def x3d_pair(points, times):
    """X3D-style: the uniform tangent (x1 - x_1) / 2 scaled per side by
    2 h_side / (h_before + h_after); incoming and outgoing differ."""
    x_1, _, x1 = np.asarray(points)
    t_1, t0, t1 = times
    tangent = (x1 - x_1) / 2
    return 2 * (t0 - t_1) / (t1 - t_1) * tangent, 2 * (t1 - t0) / (t1 - t_1) * tangent


class MeanVelocity(compat.CatmullRom):
    calls = 0

    @staticmethod
    def _calculate_tangent(points, times):
        MeanVelocity.calls += 1
        return mean_velocity(points, times)


class Wikipedia(compat.CatmullRom):
    @staticmethod
    def _calculate_tangent(points, times):
        return wikipedia(points, times)


class X3D(compat.CatmullRom):
    def _calculate_tangents(self, points, times):
        return x3d_pair(points, times)


@pytest.mark.parametrize("cls, formula", [
    (MeanVelocity, lambda p, t: (mean_velocity(p, t),) * 2),
    (compat.FiniteDifference, lambda p, t: (mean_velocity(p, t),) * 2),
    (Wikipedia, lambda p, t: (wikipedia(p, t),) * 2),
    (X3D, x3d_pair),
])
def test_tangent_hooks_are_honoured(cls, formula):
    s = cls(POINTS, grid=TIMES)
    pairs = [formula(POINTS[i - 1:i + 2], TIMES[i - 1:i + 2]) for i in range(1, len(POINTS) - 1)]
    seg_out, seg_in = open_curve_reference(POINTS, TIMES, pairs)
    t = sample_t(TIMES)
    for n in range(3):
        close(s.evaluate(t, n), hermite_eval(POINTS, seg_out, seg_in, TIMES, t, n), 100)
    # The hook matters here: the plain Catmull-Rom curve is far from it.
    plain = compat.CatmullRom(POINTS, grid=TIMES)
    assert np.abs(plain.evaluate(t) - s.evaluate(t)).max() > 1e-3


def test_hook_is_called_once_per_interior_vertex():
    MeanVelocity.calls = 0
    MeanVelocity(POINTS, grid=TIMES)
    assert MeanVelocity.calls == len(POINTS) - 2
    MeanVelocity.calls = 0
    MeanVelocity(POINTS, endconditions="closed", alpha=0.5)
    assert MeanVelocity.calls == len(POINTS)


def test_hook_on_a_closed_curve():
    # Closed: every vertex is interior; the seam tangent uses the last and
    # the second vertex (splines' convention); the grid from alpha.
    s = Wikipedia(POINTS, endconditions="closed", alpha=0.5)
    x = np.concatenate([POINTS, POINTS[:1]])
    grid = knots(x, 0.5)
    assert s.grid == pytest.approx(list(grid), rel=1e-15)
    ext = np.concatenate([x, POINTS[1:2]])
    gext = np.concatenate([grid, [grid[-1] + grid[1] - grid[0]]])
    tang = np.array([wikipedia(ext[i - 1:i + 2], gext[i - 1:i + 2]) for i in range(1, len(ext) - 1)])
    # tang[k] belongs to vertex k + 1 of x; vertex 0 (= vertex N) is the last.
    at = np.concatenate([tang[-1:], tang])  # dx/dt at x[0], x[1], ..., x[N]
    t = sample_t(grid)
    for n in range(2):
        close(s.evaluate(t, n), hermite_eval(x, at[:-1], at[1:], grid, t, n), 10)


# ------------------------------------------- Kochanek-Bartels, closed, per vertex
def kb_pair(points, times, tcb):
    """The Kochanek-Bartels tangents on a non-uniform grid (splines docs)."""
    x_1, x0, x1 = np.asarray(points)
    t_1, t0, t1 = times
    T, C, B = tcb
    a, b = (1 - T) * (1 + C) * (1 + B), (1 - T) * (1 - C) * (1 - B)
    c, d = (1 - T) * (1 - C) * (1 + B), (1 - T) * (1 + C) * (1 - B)
    h0, h1 = t0 - t_1, t1 - t0
    denominator = h0 * h1 * (h0 + h1)
    incoming = (c * h1**2 * (x0 - x_1) + d * h0**2 * (x1 - x0)) / denominator
    outgoing = (a * h1**2 * (x0 - x_1) + b * h0**2 * (x1 - x0)) / denominator
    return incoming, outgoing


@pytest.mark.parametrize("alpha", [None, 0.5, 1])
def test_closed_kochanek_bartels_with_per_vertex_tcb(alpha):
    rng = np.random.default_rng(20261124)
    x = rng.normal(size=(6, 3))
    tcb = rng.uniform(-0.8, 0.8, size=(6, 3))  # vertex 0 first
    s = compat.KochanekBartels(x, tcb=tcb, alpha=alpha, endconditions="closed")
    xc = np.concatenate([x, x[:1]])
    grid = np.arange(7.0) if alpha is None else knots(xc, alpha)
    assert np.asarray(s.grid) == pytest.approx(grid, rel=1e-15)
    # Tangents at vertex k with its own TCB, neighbours wrapping around.
    h = np.diff(grid)
    pairs = []
    for k in range(6):
        hb, ha = h[k - 1], h[k]  # interval before (wrapping) and after vertex k
        pairs.append(kb_pair((x[k - 1], x[k], x[(k + 1) % 6]), (-hb, 0.0, ha), tcb[k]))
    inc = np.array([p[0] for p in pairs])
    out = np.array([p[1] for p in pairs])
    seg_out = out                                   # segment k leaves vertex k
    seg_in = np.concatenate([inc[1:], inc[:1]])     # and arrives at vertex k + 1
    t = sample_t(grid)
    for n in range(3):
        close(s.evaluate(t, n), hermite_eval(xc, seg_out, seg_in, grid, t, n), 1000)
    # Continuity != 0 breaks C1: just left of knot 2 the incoming tangent.
    left = s.evaluate(np.nextafter(grid[2], -np.inf), 1)
    close(left, inc[2], 1000)
    close(s.evaluate(grid[2], 1), out[2], 1000)


# --------------------------------------------------- more than 4 dimensions
@pytest.mark.parametrize("dim", [5, 6, 9])
def test_more_than_four_dimensions_with_alpha(dim):
    # The knots come from the full-dimensional chord lengths: a per-group
    # curve with its own alpha knots would be wrong; crspline.splines
    # computes the knots once and splits only the Hermite data.
    rng = np.random.default_rng(dim)
    x = rng.normal(size=(7, dim))
    s = compat.CatmullRom(x, alpha=0.5)
    grid = knots(x, 0.5)
    assert np.asarray(s.grid) == pytest.approx(grid, rel=1e-15)
    pairs = []
    for i in range(1, 6):
        h0, h1 = grid[i] - grid[i - 1], grid[i + 1] - grid[i]
        v = (h1**2 * (x[i] - x[i - 1]) + h0**2 * (x[i + 1] - x[i])) / (h0 * h1 * (h0 + h1))
        pairs.append((v, v))
    seg_out, seg_in = open_curve_reference(x, grid, pairs)
    t = sample_t(grid)
    for n in range(4 if dim < 9 else 2):
        if n == 3:
            continue
        close(s.evaluate(t, n), hermite_eval(x, seg_out, seg_in, grid, t, n), 100)
    assert s.evaluate(t).shape == (len(t), dim)
    assert len(s.segments) == 6 and s.segments[0].shape == (4, dim)


# --------------------------------------------------------- CubicHermite
def test_cubic_hermite_reproduces_a_cubic():
    # Points and exact derivatives of one cubic polynomial: the curve is that
    # polynomial (closed form), on any grid.
    a, b, c, d = np.array([1.0, -2]), np.array([0.5, 3]), np.array([-1.0, 0.25]), np.array([0.3, -0.7])

    def f(t):
        return a + b * t + c * t**2 + d * t**3

    def df(t):
        return b + 2 * c * t + 3 * d * t**2

    grid = [0.0, 0.4, 1.5, 2.0, 3.25]
    x = [f(t) for t in grid]
    tangents = [v for t0, t1 in zip(grid, grid[1:]) for v in (df(t0), df(t1))]
    s = compat.CubicHermite(x, tangents, grid)
    t = sample_t(grid)
    close(s.evaluate(t), np.array([f(tt) for tt in t]), 100)
    close(s.evaluate(t, 1), np.array([df(tt) for tt in t]), 100)
    # splines' layout: two tangents per segment, else ValueError.
    with pytest.raises(ValueError, match="Exactly 2 tangents per segment are needed"):
        compat.CubicHermite(x, tangents[:-1], grid)
    with pytest.raises(ValueError, match="As many grid times as vertices are needed"):
        compat.CubicHermite(x, tangents, grid[:-1])


def test_cubic_hermite_default_grid_and_segments():
    # Uniform grid 0, 1, ...; one segment from (0, 0) to (1, 0) with
    # tangents (0, 1) and (0, -1): y(u) = u - 2u^2 + u^3 + ... the Hermite
    # basis: y = (u^3 - 2u^2 + u) * 1 + (u^3 - u^2) * (-1) = u - u^2.
    s = compat.CubicHermite([(0, 0), (1, 0)], [(0, 1), (0, -1)])
    assert s.grid == [0, 1]
    close(s.evaluate(0.5), [0.5, 0.25], 1)
    # Monomial coefficients, highest first: x = -2u^3 + 3u^2, y = -u^2 + u.
    close(s.segments[0], [[-2, 0], [3, -1], [0, 1], [0, 0]], 1)


def test_compat_is_float64_and_rejects_bad_grids_clearly():
    s = compat.CatmullRom(np.array([[0, 0], [1, 2], [3, 1]], dtype=np.float32))
    assert s.evaluate([0.5]).dtype == np.float64
    with pytest.raises(ValueError, match=r"grid must be strictly increasing: grid\[2\] = 1"):
        compat.CatmullRom([(0, 0), (1, 2), (3, 1)], grid=[0, 1, 1])
    with pytest.raises(ValueError, match=r"^vertex 1, coordinate 1 is not finite \(nan\)$"):
        compat.CatmullRom([(0, 0), (1, np.nan), (3, 1)])
    with pytest.raises(ValueError, match=r"n must be a derivative order >= 0, got -1"):
        s.evaluate(0.5, -1)


def test_crspline_closed_curve_through_two_points():
    # crspline's own class accepts it too (the core does); the value is what
    # splines returned for the same curve (probe small/2-vertices-closed).
    import crspline
    case = next(c for c in PROBES["cases"] if c["id"] == "probe/small/2-vertices-closed")
    exp = case["expected"]["probe[s]:evaluate(t_inner, 0)"]
    c = crspline.CatmullRom([(0, 0), (1, 1)], alpha=None, endconditions="closed")
    assert c.segment_count == 2
    got = c.evaluate(exp["t"])
    np.testing.assert_allclose(got.ravel(), exp["data"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(c.evaluate(1.5), [0.5, 0.5], rtol=0, atol=1e-15)


# ------------------------------------------------------- UnitSpeedAdapter
@pytest.mark.parametrize("dim", [2, 6])
def test_unit_speed_adapter_on_a_straight_line(dim):
    # x(t) = P1 (3t^2 - 2t^3) with |P1| = 5: monotone along the line, so the
    # arc length is 5 (3t^2 - 2t^3) and the point at arc length s is P1 s / 5.
    # dim 2 goes through the core's arc length, dim 6 through the adapter's
    # own quadrature. Tolerance: the arc-length accuracy 1e-12 relative to
    # the length 5, and the inversion near the zero-speed start (s ~ t^2).
    p1 = np.zeros(dim)
    p1[:2] = 3, 4
    c = compat.CubicHermite([np.zeros(dim), p1], [np.zeros(dim), np.zeros(dim)])
    u = compat.UnitSpeedAdapter(c)
    assert u.grid == pytest.approx([0, 5], abs=1e-12)
    s = np.array([0, 0.01, 1, 2.5, 4.2, 5])
    np.testing.assert_allclose(u.evaluate(s), s[:, None] * p1 / 5, rtol=0, atol=1e-10)
    with pytest.raises(ValueError, match="s too big: 5.5"):
        u.evaluate(5.5)
    # Issue 26 point 1: a total measured elsewhere is known only to the
    # accuracy promise (1e-12 relative); within it of either end maps to the
    # end, further out is refused.
    total = u.grid[-1]
    assert np.array_equal(u.evaluate(total * (1 + 8e-15)), u.evaluate(total))
    assert np.array_equal(u.evaluate(-total * 8e-15), u.evaluate(0.0))
    with pytest.raises(ValueError, match="^s too big: "):
        u.evaluate(total * (1 + 1e-9))
    with pytest.raises(ValueError, match="^s too small: "):
        u.evaluate(-total * 1e-9)


def test_unit_speed_adapter_has_unit_speed_on_the_docs_curve():
    # The splines docs' re-parameterization example: a closed centripetal
    # curve. Speed 1 everywhere (central differences, error ~ h^2 |x'''| ),
    # and the two independent arc-length computations (the core's, for 2-D,
    # and the adapter's Gauss-Legendre rule, on the same curve lifted to 5-D)
    # agree.
    points4 = [(0, 0), (0, 0.5), (1.5, 1.5), (1.6, 1.5), (3, 0.2), (3, 0)]
    s1 = compat.CatmullRom(points4, alpha=0.5, endconditions="closed")
    s2 = compat.UnitSpeedAdapter(s1)
    h = 1e-4
    s = np.linspace(h, s2.grid[-1] - h, 97)
    speed = np.linalg.norm((s2.evaluate(s + h) - s2.evaluate(s - h)) / (2 * h), axis=1)
    np.testing.assert_allclose(speed, 1, atol=1e-5)
    lifted = compat.CatmullRom([p + (0, 0, 0) for p in points4], alpha=0.5, endconditions="closed")
    s5 = compat.UnitSpeedAdapter(lifted)
    np.testing.assert_allclose(s5.grid, s2.grid, rtol=1e-11)
    np.testing.assert_allclose(s5.evaluate(s)[:, :2], s2.evaluate(s), atol=1e-9)


# ------------------------------------------- monotone cubics and NewGridAdapter
# The expected values come from the algorithm as the `splines` 0.3
# documentation states it (doc/euclidean/piecewise-monotone.ipynb): the
# three-point (Catmull-Rom) slope at interior values, limited by Dougherty et
# al. (1989) eq. 4.2, and the end condition printed there as
# `monotone_end_condition`. It is re-derived here in exact rational
# arithmetic (Fraction), independent of crspline's floating-point code.
from fractions import Fraction as F  # noqa: E402


def doc_fix_slope(slope, left, right):
    if left * right <= 0:
        return F(0)
    if right > 0:
        return min(max(F(0), slope), 3 * min(abs(left), abs(right)))
    return max(min(F(0), slope), -3 * min(abs(left), abs(right)))


def doc_end(inner, secant):
    if secant < 0:
        return -doc_end(-inner, -secant)
    assert 0 <= inner <= 3 * secant
    return 3 * secant - 2 * inner if inner <= secant else (3 * secant - inner) / 2


def doc_slopes(x, t):
    """Exact slopes at every value of an open piecewise monotone cubic."""
    x, t = [F(v) for v in x], [F(v) for v in t]
    secant = [(x[i + 1] - x[i]) / (t[i + 1] - t[i]) for i in range(len(x) - 1)]
    if len(x) == 2:
        return [secant[0]] * 2
    inner = []
    for i in range(1, len(x) - 1):
        h0, h1 = t[i] - t[i - 1], t[i + 1] - t[i]
        three_point = (h1**2 * (x[i] - x[i - 1]) + h0**2 * (x[i + 1] - x[i])) / (h0 * h1 * (h0 + h1))
        inner.append(doc_fix_slope(three_point, secant[i - 1], secant[i]))
    return [doc_end(inner[0], secant[0])] + inner + [doc_end(inner[-1], secant[-1])]


def test_monotone_cubic_by_hand():
    # values 0, 1, 5 on 0, 1, 2: secants 1 and 4, three-point slope 5/2
    # (within 3 * 1), end slopes (3 - 5/2) / 2 = 1/4 and 12 - 5 = 7. At
    # t = 1/2 the Hermite form gives 1/8 * 1/4 + 1/2 - 1/8 * 5/2 = 7/32.
    s = compat.MonotoneCubic([0, 1, 5])
    assert doc_slopes([0, 1, 5], [0, 1, 2]) == [F(1, 4), F(5, 2), F(7)]
    assert s.grid == [0, 1, 2]
    np.testing.assert_allclose(s.evaluate([0, 1, 2], 1), [0.25, 2.5, 7], rtol=0, atol=1e-15)
    assert s.evaluate(0.5) == pytest.approx(7 / 32, abs=1e-16)
    assert s.get_time(7 / 32) == pytest.approx(0.5, abs=1e-15)


def _monotone_data(rng, n, kind):
    t = np.cumsum(rng.uniform(0.2, 3, n))
    if kind == "increasing":
        x = np.cumsum(rng.uniform(0, 2, n) * (rng.random(n) > 0.2))  # plateaus too
    elif kind == "decreasing":
        x = -np.cumsum(rng.uniform(0, 2, n) * (rng.random(n) > 0.2))
    else:
        x = rng.uniform(-3, 3, n)
    return x, t


@pytest.mark.parametrize("kind", ["increasing", "decreasing", "any"])
def test_piecewise_monotone_against_the_documented_algorithm(kind):
    seed = int(np.random.SeedSequence().entropy % 2**32)
    rng = np.random.default_rng(seed)
    for trial in range(40):
        n = int(rng.integers(2, 9))
        x, t = _monotone_data(rng, n, kind)
        cls = compat.PiecewiseMonotoneCubic if kind == "any" else compat.MonotoneCubic
        s = cls(list(x), list(t))
        slopes = np.array([float(v) for v in doc_slopes(x, t)])
        tt = sample_t(t, 9)
        # Slopes are ratios of differences of inputs of size ~10: 1e-12 of scale.
        for order in (0, 1):
            np.testing.assert_allclose(s.evaluate(tt, order), hermite_eval(x[:, None], slopes[:-1, None],
                                                                           slopes[1:, None], t, tt, order)[:, 0],
                                       rtol=0, atol=1e-12 * 20, err_msg=f"seed {seed}, trial {trial}")
        # No segment leaves the range of its two values (rounding aside).
        dense = np.linspace(t[0], t[-1], 2001)
        v = s.evaluate(dense)
        i = np.clip(np.searchsorted(t, dense, side="right") - 1, 0, n - 2)
        lo, hi = np.minimum(x[i], x[i + 1]), np.maximum(x[i], x[i + 1])
        assert np.all(v >= lo - 1e-12) and np.all(v <= hi + 1e-12), f"seed {seed}, trial {trial}"
        if kind != "any":
            # Monotone data: get_time inverts the curve (away from plateaus).
            sign = 1 if kind == "increasing" else -1
            assert np.all(sign * np.diff(v) >= -1e-12), f"seed {seed}, trial {trial}"
            for u in dense[::97]:
                value = float(s.evaluate(u))
                back = s.get_time(value)
                if back is None:
                    assert np.sum(x == value) > 1  # a plateau: not unique
                    continue
                assert float(s.evaluate(back)) == pytest.approx(value, abs=1e-12), f"seed {seed}"


def test_piecewise_monotone_closed_and_given_slopes():
    # The docs' example: closed, and slopes given with None for the computed ones.
    values, times = [0, 3, 3, 7], [0, 3, 8, 10, 11]
    s = compat.PiecewiseMonotoneCubic(values, times, closed=True)
    x = values + [values[0]]
    # Closed: interior slopes at every value, the seam using x[-2] and x[1].
    ext_x = [x[-2] - 0] + x + [x[1]]  # the value before the seam is x[N-1] itself
    ext_t = [times[0] - (times[-1] - times[-2])] + times + [times[-1] + times[1] - times[0]]
    slopes = []
    for i in range(1, len(ext_x) - 1):
        h0, h1 = F(ext_t[i] - ext_t[i - 1]), F(ext_t[i + 1] - ext_t[i])
        left, right = (ext_x[i] - ext_x[i - 1]) / h0, (ext_x[i + 1] - ext_x[i]) / h1
        tp = (h1**2 * (ext_x[i] - ext_x[i - 1]) + h0**2 * (ext_x[i + 1] - ext_x[i])) / (h0 * h1 * (h0 + h1))
        slopes.append(float(doc_fix_slope(tp, left, right)))
    tt = sample_t(times, 5)
    np.testing.assert_allclose(s.evaluate(tt), hermite_eval(np.array(x, float)[:, None], np.array(slopes[:-1])[:, None],
                                                            np.array(slopes[1:])[:, None], times, tt)[:, 0],
                               rtol=0, atol=1e-13)
    g = compat.PiecewiseMonotoneCubic([0, 1, 3, 2, 1], slopes=[None, 0, None, -3, -1.5])
    np.testing.assert_allclose(g.evaluate([1, 3, 4], 1), [0, -3, -1.5], rtol=0, atol=0)


def test_monotone_cubic_errors_of_the_docs():
    # The assertions of the splines docs' piecewise-monotone notebook.
    s = compat.MonotoneCubic([0, 2, 2, 6, 6], grid=[0, 2, 3, 6, 8])
    assert s.get_time(2) is None
    times = s.get_time([1, 3, 5])
    # get_time solves to the last bits of t; values ~5: a few ulps.
    np.testing.assert_allclose(s.evaluate(times.astype(float)), [1, 3, 5], rtol=0, atol=1e-14)
    with pytest.raises(TypeError, match="closed"):
        compat.MonotoneCubic([0, 2, 2, 6, 6], closed=True)
    with pytest.raises(ValueError, match="too steep"):
        compat.PiecewiseMonotoneCubic([0, 1, 3, 2, 1], slopes=[None, 4, None, None, None])
    with pytest.raises(ValueError, match="cyclic"):
        compat.MonotoneCubic([0, 1, 5], slopes=[1, None, None], cyclic=True)
    with pytest.raises(ValueError, match="Only monotone values are allowed"):
        compat.MonotoneCubic([0, 2, 1])
    with pytest.raises(ValueError, match="value outside allowed range: 7"):
        s.get_time(7)


def test_monotone_cubic_cyclic_has_one_slope_at_both_ends():
    # cyclic: crspline's definition (the docs show the flag, not its numbers):
    # the limited three-point slope at the first value with the data
    # continued periodically. [0, 1, 5] on 0, 1, 2: the value before is
    # 1 - 5 = -4 at t = -1, secants 4 and 1, three-point slope 5/2.
    s = compat.MonotoneCubic([0, 1, 5], cyclic=True)
    np.testing.assert_allclose(s.evaluate([0, 1, 2], 1), [2.5, 2.5, 2.5], rtol=0, atol=1e-15)


def test_new_grid_adapter_scalar_and_partial_grids_in_closed_form():
    # A map through two points is a straight line (both end slopes are the
    # secant), and collinear (new, old) pairs keep it one: the new knots are
    # then exact multiples of the old ones.
    cr = compat.CatmullRom([(0, 0), (1, 0), (3, 1), (4, 4)])  # grid 0, 1, 2, 3
    a = compat.NewGridAdapter(cr, 6)
    assert a.grid == pytest.approx([0, 2, 4, 6], abs=1e-15)
    assert a.grid[0] == 0 and a.grid[-1] == 6
    u = np.linspace(0, 6, 25)
    np.testing.assert_allclose(a.evaluate(u), cr.evaluate(u / 2), rtol=0, atol=1e-14)
    cr2 = compat.CatmullRom([(0, 0), (1, 0), (3, 1), (4, 4)], grid=[0, 1, 3, 4])
    b = compat.NewGridAdapter(cr2, [0, None, 6, 8])
    assert b.grid == pytest.approx([0, 2, 6, 8], abs=1e-14)
    np.testing.assert_allclose(b.evaluate([0, 2, 6, 8]), cr2.evaluate([0, 1, 3, 4]), rtol=0, atol=1e-14)
    assert compat.NewGridAdapter(cr).grid[-1] == 1  # default: 0 .. 1


def test_new_grid_adapter_nonlinear_map():
    # Old grid 0, 1, 2, 3; new values 0, None, 5, 6: the map through (0, 0),
    # (5, 2), (6, 3) has slopes 3/20, 9/10, 6/5 (doc_slopes); the None knot
    # (old t = 1) is where the first segment's cubic reaches 1: with h = 5,
    # m0 = 3/4, m1 = 9/2 the cubic is 5/4 u^3 + 3/4 u, so 5 u^3 + 3 u - 4 = 0.
    assert doc_slopes([0, 2, 3], [0, 5, 6]) == [F(3, 20), F(9, 10), F(6, 5)]
    roots = np.roots([5, 0, 3, -4])
    u1 = float(roots[np.abs(roots.imag) < 1e-12].real[0])
    cr = compat.CatmullRom([(0, 0), (1, 2), (3, 2.5), (4, 0)])
    a = compat.NewGridAdapter(cr, [0, None, 5, 6])
    assert a.grid[0] == 0 and a.grid[2:] == [5, 6]
    assert a.grid[1] == pytest.approx(5 * u1, abs=1e-14)
    u = np.linspace(0, 6, 31)
    slopes = np.array([0.15, 0.9, 1.2])
    t = hermite_eval(np.array([[0.0], [2], [3]]), slopes[:-1, None], slopes[1:, None], [0, 5, 6], u)[:, 0]
    np.testing.assert_allclose(a.evaluate(u), cr.evaluate(t), rtol=0, atol=1e-13)
    np.testing.assert_allclose(a.evaluate(a.grid), cr.evaluate(cr.grid), rtol=0, atol=1e-13)
    assert a.evaluate(2.5).shape == (2,)


def test_new_grid_adapter_errors():
    cr = compat.CatmullRom([(0, 0), (1, 0), (3, 1), (4, 4)])
    with pytest.raises(ValueError, match="^new_grid must have same length as curve.grid$"):
        compat.NewGridAdapter(cr, [0, 1, 2])
    with pytest.raises(TypeError, match="^first/last element of new_grid cannot be None$"):
        compat.NewGridAdapter(cr, [None, 1, 2, 3])
    with pytest.raises(TypeError, match="^first/last element of new_grid cannot be None$"):
        compat.NewGridAdapter(cr, [0, 1, 2, None])
    with pytest.raises(ValueError, match=r"new_grid\[2\] = 1 is not greater than new_grid\[1\] = 2"):
        compat.NewGridAdapter(cr, [0, 2, 1, 3])
    a = compat.NewGridAdapter(cr, [0, None, 2, 3])
    with pytest.raises(ValueError, match="^u too big: 3.5$"):
        a.evaluate(3.5)
    with pytest.raises(ValueError, match="^u too small: -1.0$"):
        a.evaluate([0, -1.0])
    with pytest.raises(NotImplementedError):
        a.evaluate(1, 1)


def test_new_grid_adapter_on_unit_speed_and_crspline_curves():
    # The docs' re-parameterization example: a closed centripetal curve, its
    # unit-speed form, then new values at some knots. Every knot keeps its
    # point, and the new parameter never runs backwards.
    points4 = [(0, 0), (0, 0.5), (1.5, 1.5), (1.6, 1.5), (3, 0.2), (3, 0)]
    s1 = compat.CatmullRom(points4, alpha=0.5, endconditions="closed")
    s2 = compat.UnitSpeedAdapter(s1)
    new_grid = [-1, -0.5, None, None, 2, None, 3]
    for cyclic in (False, True):
        s3 = compat.NewGridAdapter(s2, new_grid, cyclic=cyclic)
        assert [g for g, n in zip(s3.grid, new_grid) if n is not None] == [-1, -0.5, 2, 3]
        assert all(b > a for a, b in zip(s3.grid, s3.grid[1:]))
        # 1e-9: the knots go through get_time (to the last bits of t), the
        # monotone map and the unit-speed inversion (arc length to 1e-12
        # relative of a length ~8, inverted by Newton steps).
        np.testing.assert_allclose(s3.evaluate(s3.grid), s1.evaluate(s1.grid), rtol=0, atol=1e-9)
        t = s3._new2old.evaluate(np.linspace(-1, 3, 400))
        assert np.all(np.diff(t) >= 0)
    # A crspline curve (ndarray grid, vectorized evaluate) works the same.
    import crspline
    c = crspline.CatmullRom(points4, endconditions="closed")
    a = compat.NewGridAdapter(c, 10)
    np.testing.assert_allclose(a.evaluate(a.grid), c.evaluate(c.grid), rtol=0, atol=1e-12)
