"""A drop-in for ``splines.quaternion`` (``splines`` 0.3.3), on crspline's core.

``from crspline.splines import quaternion`` gives the same classes with the
same signatures and defaults: ``Quaternion``, ``UnitQuaternion``, ``slerp``,
``canonicalized``, ``PiecewiseSlerp``, ``DeCasteljau``, ``KochanekBartels``,
``CatmullRom``, ``BarryGoldman`` and ``Squad``. Their numbers are the
package's, including where the package departs from its documentation
(see docs/rotation.md):

* the natural end of ``KochanekBartels``/``CatmullRom`` is the one the
  package computes (second control quaternion slerp(k0, k1, 1/2)), not the
  documented slerp(k0, c1-, 1/2) (crspline.rotation.QuaternionSpline's
  default 'natural');
* ``evaluate(t, 1)`` is the package's formula 2 (m - 1) log(B A*) / dt from
  the last two De Casteljau points, exact at the knots only (the curve's
  true angular velocity: crspline.rotation.QuaternionSpline.evaluate(t, 1));
* an alpha grid is computed from 2 acos(q_i . q_(i+1)) as the package does
  (so repeated keys raise the package's errors and nearly equal keys get its
  grid); crspline.rotation uses 4 atan2(|a - b|, |a + b|).

Deliberate differences: keys must be unit quaternions to within 1e-6
(ValueError naming the key), an explicit grid must increase strictly, and the
log map uses atan2 (the package's sqrt(1 - w^2) loses up to 3e-10 relative
for angles of 1e-4 rad). Values come from the C++ core
(crspline::rotation::quaternion_spline), with the keys' signs, grid and
segment choice of the package.
"""
import math as _math

import numpy as _np

from . import _crspline

__all__ = ["Quaternion", "UnitQuaternion", "slerp", "canonicalized", "PiecewiseSlerp", "DeCasteljau",
           "KochanekBartels", "CatmullRom", "BarryGoldman", "Squad"]


class Quaternion:
    """A quaternion: ``scalar`` and 3-tuple ``vector``."""

    __slots__ = "_scalar", "_vector"

    def __new__(cls, scalar, vector):
        obj = super().__new__(cls)
        x, y, z = vector
        obj._scalar, obj._vector = scalar, (x, y, z)
        return obj

    @property
    def scalar(self):
        return self._scalar

    @property
    def vector(self):
        return self._vector

    def __repr__(self):
        return f"{type(self).__name__}(scalar={self.scalar}, vector={self.vector})"

    def __eq__(self, other):
        if not isinstance(other, Quaternion):
            return NotImplemented
        return self.xyzw == other.xyzw

    __hash__ = None

    def __add__(self, other):
        if not isinstance(other, Quaternion):
            return NotImplemented
        return Quaternion(self.scalar + other.scalar, tuple(a + b for a, b in zip(self.vector, other.vector)))

    def __sub__(self, other):
        if not isinstance(other, Quaternion):
            return NotImplemented
        return Quaternion(self.scalar - other.scalar, tuple(a - b for a, b in zip(self.vector, other.vector)))

    def __mul__(self, other):
        if not isinstance(other, Quaternion):
            return Quaternion(self.scalar * other, tuple(c * other for c in self.vector))
        unit = isinstance(self, UnitQuaternion) and isinstance(other, UnitQuaternion)
        w1, (x1, y1, z1) = self.scalar, self.vector
        w2, (x2, y2, z2) = other.scalar, other.vector
        return Quaternion.__new__(UnitQuaternion if unit else Quaternion,
                                  w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
                                  (w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                                   w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                                   w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2))

    def __rmul__(self, other):
        return self.__mul__(other)

    def __neg__(self):
        x, y, z = self.vector
        return Quaternion.__new__(type(self), -self.scalar, (-x, -y, -z))

    def conjugate(self):
        x, y, z = self.vector
        return Quaternion.__new__(type(self), self.scalar, (-x, -y, -z))

    def normalized(self):
        n = self.norm
        x, y, z, w = self.xyzw
        return UnitQuaternion.from_unit_xyzw((x / n, y / n, z / n, w / n))

    def dot(self, other):
        """The 4-D dot product."""
        return sum(a * b for a, b in zip(self.xyzw, other.xyzw))

    @property
    def norm(self):
        return _math.sqrt(sum(c * c for c in self.xyzw))

    @property
    def xyzw(self):
        x, y, z = self.vector
        return x, y, z, self.scalar

    @property
    def wxyz(self):
        x, y, z = self.vector
        return self.scalar, x, y, z


class UnitQuaternion(Quaternion):
    """A unit quaternion (a rotation); ``UnitQuaternion()`` is the identity."""

    __slots__ = ()

    def __new__(cls):
        return Quaternion.__new__(cls, 1.0, (0.0, 0.0, 0.0))

    @classmethod
    def from_axis_angle(cls, axis, angle):
        x, y, z = axis
        s = angle / (2 * _math.sqrt(x * x + y * y + z * z))
        return cls.exp_map((s * x, s * y, s * z))

    @classmethod
    def from_unit_xyzw(cls, xyzw):
        """From the components (scalar last) of a unit quaternion; not normalized."""
        x, y, z, w = xyzw
        return Quaternion.__new__(cls, w, (x, y, z))

    def __pow__(self, alpha):
        if not _np.isscalar(alpha):
            return _np.array([self.__pow__(a) for a in alpha])
        if abs(self.scalar) >= 1:  # as splines: q itself (so (-1)^s = -1)
            return Quaternion.__new__(UnitQuaternion, self.scalar, self.vector)
        return UnitQuaternion.exp_map(alpha * self.log_map())

    def inverse(self):
        return self.conjugate()

    @classmethod
    def exp_map(cls, value):
        """[cos|v|, sin|v| v/|v|] (half-angle units)."""
        x, y, z = value
        n = _math.sqrt(x * x + y * y + z * z)
        if n == 0:
            return Quaternion.__new__(cls, n + 1, (n, n, n))
        s = _math.sin(n) / n
        return Quaternion.__new__(cls, _math.cos(n), (s * x, s * y, s * z))

    def log_map(self):
        """The vector part scaled to half the rotation angle (atan2, no acos)."""
        v = _np.asarray(self.vector, dtype=float)
        s = float(_np.sqrt(v @ v))
        if self.scalar >= 1 or s == 0:
            return _np.zeros(3)
        return v * (_math.atan2(s, self.scalar) / s)

    @property
    def axis(self):
        v = _np.asarray(self.vector, dtype=float)
        with _np.errstate(invalid="ignore", divide="ignore"):
            return v / _np.sqrt(v @ v)

    @property
    def angle(self):
        return 2 * _math.atan2(_math.sqrt(sum(c * c for c in self.vector)), self.scalar)

    def rotation_to(self, other):
        """other * self^-1: the rotation taking self to other (world frame)."""
        return other * self.inverse()

    def rotate_vector(self, v):
        return (self * Quaternion(0, v) * self.inverse()).vector


def slerp(one, two, t):
    """(two one^-1)^t one: no sign change (a negative dot takes the long way)."""
    return (two * one.inverse()) ** t * one


def canonicalized(quaternions):
    """Each quaternion negated where its dot with the previous (the identity
    before the first) is negative."""
    p = UnitQuaternion()
    for q in quaternions:
        if p.dot(q) < 0:
            q = -q
        yield q
        p = q


# ----- helpers --------------------------------------------------------------------

def _rows(quaternions):
    return _np.array([q.wxyz for q in quaternions], dtype=_np.float64).reshape(-1, 4)


def _unit(row):
    return Quaternion.__new__(UnitQuaternion, float(row[0]), (float(row[1]), float(row[2]), float(row[3])))


def _check_quaternions(quaternions, closed):
    quaternions = list(quaternions)
    if len(quaternions) < 2:
        raise ValueError("At least two quaternions are required")
    if closed:
        quaternions = quaternions + quaternions[:1]
    return list(canonicalized(quaternions))


def _check_grid(grid, alpha, quaternions):
    """The package's grid: range(n), or 2 acos(dot)^alpha steps (its errors
    included), or the given grid."""
    if grid is None:
        if alpha is None:
            return list(range(len(quaternions)))
        grid = [0]
        for a, b in zip(quaternions, quaternions[1:]):
            delta = (2 * _math.acos(a.dot(b))) ** alpha
            if delta == 0:
                raise ValueError("Repeated quaternions are not possible with alpha != 0")
            grid.append(grid[-1] + delta)
        return grid
    if alpha is not None:
        raise TypeError("Only one of {grid, alpha} is allowed")
    if len(quaternions) != len(grid):
        raise ValueError("Number of grid values must be same as quaternions (one more for closed curves)")
    return list(grid)


class _Curve:
    """Evaluation on the core, with the package's segment choice and errors."""

    def _segment(self, t):
        g = self.grid
        if t < g[0]:
            raise ValueError(f"t too small: {t}")
        if not (t < g[-1] or t == g[-1]):
            raise ValueError(f"t too big: {t}")
        return min(int(_np.searchsorted(g, t, side="right")) - 1, len(g) - 2)

    def _value(self, t):
        seg = self._segment(t)
        q = self._core.evaluate_on(_np.array([seg], dtype=_np.int64), _np.array([float(t)]), 0, "world")[0]
        return _unit(q[0])

    def _values(self, t):
        """Rotations at an array of t in one call to the core (the package
        loops in Python); the first t outside the grid raises as it would."""
        a = _np.asarray(t, dtype=_np.float64)
        flat = a.reshape(-1)
        g = self.grid
        bad = ~((flat >= g[0]) & (flat <= g[-1]))
        if bad.any():
            self._segment(flat[int(_np.argmax(bad))])  # raises 't too small/big: ...'
        seg = _np.minimum(_np.searchsorted(g, flat, side="right") - 1, len(g) - 2).astype(_np.int64)
        q = self._core.evaluate_on(seg, _np.ascontiguousarray(flat), 0, "world")[0]
        out = _np.empty(len(flat), dtype=object)
        out[:] = [_unit(r) for r in q]
        return out.reshape(a.shape)

    def _many(self, t, one):
        a = _np.asarray(t)
        out = [one(x) for x in a.reshape(-1)]
        if out and isinstance(out[0], Quaternion):
            result = _np.empty(len(out), dtype=object)
            result[:] = out
            return result.reshape(a.shape)
        return _np.array(out).reshape(a.shape + _np.shape(out[0]) if out else a.shape)

    def _core_from_keys(self, keys, closed, kind, tcb=None):
        k = _rows(keys[:-1] if closed else keys)
        g = _np.asarray(self.grid, dtype=_np.float64)
        return _crspline._QuaternionSpline(k, kind, closed, None, g, "natural_splines", "natural_splines", "world",
                                           tcb, False, False, 1e-6)


class PiecewiseSlerp(_Curve):
    """Slerp between consecutive (canonicalized) keys."""

    def __init__(self, quaternions, *, grid=None, closed=False):
        quaternions = _check_quaternions(quaternions, closed)
        if grid is None:
            grid = range(len(quaternions))
        if len(quaternions) != len(grid):
            raise ValueError("Number of grid values must be same as quaternions (one more for closed curves)")
        self.quaternions = quaternions
        self.grid = list(grid)
        self._core = self._core_from_keys(quaternions, closed, "piecewise_slerp")

    def evaluate(self, t, n=0):
        if n != 0:
            raise NotImplementedError("Derivatives are not implemented yet")
        if not _np.isscalar(t):
            return self._values(t)
        return self._value(t)


class DeCasteljau(_Curve):
    """Segments of control quaternions, each reduced by slerps (De Casteljau)."""

    def __init__(self, segments, grid=None):
        if len(segments) < 1:
            raise ValueError("There must be at least one segment")
        if grid is None:
            grid = range(len(segments) + 1)
        elif len(segments) + 1 != len(grid):
            raise ValueError("Number of grid values must be one more than number of segments")
        self.segments = segments
        self.grid = list(grid)
        for i, s in enumerate(segments):
            if len(s) < 2:
                raise ValueError(f"Segment must have at least two quaternions (segment {i} has {len(s)})")
        self._core = _crspline._QuaternionSpline.de_casteljau([_rows(s) for s in segments],
                                                              _np.asarray(self.grid, dtype=_np.float64))

    def evaluate(self, t, n=0):
        """The rotation (n=0) or the package's angular-velocity formula (n=1)."""
        if n not in (0, 1):
            raise ValueError(f"Unsupported n: {n!r}")
        one = self._value if n == 0 else self._formula_omega
        if not _np.isscalar(t):
            return self._values(t) if n == 0 else self._many(t, one)
        return one(t)

    def _formula_omega(self, t):
        # 2 (m - 1) log(B A^-1) / dt, (A, B) the last two De Casteljau points:
        # the package's evaluate(t, 1), exact at u = 0 and u = 1 only.
        seg = self._segment(t)
        t0, t1 = self.grid[seg:seg + 2]
        u = (t - t0) / (t1 - t0)
        level = list(self.segments[seg])
        while len(level) > 2:
            level = [slerp(a, b, u) for a, b in zip(level, level[1:])]
        a, b = level
        return (b * a.inverse()).log_map() * 2 * (len(self.segments[seg]) - 1) / (t1 - t0)


class KochanekBartels(DeCasteljau):
    """Kochanek-Bartels-like rotation spline (cubic De Casteljau segments)."""

    def __init__(self, quaternions, grid=None, *, tcb=(0, 0, 0), alpha=None, endconditions="natural"):
        closed = isinstance(endconditions, str) and endconditions == "closed"
        slots = len(quaternions) if closed else len(quaternions) - 2
        keys = _check_quaternions(quaternions, closed)
        self.grid = _check_grid(grid, alpha, keys)
        tcb = _np.asarray(tcb, dtype=_np.float64)
        if tcb.ndim == 1 and len(tcb) == 3:
            tcb = _np.tile(tcb, (max(slots, 0), 1))
        elif len(tcb) != slots:
            raise ValueError("There must be two more quaternions than TCB values (except for closed curves)")
        if not closed and len(keys) > 2:
            if isinstance(endconditions, str):
                start = end = endconditions
            else:
                try:
                    start, end = endconditions
                except (TypeError, ValueError):
                    raise TypeError("endconditions must be a string or a pair") from None
            for c in (start, end):
                if isinstance(c, str) and c == "natural":
                    continue
                if _np.shape(c) == ():
                    raise NotImplementedError("TODO")
                raise ValueError(f"{c!r} is not a valid start/end condition")
        flat = tcb.reshape(-1) if len(keys) > 2 and tcb.size else None
        self._core = self._core_from_keys(keys, closed, "kochanek_bartels", flat)
        self.segments = [tuple(_unit(r) for r in s) for s in self._core.control_quaternions]


class CatmullRom(KochanekBartels):
    """KochanekBartels with TCB (0, 0, 0)."""

    def __init__(self, quaternions, grid=None, *, alpha=None, endconditions="natural"):
        super().__init__(quaternions, grid, tcb=(0, 0, 0), alpha=alpha, endconditions=endconditions)


class BarryGoldman(_Curve):
    """The Barry-Goldman pyramid of slerps; always closed."""

    def __init__(self, quaternions, grid=None, *, alpha=None):
        self.quaternions = _check_quaternions(quaternions, True)
        self.grid = _check_grid(grid, alpha, self.quaternions)
        self._core = self._core_from_keys(self.quaternions, True, "barry_goldman")

    def evaluate(self, t):
        if not _np.isscalar(t):
            return self._values(t)
        return self._value(t)


class Squad(_Curve):
    """Spherical quadrangle interpolation; always closed."""

    def __init__(self, quaternions, grid=None, *, alpha=None):
        self.quaternions = _check_quaternions(quaternions, True)
        self.grid = _check_grid(grid, alpha, self.quaternions)
        self._core = self._core_from_keys(self.quaternions, True, "squad")
        self.segments = [[_unit(r) for r in s] for s in self._core.control_quaternions]

    def evaluate(self, t):
        if not _np.isscalar(t):
            return self._values(t)
        return self._value(t)
