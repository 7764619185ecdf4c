"""fit: a Catmull-Rom curve with few control points within a proved
tolerance of dense or noisy samples (issue 40; the C++ core's fit.hpp)."""
from . import _crspline
from ._arguments import _as_points, _real
from ._curve import CatmullRom
from ._kochanek_bartels import KochanekBartels
from ._crspline import InvalidInput

_MODES = ("subset", "free")


class FitResult:
    """What :func:`fit` returns.

    Attributes
    ----------
    curve : CatmullRom or KochanekBartels
        The fitted curve: a ``CatmullRom``, or a ``KochanekBartels`` (centripetal
        or the given alpha) where the fit raised the tension of some vertices.
    deviation : float
        The proved bound (<= tolerance) on the distance both ways: every curve
        point to the input polyline, every input point to the curve.
    curve_to_input, input_to_curve : float
        The two directions' proved bounds.
    indices : ndarray of int64 or None
        Subset mode: the input index of each control point (first and last of
        an open line included). ``None`` in free mode.
    count : int
        Number of control points.
    tensioned : int
        Vertices whose tension the fit raised (where no choice of points keeps
        the tolerance).
    rounding_floor : float
        The input's rounding floor (tolerances at or below it are refused).
    """

    __slots__ = ("curve", "deviation", "curve_to_input", "input_to_curve", "indices", "count", "tensioned",
                 "rounding_floor")

    def __repr__(self):
        return (f"FitResult(count={self.count}, deviation={self.deviation!r}, "
                f"indices={'None' if self.indices is None else '[...]'}, curve={type(self.curve).__name__})")


def _ends(endconditions, closed):
    if closed:
        return "natural", "natural"
    if isinstance(endconditions, str):
        return endconditions, endconditions
    try:
        start, end = endconditions
    except (TypeError, ValueError):
        raise TypeError("endconditions must be 'natural', 'reflect' or a pair of them, "
                        f"got {type(endconditions).__name__}") from None
    if not isinstance(start, str) or not isinstance(end, str):
        raise ValueError("fit: the ends must be 'natural' or 'reflect' (the fit chooses the end tangents)")
    return start, end


def fit(points, *, tolerance, alpha=0.5, closed=False, mode="subset", tension=0.0, endconditions="natural"):
    """Fit a Catmull-Rom curve with few control points to dense or noisy points.

    ``r = crspline.fit(points, *, tolerance, alpha=0.5, closed=False,
    mode="subset", tension=0.0, endconditions="natural")``

    Every point of ``r.curve`` is within ``tolerance`` of the input polyline
    and every input point within ``tolerance`` of the curve: proved segment
    by segment, rounding included (``r.deviation`` is the bound proved).
    Where no choice of points keeps the tolerance (a curve through every
    point can overshoot a sharp kink), the tension of the vertices there is
    raised (0.5, 0.8, 0.95, 1; at 1 a segment is its input segment), so the
    tolerance is always met.

    Parameters
    ----------
    points : array_like, shape (N, dim) or (N,)
        The samples, dim 1 to 16; float32 input fits a float32 curve.
    tolerance : float
        Distance allowed both ways, in the points' units (> 0, above the
        coordinates' rounding floor).
    alpha : float, default 0.5
        Knot exponent of the curve in [0, 1] (0.5 centripetal).
    closed : bool, default False
        The points are a ring (the first point not repeated).
    mode : {'subset', 'free'}, default 'subset'
        ``'subset'``: the control points are input points (``r.indices``);
        ``'free'``: they may move off the input points onto the middles of the
        input segments, for noisy data.
    tension : float, default 0
        The curve's own tension in [0, 1]; the fit raises it per vertex where needed.
    endconditions : str or pair, default 'natural'
        ``'natural'`` or ``'reflect'`` (or a pair of them) for an open curve.

    Returns
    -------
    FitResult
        ``curve``, ``deviation``, ``indices`` (None in free mode), ``count``, ...

    Raises
    ------
    ValueError
        (``InvalidInput``) a tolerance that is not a positive number or is at
        or below the rounding floor (named in the message) or below 1.5e-154,
        a non-finite coordinate or one beyond 2.4e153 (2-D; the proof squares
        distances: scale such data), fewer than 2 points (3 closed), a bad
        mode, alpha or tension.
    """
    pts = _as_points(points)
    tolerance = _real(tolerance, "tolerance")
    alpha = _real(alpha, "alpha")
    tension = _real(tension, "tension")
    if not isinstance(mode, str) or mode not in _MODES:
        raise InvalidInput(f"mode must be 'subset' or 'free', got {mode!r}")
    closed = bool(closed)
    start, end = _ends(endconditions, closed)
    d = _crspline._fit(pts, tolerance, alpha, closed, mode, tension, start, end)
    cp = d["points"]
    ends = "closed" if closed else (start if start == end else (start, end))
    kb = d["kb_tension"]
    if kb is None:
        curve = CatmullRom(cp, alpha=alpha, endconditions=ends, tension=tension)
    else:
        # The same construction as the core's curve: per-vertex tension,
        # no continuity or bias, the curve's own tension on top.
        curve = KochanekBartels.__new__(KochanekBartels)
        curve._build(_as_points(cp), alpha, None, ends, tension, (list(kb), [], []), False)
        import numpy as _np
        inner = kb if closed else kb[1:-1]
        tcb = _np.zeros((len(inner), 3))
        tcb[:, 0] = inner
        tcb.flags.writeable = False
        curve._tcb = tcb
    r = FitResult()
    r.curve = curve
    r.deviation = d["deviation"]
    r.curve_to_input = d["curve_to_input"]
    r.input_to_curve = d["input_to_curve"]
    r.indices = d["indices"]
    if r.indices is not None:
        r.indices.flags.writeable = False
    r.count = d["count"]
    r.tensioned = d["tensioned"]
    r.rounding_floor = d["rounding_floor"]
    return r
