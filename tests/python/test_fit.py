"""crspline.fit (issue 40): the Python face of the core's fit.hpp.

The proved tolerance is checked against dense sampling of the returned curve
object (an independent check of the curve Python rebuilds, not of the core's
report), the report's fields, the curve classes, errors as ValueError with
the core's words, and the GIL released while fitting."""
import threading

import numpy as np
import pytest

import crspline


def _noisy(seed, n=200, noise=0.1):
    rng = np.random.default_rng(seed)
    angle = np.cumsum(rng.normal(0, 0.12, n))
    steps = np.stack([np.cos(angle), np.sin(angle)], axis=1)
    return np.cumsum(steps, axis=0) + rng.uniform(-noise, noise, (n, 2))


def _seg_dist(p, a, b):
    """Distance of each point p (M, dim) to the segments a -> b (K, dim): (M, K)."""
    d = b - a
    w = p[:, None, :] - a[None, :, :]
    l2 = np.maximum((d * d).sum(-1), 1e-300)
    f = np.clip((w * d[None]).sum(-1) / l2, 0, 1)
    e = w - f[..., None] * d[None]
    return np.sqrt((e * e).sum(-1))


def _measure(curve, pts, closed):
    """Largest sampled curve-to-polyline distance, and the largest input-to-curve
    distance bounded below interval by interval: the nearer of an interval's two
    samples less 0.6 of its own gap (the largest gap anywhere, a closed line's long
    closing segment, made the bound idle)."""
    t = np.linspace(curve.grid[0], curve.grid[-1], 60 * len(curve.grid))
    s = curve.evaluate(t)
    poly = np.vstack([pts, pts[:1]]) if closed else pts
    c2i = _seg_dist(s, poly[:-1], poly[1:]).min(axis=1).max()
    gap = np.linalg.norm(np.diff(s, axis=0), axis=1)
    d = np.sqrt(((pts[:, None, :] - s[None, :, :]) ** 2).sum(-1))
    lower = (np.minimum(d[:, :-1], d[:, 1:]) - 0.6 * gap[None, :]).min(axis=1)
    return c2i, lower.max()


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("closed", [False, True])
@pytest.mark.parametrize("mode", ["subset", "free"])
def test_proved_tolerance_by_dense_sampling(seed, closed, mode):
    pts = _noisy(seed)
    tol = [0.05, 0.2, 0.5][seed % 3]
    r = crspline.fit(pts, tolerance=tol, closed=closed, mode=mode)
    assert r.deviation <= tol
    assert r.count == len(r.curve.points) < len(pts)
    c2i, i2c = _measure(r.curve, pts, closed)
    # Sampled distances are lower bounds of the true ones; the proof bounds
    # the true ones (1e-9: the sampling's own rounding at this scale).
    assert c2i <= r.curve_to_input + 1e-9, (seed, c2i, r.curve_to_input)
    assert i2c <= r.input_to_curve + 1e-9, (seed, i2c, r.input_to_curve)
    assert r.curve.closed == closed
    if mode == "subset":
        assert r.indices.dtype == np.int64
        np.testing.assert_array_equal(r.curve.points, pts[r.indices])
        if not closed:
            assert r.indices[0] == 0 and r.indices[-1] == len(pts) - 1
    else:
        assert r.indices is None


def test_curve_classes_and_options():
    pts = _noisy(1)
    r = crspline.fit(pts, tolerance=0.3, alpha=0.0, tension=0.1, endconditions="reflect")
    assert isinstance(r.curve, crspline.CatmullRom)
    # A zigzag with right-angle kinks at a small tolerance needs tension: a KochanekBartels.
    zig = np.array([[i // 2 + i % 2, i // 2] for i in range(30)], dtype=float)
    k = crspline.fit(zig, tolerance=0.01)
    assert k.tensioned > 0
    assert isinstance(k.curve, crspline.KochanekBartels)
    assert k.curve.tcb.shape == (len(k.curve.points) - 2, 3)
    assert (k.curve.tcb[:, 0] > 0).any() and (k.curve.tcb[:, 1:] == 0).all()
    c2i, i2c = _measure(k.curve, zig, False)
    assert c2i <= 0.01 and i2c <= 0.01
    # float32 in, float32 curve; 3-D.
    f = crspline.fit(pts.astype(np.float32), tolerance=0.3)
    assert f.curve.points.dtype == np.float32
    p3 = np.column_stack([pts, np.sin(np.arange(len(pts)) / 9)])
    assert crspline.fit(p3, tolerance=0.2).curve.dim == 3
    assert "FitResult(count=" in repr(r)


def test_errors_are_value_errors_with_the_cores_words():
    pts = _noisy(2)
    for tol in (0.0, -1.0, float("nan")):
        with pytest.raises(ValueError, match="tolerance must be a positive finite number"):
            crspline.fit(pts, tolerance=tol)
    bad = pts.copy()
    bad[5, 1] = np.nan
    with pytest.raises(ValueError, match="point 5 has a non-finite coordinate 1: nan"):
        crspline.fit(bad, tolerance=0.1)
    with pytest.raises(ValueError, match="needs at least 2 points, got 1"):
        crspline.fit(pts[:1], tolerance=0.1)
    with pytest.raises(ValueError, match=r"rounding floor 5\.68.*e-08 of the coordinates \(256 ulps"):
        crspline.fit(pts + 1e6, tolerance=1e-8)
    with pytest.raises(ValueError, match="mode must be 'subset' or 'free'"):
        crspline.fit(pts, tolerance=0.1, mode="best")
    with pytest.raises(ValueError, match="must be 'natural' or 'reflect'"):
        crspline.fit(pts, tolerance=0.1, endconditions=([1, 0], "natural"))
    with pytest.raises(TypeError):
        crspline.fit(pts, 0.1)  # tolerance is keyword-only


def test_gil_released_while_fitting():
    """A Python thread keeps running while another thread fits: it counts
    while the fit runs (with the GIL held it could not)."""
    pts = _noisy(3, n=3000)
    done = threading.Event()
    ticks = []

    def count():
        while not done.is_set():
            ticks.append(1)

    t = threading.Thread(target=count)
    t.start()
    try:
        before = len(ticks)
        crspline.fit(pts, tolerance=0.05, mode="free")
        during = len(ticks) - before
    finally:
        done.set()
        t.join()
    assert during > 1000
