"""The ``splines`` drop-in's monotone cubics and new-grid adapter
(``crspline.splines.PiecewiseMonotoneCubic``, ``MonotoneCubic``,
``NewGridAdapter``): the algorithm of the ``splines`` documentation on
crspline's Hermite curves. Import them from ``crspline.splines``."""
import numbers as _numbers

import numpy as _np

from .splines import CatmullRom, _check_grid, _float_array, _num, _vertices


# ------------------------------------------------------------ monotone cubics
def _fix_slope(slope, left, right):
    """Dougherty et al. (1989), eq. 4.2: the slope at a vertex limited so that
    both neighbouring segments stay monotone; zero at a local extremum.
    ``left`` and ``right`` are the secant slopes on either side."""
    if left * right <= 0:
        return 0
    if right > 0:
        return min(max(0, slope), 3 * min(abs(left), abs(right)))
    return max(min(0, slope), -3 * min(abs(left), abs(right)))


def _monotone_end_slope(inner, secant):
    """The first (last) slope from the second (penultimate) one and the end
    segment's secant slope: the ``splines`` end condition of its piecewise
    monotone cubics (3 S - 2 inner when inner <= S, else (3 S - inner) / 2,
    mirrored for S < 0). ``inner`` is already limited to [0, 3 S]."""
    if secant < 0:
        return -_monotone_end_slope(-inner, -secant)
    if inner <= secant:
        return 3 * secant - 2 * inner
    return (3 * secant - inner) / 2


def _slope_list(slopes, n, closed):
    """The given slopes (None: computed), one per value, as floats or None."""
    if slopes is None:
        return [None] * n
    slopes = list(slopes)
    if closed:
        slopes = slopes + slopes[:1]
    if len(slopes) != n:
        raise ValueError("Same number of values and slopes is required")
    out = []
    for i, s in enumerate(slopes):
        if s is None:
            out.append(None)
            continue
        if isinstance(s, bool) or not isinstance(s, _numbers.Real):
            raise TypeError(f"slopes[{i}] must be a number or None, got {type(s).__name__}")
        if not _np.isfinite(s):
            raise ValueError(f"slopes[{i}] is not finite ({_num(s)})")
        out.append(s)
    return out


class PiecewiseMonotoneCubic(CatmullRom):
    """Piecewise monotone cubic curve through one-dimensional values, as
    ``splines.PiecewiseMonotoneCubic(values, grid=None, slopes=None, *,
    alpha=None, closed=False)``: no segment overshoots its two values.

    The slope at an interior value is the Catmull-Rom (three-point) tangent
    ``_calculate_tangent(points, times)``, limited by Dougherty et al. (1989)
    eq. 4.2 (zero at a local extremum, at most three times the smaller
    neighbouring secant slope); the first and last slopes follow ``splines``'
    monotone end condition. ``slopes`` may give any slope (None: computed);
    a given slope that would make a segment non-monotone raises ValueError
    ('Slope too steep: ...')."""

    def __init__(self, values, grid=None, slopes=None, *, alpha=None, closed=False):
        if len(values) < 2:
            raise ValueError("At least two values are required")
        a, scalar = _vertices(values)
        if not scalar:
            raise ValueError(f"values must be a sequence of numbers (one-dimensional), got shape {a.shape}")
        x = a[:, 0]
        if closed:
            x = _np.concatenate([x, x[:1]])
        grid = _check_grid(grid, alpha, x[:, None])
        n = len(x)
        given = _slope_list(slopes, n, closed)
        xs, ts = [float(v) for v in x], [float(v) for v in grid]
        if closed:  # the second value again after the first, for the slope at the seam
            xs.append(xs[1])
            ts.append(ts[-1] + (ts[1] - ts[0]))
        final = []  # incoming, outgoing at every interior vertex
        for i in range(1, len(xs) - 1):
            left = (xs[i] - xs[i - 1]) / (ts[i] - ts[i - 1])
            right = (xs[i + 1] - xs[i]) / (ts[i + 1] - ts[i])
            slope = given[i]
            if slope is None:
                slope = _fix_slope(float(self._calculate_tangent(tuple(xs[i - 1:i + 2]), tuple(ts[i - 1:i + 2]))),
                                   left, right)
            elif slope != _fix_slope(slope, left, right):
                raise ValueError(f"Slope too steep: {slope}")
            final += [slope, slope]

        def checked(slope, secant):
            if slope != _fix_slope(slope, secant, secant):
                raise ValueError(f"Slope too steep or wrong sign: {slope}")
            return slope

        if closed:
            final = final[-1:] + final[:-1]  # the seam's outgoing slope starts segment 0
        elif not final:  # two values
            secant = (xs[1] - xs[0]) / (ts[1] - ts[0])
            one, two = given
            if one is None and two is None:
                final = [secant, secant]
            elif one is None:
                final = [_monotone_end_slope(checked(two, secant), secant), two]
            elif two is None:
                final = [checked(one, secant), _monotone_end_slope(one, secant)]
            else:
                final = [checked(one, secant), checked(two, secant)]
        else:
            def end_slope(outer, inner, secant):
                return _monotone_end_slope(inner, secant) if outer is None else checked(outer, secant)

            first = end_slope(given[0], final[0], (xs[1] - xs[0]) / (ts[1] - ts[0]))
            last = end_slope(given[n - 1], final[-1], (xs[n - 1] - xs[n - 2]) / (ts[n - 1] - ts[n - 2]))
            final = [first] + final + [last]
        f = _np.asarray(final, dtype=_np.float64)[:, None]
        self._init_hermite(x[:, None], True, f[0::2], f[1::2], grid)


class MonotoneCubic(PiecewiseMonotoneCubic):
    """Monotone cubic curve, as ``splines.MonotoneCubic(values, grid=None,
    slopes=None, *, alpha=None, cyclic=False)``: a ``PiecewiseMonotoneCubic``
    of monotone (non-decreasing or non-increasing) values, so the whole curve
    is monotone and ``get_time(value)`` inverts it.

    ``cyclic=True`` gives the first and the last slope one value: the
    limited three-point slope at the first value with the data continued
    periodically (the value before the first is values[-2] - (values[-1] -
    values[0]) at grid[-2] - (grid[-1] - grid[0])). This definition is
    crspline's; ``splines`` has the flag, but no numbers of it were
    available to compare with."""

    def __init__(self, values, grid=None, slopes=None, *, alpha=None, cyclic=False, **kwargs):
        if "closed" in kwargs:
            raise TypeError('The "closed" argument is not allowed')
        if kwargs:
            raise TypeError(f"MonotoneCubic() got an unexpected keyword argument {next(iter(kwargs))!r}")
        if cyclic and slopes is not None and (slopes[0] is not None or slopes[-1] is not None):
            raise ValueError('The "cyclic" flag needs the first and the last slope to be None')
        PiecewiseMonotoneCubic.__init__(self, values, grid, slopes, alpha=alpha)
        x = self._vertices_[:, 0]
        diffs = _np.diff(x)
        if not (all(diffs >= 0) or all(diffs <= 0)):
            raise ValueError("Only monotone values are allowed")
        if cyclic:
            g = [float(v) for v in self.grid]
            period_t, period_x = g[-1] - g[0], x[-1] - x[0]
            xs = (x[-2] - period_x, x[0], x[1])
            ts = (g[-2] - period_t, g[0], g[1])
            slope = _fix_slope(float(self._calculate_tangent(xs, ts)),
                               (xs[1] - xs[0]) / (ts[1] - ts[0]), (xs[2] - xs[1]) / (ts[2] - ts[1]))
            given = [None] * len(x) if slopes is None else list(slopes)
            given[0] = given[-1] = slope
            PiecewiseMonotoneCubic.__init__(self, values, grid, given, alpha=alpha)

    def get_time(self, value):
        """The parameter value t where the curve has the given value (a
        number, or a sequence: an array of the answers). ``None`` where the
        answer is not unique (a plateau of equal values); ValueError
        ('value outside allowed range: ...') outside the values.

        Found on the segment that holds the value by Newton steps safeguarded
        by bisection, to the last bits of t (``splines`` takes the roots of
        the segment's cubic)."""
        if not _np.isscalar(value):
            return _np.array([self.get_time(v) for v in value])
        x = self._vertices_[:, 0]
        if x[0] <= value <= x[-1]:
            sign = 1.0
        elif x[-1] <= value <= x[0]:
            sign = -1.0
        else:
            raise ValueError(f"value outside allowed range: {value}")
        matches = _np.nonzero(x == value)[0]
        if len(matches) > 1:
            return None
        if len(matches) == 1:
            return self.grid[matches[0]]
        # The segment i with x[i] < value < x[i + 1] (in the direction of sign).
        i = int(_np.searchsorted(sign * x, sign * value, side="right")) - 1
        t0, t1 = float(self.grid[i]), float(self.grid[i + 1])
        h = t1 - t0
        x0, x1 = x[i], x[i + 1]
        m0, m1 = h * self._out[i, 0], h * self._in[i + 1, 0]

        def p(u):  # the segment's Hermite form minus the value, and its derivative
            return (((2 * x0 - 2 * x1 + m0 + m1) * u + (-3 * x0 + 3 * x1 - 2 * m0 - m1)) * u + m0) * u + x0 - value

        def dp(u):
            return (3 * (2 * x0 - 2 * x1 + m0 + m1) * u + 2 * (-3 * x0 + 3 * x1 - 2 * m0 - m1)) * u + m0

        lo, hi = 0.0, 1.0  # sign * p(lo) < 0 < sign * p(hi)
        u = (value - x0) / (x1 - x0)
        for _ in range(200):
            f = sign * p(u)
            if f == 0:
                break
            if f < 0:
                lo = u
            else:
                hi = u
            d = sign * dp(u)
            step = u - f / d if d > 0 else 0.5 * (lo + hi)
            u_next = step if lo < step < hi else 0.5 * (lo + hi)
            if u_next == u or hi - lo <= 2 * _np.finfo(float).eps:
                break
            u = u_next
        return t0 + u * h


class NewGridAdapter:
    """A curve with new parameter values at its knots, as
    ``splines.NewGridAdapter(curve, new_grid=1, *, cyclic=False)``.

    ``new_grid`` is one value per knot of ``curve.grid`` (``None``: chosen
    automatically), or one number X, meaning [0, None, ..., None, X]. The
    first and last value must be given (TypeError otherwise); the given ones
    must increase strictly. A ``MonotoneCubic`` through the pairs (new,
    old) of the given values maps a new parameter u to the curve's t, so the
    image of the curve is unchanged and it never runs backwards; a ``None``
    knot gets the new value that this map takes to its old one
    (``get_time``). ``evaluate(u)`` is ``curve.evaluate(t(u))``; ``.grid``
    holds the new values. ``curve`` is any curve with ``grid`` and a
    vectorized ``evaluate(t)``: a ``crspline.splines`` curve, a
    ``UnitSpeedAdapter``, or a ``crspline.CatmullRom``."""

    def __init__(self, curve, new_grid=1, *, cyclic=False):
        old_grid = list(curve.grid)
        if _np.isscalar(new_grid):
            new_grid = [0] + [None] * (len(old_grid) - 2) + [new_grid]
        new_grid = list(new_grid)
        if len(new_grid) != len(old_grid):
            raise ValueError("new_grid must have same length as curve.grid")
        if new_grid[0] is None or new_grid[-1] is None:
            raise TypeError("first/last element of new_grid cannot be None")
        previous = None
        for i, v in enumerate(new_grid):
            if v is None:
                continue
            if isinstance(v, bool) or not isinstance(v, _numbers.Real):
                raise TypeError(f"new_grid[{i}] must be a number or None, got {type(v).__name__}")
            if not _np.isfinite(v):
                raise ValueError(f"new_grid[{i}] is not finite ({_num(v)})")
            if previous is not None and not v > new_grid[previous]:
                raise ValueError(f"new_grid must be strictly increasing: new_grid[{i}] = {_num(v)} is not greater "
                                 f"than new_grid[{previous}] = {_num(new_grid[previous])}")
            previous = i
        old_values = [float(o) for o, v in zip(old_grid, new_grid) if v is not None]
        new_values = [v for v in new_grid if v is not None]
        self._new2old = MonotoneCubic(old_values, grid=new_values, cyclic=cyclic)
        self.grid = [self._new2old.get_time(float(o)) if v is None else v for o, v in zip(old_grid, new_grid)]
        self.curve = curve
        self._t_range = float(old_grid[0]), float(old_grid[-1])

    def evaluate(self, u, n=0):
        """The curve's point at the new parameter value(s) u (a number, or a
        sequence or array: that shape plus the point's). Raises ValueError
        ('u too small: ...' / 'u too big: ...') outside ``grid``; derivatives
        (n > 0) are not implemented, as in ``splines``."""
        if n != 0:
            raise NotImplementedError("Derivatives are not implemented yet")
        g0, g1 = self.grid[0], self.grid[-1]
        if _np.isscalar(u):
            if u < g0:
                raise ValueError(f"u too small: {u}")
            if not (u < g1 or u == g1):
                raise ValueError(f"u too big: {u}")
            # The map hits the old knots to rounding; keep t inside the curve's domain.
            t = min(max(float(self._new2old.evaluate(u)), self._t_range[0]), self._t_range[1])
            return self.curve.evaluate(t)
        uu = _float_array(u, "u")
        bad = ~((uu >= g0) & (uu <= g1))
        if bad.any():
            value = uu.ravel()[int(_np.argmax(bad.ravel()))]
            raise ValueError(f"u too {'small' if value < g0 else 'big'}: {value}")
        if uu.size == 0:
            return _np.zeros(uu.shape)
        t = _np.clip(self._new2old.evaluate(uu), *self._t_range)
        return _np.asarray(self.curve.evaluate(t))
