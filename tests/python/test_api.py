"""The Python API: construction, attributes, shapes, dtypes and end conditions."""
import math

import numpy as np
import pytest

import crspline

SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
WAVE = [[0, 0], [1, 2], [3, 2], [4, 0], [6, -1]]


def chord_grid(points, alpha, closed=False):
    p = np.asarray(points, dtype=float)
    if closed:
        p = np.vstack([p, p[:1]])
    h = np.linalg.norm(np.diff(p, axis=0), axis=1) ** alpha
    return np.concatenate([[0.0], np.cumsum(h)])


def test_default_is_centripetal_and_none_is_uniform():
    c = crspline.CatmullRom(WAVE)
    np.testing.assert_allclose(c.grid, chord_grid(WAVE, 0.5), rtol=1e-15)
    u = crspline.CatmullRom(WAVE, alpha=None)
    assert u.grid.tolist() == [0, 1, 2, 3, 4]
    assert crspline.CatmullRom(WAVE, alpha=crspline.chordal).grid[1] == pytest.approx(math.sqrt(5))
    # KochanekBartels follows the splines package: None (its default) is uniform.
    assert crspline.KochanekBartels(WAVE).grid.tolist() == [0, 1, 2, 3, 4]
    assert crspline.KochanekBartels(WAVE, alpha=0.5).grid.tolist() == c.grid.tolist()


def test_attributes():
    c = crspline.CatmullRom(WAVE)
    assert c.dim == 2 and not c.closed and c.segment_count == 4
    assert c.dtype == np.float64
    assert c.points.tolist() == WAVE
    assert c.domain == (0.0, c.grid[-1])
    with pytest.raises(ValueError):
        c.points[0, 0] = 5  # read-only views
    with pytest.raises(ValueError):
        c.grid[0] = 5
    assert "CatmullRom(dim=2, points=5" in repr(c)
    closed = crspline.CatmullRom(SQUARE, endconditions="closed")
    assert closed.closed and closed.segment_count == 4 and len(closed.grid) == 5


def test_one_dimensional_points_may_be_a_flat_sequence():
    a = crspline.CatmullRom([1.0, 3.0, 2.0, 5.0])
    b = crspline.CatmullRom([[1.0], [3.0], [2.0], [5.0]])
    assert a.dim == 1 and a.points.shape == (4, 1)
    assert np.array_equal(a.evaluate([0.3, 1.7]), b.evaluate([0.3, 1.7]))


@pytest.mark.parametrize("dim", [1, 2, 3, 4])
def test_every_dimension(dim):
    rng = np.random.default_rng(7 + dim)
    p = rng.normal(size=(6, dim))
    c = crspline.CatmullRom(p)
    assert c.dim == dim
    assert np.array_equal(c.evaluate(c.grid), p)
    assert c.to_bezier().shape == (5, 4, dim)


def test_evaluate_shapes():
    c = crspline.CatmullRom(WAVE)
    assert c.evaluate(0.5).shape == (2,)
    assert c.evaluate(np.float32(0.5)).shape == (2,)
    assert c.evaluate([0.5]).shape == (1, 2)
    t = np.linspace(*c.domain, 12).reshape(3, 4)
    out = c.evaluate(t)
    assert out.shape == (3, 4, 2)
    assert np.array_equal(out.reshape(-1, 2), c.evaluate(t.ravel()))
    assert c.evaluate(np.empty((0,))).shape == (0, 2)
    assert c(0.5).tolist() == c.evaluate(0.5).tolist()
    # Non-contiguous and integer input.
    assert np.array_equal(c.evaluate(t[:, ::2]), c.evaluate(np.ascontiguousarray(t[:, ::2])))
    assert np.array_equal(c.evaluate(np.array([0, 1, 2])), c.evaluate([0.0, 1.0, 2.0]))


def test_evaluate_unsorted_equals_sorted():
    c = crspline.CatmullRom(WAVE)
    rng = np.random.default_rng(3)
    t = rng.uniform(*c.domain, 1000)
    for n in range(4):
        a = c.evaluate(t, n)
        order = np.argsort(t)
        b = c.evaluate(t[order], n)
        # The sorted walk folds 1/h into its coefficients: derivatives agree
        # to rounding, positions exactly.
        if n == 0:
            assert np.array_equal(a[order], b)
            assert np.array_equal(a[17], c.evaluate(t[17]))
        else:
            scale = np.abs(b).max()
            assert np.max(np.abs(a[order] - b)) <= 8 * np.finfo(float).eps * scale, n


def test_derivatives_by_finite_differences():
    c = crspline.CatmullRom(WAVE)
    t = np.linspace(0.1, c.domain[1] - 0.1, 50)
    h = 1e-5
    for n in (1, 2, 3):
        fd = (c.evaluate(t + h, n - 1) - c.evaluate(t - h, n - 1)) / (2 * h)
        d = c.evaluate(t, n)
        # Away from knots (the cubic pieces are smooth; third derivatives jump).
        away = np.min(np.abs(t[:, None] - c.grid[None, :]), axis=1) > 2 * h
        np.testing.assert_allclose(d[away], fd[away], atol=1e-5 * (1 + np.abs(d[away]).max()))


def test_evaluate_unchecked_extrapolates():
    c = crspline.CatmullRom(WAVE)
    with pytest.raises(crspline.OutOfDomain):
        c.evaluate(-0.5)
    x = c.evaluate_unchecked([-0.5, c.domain[1] + 0.5])
    assert x.shape == (2, 2) and np.all(np.isfinite(x))


def test_closed_curve_is_periodic():
    c = crspline.CatmullRom(SQUARE, endconditions="closed")
    a, b = c.domain
    assert np.array_equal(c.evaluate(b), c.evaluate(a))
    for n in (1, 2):
        # C1 across the seam; the second derivative's jump is the curve's.
        left = c.evaluate_unchecked(b - 1e-9, 1)
        assert np.allclose(left, c.evaluate(a, 1), atol=1e-6)


def test_endconditions_forms():
    natural = crspline.CatmullRom(WAVE, endconditions="natural")
    pair = crspline.CatmullRom(WAVE, endconditions=("natural", "natural"))
    mapping = crspline.CatmullRom(WAVE, endconditions={"start": "natural", "end": "natural"})
    t = np.linspace(*natural.domain, 33)
    assert np.array_equal(natural.evaluate(t), pair.evaluate(t))
    assert np.array_equal(natural.evaluate(t), mapping.evaluate(t))
    # Natural: zero second derivative at both ends.
    assert np.allclose(natural.evaluate(list(natural.domain), 2), 0, atol=1e-12)
    # Tangents are dx/dt, taken as is.
    clamped = crspline.CatmullRom(WAVE, endconditions=([1.0, 0.5], "natural"))
    assert np.allclose(clamped.evaluate(0.0, 1), [1.0, 0.5])
    assert np.allclose(clamped.evaluate(clamped.domain[1], 2), 0, atol=1e-12)
    clamped2 = crspline.CatmullRom(WAVE, endconditions=np.array([[1.0, 0.5], [0.0, -2.0]]))
    assert np.allclose(clamped2.evaluate(clamped2.domain[1], 1), [0, -2])
    # Reflect: phantom point 2 P0 - P1 with the first interval, so the start
    # tangent is the first chord velocity.
    r = crspline.CatmullRom(WAVE, endconditions="reflect")
    v0 = (np.array(WAVE[1]) - WAVE[0]) / (r.grid[1] - r.grid[0])
    assert np.allclose(r.evaluate(0.0, 1), v0)
    mixed = crspline.CatmullRom(WAVE, endconditions=("reflect", [0, 1]))
    assert np.allclose(mixed.evaluate(0.0, 1), v0) and np.allclose(mixed.evaluate(mixed.domain[1], 1), [0, 1])
    # 1-D tangents may be numbers.
    one = crspline.CatmullRom([0.0, 1.0, 3.0], endconditions=(2.0, [0.5]))
    assert one.evaluate(0.0, 1).tolist() == [2.0]


def test_explicit_grid():
    grid = [0.0, 0.5, 2.0, 2.5, 4.0]
    c = crspline.CatmullRom(WAVE, grid=grid)
    assert c.grid.tolist() == grid
    assert np.array_equal(c.evaluate(grid), np.asarray(WAVE, dtype=float))
    closed = crspline.CatmullRom(SQUARE, grid=[0, 1, 2, 3, 4], endconditions="closed")
    assert closed.grid.tolist() == [0, 1, 2, 3, 4]
    # The grid the curve chose, given back, gives the same knots, and the
    # curve within the knots' rounding: the intervals d = diff(grid) are
    # within eps * grid[i+1] of the ones computed from the points, which
    # moves the curve by a few of that relative change times its size
    # (docs/spec.md, "Knots and knot intervals").
    d = crspline.CatmullRom(WAVE)
    e = crspline.CatmullRom(WAVE, grid=d.grid)
    assert np.array_equal(e.grid, d.grid)
    t = np.linspace(*d.domain, 41)
    delta = np.max(np.finfo(float).eps * d.grid[1:] / np.diff(d.grid))
    assert np.max(np.abs(d.evaluate(t) - e.evaluate(t))) <= 8 * delta * np.max(np.abs(WAVE))


def test_tension():
    t0 = crspline.CatmullRom(WAVE, alpha=0)
    t1 = crspline.CatmullRom(WAVE, alpha=0, tension=1, endconditions="reflect")
    assert np.allclose(t1.evaluate(t1.grid, 1), 0)
    half = crspline.CatmullRom(WAVE, alpha=0, tension=0.5, endconditions="reflect")
    full = crspline.CatmullRom(WAVE, alpha=0, endconditions="reflect")
    assert np.allclose(half.evaluate(half.grid, 1), 0.5 * full.evaluate(full.grid, 1))
    assert not np.array_equal(t0.evaluate(1.5), half.evaluate(1.5))


def test_kochanek_bartels_tcb_forms():
    n = len(WAVE)
    zero = crspline.KochanekBartels(WAVE, alpha=0.5)
    plain = crspline.CatmullRom(WAVE)
    t = np.linspace(*plain.domain, 29)
    assert np.array_equal(zero.evaluate(t), plain.evaluate(t))  # TCB 0 is Catmull-Rom bit for bit
    one = crspline.KochanekBartels(WAVE, tcb=(0.3, -0.2, 0.1))
    many = crspline.KochanekBartels(WAVE, tcb=[(0.3, -0.2, 0.1)] * (n - 2))
    assert np.array_equal(one.evaluate([0.5, 2.5]), many.evaluate([0.5, 2.5]))
    assert one.tcb.shape == (n - 2, 3)
    # Continuity breaks C1 at interior knots: incoming and outgoing differ.
    c = crspline.KochanekBartels(WAVE, tcb=(0, 0.5, 0))
    tan = c.tangents()
    assert not np.allclose(tan[0, 1], tan[1, 0])
    # Tension 1 everywhere: zero tangents at the interior vertices.
    t1 = crspline.KochanekBartels(WAVE, tcb=(1, 0, 0))
    assert np.allclose(t1.evaluate(t1.grid[1:-1], 1), 0)
    # Closed: one triple per vertex, vertex 0 first.
    closed = crspline.KochanekBartels(SQUARE, tcb=[(1, 0, 0), (0, 0, 0), (0, 0, 0), (0, 0, 0)],
                                      endconditions="closed")
    assert np.allclose(closed.evaluate(0.0, 1), 0)
    assert not np.allclose(closed.evaluate(1.0, 1), 0)
    with pytest.raises(ValueError, match="expected one per interior vertex"):
        crspline.KochanekBartels(WAVE, tcb=[(0, 0, 0)] * n)
    with pytest.raises(ValueError, match="triple"):
        crspline.KochanekBartels(WAVE, tcb=(0, 0))


def test_two_points_are_a_straight_line():
    c = crspline.CatmullRom([[0, 0], [2, 4]], endconditions=([9, 9], [-3, 1]))
    t = np.linspace(*c.domain, 7)
    w = (t / c.domain[1])[:, None]
    assert np.allclose(c.evaluate(t), w * [2, 4], atol=1e-15)


def test_to_bezier():
    c = crspline.CatmullRom(WAVE)
    b = c.to_bezier()
    assert b.shape == (4, 4, 2)
    assert np.array_equal(b[:, 0], c.points[:-1]) and np.array_equal(b[:, 3], c.points[1:])
    # De Casteljau at u = 0.3 of each segment equals the curve.
    u = 0.3
    g = c.grid
    for i in range(4):
        q = b[i]
        for _ in range(3):
            q = (1 - u) * q[:-1] + u * q[1:]
        assert np.allclose(q[0], c.evaluate(g[i] + u * (g[i + 1] - g[i])), atol=1e-14)
    # B1 - B0 = h/3 x'(t_i).
    h = np.diff(g)
    assert np.allclose(b[:, 1] - b[:, 0], (h / 3)[:, None] * c.evaluate(g[:-1], 1))


def test_segment_index():
    c = crspline.CatmullRom(WAVE, alpha=0)
    assert c.segment_index([0, 0.5, 1, 3.9, 4]).tolist() == [0, 0, 1, 3, 3]
    assert c.segment_index(2.0) == 2


def test_float32_curve():
    p32 = np.asarray(WAVE, dtype=np.float32)
    c = crspline.CatmullRom(p32)
    d = crspline.CatmullRom(np.asarray(WAVE, dtype=np.float64))
    assert c.dtype == np.float32 and c.grid.dtype == np.float32 and c.points.dtype == np.float32
    t = np.linspace(*d.domain, 50)
    x = c.evaluate(t)
    assert x.dtype == np.float32
    # float agrees with double to float precision (relative to the scale).
    assert np.max(np.abs(x - d.evaluate(np.minimum(t, c.domain[1])))) < 1e-5 * 6
    assert c.to_bezier().dtype == np.float32
    assert c.sample(5)["points"].dtype == np.float32
    assert abs(c.arc_length() - d.arc_length()) < 1e-5 * d.arc_length()
    assert crspline.CatmullRom(np.asarray(WAVE, dtype=np.float16)).dtype == np.float32
    assert crspline.CatmullRom(np.asarray(WAVE, dtype=np.int32)).dtype == np.float64


def test_strict_rejects_coincident_points():
    p = [[0, 0], [1, 1], [1, 1], [2, 0]]
    c = crspline.CatmullRom(p)  # default: zero knot interval, a constant segment
    assert c.grid[1] == c.grid[2]
    with pytest.raises(ValueError, match="coincident consecutive points"):
        crspline.CatmullRom(p, strict=True)


def test_version_and_constants():
    assert crspline.__version__ == "0.1.0"
    assert (crspline.uniform, crspline.centripetal, crspline.chordal) == (0.0, 0.5, 1.0)
    assert crspline.max_dimension == 16 and crspline.default_accuracy == 1e-12
    assert issubclass(crspline.InvalidInput, ValueError) and issubclass(crspline.OutOfDomain, ValueError)
    for name in crspline.__all__:
        obj = getattr(crspline, name)
        if callable(obj):
            assert obj.__doc__, name
    for name in dir(crspline.CatmullRom):
        if not name.startswith("_"):
            assert getattr(crspline.CatmullRom, name).__doc__, name


def test_stubs_cover_every_public_name():
    import ast
    import pathlib

    folder = pathlib.Path(crspline.__file__).parent
    stub = ast.parse((folder / "__init__.pyi").read_text())
    top = {n.name for n in stub.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    top |= {t.id for n in stub.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    assert set(crspline.__all__) <= top, set(crspline.__all__) - top
    classes = {n.name: n for n in stub.body if isinstance(n, ast.ClassDef)}
    for cls in (crspline.CatmullRom, crspline.KochanekBartels):
        members = {n.name for n in classes[cls.__name__].body if isinstance(n, ast.FunctionDef)}
        if cls is crspline.KochanekBartels:
            members |= {n.name for n in classes["CatmullRom"].body if isinstance(n, ast.FunctionDef)}
        public = {name for name in dir(cls) if not name.startswith("_")}
        assert public <= members, public - members
    ext = ast.parse((folder / "_crspline.pyi").read_text())
    ext_classes = {n.name: n for n in ext.body if isinstance(n, ast.ClassDef)}
    curve_methods = {n.name for n in ext_classes["_Curve"].body if isinstance(n, ast.FunctionDef)}
    compiled = {name for name in dir(crspline._crspline._Curve) if not name.startswith("_")}
    assert compiled <= curve_methods, compiled - curve_methods
    assert (folder / "py.typed").exists()
