"""crspline.rotation's batch calls (issue 28): RotationSpline.__call__,
Slerp.__call__ and the native classes' evaluate go through the core's batch
kernels (include/crspline/rotation/batch.hpp) in one call. Checked here
against the per-segment evaluation (evaluate_on, one sample at a time in the
core's scalar code), on seeded random curves (the seed is printed on
failure)."""
import numpy as np
import pytest

from crspline import rotation

try:
    from scipy.spatial.transform import Rotation
except ImportError:
    Rotation = None
needs_scipy = pytest.mark.skipif(Rotation is None, reason="SciPy is not installed (apt python3-scipy)")

EPS = np.finfo(np.float64).eps


def random_keys(rng, n, max_angle):
    """A walk of n unit quaternions [w, x, y, z], steps up to max_angle rad, random signs."""
    keys = [np.array([1.0, 0, 0, 0])]
    for _ in range(n - 1):
        axis = rng.normal(size=3)
        a = rng.uniform(0.05, 1.0) * max_angle
        step = np.concatenate([[np.cos(a / 2)], np.sin(a / 2) * axis / np.linalg.norm(axis)])
        q = keys[-1]
        w = step[0] * q[0] - step[1:] @ q[1:]
        v = step[0] * q[1:] + q[0] * step[1:] + np.cross(step[1:], q[1:])
        keys.append(np.concatenate([[w], v]) * rng.choice([-1.0, 1.0]))
    return np.array(keys)


def close(a, b, tol):
    return float(np.abs(np.asarray(a) - np.asarray(b)).max(initial=0.0)) <= tol


# Tolerances, as tests/rotation/test_rotation_batch.cpp derives them: the
# kernel's sine and cosine and libm's are each within an ulp and about ten
# roundings follow, so 8 eps on O(1) quaternions; rates to 64 eps of the
# largest rate in the batch.
def check_against_segments(c, t, order, frame, seg, tol_q=8 * EPS):
    got = c._c.evaluate(t, order, frame)[order]
    ref = c._c.evaluate_on(seg, t, order, frame)[order]
    scale = 1.0 if order == 0 else max(1.0, float(np.abs(ref).max()))
    tol = tol_q if order == 0 else 64 * EPS * scale
    assert close(got, ref, tol), (order, frame, float(np.abs(got - ref).max()), tol)


def test_native_batches_match_per_segment(seed):
    rng = np.random.default_rng(seed)
    checked = 0
    for round_ in range(8):
        n = int(rng.integers(2, 12))
        keys = random_keys(rng, n, 3.0 if round_ % 2 else 0.5)
        times = np.cumsum(rng.uniform(0.2, 2.0, n)) - 1
        curves = [rotation.C2RotationSpline(times, keys, "natural" if round_ % 3 == 1 else "scipy", "scipy"),
                  rotation.QuaternionSpline(keys, "piecewise_slerp", alpha=0.5),
                  rotation.QuaternionSpline(keys, "catmull_rom", alpha=0.5)]
        for c in curves:
            g = c.grid
            t = np.concatenate([rng.uniform(g[0], g[-1], 500), g])
            seg = np.clip(np.searchsorted(g, t, side="right") - 1, 0, len(g) - 2).astype(np.int64)
            # A repeated knot (zero interval) belongs to the segment before it at the end.
            for k in range(len(t)):
                while seg[k] > 0 and not g[seg[k] + 1] > g[seg[k]] and t[k] >= g[seg[k] + 1]:
                    seg[k] -= 1
            for order in (0, 1, 2):
                for frame in ("world", "body"):
                    check_against_segments(c, t, order, frame, seg)
                    checked += 1
    assert checked == 8 * 3 * 6


def test_batch_makes_only_the_arrays_asked_for():
    keys = random_keys(np.random.default_rng(1), 5, 1.0)
    c = rotation.C2RotationSpline(np.arange(5.0), keys)
    q, w, a = c._c.evaluate(np.linspace(0, 4, 7), 0, "world")
    assert q.shape == (7, 4) and w is None and a is None
    q, w, a = c._c.evaluate(np.linspace(0, 4, 7), 1, "world")
    assert w.shape == (7, 3) and a is None
    with pytest.raises(ValueError, match=r"t = 9 \(index 2\) is outside the curve's domain"):
        c.evaluate([0.0, 1.0, 9.0])


def test_rotation_spline_call_extrapolates_as_scipy(seed):
    """RotationSpline(t, order): the segment of each t found in the core (t
    outside the times takes the end segment, as SciPy's searchsorted does)."""
    rng = np.random.default_rng(seed)
    keys = random_keys(rng, 9, 2.5)
    times = np.cumsum(rng.uniform(0.3, 1.5, 9))
    s = rotation.RotationSpline(times, keys)
    span = times[-1] - times[0]
    t = np.concatenate([rng.uniform(times[0] - span, times[-1] + span, 2000), times])
    seg = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(times) - 2).astype(np.int64)
    for order in (0, 1, 2):
        got = s(t, order)
        ref = s._c.evaluate_on(seg, t, order, "body")[order]
        scale = 1.0 if order == 0 else max(1.0, float(np.abs(ref).max()))
        assert close(got, ref, 8 * EPS if order == 0 else 64 * EPS * scale), order
    # A scalar t gives one row.
    assert s(float(times[3])).shape == (4,) and s(float(times[3]), 1).shape == (3,)


@needs_scipy
def test_rotation_objects_in_and_out(seed):
    """With a SciPy Rotation in, the kernels write x, y, z, w rows: the same
    rotations as the arrays path, and Slerp likewise."""
    rng = np.random.default_rng(seed)
    keys = random_keys(rng, 7, 2.0)
    times = np.cumsum(rng.uniform(0.3, 1.5, 7))
    rots = Rotation.from_quat(keys[:, [1, 2, 3, 0]])
    t = rng.uniform(times[0], times[-1], 1000)
    for cls in (rotation.RotationSpline, rotation.Slerp):
        a, b = cls(times, keys)(t), cls(times, rots)(t)
        assert isinstance(b, Rotation) and len(b) == len(t)
        bq = b.as_quat()[:, [3, 0, 1, 2]]
        # Up to sign (SciPy may flip to w >= 0); Rotation.from_quat normalizes
        # the unit rows again: a few eps.
        gap = np.minimum(np.abs(a - bq).max(axis=1), np.abs(a + bq).max(axis=1)).max()
        assert gap <= 8 * EPS, (cls.__name__, gap)
        one = cls(times, rots)(float(times[2]))
        assert isinstance(one, Rotation) and one.single
