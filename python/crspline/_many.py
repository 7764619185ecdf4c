"""Many curves in one call: arc_lengths and tessellate_many, run in C++ on
several threads with the GIL released."""
import operator as _operator
import os as _os

import numpy as _np

from . import _crspline
from ._arguments import _as_points, _parse_endconditions, _real
from ._constants import centripetal, default_accuracy, uniform


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
