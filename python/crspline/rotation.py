"""Rotation and pose splines (crspline's core, include/crspline/rotation/).

Quaternions are NumPy arrays of rows ``[w, x, y, z]`` (scalar first, as in
``splines``; SciPy's order is x, y, z, w and is converted at its boundary).
Angular velocities are 3-vectors in radians per unit of t, in the world frame
unless ``frame='body'``.

Native classes:

* ``QuaternionSpline(keys, kind='catmull_rom', ...)``: Catmull-Rom and
  Kochanek-Bartels (the tangent-space construction of ``splines.quaternion``),
  piecewise slerp, Barry-Goldman and Squad, open or closed, alpha on the
  rotation angle or an explicit grid; exact angular velocity and acceleration.
* ``C2RotationSpline(times, keys, start='scipy', end='scipy', closed=False)``:
  SciPy's C2 construction solved to convergence (``residual`` says how well).
* ``PoseCurve(positions, rotations, ...)``: position and rotation on one grid.

SciPy-compatible: ``RotationSpline(times, rotations)`` and ``Slerp(times,
rotations)`` take and give ``scipy.spatial.transform.Rotation`` objects when
given one (arrays of [w, x, y, z] otherwise); ``spline(t, 1)`` and
``spline(t, 2)`` are body-frame rates, as SciPy's are.
"""
import numpy as _np

from . import _crspline

__all__ = ["QuaternionSpline", "C2RotationSpline", "PoseCurve", "RotationSpline", "Slerp", "slerp", "as_matrix",
           "from_matrix", "as_rotvec", "from_rotvec", "as_euler", "from_euler", "fit", "RotationFit"]


def _quats(q, what="keys"):
    a = _np.asarray(q, dtype=_np.float64)
    if a.ndim == 1:
        a = a.reshape(1, -1)
    if a.ndim != 2 or a.shape[1] != 4:
        raise ValueError(f"{what} must have shape (n, 4), rows [w, x, y, z]; got shape {_np.shape(q)}")
    return _np.ascontiguousarray(a)


def _times(t):
    a = _np.asarray(t, dtype=_np.float64)
    return a, _np.ascontiguousarray(a.reshape(-1))


def _shape(result, t_array, width):
    return result.reshape(t_array.shape + (width,))


class _Evaluating:
    """evaluate(t, order=0, frame='world'): quaternions [w, x, y, z] (order 0),
    angular velocity (1) or angular acceleration (2); t a number or an array."""

    def evaluate(self, t, order=0, frame="world"):
        ta, flat = _times(t)
        q, w, a = self._c.evaluate(flat, order, frame)
        out = (q, w, a)[order] if order in (0, 1, 2) else None
        if out is None:
            raise ValueError(f"derivative order must be 0, 1 or 2, got {order}")
        return _shape(out, ta, out.shape[1])

    __call__ = evaluate

    def angular_velocity(self, t, frame="world"):
        return self.evaluate(t, 1, frame)

    def angular_acceleration(self, t, frame="world"):
        return self.evaluate(t, 2, frame)

    @property
    def grid(self):
        return self._c.grid

    @property
    def keys(self):
        return self._c.keys

    def angle_length(self, accuracy=1e-12):
        """The total angle turned through, the integral of |omega| dt (radians)."""
        return self._c.angle_length(accuracy)

    def constant_angular_speed_times(self, n, accuracy=1e-12):
        """n values of t at equal steps of turned angle, from the start to the end."""
        return self._c.constant_angular_speed_times(int(n), accuracy)


class QuaternionSpline(_Evaluating):
    """A rotation spline through unit-quaternion keys (rows [w, x, y, z]).

    kind: 'catmull_rom' (default), 'kochanek_bartels' (tcb: one (T, C, B)
    triple or one per key that uses it), 'piecewise_slerp', 'barry_goldman',
    'squad'. alpha (on the rotation angle between keys) or grid; neither:
    0, 1, 2, ... start/end (open Catmull-Rom and Kochanek-Bartels): 'natural'
    (the documented end), 'natural_splines' (what splines 0.3.3 computes) or
    an angular velocity (3-vector, in velocity_frame). Keys are made
    hemisphere-continuous unless keep_signs; repeated keys with alpha > 0 are
    the curve's limit unless strict. Keys are normalized, as SciPy's
    Rotation.from_quat does; a zero or non-finite key raises ValueError, and
    so does one farther than a finite unit_tolerance from unit norm (the
    ``splines`` drop-in keeps that package's check: 1e-6)."""

    def __init__(self, keys, kind="catmull_rom", *, alpha=None, grid=None, closed=False, start="natural",
                 end="natural", velocity_frame="world", tcb=None, keep_signs=False, strict=False,
                 unit_tolerance=_np.inf):
        start = start if isinstance(start, str) else _np.asarray(start, dtype=_np.float64)
        end = end if isinstance(end, str) else _np.asarray(end, dtype=_np.float64)
        self._c = _crspline._QuaternionSpline(
            _quats(keys), kind, closed, None if alpha is None else float(alpha),
            None if grid is None else _np.asarray(grid, dtype=_np.float64), start, end, velocity_frame,
            None if tcb is None else _np.asarray(tcb, dtype=_np.float64).reshape(-1), keep_signs, strict,
            unit_tolerance)

    @classmethod
    def de_casteljau(cls, segments, grid=None):
        """Segments of control quaternions (each (m, 4), m >= 2), used as given."""
        self = cls.__new__(cls)
        self._c = _crspline._QuaternionSpline.de_casteljau([_quats(s, "segment") for s in segments],
                                                           None if grid is None else _np.asarray(grid, dtype=float))
        return self

    @property
    def control_quaternions(self):
        return self._c.control_quaternions

    def evaluate_on(self, segment, t, order=0, frame="world"):
        """Like evaluate, on the given segment(s) (one-sided at knots; extrapolates outside)."""
        ta, flat = _times(t)
        seg = _np.ascontiguousarray(_np.broadcast_to(_np.asarray(segment, dtype=_np.int64), ta.shape).reshape(-1))
        out = self._c.evaluate_on(seg, flat, order, frame)[order]
        return _shape(out, ta, out.shape[1])


class C2RotationSpline(_Evaluating):
    """SciPy's C2 rotation spline (a rotation-vector cubic per segment, angular
    rate continuous, angular acceleration matched at every key), solved by
    Newton's method to rounding. start/end: 'scipy' (SciPy's chord rates),
    'natural' (zero angular acceleration) or an angular velocity (3-vector in
    velocity_frame). closed: periodic, times has one more value than keys
    (the return to key 0). residual: the largest acceleration jump left.
    Keys are normalized as in QuaternionSpline (zero or non-finite refused)."""

    def __init__(self, times, keys, start="scipy", end="scipy", *, velocity_frame="world", closed=False,
                 keep_signs=False, unit_tolerance=_np.inf):
        start = start if isinstance(start, str) else _np.asarray(start, dtype=_np.float64)
        end = end if isinstance(end, str) else _np.asarray(end, dtype=_np.float64)
        self._c = _crspline._C2Spline(_np.asarray(times, dtype=_np.float64), _quats(keys), start, end, velocity_frame,
                                      closed, keep_signs, unit_tolerance)

    residual = property(lambda self: self._c.residual)
    acceleration_scale = property(lambda self: self._c.acceleration_scale)
    iterations = property(lambda self: self._c.iterations)
    key_rates = property(lambda self: self._c.key_rates, doc="body-frame angular velocity at each key")

    def evaluate_on(self, segment, t, order=0, frame="world"):
        ta, flat = _times(t)
        seg = _np.ascontiguousarray(_np.broadcast_to(_np.asarray(segment, dtype=_np.int64), ta.shape).reshape(-1))
        out = self._c.evaluate_on(seg, flat, order, frame)[order]
        return _shape(out, ta, out.shape[1])


class PoseCurve:
    """A pose curve: positions (n, 3) on crspline's Catmull-Rom (alpha, default
    centripetal, or grid) and rotations (n, 4) on the same grid (the C2 spline,
    or Catmull-Rom with c2=False). evaluate(t, frame) gives (position,
    quaternion, velocity, angular velocity)."""

    def __init__(self, positions, rotations, *, alpha=None, grid=None, closed=False, c2=True):
        self._c = _crspline._PoseCurve(_np.asarray(positions, dtype=_np.float64), _quats(rotations, "rotations"),
                                       None if alpha is None else float(alpha),
                                       None if grid is None else _np.asarray(grid, dtype=_np.float64), closed, c2)

    @property
    def grid(self):
        return self._c.grid

    def evaluate(self, t, frame="world"):
        ta, flat = _times(t)
        pos, q, vel, w = self._c.evaluate(flat, frame)
        return (_shape(pos, ta, 3), _shape(q, ta, 4), _shape(vel, ta, 3), _shape(w, ta, 3))

    def constant_speed_times(self, n, position_weight=1.0, angle_weight=0.0, accuracy=1e-12):
        return self._c.constant_speed_times(int(n), position_weight, angle_weight, accuracy)


# ----- keyframe reduction ------------------------------------------------------------

class RotationFit:
    """What ``fit`` returns: ``indices`` (kept samples, int64, first and last
    included), ``times`` and ``keys`` (their times and quaternions [w, x, y,
    z], normalized, signed as the curve signs them), ``curve`` (a
    ``QuaternionSpline``: Catmull-Rom on grid ``times``, natural ends),
    ``max_angle`` (the proved largest angle, radians, at the samples),
    ``worst`` (the sample where it is reached) and ``count``."""

    __slots__ = ("indices", "times", "keys", "curve", "max_angle", "worst")

    def __init__(self, indices, times, keys, curve, max_angle, worst):
        self.indices, self.times, self.keys, self.curve = indices, times, keys, curve
        self.max_angle, self.worst = max_angle, worst

    @property
    def count(self):
        return len(self.indices)

    def __repr__(self):
        return f"RotationFit(count={self.count}, max_angle={self.max_angle!r})"


def fit(times, quaternions, *, angle_tolerance, unit_tolerance=_np.inf):
    """Keyframe reduction: the fewest samples whose Catmull-Rom rotation curve
    (the samples' times as its grid) is within ``angle_tolerance`` radians of
    every sample at its time, proved at the samples (rounding included).

    times: strictly increasing (n,); quaternions: (n, 4) rows [w, x, y, z],
    normalized here (zero or non-finite rows refused, and with a finite
    ``unit_tolerance`` rows farther from unit norm), signs free. Returns a
    ``RotationFit``. Bad input raises ValueError naming the field, index and
    value."""
    t = _np.ascontiguousarray(_np.asarray(times, dtype=_np.float64))
    indices, key_times, keys, native, max_angle, worst = _crspline._rotation_fit(
        t, _quats(quaternions, "quaternions"), float(angle_tolerance), float(unit_tolerance))
    curve = QuaternionSpline.__new__(QuaternionSpline)
    curve._c = native
    return RotationFit(indices, key_times, keys, curve, max_angle, worst)


# ----- conversions (rows [w, x, y, z]) ------------------------------------------

def slerp(a, b, u):
    """slerp(a, b, u) = (b a*)^u a, row by row (no sign change: a.b < 0 takes the long way)."""
    a, b = _quats(a, "a"), _quats(b, "b")
    u = _np.ascontiguousarray(_np.broadcast_to(_np.asarray(u, dtype=_np.float64), (len(a),)))
    return _crspline._rotation_slerp(a, b, u)


def as_matrix(q):
    return _crspline._rotation_to_matrix(_quats(q, "quaternions"))


def from_matrix(m, tolerance=1e-9):
    m = _np.ascontiguousarray(_np.asarray(m, dtype=_np.float64).reshape(-1, 3, 3))
    return _crspline._rotation_from_matrix(m, tolerance)


def as_rotvec(q):
    return _crspline._rotation_to_rotvec(_quats(q, "quaternions"))


def from_rotvec(r):
    return _crspline._rotation_from_rotvec(_np.ascontiguousarray(_np.asarray(r, dtype=_np.float64).reshape(-1, 3)))


def as_euler(q, seq):
    """Euler angles (radians) in SciPy's convention names: 'xyz' extrinsic, 'XYZ' intrinsic."""
    return _crspline._rotation_to_euler(_quats(q, "quaternions"), seq)


def from_euler(seq, angles):
    return _crspline._rotation_from_euler(seq, _np.ascontiguousarray(_np.asarray(angles, dtype=_np.float64).reshape(-1, 3)))


# ----- SciPy-compatible classes ------------------------------------------------------

def _scipy_rotation_class():
    try:
        from scipy.spatial.transform import Rotation
    except ImportError:  # SciPy is optional: arrays in, arrays out
        return None
    return Rotation


def _from_rotations(rotations):
    """(quaternions [w, x, y, z] (n, 4), whether a SciPy Rotation came in)."""
    R = _scipy_rotation_class()
    if R is not None and isinstance(rotations, R):
        xyzw = _np.atleast_2d(rotations.as_quat())
        return _np.ascontiguousarray(xyzw[:, [3, 0, 1, 2]]), True
    return _quats(rotations, "rotations"), False


def _to_rotations(q, as_scipy, scalar, xyzw=False):
    """q: rows [w, x, y, z], or [x, y, z, w] already with xyzw (only for a SciPy Rotation)."""
    if as_scipy:
        R = _scipy_rotation_class()
        if not xyzw:
            q = q[..., [1, 2, 3, 0]]
        return R.from_quat(q[0] if scalar else q)
    return q[0] if scalar else q


def _check_times(times, n_rotations, what="rotations"):
    times = _np.asarray(times, dtype=_np.float64)
    if times.ndim != 1:
        raise ValueError("`times` must be 1-dimensional.")
    if len(times) < 2:
        raise ValueError("`times` must have at least 2 elements.")
    if n_rotations != len(times):
        raise ValueError(f"Expected number of {what} to be equal to number of timestamps given, got "
                         f"{n_rotations} {what} and {len(times)} timestamps.")
    dt = _np.diff(times)
    if _np.any(dt <= 0):
        raise ValueError("Values in `times` must be in a strictly increasing order.")
    return _np.ascontiguousarray(times)


class RotationSpline:
    """SciPy's ``RotationSpline(times, rotations)``, C2 to rounding (SciPy
    stops its iteration after 10 rounds). ``spline(t)`` gives rotations
    (a SciPy Rotation if one was given, else rows [w, x, y, z]); ``spline(t,
    1)`` and ``spline(t, 2)`` the angular rate and acceleration in the body
    frame, as SciPy's. t outside [times[0], times[-1]] extrapolates the end
    segments, as SciPy does."""

    def __init__(self, times, rotations):
        q, self._scipy = _from_rotations(rotations)
        self.times = _check_times(times, len(q))
        self.rotations = rotations
        # Keys normalized, as SciPy's from_quat does (a Rotation's are already).
        self._c = _crspline._C2Spline(self.times, q, "scipy", "scipy", "world", False, False, _np.inf)

    residual = property(lambda self: self._c.residual, doc="largest angular-acceleration jump left at a key")
    iterations = property(lambda self: self._c.iterations)

    def __call__(self, times, order=0):
        if order not in (0, 1, 2):
            raise ValueError("`order` must be 0, 1 or 2.")
        ta, flat = _times(times)
        # One call into the batch kernels (GIL released): the segment of each
        # t found there (t before the first or after the last time takes the
        # end segment, as SciPy's searchsorted does), the rotations written
        # in SciPy's x, y, z, w order when a Rotation is to be made; with
        # order 1 or 2 the rates alone (no rotations formed or written).
        out = self._c.evaluate(flat, order, "body", True, order == 0 and self._scipy, order == 0)[order]
        if order == 0:
            return _to_rotations(out, self._scipy, ta.ndim == 0, xyzw=self._scipy)
        return out[0] if ta.ndim == 0 else out


class Slerp:
    """SciPy's ``Slerp(times, rotations)``: slerp between consecutive keys,
    the short way; ``slerp(t)`` for t in [times[0], times[-1]]."""

    def __init__(self, times, rotations):
        q, self._scipy = _from_rotations(rotations)
        if len(q) == 1:
            raise ValueError("`rotations` must contain at least 2 rotations.")
        self.times = _check_times(times, len(q))
        self.rotations = rotations
        self._c = _crspline._QuaternionSpline(q, "piecewise_slerp", False, None, self.times, "natural", "natural",
                                              "world", None, False, False, _np.inf)  # normalized, as SciPy

    def __call__(self, times):
        ta, flat = _times(times)
        if _np.any(flat < self.times[0]) or _np.any(flat > self.times[-1]):
            raise ValueError("Interpolation times must be within the range "
                             f"[{self.times[0]}, {self.times[-1]}], both inclusive.")
        q = self._c.evaluate(flat, 0, "world", self._scipy)[0]
        return _to_rotations(q, self._scipy, ta.ndim == 0, xyzw=self._scipy)
