"""crspline: cubic Catmull-Rom curves in any dimension, over NumPy.

The compiled core (``crspline._crspline``, pybind11) does the work; this
module turns Python arguments into its normalized form and its results into
plain ndarrays and dicts.

>>> import crspline
>>> c = crspline.CatmullRom([[0, 0], [1, 2], [3, 2], [4, 0]])   # centripetal
>>> c.evaluate(c.grid).tolist() == c.points.tolist()          # interpolates
True

Conventions (those of the C++ library and of the ``splines`` package):

* ``t`` is the curve parameter, running over ``grid[0] .. grid[-1]``; ``s`` is
  arc length. Segment ``i`` joins ``points[i]`` and ``points[i+1]`` on
  ``[grid[i], grid[i+1]]``; an interior knot belongs to the segment on its
  right, the last knot to the last segment.
* Knots from ``alpha``: ``t[0] = 0``, ``t[i+1] = t[i] + |x[i+1] - x[i]|**alpha``
  (0 uniform, 0.5 centripetal, 1 chordal). A closed curve does not repeat its
  first point and has one more knot than points.
* float32 points give a float32 curve (float32 results); anything else real
  gives float64. Dimensions 1 to ``max_dimension`` (16).
* Errors: bad values raise ``ValueError`` (``InvalidInput`` or, for a
  parameter outside the domain, ``OutOfDomain``, both subclasses of
  ``ValueError``) with the core's message; arguments of the wrong kind raise
  ``TypeError``.
* Batch work (evaluation, arc-length inversion, nearest points, ...) runs in
  C++ with the GIL released.
"""
from collections.abc import Mapping as _Mapping
import json as _json
import numbers as _numbers
import operator as _operator
import os as _os

import numpy as _np

from . import _crspline
from ._crspline import InvalidInput, OutOfDomain, SpecError, __version__

__all__ = [
    "CatmullRom",
    "KochanekBartels",
    "InvalidInput",
    "SpecError",
    "OutOfDomain",
    "load",
    "save",
    "from_spec",
    "arc_lengths",
    "tessellate_many",
    "uniform",
    "centripetal",
    "chordal",
    "default_accuracy",
    "max_dimension",
    "__version__",
]

#: alpha = 0: every knot interval is 1.
uniform = 0.0
#: alpha = 1/2: the default of CatmullRom; no cusps or loops within a segment.
centripetal = 0.5
#: alpha = 1: knot intervals equal to the chord lengths.
chordal = 1.0
#: Default relative accuracy of arc lengths (1e-12).
default_accuracy = float(_crspline.default_accuracy)
#: Largest dimension compiled into the module.
max_dimension = int(_crspline.max_dimension)


class _DefaultAlpha(float):
    """0.5, marked as "not given" (so that a grid alone is not "alpha and grid")."""

    __slots__ = ()


_DEFAULT_ALPHA = _DefaultAlpha(0.5)


# ----------------------------------------------------------------- arguments
def _real(x, name):
    if isinstance(x, bool) or not isinstance(x, _numbers.Real):
        raise TypeError(f"{name} must be a real number, got {type(x).__name__}")
    return float(x)


def _numeric_array(x, name):
    """x as an ndarray of real numbers (TypeError otherwise), not yet converted."""
    try:
        a = _np.asarray(x)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{name}: {e}") from None
    if a.dtype.kind == "c":
        raise TypeError(f"{name} must be real numbers, got complex values (dtype {a.dtype})")
    if a.dtype.kind not in "fiu":
        raise TypeError(f"{name} must be real numbers, got dtype {a.dtype}")
    return a


def _as_points(points):
    """(N, dim) C-contiguous float32 or float64 array of the points."""
    if isinstance(points, (list, tuple)) and points and all(isinstance(p, (list, tuple)) for p in points):
        # Nested lists: a point with another number of coordinates is named
        # (NumPy would say only "inhomogeneous shape").
        for i, p in enumerate(points):
            if len(p) != len(points[0]):
                raise ValueError(f"point {i} has {len(p)} coordinates, expected {len(points[0])} like point 0")
    a = _numeric_array(points, "points")
    dtype = _np.float32 if a.dtype in (_np.float32, _np.float16) else _np.float64
    if a.ndim == 1:
        a = a.reshape(-1, 1)  # a sequence of numbers: points in 1-D
    elif a.ndim != 2:
        raise ValueError(f"points must be an N x dim array (one row per point), got shape {a.shape}")
    return _np.ascontiguousarray(a, dtype=dtype)


def _as_vector(x, name):
    a = _numeric_array(x, name)
    if a.ndim != 1:
        raise ValueError(f"{name} must be a 1-D sequence of numbers, got shape {a.shape}")
    return [float(v) for v in a]


def _end(spec, which):
    """One end as the core takes it: a name (the core checks it) or a tangent
    as a flat list of floats (the core checks its length and values)."""
    if isinstance(spec, str):
        return spec
    v = _numeric_array(spec, f"{which} tangent")
    if v.ndim > 1:
        raise ValueError(f"{which} tangent must be one vector dx/dt, got shape {v.shape}")
    return [float(x) for x in v.reshape(-1)]


def _parse_endconditions(endconditions):
    """The ends in the core's form: one name for both ('natural', 'reflect',
    'closed') or a pair (start, end), each a name or a tangent. Only the
    Python forms are checked here (a string, a pair, a mapping); the names
    and tangents are checked by the core's specification (spec.hpp)."""
    if isinstance(endconditions, str):
        return endconditions
    if isinstance(endconditions, _Mapping):
        if set(endconditions) != {"start", "end"}:
            raise ValueError(f"endconditions as a mapping needs exactly the keys 'start' and 'end', "
                             f"got {sorted(endconditions)}")
        start, end = endconditions["start"], endconditions["end"]
    else:
        try:
            start, end = endconditions
        except (TypeError, ValueError):
            raise TypeError("endconditions must be a string or a pair (start, end), "
                            f"got {type(endconditions).__name__}") from None
    return _end(start, "start"), _end(end, "end")


def _scalar_or_array(a):
    """A 0-d result as a NumPy scalar, anything else as is."""
    return a[()] if a.ndim == 0 else a


def _readonly(a):
    a.flags.writeable = False
    return a


# --------------------------------------------------------------------- curves
class CatmullRom:
    """A cubic Catmull-Rom curve through the given points.

    ``CatmullRom(points, *, alpha=0.5, grid=None, endconditions='natural',
    tension=0.0, strict=False)``

    .. warning::
       **The default is centripetal (alpha = 0.5), not uniform.** The
       ``splines`` package's ``CatmullRom`` (and ``KochanekBartels`` here and
       there) default to ``alpha=None``, a *uniform* grid 0, 1, 2, ... To get
       the ``splines`` curve, pass ``alpha=None`` (or ``alpha=0``) or its grid.

    Parameters
    ----------
    points : array_like, shape (N, dim) or (N,)
        The points, dim 1 to 16 (a flat sequence is N points in 1-D). float32
        input makes a float32 curve; other real input float64.
    alpha : float or None, default 0.5
        Knot exponent in [0, 1]: 0 uniform, 0.5 centripetal, 1 chordal.
        ``None`` means uniform, as in the ``splines`` package. Give ``alpha``
        or ``grid``, not both (a grid alone ignores the default).
    grid : array_like, optional
        Explicit, strictly increasing knots: N values, N + 1 when closed.
    endconditions : str or pair, default 'natural'
        ``'natural'`` (zero second derivative at both ends), ``'closed'``
        (periodic; the first point is not repeated), ``'reflect'`` (phantom
        points 2 P0 - P1 as in three.js), or a pair ``(start, end)`` whose
        items are each ``'natural'``, ``'reflect'`` or a tangent vector dx/dt
        in grid units (a mapping ``{'start': ..., 'end': ...}`` works too).
    tension : float, default 0
        Cardinal tension tau in [0, 1]: computed tangents are scaled by
        1 - tau (1 gives zero tangents at the points).
    strict : bool, default False
        Reject coincident consecutive points (when alpha > 0) instead of
        giving them a zero knot interval.

    Raises
    ------
    ValueError
        Invalid values (too few points, non-finite coordinates, alpha outside
        [0, 1], a grid that is not increasing or has the wrong length, ...).
    TypeError
        Arguments of the wrong kind (strings or complex numbers as points, ...).
    """

    __slots__ = ("_c", "_dim", "_grid", "_points", "_tables")

    def __init__(self, points, *, alpha=_DEFAULT_ALPHA, grid=None, endconditions="natural", tension=0.0,
                 strict=False):
        pts = _as_points(points)
        if alpha is _DEFAULT_ALPHA:
            alpha = None if grid is not None else centripetal
        elif alpha is None:
            alpha = None if grid is not None else uniform  # the splines package's convention
        else:
            alpha = _real(alpha, "alpha")
        self._build(pts, alpha, grid, endconditions, _real(tension, "tension"), ([], [], []), bool(strict))

    def _build(self, pts, alpha, grid, endconditions, tension, kb, strict):
        # The core validates the whole specification once (spec.hpp) and
        # builds 5 to 16 coordinates as its wide, zero-padded curve; results
        # are cut back to the points' own coordinates (_cut).
        ends = _parse_endconditions(endconditions)
        grid = None if grid is None else _as_vector(grid, "grid")
        self._dim = pts.shape[1]
        self._c = _crspline._make_curve(pts, alpha, grid, ends, tension, kb[0], kb[1], kb[2], strict)
        self._grid = _readonly(self._c.grid)
        self._points = _readonly(self._cut(self._c.points))
        self._tables = {}

    def _cut(self, a):
        """Results of a wide (zero-padded) curve cut back to the curve's own coordinates."""
        if self._dim == self._c.dim:
            return a
        return _np.ascontiguousarray(a[..., :self._dim])

    def _low_dimension_only(self, what):
        """The wide curve must not answer questions whose answer depends on its padded dimension."""
        if self._dim != self._c.dim:
            raise InvalidInput(what.format(self._dim))

    # ------------------------------------------------------------ attributes
    @property
    def grid(self):
        """The knots, shape (N,) or (N + 1,) when closed (read-only)."""
        return self._grid

    @property
    def points(self):
        """The control points, shape (N, dim) (read-only)."""
        return self._points

    @property
    def dim(self):
        """The dimension of the points."""
        return self._dim

    @property
    def closed(self):
        """True for a closed (periodic) curve."""
        return self._c.closed

    @property
    def dtype(self):
        """numpy.float32 or numpy.float64: the scalar type of the curve and its results."""
        return self._c.dtype

    @property
    def segment_count(self):
        """The number of cubic segments (N - 1, or N when closed)."""
        return self._c.segment_count

    @property
    def domain(self):
        """(t_min, t_max): the first and last knot."""
        return float(self._grid[0]), float(self._grid[-1])

    def __repr__(self):
        return (f"{type(self).__name__}(dim={self.dim}, points={len(self._points)}, closed={self.closed}, "
                f"dtype={_np.dtype(self.dtype).name}, domain=({self.domain[0]:g}, {self.domain[1]:g}))")

    def spec(self):
        """How the curve was built, as the curve file holds it (docs/spec.md):
        a dict with ``points`` (lists), ``alpha`` or ``grid``, ``end``
        (``'natural'``, ``'reflect'``, ``'closed'`` or ``{'start': ...,
        'end': ...}`` with names or tangents), ``tension``, and ``kb`` and
        ``strict`` when set. ``crspline.from_spec(c.spec())`` builds the same
        curve (in float64); ``crspline.save`` writes it as JSON."""
        s = self._c.spec()
        dim = self._dim
        pts = _np.asarray(s["points"], dtype=_np.float64).reshape(-1, s["dimension"])[:, :dim]
        out = {"points": pts.tolist()}
        if s["grid"] is not None:
            out["grid"] = list(s["grid"])
        else:
            out["alpha"] = 0.5 if s["alpha"] is None else s["alpha"]

        def end(e):
            return e if isinstance(e, str) else list(e[:dim])

        if s["closed"]:
            out["end"] = "closed"
        elif isinstance(s["start"], str) and s["start"] == s["end"]:
            out["end"] = s["start"]
        else:
            out["end"] = {"start": end(s["start"]), "end": end(s["end"])}
        out["tension"] = s["tension"]
        kb = {k: s["kb_" + k] for k in ("tension", "continuity", "bias") if s["kb_" + k]}
        if kb:
            n = len(pts)
            for k, v in kb.items():
                # The end values of an open curve are not used; NaN there is null.
                kb[k] = [None if (x != x and not s["closed"] and i in (0, n - 1)) else x for i, x in enumerate(v)]
            out["kb"] = kb
        if s["strict"]:
            out["strict"] = True
        return out

    # ------------------------------------------------------------ evaluation
    def _t(self, t, name="t"):
        a = _numeric_array(t, name)
        return a

    def evaluate(self, t, n=0):
        """Position (n = 0) or n-th derivative d^n x / dt^n (n = 0..3) at t.

        ``t`` is a number or an array of any shape (sorted or not); the result
        has shape ``t.shape + (dim,)`` and the curve's dtype. Vectorized in
        C++ with the GIL released. Raises ``OutOfDomain`` (a ``ValueError``)
        naming the first t outside ``domain`` (its index in ``t.ravel()``).
        """
        return self._cut(self._c.evaluate(self._t(t), _operator.index(n)))

    __call__ = evaluate

    def evaluate_unchecked(self, t, n=0):
        """Like ``evaluate``, but t outside the domain extrapolates the first
        or last segment's cubic instead of raising (NaN gives NaN)."""
        return self._cut(self._c.evaluate_unchecked(self._t(t), _operator.index(n)))

    def to_bezier(self):
        """Bézier control points of every segment, shape (segment_count, 4, dim).

        ``B0`` and ``B3`` are the segment's points exactly; ``B1``, ``B2`` come
        from the Hermite tangents (``B1 = B0 + h/3 x'(t_i)``)."""
        return self._cut(self._c.bezier())

    def tangents(self):
        """dx/dt at the start and end of every segment, shape (segment_count, 2, dim).

        Equal at interior knots unless Kochanek-Bartels continuity breaks them."""
        return self._cut(self._c.tangents())

    def segment_index(self, t):
        """Index of the segment that owns each t (clamped to the first and last);
        an int64 array shaped like t (a NumPy integer for a number)."""
        return _scalar_or_array(self._c.locate(self._t(t)))

    # ------------------------------------------------------------ arc length
    def _table(self, accuracy):
        accuracy = _real(accuracy, "accuracy")
        table = self._tables.get(accuracy)
        if table is None:
            table = self._tables[accuracy] = self._c.arc_length_table(accuracy)
        return table

    def arc_length(self, t0=None, t1=None, *, accuracy=default_accuracy):
        """Arc length of the curve over [t0, t1] (default: the whole domain).

        ``accuracy`` is relative to the length (default 1e-12); the error is
        that small for double, about 1e-6 for float32 curves."""
        accuracy = _real(accuracy, "accuracy")
        if t0 is None and t1 is None:
            return self._c.arc_length(accuracy)
        a = self.domain[0] if t0 is None else _real(t0, "t0")
        b = self.domain[1] if t1 is None else _real(t1, "t1")
        return self._c.arc_length_between(a, b, accuracy)

    def arc_length_at(self, t, *, accuracy=default_accuracy):
        """Arc length from the start of the curve to each t (array or number)."""
        return _scalar_or_array(self._table(accuracy).s_at(self._t(t)))

    def t_at_arc_length(self, s, *, accuracy=default_accuracy):
        """The parameter t at arc length s from the start (array or number).

        s must lie in [0, arc_length()]; the result satisfies
        ``arc_length_at(t) == s`` to the accuracy. The table behind it is
        built once per accuracy and reused."""
        return _scalar_or_array(self._table(accuracy).t_at(self._t(s, "s")))

    def knot_arc_lengths(self, *, accuracy=default_accuracy):
        """Cumulative arc length at every knot, shape like ``grid``."""
        return self._table(accuracy).knot_lengths

    def sample(self, n, *, by="arc_length", accuracy=default_accuracy):
        """n points along the curve, ends included.

        ``by='arc_length'`` (default): evenly spaced in arc length; returns
        ``{'t', 's', 'points'}``. ``by='t'``: evenly spaced in the parameter;
        returns ``{'t', 'points'}``. A closed curve gives its first point at
        both ends."""
        n = _operator.index(n)
        if n < 2:
            raise ValueError(f"need at least 2 samples, got {n}")
        if by == "arc_length":
            t, s, p = self._c.sample_arc_length(n, _real(accuracy, "accuracy"))
            return {"t": t, "s": s, "points": self._cut(p)}
        if by == "t":
            lo, hi = self._grid[0], self._grid[-1]
            t = _np.linspace(lo, hi, n).astype(self.dtype)
            t[0], t[-1] = lo, hi
            return {"t": t, "points": self.evaluate(t)}
        raise ValueError(f"by must be 'arc_length' or 't', got {by!r}")

    # -------------------------------------------------------------- geometry
    def _need(self, name, header):
        f = getattr(self._c, name, None)
        if f is None:
            raise NotImplementedError(f"crspline was built without {header}")
        return f

    def tessellate(self, tolerance=None):
        """Adaptive polyline within ``tolerance`` (an absolute distance) of the
        curve, both ways. Default: 1e-3 times the bounding-box diagonal.

        Returns ``{'points': (M, dim), 't': (M,)}``; every knot is a vertex and
        ``points[k] == evaluate(t[k])`` exactly."""
        f = self._need("tessellate", "tessellate.hpp")
        points, t = f(None if tolerance is None else _real(tolerance, "tolerance"))
        return {"points": self._cut(points), "t": t}

    def bounding_box(self, *, tight=True):
        """Axis-aligned box of the curve as an array [[lo...], [hi...]], shape (2, dim).

        ``tight=True``: every face touches the curve (interior extrema found
        exactly). ``tight=False``: the box of the Bézier control points, which
        contains the curve."""
        return self._cut(self._need("bounding_box", "bounds.hpp")(bool(tight)))

    def nearest(self, points):
        """Nearest point of the curve to each query point.

        ``points`` has shape ``(..., dim)`` (one point: ``(dim,)``). Returns
        ``{'t', 'distance_sq', 'segment', 'point'}`` with shapes ``(...)``,
        ``(...)``, ``(...)`` (int64) and ``(..., dim)``. Exact up to rounding
        (every segment's candidates are the roots of a quintic); ties go to
        the smaller t."""
        f = self._need("nearest", "nearest.hpp")
        q = _numeric_array(points, "points")
        if q.ndim == 0 and self.dim == 1:
            q = q.reshape(1)
        if q.ndim == 0 or q.shape[-1] != self.dim:
            raise ValueError(f"query points must have shape (..., {self.dim}), got {q.shape}")
        shape = q.shape[:-1]
        q = _np.ascontiguousarray(q.reshape(-1, self.dim), dtype=self.dtype)
        if self._dim != self._c.dim:
            wide = _np.zeros((len(q), self._c.dim), dtype=self.dtype)
            wide[:, :self._dim] = q
            q = wide
        t, d2, seg, p = f(q)
        p = self._cut(p)
        return {"t": _scalar_or_array(t.reshape(shape)), "distance_sq": _scalar_or_array(d2.reshape(shape)),
                "segment": _scalar_or_array(seg.reshape(shape)), "point": p.reshape(shape + (self.dim,))}

    def curvature(self, t):
        """Curvature |x' ^ x''| / |x'|^3 at each t (any dimension; 0 in 1-D).

        At a zero-speed point: 0 where the curve is locally straight, +inf at
        a cusp. Never NaN."""
        return _scalar_or_array(self._need("curvature", "frames.hpp")(self._t(t)))

    def signed_curvature(self, t):
        """Signed curvature of a plane curve (2-D only): positive turning left."""
        self._low_dimension_only("signed curvature needs a 2-D curve, this one is {}-D")
        return _scalar_or_array(self._need("signed_curvature", "frames.hpp")(self._t(t)))

    def torsion(self, t):
        """Torsion det(x', x'', x''') / |x' ^ x''|^2 of a space curve (3-D only)."""
        self._low_dimension_only("torsion needs a 3-D curve, this one is {}-D")
        return _scalar_or_array(self._need("torsion", "frames.hpp")(self._t(t)))

    def frames(self, t, *, kind="rotation_minimizing", initial_normal=None):
        """Moving frames at the parameters t (a 1-D array, usually sorted).

        ``kind='rotation_minimizing'`` (2-D and 3-D; double reflection, closed
        curves close up) or ``'frenet'`` (3-D). ``initial_normal`` sets the
        first normal of a rotation-minimizing frame (3-D), or picks the left
        or right normal in 2-D. Returns ``{'position', 'tangent', 'normal',
        'binormal'}``, each of shape (len(t), dim); the binormal is zero in
        2-D."""
        f = self._need("frames", "frames.hpp")
        if kind == "frenet":
            self._low_dimension_only("Frenet frames need a 3-D curve, this one is {}-D")
        self._low_dimension_only("rotation-minimizing frames need a 2-D or 3-D curve, this one is {}-D")
        tt = self._t(t)
        if tt.ndim != 1:
            raise ValueError(f"t must be a 1-D array for frames, got shape {tt.shape}")
        if kind not in ("rotation_minimizing", "frenet"):
            raise ValueError(f"kind must be 'rotation_minimizing' or 'frenet', got {kind!r}")
        normal = None if initial_normal is None else _as_vector(initial_normal, "initial_normal")
        position, tangent, nrm, binormal = f(tt, kind, normal)
        return {"position": position, "tangent": tangent, "normal": nrm, "binormal": binormal}

    def analyze(self, *, intersections=True):
        """The analysis report of the curve, as plain dicts, lists, floats,
        ints, bools, strings and None: the same keys and values as
        ``crspline analyze`` prints, so ``json.dumps`` writes the CLI's
        report. The schema, field by field: docs/report.md.

        ``{'dimension', 'segments': [...], 'cusp_t', 'has_cusp',
        'has_self_intersection', 'intersections', 'folds', 'complete',
        'certificate'}``: one dict per segment (cusps, loops and folds with
        their local u and global t, chord-frame quantities, measured
        distances, the paper's bounds), the whole-curve search (crossings
        between segments, loops inside one, each with its ``distance``;
        ``complete`` is False if the search ran out of its work budget) and
        the Section 5 certificate. ``intersections=False`` skips the search
        (``intersections``, ``folds`` and ``complete`` are then None).
        """
        f = self._need("analyze", "report.hpp")
        return f(bool(intersections), None, self._dim)

    def intersections(self, tolerance=None):
        """Every meeting of the curve with itself closer than ``tolerance`` (a
        distance; default 1e-9 times the size of the Bézier points' box):
        crossings between segments, loops inside segments, folds.

        Returns the report's search object (docs/report.md):
        ``{'intersections': [{'segments': [i, j], 'u': [u_i, u_j], 't': [t_i,
        t_j], 'point': [...], 'distance': d}, ...], 'folds': [...],
        'complete': bool, 'any': bool}``. ``complete`` is False if a pair of
        segments exhausted the search's work budget."""
        f = self._need("intersections", "intersections.hpp")
        return f(None if tolerance is None else _real(tolerance, "tolerance"), self._dim)

    def certify_intersection_free(self, *, safe_angle=None, search_on_failure=True, tolerance=None):
        """Section 5's certificate that the curve does not intersect itself.

        Rules: (1) centripetal knots and plain interior segments, end segments
        without cusp or loop; (2) every polygon angle above ``safe_angle``
        (default pi/3, radians); (3) disjoint bounding boxes of non-adjacent
        segments. Returns the report's certificate object (docs/report.md):
        ``{'certified', 'failed_rule' (None when certified), 'detail',
        'vertex', 'segment', 'segments', 'angle', 'intersects', 'search'}``;
        when not certified and ``search_on_failure``, ``intersects`` and
        ``search`` (as ``intersections()``) say whether it really does."""
        f = self._need("certify_intersection_free", "certify.hpp")
        angle = _crspline.safe_adjacent_angle if safe_angle is None else _real(safe_angle, "safe_angle")
        return f(angle, bool(search_on_failure), None if tolerance is None else _real(tolerance, "tolerance"),
                 self._dim)


class KochanekBartels(CatmullRom):
    """A Kochanek-Bartels (TCB) spline, with the ``splines`` package's signature.

    ``KochanekBartels(vertices, grid=None, *, tcb=(0, 0, 0), alpha=None,
    endconditions='natural')``

    .. warning::
       **Here ``alpha=None`` (the default) means a uniform grid 0, 1, 2, ...**,
       as in the ``splines`` package, while ``CatmullRom``'s default is
       centripetal (alpha = 0.5). Pass ``alpha=0.5`` for a centripetal
       Kochanek-Bartels spline.

    Parameters
    ----------
    vertices : array_like, shape (N, dim) or (N,)
        The points (as for ``CatmullRom``).
    grid : array_like, optional
        Explicit knots (N, or N + 1 when closed). Not with ``alpha``.
    tcb : array_like, default (0, 0, 0)
        One (tension, continuity, bias) triple for every interior vertex, or
        a sequence of triples: N - 2 of them for an open curve (vertices 1 ..
        N - 2; the end vertices take none), N for a closed one (vertex 0 ..
        N - 1). All zero is the Catmull-Rom spline, bit for bit.
    alpha : float or None, default None
        Knot exponent in [0, 1]; ``None`` means uniform.
    endconditions : str or pair, default 'natural'
        As for ``CatmullRom``: 'natural', 'closed', 'reflect' or a pair.
    """

    __slots__ = ("_tcb",)

    def __init__(self, vertices, grid=None, *, tcb=(0, 0, 0), alpha=None, endconditions="natural"):
        pts = _as_points(vertices)
        closed = isinstance(endconditions, str) and endconditions == "closed"
        n = len(pts)
        slots = n if closed else n - 2
        values = _numeric_array(tcb, "tcb").astype(_np.float64)
        if values.shape == (3,):
            values = _np.tile(values, (max(slots, 0), 1))
        elif values.ndim != 2 or values.shape[1] != 3:
            raise ValueError(f"tcb must be one (tension, continuity, bias) triple or a sequence of triples, "
                             f"got shape {values.shape}")
        elif len(values) != max(slots, 0):
            raise ValueError(f"tcb has {len(values)} triples, expected one per interior vertex: {max(slots, 0)} "
                             f"for {n} vertices ({'closed' if closed else 'open: two more vertices than triples'})")
        if slots >= 0 and not closed:
            zero = _np.zeros((1, 3))
            per_vertex = _np.concatenate([zero, values, zero])  # the ends take no TCB
        else:
            per_vertex = values
        kb = tuple([float(x) for x in per_vertex[:, k]] for k in range(3)) if n >= 2 else ([], [], [])
        if alpha is None:
            alpha = None if grid is not None else uniform
        else:
            alpha = _real(alpha, "alpha")
        self._tcb = _readonly(values.copy())
        self._build(pts, alpha, grid, endconditions, 0.0, kb, False)

    @property
    def tcb(self):
        """The (tension, continuity, bias) triples, one per interior vertex (read-only)."""
        return self._tcb


# ------------------------------------------------------------ the curve file
#: The fields of the curve file that crspline.load reads (docs/spec.md).
_FILE_FIELDS = ("points", "alpha", "grid", "end", "tension", "kb", "strict")


def _file_end(e, which):
    if isinstance(e, str):
        return e
    if isinstance(e, list):
        return e
    raise TypeError(f"'{which}' must be \"natural\", \"reflect\" or a tangent [dx/dt, ...], got {type(e).__name__}")


def _file_kb(values, which):
    if not isinstance(values, (list, tuple)):
        raise TypeError(f"'kb.{which}' must be a list of numbers, one per point, got {type(values).__name__}")
    out = []
    for i, v in enumerate(values):
        if v is None:
            out.append(float("nan"))  # allowed only where the core ignores it (open ends)
        elif isinstance(v, bool) or not isinstance(v, _numbers.Real):
            raise TypeError(f"'kb.{which}[{i}]' must be a number or null, got {type(v).__name__}")
        else:
            out.append(float(v))
    return out


def from_spec(spec):
    """The curve a curve-file dict describes (the form ``CatmullRom.spec()``
    returns and ``crspline.load`` reads; docs/spec.md): a ``CatmullRom``, or
    a ``KochanekBartels`` when it has ``kb``. Always float64.

    A field that is not part of the curve file raises ``ValueError`` naming it
    (``unknown field 'foo'``, the command line's words); ``tangents`` (a
    Hermite curve, which the command line reads) is refused by name. The
    values are checked by the core (``SpecError``)."""
    if not isinstance(spec, _Mapping):
        raise TypeError(f"a curve file holds a JSON object {{\"points\": ...}}, got {type(spec).__name__}")
    for key in spec:
        if key == "tangents":
            raise ValueError("field 'tangents' (a Hermite curve) is not supported by crspline.load; "
                             "crspline.splines.CubicHermite builds one from tangents")
        if key not in _FILE_FIELDS:
            raise ValueError(f"unknown field '{key}'")
    if "points" not in spec:
        raise ValueError("missing field 'points'")
    pts = _as_points(spec["points"]).astype(_np.float64)
    alpha = spec.get("alpha")
    if alpha is not None:
        alpha = _real(alpha, "alpha")
    grid = spec.get("grid")
    end = spec.get("end", "natural")
    if isinstance(end, _Mapping):
        for key in end:
            if key not in ("start", "end"):
                raise ValueError(f"unknown field '{key}' in 'end' (expected \"start\" and \"end\")")
        end = (_file_end(end.get("start", "natural"), "end.start"), _file_end(end.get("end", "natural"), "end.end"))
    elif not isinstance(end, str):
        raise TypeError(f"'end' must be \"natural\", \"reflect\", \"closed\" or {{\"start\": ..., \"end\": ...}}, "
                        f"got {type(end).__name__}")
    tension = _real(spec.get("tension", 0.0), "tension")
    strict = spec.get("strict", False)
    if not isinstance(strict, bool):
        raise TypeError(f"'strict' must be true or false, got {type(strict).__name__}")
    kb = spec.get("kb")
    if kb is not None:
        if not isinstance(kb, _Mapping):
            raise TypeError(f"'kb' must be an object {{\"tension\": [...], \"continuity\": [...], \"bias\": [...]}}, "
                            f"got {type(kb).__name__}")
        for key in kb:
            if key not in ("tension", "continuity", "bias"):
                raise ValueError(f"unknown field '{key}' in 'kb' (expected \"tension\", \"continuity\", \"bias\")")
        values = tuple(_file_kb(kb[k], k) if k in kb else [] for k in ("tension", "continuity", "bias"))
        curve = KochanekBartels.__new__(KochanekBartels)
        curve._build(pts, alpha, grid, end, tension, values, strict)
        closed = curve.closed
        n = len(pts)
        rows = range(n) if closed else range(1, n - 1)
        curve._tcb = _readonly(_np.array([[v[i] if v else 0.0 for v in values] for i in rows],
                                         dtype=_np.float64).reshape(-1, 3))
        return curve
    curve = CatmullRom.__new__(CatmullRom)
    curve._build(pts, alpha, grid, end, tension, ([], [], []), strict)
    return curve


def load(path):
    """The curve in a curve file (JSON, docs/spec.md; what ``crspline save``
    and the command line's inputs hold): ``from_spec`` of its object."""
    with open(path, encoding="utf-8") as f:
        try:
            spec = _json.load(f)
        except _json.JSONDecodeError as e:
            raise ValueError(f"{path}: not JSON: {e}") from None
    return from_spec(spec)


def save(path, curve):
    """Writes the curve's specification (``curve.spec()``) to a curve file,
    as JSON that ``crspline.load`` and the command line read (numbers
    written to round-trip exactly). The file is replaced whole or not at
    all (written beside it, then renamed)."""
    if not isinstance(curve, CatmullRom):
        raise TypeError(f"save takes a crspline.CatmullRom or KochanekBartels, got {type(curve).__name__}")
    text = _json.dumps(curve.spec(), allow_nan=False)
    path = _os.fspath(path)
    tmp = f"{path}.tmp{_os.getpid()}"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text + "\n")
        _os.replace(tmp, path)
    except BaseException:
        if _os.path.exists(tmp):
            _os.remove(tmp)
        raise


# ------------------------------------------------------------ many curves
def _curve_list(curves):
    """Every curve's points as a C-contiguous float64 (N, dim) array; an
    error names the curve's index. ``curves`` is a list (or any iterable) of
    point arrays, or an array whose first axis runs over the curves."""
    if isinstance(curves, (str, bytes)) or not hasattr(curves, "__iter__"):
        raise TypeError(f"curves must be a list of point arrays, got {type(curves).__name__}")
    out = []
    for i, c in enumerate(curves):
        try:
            a = _as_points(c)
        except (TypeError, ValueError) as e:
            raise type(e)(f"curve {i}: {e}") from None
        out.append(_np.ascontiguousarray(a, dtype=_np.float64))
    return out


def _workers(workers):
    if workers is None:
        try:
            return max(1, len(_os.sched_getaffinity(0)))
        except AttributeError:  # not on Linux
            return max(1, _os.cpu_count() or 1)
    workers = _operator.index(workers)
    if workers < 1:
        raise ValueError(f"workers must be at least 1, got {workers}")
    return workers


def _shared(alpha, endconditions, tension, strict):
    alpha = uniform if alpha is None else _real(alpha, "alpha")  # None: uniform, as for CatmullRom
    return alpha, _parse_endconditions(endconditions), _real(tension, "tension"), bool(strict)


def arc_lengths(curves, *, alpha=centripetal, endconditions="natural", tension=0.0, strict=False,
                accuracy=default_accuracy, workers=None):
    """Arc length of every curve in one call: ``curves`` is a list (or any
    iterable, or an array whose first axis runs over the curves) of point
    arrays (N_i, dim_i), each a curve built with the shared options as
    ``CatmullRom(points, alpha=..., endconditions=..., tension=..,
    strict=...)`` would build it (in float64). Returns a float64 array, one
    length per curve in input order, the numbers ``CatmullRom(...).
    arc_length(accuracy=...)`` gives.

    Runs in C++ with the GIL released, on ``workers`` threads (default: the
    cores this process may use). A bad curve raises the error one curve
    would, with its index in front: ``curve 17: point 2, coordinate 0 is not
    finite (nan)`` (the lowest failing index, whatever the threads did)."""
    pts = _curve_list(curves)
    alpha, ends, tension, strict = _shared(alpha, endconditions, tension, strict)
    return _crspline._arc_lengths(pts, alpha, ends, tension, strict, _real(accuracy, "accuracy"), _workers(workers))


def tessellate_many(curves, tolerance=None, *, alpha=centripetal, endconditions="natural", tension=0.0,
                    strict=False, workers=None):
    """``CatmullRom(points, ...).tessellate(tolerance)`` for every curve in
    one call: a list of ``{'points', 't'}`` dicts in input order. Curves,
    options, threads and errors as for ``arc_lengths``; ``tolerance`` is an
    absolute distance shared by all curves (default: 1e-3 times each
    curve's bounding-box diagonal)."""
    pts = _curve_list(curves)
    alpha, ends, tension, strict = _shared(alpha, endconditions, tension, strict)
    f = getattr(_crspline, "_tessellate_many", None)
    if f is None:
        raise NotImplementedError("crspline was built without tessellate.hpp")
    tol = None if tolerance is None else _real(tolerance, "tolerance")
    return [{"points": p, "t": t} for p, t in f(pts, alpha, ends, tension, strict, tol, _workers(workers))]
