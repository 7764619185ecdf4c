"""The proved decision on crossings (issue 27; C++ ``crspline/decision.hpp``):
does a plane curve cross itself, do two curves cross, do any curves of a
set cross? And the clearance: the least distance between non-adjacent parts
of a curve, or between two curves, in any dimension.

The names are the npm package's in snake_case (decide, decidePair,
decideSet, clearance). The decision is a dict in the shape the core's
``report_decision`` writes (crspline/decision.hpp)::

    {'verdict': 'simple' | 'crosses' | 'touches', 'fast_path': bool,
     'floor': float,
     'crossings': [{'curves': [i, j], 'segments': [a, b],
                    'u': [[lo, hi], [lo, hi]], 'point': [x, y]}, ...],
     'touches': [{'curves', 'segments', 'u': [u, v], 'distance',
                  'budget_exhausted'}, ...],
     'pairs': [{'curves', 'segments', 'arguments': ['separation', ...]}, ...]}

What each verdict guarantees: docs/analysis.md. The work runs in C++ with
the GIL released.
"""
import operator as _operator

from . import _crspline
from ._arguments import _real
from ._curve import CatmullRom


def _curve(c, what):
    if not isinstance(c, CatmullRom):
        raise TypeError(f"{what} must be a crspline curve (CatmullRom, KochanekBartels), got {type(c).__name__}")
    return c


def _plane(c, what):
    _curve(c, what)
    if c._dim != 2:
        raise ValueError(f"{what}: the decision needs plane curves (dimension 2), got dimension {c._dim} "
                         "(clearance works in any dimension)")
    return c._c


def _count(value, name):
    if value is None:
        return None
    if isinstance(value, bool):
        raise TypeError(f"{name} must be a non-negative integer, got {value!r}")
    value = _operator.index(value)
    if value < 0:
        raise ValueError(f"{name} must be a non-negative integer, got {value}")
    return value


def _options(fast_path, budget, pair_budget, record_pairs):
    return bool(fast_path), _count(budget, "budget"), _count(pair_budget, "pair_budget"), bool(record_pairs)


def decide(curve, *, fast_path=True, budget=None, pair_budget=None, record_pairs=True):
    """Does the plane curve cross itself? A proved ``'simple'``, a proved
    ``'crosses'`` (each crossing with parameter intervals that contain it),
    or ``'touches'`` (pieces within the floor that neither proof resolves).

    ``fast_path``: try the paper's certificate first (float64 curves);
    ``budget``, ``pair_budget``: work budgets (None: the core's defaults);
    ``record_pairs``: fill ``pairs`` with the argument that decided each
    pair of segments. A curve that is not 2-D raises ValueError."""
    c = _plane(curve, "the curve")
    return _crspline._decide(c, *_options(fast_path, budget, pair_budget, record_pairs))


def decide_pair(a, b, *, budget=None, pair_budget=None, record_pairs=True):
    """Do two plane curves cross each other? (Each one's own crossings are
    ``decide``'s business.) Crossings name curve 0 (``a``) and 1 (``b``)."""
    curves = [_plane(a, "curve a"), _plane(b, "curve b")]
    return _crspline._decide_set(curves, "pair", False, True, *_options(True, budget, pair_budget, record_pairs)[1:])


def decide_set(curves, *, self=False, budget=None, pair_budget=None, record_pairs=True):
    """Do any two curves of the set cross? Every pair of pieces whose boxes
    meet is found through one box tree over all the curves; crossings name
    the curves by their index in ``curves``. ``self=True``: each curve's own
    crossings are decided too."""
    if isinstance(curves, (str, bytes)) or not hasattr(curves, "__iter__"):
        raise TypeError(f"curves must be a list of curves, got {type(curves).__name__}")
    cs = [_plane(c, f"curve {i} of the set") for i, c in enumerate(curves)]
    return _crspline._decide_set(cs, "set", bool(self), True, *_options(True, budget, pair_budget, record_pairs)[1:])


def clearance(curve_or_a, b=None, *, accuracy=0.0, budget=None):
    """The least distance between non-adjacent segments of a curve (``b``
    None), or between two curves of one dimension; any dimension.

    Returns ``{'distance', 'lower_bound', 'curves': (i, j), 'segments': (a,
    b), 'u': (u_a, u_b), 'points': ndarray (2, dim), 'exhausted'}``: the true
    least distance lies in ``[lower_bound, distance]``, and their difference
    is at most ``accuracy`` (0: 1e-10 of the curves' extent from the first
    point) unless ``exhausted`` (the work budget ran out). ``distance`` is
    ``inf`` when there is no pair to measure (an open curve of one or two
    segments has no non-adjacent pair)."""
    a = _curve(curve_or_a, "curve_or_a")
    accuracy = _real(accuracy, "accuracy")
    budget = _count(budget, "budget")
    if b is None:
        return _crspline._clearance(a._c, accuracy, budget, a._dim)
    _curve(b, "b")
    if a._dim != b._dim:
        raise ValueError(f"clearance between curves of dimensions {a._dim} and {b._dim}: they must be equal")
    return _crspline._clearance_pair(a._c, b._c, accuracy, budget, a._dim)
