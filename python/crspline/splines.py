"""A drop-in for the ``splines`` package's Euclidean curves, on crspline's core.

Replace ``import splines`` by ``from crspline import splines``: ``CatmullRom``,
``KochanekBartels`` and ``CubicHermite`` take the ``splines`` 0.3 signatures
and give its results, shapes, types and errors::

    from crspline import splines
    s = splines.CatmullRom([(0, 0), (1, 2), (3, 2.5), (4, 0)])   # uniform, as in splines
    s.evaluate([0.5, 1.5])             # shape (2, 2)
    s.grid                             # [0, 1, 2, 3], a list
    s.segments                         # monomial coefficients, (4, dim) per segment

How: the knots and the tangents at the vertices are computed here in NumPy
with the ``splines`` formulas (a subclass that overrides
``_calculate_tangent(points, times)`` or ``_calculate_tangents`` gets its own
tangents, one call per vertex as in ``splines``); the curve itself is a cubic
Hermite curve built and evaluated by the C++ core
(``crspline._crspline._make_hermite``), vectorized, with the GIL released.
More coordinates than the core's Hermite curves take (4: its fixed-dimension
curves; ``crspline.max_dimension``, 16, is what ``crspline.CatmullRom`` takes) are
split into groups of at most 4 coordinates, each a Hermite curve on the same
grid with its part of the tangents: every quantity here is computed per
coordinate from the shared knots, so this is exact, whatever alpha.

Differences from ``splines`` (each deliberate):

* A grid that is not strictly increasing raises ``ValueError`` naming the
  index and value (``splines`` does not check it and divides by zero).
* ``evaluate(t, n)`` with a negative ``n`` raises ``ValueError``.
* Non-finite vertices or tangents raise ``ValueError`` naming the index.
* ``PiecewiseMonotoneCubic``, ``MonotoneCubic`` and ``NewGridAdapter`` follow
  the algorithm of the ``splines`` documentation (no recorded ``splines``
  numbers exist for them); ``get_time`` solves by safeguarded Newton steps,
  the given ``new_grid`` values must increase strictly, and
  ``MonotoneCubic(..., cyclic=True)`` is crspline's definition (see there).

crspline's own ``crspline.CatmullRom`` keeps its own API (centripetal by
default, coincident points allowed); see docs/python.md, "From splines to
crspline".
"""
import operator as _operator

import numpy as _np

from . import _crspline

__all__ = ["CubicHermite", "CatmullRom", "FiniteDifference", "KochanekBartels", "MonotoneCubic", "NewGridAdapter",
           "PiecewiseMonotoneCubic", "UnitSpeedAdapter"]

# Coordinates per core curve: the fixed-dimension fast path (1 to 4). Wider
# points are split into groups on one grid (knots and tangents come from the
# full vectors), which is exact for any alpha.
_GROUP = 4


def _float_array(x, name):
    try:
        a = _np.asarray(x)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{name}: {e}") from None
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be real numbers, got dtype {a.dtype}")
    return _np.array(a, dtype=_np.float64)  # a copy: float32 input computes in float64, as splines does


def _num(v):
    r = repr(float(v))
    return r[:-2] if r.endswith(".0") else r


def _vertices(vertices):
    """(N, dim) float64 array and whether the vertices were scalars (1-D)."""
    a = _float_array(vertices, "vertices")
    scalar = a.ndim == 1
    if scalar:
        a = a.reshape(-1, 1)
    elif a.ndim != 2:
        raise ValueError(f"vertices must be a sequence of numbers or of vectors, got shape {a.shape}")
    bad = ~_np.isfinite(a)
    if bad.any():
        i, k = _np.argwhere(bad)[0]
        raise ValueError(f"vertex {i}, coordinate {k} is not finite ({_num(a[i, k])})")
    return a, scalar


def _check_increasing(grid):
    """A given grid: finite and strictly increasing (splines does not check;
    its curve would divide by zero), by the core's rule and in its words."""
    _crspline._check_grid([float(v) for v in _float_array(grid, "grid").reshape(-1)])


def _check_vertices(vertices, closed):
    if len(vertices) < 2:
        raise ValueError("At least two vertices are required")
    a, scalar = _vertices(vertices)
    if closed:
        a = _np.concatenate([a, a[:1]])
    return a, scalar


def _check_grid(grid, alpha, a):
    """The grid as splines makes it: range, accumulated |dx|**alpha, or the given one."""
    if grid is None:
        if alpha is None:
            return list(range(len(a)))
        delta = _np.linalg.norm(_np.diff(a, axis=0), axis=1) ** alpha
        if _np.any(delta == 0):
            raise ValueError("Repeated vertices are not possible with alpha != 0")
        return [0] + list(_np.cumsum(delta))
    if alpha is not None:
        raise TypeError("Only one of {grid, alpha} is allowed")
    if len(a) != len(grid):
        raise ValueError("Number of grid values must be same as vertices (one more for closed curves)")
    _check_increasing(grid)
    return list(grid)


def _is_closed(endconditions):
    return isinstance(endconditions, str) and endconditions == "closed"


def _start_end(endconditions):
    if _is_closed(endconditions):
        return None, None
    if isinstance(endconditions, str):
        return endconditions, endconditions
    try:
        start, end = endconditions
    except (TypeError, ValueError):
        raise TypeError("endconditions must be a string or a pair") from None
    return start, end


def _triples(a, grid, closed):
    """The (previous, this, next) vertices and times of every interior vertex
    (closed: the extended curve's vertices 1 .. N, as splines zips them)."""
    g = list(grid)
    if closed:
        a = _np.concatenate([a, a[1:2]])
        g = g + [g[-1] + (g[1] - g[0])]
    t = _np.asarray(g, dtype=_np.float64)
    return a, g, t


def _end_tangent(condition, x0, x1, t0, t1, other, scalar):
    """The tangent at an open end: 'natural' (zero second derivative) or given."""
    if isinstance(condition, str):
        if condition == "natural":
            delta = t1 - t0
            return (3 * x1 - 3 * x0 - delta * other) / (2 * delta)
    elif _np.shape(condition) == (() if scalar else x0.shape):
        v = _float_array(condition, "end tangent")
        return v.reshape(x0.shape)
    raise ValueError(f"{condition!r} is not a valid start/end condition")


class CubicHermite:
    """Cubic Hermite curve: ``CubicHermite(vertices, tangents, grid=None)``.

    ``tangents`` holds two per segment, outgoing then incoming (dx/dt);
    ``grid`` defaults to 0, 1, 2, ... As ``splines.CubicHermite``; built and
    evaluated by crspline's core."""

    def __init__(self, vertices, tangents, grid=None):
        if len(vertices) < 2:
            raise ValueError("At least 2 vertices are needed")
        if len(tangents) != 2 * (len(vertices) - 1):
            raise ValueError("Exactly 2 tangents per segment are needed")
        if grid is None:
            grid = range(len(vertices))
        if len(vertices) != len(grid):
            raise ValueError("As many grid times as vertices are needed")
        _check_increasing(grid)
        a, scalar = _vertices(vertices)
        v = _float_array(tangents, "tangents").reshape(len(tangents), -1)
        if v.shape[1] != a.shape[1]:
            raise ValueError(f"tangents must have {a.shape[1]} coordinates each, got {v.shape[1]}")
        self._init_hermite(a, scalar, v[0::2], v[1::2], list(grid))

    def _init_hermite(self, a, scalar, out, inc, grid):
        """The curve through the rows of a (N, dim) on grid (N values) with
        out[i] leaving vertex i and inc[i] arriving at vertex i + 1."""
        n, dim = a.shape
        outgoing = _np.empty((n, dim))
        incoming = _np.empty((n, dim))
        outgoing[:-1], outgoing[-1] = out, inc[-1]  # the last entries are not used by an open curve
        incoming[1:], incoming[0] = inc, out[0]
        g = [float(x) for x in grid]
        self._scalar = scalar
        self._dim = dim
        self._vertices_ = a
        self._out = outgoing
        self._in = incoming
        self.grid = list(grid)
        self._segments = None
        self._curves = [
            _crspline._make_hermite(_np.ascontiguousarray(a[:, k:k + _GROUP]),
                                    _np.ascontiguousarray(outgoing[:, k:k + _GROUP]),
                                    _np.ascontiguousarray(incoming[:, k:k + _GROUP]), g, False)
            for k in range(0, dim, _GROUP)]

    def _init_from_hook(self, a, scalar, grid, closed, start, end, hook, vectorized):
        """Tangents at the interior vertices (from hook(points, times, k) per
        vertex, or vectorized(points, times) on all of them at once), the end
        conditions, then the core's Hermite curve."""
        ext, g, t = _triples(a, grid, closed)
        m = len(ext) - 2  # interior vertices
        if m > 0:
            if hook is None:
                col = t[:, None]
                inc, out = vectorized((ext[:-2], ext[1:-1], ext[2:]), (col[:-2], col[1:-1], col[2:]))
                inc = _np.broadcast_to(inc, (m, a.shape[1]))
                out = _np.broadcast_to(out, (m, a.shape[1]))
            else:
                inc, out = _np.empty((m, a.shape[1])), _np.empty((m, a.shape[1]))
                for k in range(m):
                    rows = ext[k:k + 3, 0] if scalar else ext[k:k + 3]
                    i, o = hook(tuple(rows), tuple(g[k:k + 3]), k)
                    inc[k] = _float_array(i, "incoming tangent").reshape(-1)
                    out[k] = _float_array(o, "outgoing tangent").reshape(-1)
        if closed:
            # vertex k + 1 of the extended list; the last is vertex 0 again
            seg_out = _np.concatenate([out[-1:], out[:-1]])
            seg_in = inc
        elif m == 0:
            v = (a[1] - a[0]) / (grid[1] - grid[0])  # two vertices: a straight line
            seg_out, seg_in = v[None, :], v[None, :]
        else:
            def end_tangent(cond, i0, i1, other):
                x0, x1 = (a[i0, 0], a[i1, 0]) if scalar else (a[i0], a[i1])
                o = other[0] if scalar else other
                return _np.reshape(_end_tangent(cond, x0, x1, grid[i0], grid[i1], o, scalar), -1)
            first = end_tangent(start, 0, 1, inc[0])
            last = end_tangent(end, -2, -1, out[-1])
            seg_out = _np.concatenate([first[None, :], out])
            seg_in = _np.concatenate([inc, last[None, :]])
        self._init_hermite(a, scalar, seg_out, seg_in, grid)

    @property
    def segments(self):
        """Monomial coefficients of every segment in the local parameter
        u = (t - t_i) / (t_{i+1} - t_i), highest degree first: a list of
        (4, dim) arrays ((4,) for scalar vertices), as splines."""
        if self._segments is None:
            a, g = self._vertices_, _np.asarray(self.grid, dtype=_np.float64)
            h = _np.diff(g)[:, None]
            x0, x1 = a[:-1], a[1:]
            m0, m1 = h * self._out[:-1], h * self._in[1:]
            c = _np.stack([2 * x0 - 2 * x1 + m0 + m1, -3 * x0 + 3 * x1 - 2 * m0 - m1, m0, x0], axis=1)
            self._segments = [s[:, 0].copy() if self._scalar else s for s in c]
        return self._segments

    def evaluate(self, t, n=0):
        """Value (or n-th derivative) at the parameter value(s) t, as splines:
        a number gives one vertex-shaped result, a sequence or array of any
        shape gives that shape plus the vertex shape; n >= 4 gives zeros.
        Raises ValueError('t too small: ...' / 't too big: ...') outside the grid."""
        n = _operator.index(n)
        if n < 0:
            raise ValueError(f"n must be a derivative order >= 0, got {n}")
        g0, g1 = self.grid[0], self.grid[-1]
        if _np.isscalar(t):
            if t < g0:
                raise ValueError(f"t too small: {t}")
            if not (t < g1 or t == g1):
                raise ValueError(f"t too big: {t}")
            tt = _np.asarray(t, dtype=_np.float64)
        else:
            tt = _float_array(t, "t")
            if tt.size == 0:
                return _np.zeros(tt.shape)
            bad = ~((tt >= g0) & (tt <= g1))
            if bad.any():
                k = int(_np.argmax(bad.ravel()))
                value = t
                if isinstance(t, _np.ndarray):
                    value = t.ravel()[k]
                else:
                    for i in _np.unravel_index(k, tt.shape):
                        value = value[int(i)]
                raise ValueError(f"t too {'small' if value < g0 else 'big'}: {value}")
        if n > 3:
            out = _np.zeros(tt.shape + (self._dim,))
        elif len(self._curves) == 1:
            out = self._curves[0].evaluate(tt, n)
        else:
            out = _np.concatenate([c.evaluate(tt, n) for c in self._curves], axis=-1)
        if self._scalar:
            out = out[..., 0]
        return out[()] if out.ndim == 0 else out


class CatmullRom(CubicHermite):
    """Catmull-Rom spline with the ``splines`` signature and defaults:
    ``CatmullRom(vertices, grid=None, *, alpha=None, endconditions='natural')``.

    ``alpha=None`` and no grid is the uniform grid 0, 1, 2, ... (unlike
    ``crspline.CatmullRom``, whose default is centripetal). ``endconditions``:
    ``'natural'``, ``'closed'`` or a pair ``(start, end)`` of ``'natural'`` or
    a tangent. Subclasses may override ``_calculate_tangent(points, times)``
    (one tangent per interior vertex) or ``_calculate_tangents(points, times)``
    (a pair: incoming, outgoing)."""

    @staticmethod
    def _calculate_tangent(points, times):
        x_1, x0, x1 = points
        t_1, t0, t1 = times
        delta_1 = t0 - t_1
        delta0 = t1 - t0
        return ((delta0**2 * (x0 - x_1) + delta_1**2 * (x1 - x0)) / (delta0 * delta_1 * (delta0 + delta_1)))

    def _calculate_tangents(self, points, times):
        tangent = self._calculate_tangent(points, times)
        return tangent, tangent

    def __init__(self, vertices, grid=None, *, alpha=None, endconditions="natural"):
        closed = _is_closed(endconditions)
        a, scalar = _check_vertices(vertices, closed)
        grid = _check_grid(grid, alpha, a)
        start, end = _start_end(endconditions)
        cls = type(self)
        if cls._calculate_tangents is CatmullRom._calculate_tangents and \
                cls._calculate_tangent is CatmullRom._calculate_tangent:
            hook = None
        else:
            hook = lambda points, times, k: self._calculate_tangents(points, times)  # noqa: E731
        self._init_from_hook(a, scalar, grid, closed, start, end, hook,
                             lambda p, t: CatmullRom._calculate_tangents(self, p, t))

class FiniteDifference(CatmullRom):
    """Finite-difference spline, as ``splines.FiniteDifference``: the
    ``CatmullRom`` signature, with the tangent at a vertex the mean of the
    chord velocities on its two sides (the Catmull-Rom tangent only on a
    uniform grid)."""

    @staticmethod
    def _calculate_tangent(points, times):
        x_1, x0, x1 = points
        t_1, t0, t1 = times
        return ((x0 - x_1) / (t0 - t_1) + (x1 - x0) / (t1 - t0)) / 2


class KochanekBartels(CubicHermite):
    """Kochanek-Bartels spline with the ``splines`` signature:
    ``KochanekBartels(vertices, grid=None, *, tcb=(0, 0, 0), alpha=None,
    endconditions='natural')``; ``tcb`` one triple or one per interior vertex
    (N - 2 open, N closed with vertex 0 first). Subclasses may override
    ``_calculate_tangents(points, times, tcb)``."""

    @staticmethod
    def _calculate_tangents(points, times, tcb):
        x_1, x0, x1 = points
        t_1, t0, t1 = times
        T, C, B = tcb
        a = (1 - T) * (1 + C) * (1 + B)
        b = (1 - T) * (1 - C) * (1 - B)
        c = (1 - T) * (1 - C) * (1 + B)
        d = (1 - T) * (1 + C) * (1 - B)
        incoming = (c * (t1 - t0)**2 * (x0 - x_1) + d * (t0 - t_1)**2 * (x1 - x0)) / (
            (t1 - t0) * (t0 - t_1) * (t1 - t_1))
        outgoing = (a * (t1 - t0)**2 * (x0 - x_1) + b * (t0 - t_1)**2 * (x1 - x0)) / (
            (t1 - t0) * (t0 - t_1) * (t1 - t_1))
        return incoming, outgoing

    def __init__(self, vertices, grid=None, *, tcb=(0, 0, 0), alpha=None, endconditions="natural"):
        closed = _is_closed(endconditions)
        slots = len(vertices) if closed else len(vertices) - 2
        a, scalar = _check_vertices(vertices, closed)
        grid = _check_grid(grid, alpha, a)
        tcb = _float_array(tcb, "tcb")
        if tcb.ndim == 1 and len(tcb) == 3:
            tcb = _np.tile(tcb, (max(slots, 0), 1))
        elif len(tcb) != slots:
            raise ValueError("There must be two more vertices than TCB values (except for closed curves)")
        if tcb.size and (tcb.ndim != 2 or tcb.shape[1] != 3):
            raise ValueError(f"tcb must be (tension, continuity, bias) triples, got shape {tcb.shape}")
        if closed:
            tcb = _np.roll(tcb, -1, axis=0)  # the extended curve's interior vertices are 1 .. N
        start, end = _start_end(endconditions)
        if type(self)._calculate_tangents is KochanekBartels._calculate_tangents:
            hook = None
        else:
            hook = lambda points, times, k: self._calculate_tangents(points, times, tcb[k])  # noqa: E731
        per = tcb.reshape(-1, 3)

        def vectorized(points, times):
            return KochanekBartels._calculate_tangents(points, times, (per[:, 0:1], per[:, 1:2], per[:, 2:3]))

        self._init_from_hook(a, scalar, grid, closed, start, end, hook, vectorized)


# Gauss-Legendre nodes and weights on [0, 1] for the arc length of curves the
# core cannot measure itself (more than 4 coordinates, or foreign curves).
_GL_X, _GL_W = _np.polynomial.legendre.leggauss(10)
_GL_X, _GL_W = (_GL_X + 1) / 2, _GL_W / 2
_GL_PIECES = 64  # per segment: the speed of a cubic is smooth away from cusps
# The arc-length accuracy promise (relative to the length): the core's table
# is built to it, and an s within it of either end maps to that end.
_ARC_LENGTH_ACCURACY = 1e-12


class UnitSpeedAdapter:
    """Arc-length (unit-speed) re-parameterization of a curve, as
    ``splines.UnitSpeedAdapter(curve)``: ``.grid`` holds the arc length at the
    curve's knots, ``evaluate(s)`` the point at arc length s.

    For crspline curves of up to 4 coordinates the core measures the length
    (to 1e-12 relative) and inverts it; otherwise (more coordinates, or any
    object with ``grid`` and a vectorized ``evaluate(t, 1)``) a composite
    10-point Gauss-Legendre rule on 64 pieces per segment and Newton steps
    safeguarded by bisection."""

    def __init__(self, curve):
        self.curve = curve
        curves = getattr(curve, "_curves", None)
        self._table = None
        if isinstance(curve, CubicHermite) and len(curves) == 1:
            self._table = curves[0].arc_length_table(_ARC_LENGTH_ACCURACY)
            self.grid = [float(s) for s in self._table.knot_lengths]
            return
        g = _np.asarray(curve.grid, dtype=_np.float64)
        # Cumulative length at 64 pieces per segment (t_pieces, s_pieces).
        t = _np.concatenate([_np.linspace(g[i], g[i + 1], _GL_PIECES + 1)[:-1] for i in range(len(g) - 1)] + [g[-1:]])
        self._t = t
        h = _np.diff(t)
        nodes = t[:-1, None] + h[:, None] * _GL_X[None, :]
        # Keep each node inside its own segment (a knot belongs to the right).
        speed = _np.linalg.norm(_np.asarray(curve.evaluate(nodes.ravel(), 1)).reshape(nodes.size, -1), axis=1)
        pieces = (speed.reshape(nodes.shape) * _GL_W[None, :]).sum(axis=1) * h
        self._s = _np.concatenate([[0.0], _np.cumsum(pieces)])
        self.grid = [float(x) for x in self._s[::_GL_PIECES]]

    def _length_in_piece(self, k, t):
        t0 = self._t[k]
        nodes = t0 + (t - t0) * _GL_X
        speed = _np.linalg.norm(_np.asarray(self.curve.evaluate(nodes, 1)).reshape(len(nodes), -1), axis=1)
        return self._s[k] + (t - t0) * float(speed @ _GL_W)

    def _s2t(self, s):
        if self._table is not None:
            return float(self._table.t_at(_np.asarray([s], dtype=_np.float64))[0])
        k = min(int(_np.searchsorted(self._s, s, side="right")) - 1, len(self._t) - 2)
        lo, hi = self._t[k], self._t[k + 1]
        t = lo + (hi - lo) * (s - self._s[k]) / max(self._s[k + 1] - self._s[k], 1e-300)
        for _ in range(50):  # Newton, kept in [lo, hi] by bisection
            f = self._length_in_piece(k, t) - s
            if f > 0:
                hi = t
            else:
                lo = t
            speed = float(_np.linalg.norm(self.curve.evaluate(t, 1)))
            step = t - f / speed if speed > 0 else (lo + hi) / 2
            t_next = step if lo < step < hi else (lo + hi) / 2
            if abs(t_next - t) <= 1e-15 * max(1.0, abs(t)):
                return t_next
            t = t_next
        return t

    def evaluate(self, s):
        """The point at arc length s (a number, or any sequence or array).

        A length measured by another tool (``splines``' own total, say) is
        known only to the accuracy promise, 1e-12 relative: s within that of
        either end maps to the end, as in the core (issue 26); further out
        raises ValueError('s too small: ...' / 's too big: ...')."""
        if not _np.isscalar(s):
            return _np.array([self.evaluate(x) for x in s])
        slack = _ARC_LENGTH_ACCURACY * self.grid[-1]
        if s < self.grid[0]:
            if not s >= self.grid[0] - slack:
                raise ValueError(f"s too small: {s}")
            s = self.grid[0]
        if not (s < self.grid[-1] or s == self.grid[-1]):
            if not s <= self.grid[-1] + slack:
                raise ValueError(f"s too big: {s}")
            s = self.grid[-1]
        return self.curve.evaluate(self._s2t(s))


# The monotone cubics and the new-grid adapter (their own file, issue 42).
from ._splines_monotone import MonotoneCubic, NewGridAdapter, PiecewiseMonotoneCubic  # noqa: E402,F401

from . import _splines_quaternion as quaternion  # noqa: E402  (splines.quaternion's drop-in, issue 28)
