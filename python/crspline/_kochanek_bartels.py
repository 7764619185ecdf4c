"""KochanekBartels: the TCB spline with the ``splines`` package's signature,
a CatmullRom built with per-vertex tension, continuity and bias."""
import numpy as _np

from ._arguments import _as_points, _numeric_array, _readonly, _real
from ._constants import uniform
from ._curve import CatmullRom


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
