"""Python arguments turned into the compiled core's normalized form: real
numbers, point arrays, vectors and end conditions (the core validates the
values; these check only the Python forms), and results handed back."""
from collections.abc import Mapping as _Mapping
import numbers as _numbers

import numpy as _np


class _DefaultAlpha(float):
    """0.5, marked as "not given" (so that a grid alone is not "alpha and grid")."""

    __slots__ = ()


_DEFAULT_ALPHA = _DefaultAlpha(0.5)

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
