"""The curve class, CatmullRom: construction from the normalized arguments,
attributes, evaluation, arc length, geometry and analysis over the compiled
curve (``_crspline._Curve``)."""
import operator as _operator

import numpy as _np

from . import _crspline
from ._arguments import (_DEFAULT_ALPHA, _as_points, _as_vector, _numeric_array, _parse_endconditions, _readonly,
                         _real, _scalar_or_array)
from ._constants import centripetal, default_accuracy, uniform
from ._crspline import InvalidInput


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
        a dict with ``points`` (lists), ``alpha`` or ``grid``, then
        ``closed: True`` for a closed curve or ``start`` and ``end`` for an
        open one (each ``'natural'``, ``'reflect'`` or a tangent list),
        ``tension``, and ``kb`` and ``strict`` when set: the words of the
        specification's table, one spelling. ``crspline.from_spec(c.spec())``
        builds the same curve (in float64); ``crspline.save`` writes it as
        JSON."""
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
            out["closed"] = True  # a closed curve has no end conditions
        else:
            out["start"] = end(s["start"])
            out["end"] = end(s["end"])
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
        """Index of the segment that owns each t; an int64 array shaped like t
        (a NumPy integer for a number).

        t outside the domain, infinities included, clamps to the first or
        last segment (no error: this answers "which piece", not "is t on the
        curve"; ``evaluate`` checks the domain). NaN is refused: it raises
        ``OutOfDomain`` (a ``ValueError``) naming its index in ``t.ravel()``."""
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
        """Arc length from the start of the curve to each t (array or number).

        Raises ``OutOfDomain`` (a ``ValueError``) for t outside ``domain``,
        naming the first such value and its index in ``t.ravel()``."""
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
        a cusp. Never NaN. A t outside ``domain`` raises ``OutOfDomain`` naming
        the first such value and its index in ``t.ravel()`` (so do
        ``signed_curvature`` and ``torsion``)."""
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

        ``{'verdict', 'dimension', 'segments': [...], 'cusp_t', 'has_cusp',
        'has_self_intersection', 'intersections', 'overlaps', 'folds',
        'complete', 'certificate'}``: decide()'s proved verdict ('simple',
        'crosses' or 'touches'; None for a curve that is not plane), one dict per segment (cusps, loops and
        folds with their local u and global t, chord-frame quantities,
        measured distances, the paper's bounds), the whole-curve search
        (crossings between segments, loops inside one, each with its
        ``distance``; collinear overlaps; ``complete`` is False if the search
        ran out of its work budget) and the Section 5 certificate.
        ``intersections=False`` skips the search: ``intersections``,
        ``overlaps``, ``folds`` and ``complete`` are then None, and so is
        ``has_self_intersection`` (unknown) unless a segment loops or folds
        by itself (then True).
        """
        f = self._need("analyze", "report.hpp")
        return f(bool(intersections), None, self._dim)

    def intersections(self, tolerance=None):
        """Every meeting of the curve with itself closer than ``tolerance`` (a
        distance; default 1e-9 times the size of the Bézier points' box):
        crossings between segments, loops inside segments, folds.

        Returns the report's search object (docs/report.md):
        ``{'intersections': [{'segments': [i, j], 'u': [u_i, u_j], 't': [t_i,
        t_j], 'point': [...], 'distance': d}, ...], 'overlaps': [{'segments':
        [i, j], 'u': [u0, u1], 'v': [v0, v1]}, ...], 'folds': [...],
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
