"""Many curves in one call (crspline.arc_lengths, crspline.tessellate_many):
the same numbers as the single-curve path, in input order, on several
threads, with the curve's index in every error."""

import numpy as np
import pytest

import crspline
from conftest import assert_releases_the_gil


def _polygons(seed, count=300):
    """Closed and open polygons of 3 to 40 points, mostly 2-D (a font's or a
    map's contours), some 1-D, 3-D and 7-D; random radii, so lengths differ."""
    rng = np.random.default_rng(seed)
    out = []
    for k in range(count):
        n = int(rng.integers(3, 41))
        dim = int(rng.choice([2, 2, 2, 2, 1, 3, 7]))
        a = np.sort(rng.uniform(0, 2 * np.pi, n))
        r = rng.uniform(0.5, 2, n) * 10 ** rng.uniform(-2, 3)
        pts = np.zeros((n, dim))
        pts[:, 0] = r * np.cos(a)
        if dim > 1:
            pts[:, 1] = r * np.sin(a)
        if dim > 2:
            pts[:, 2:] = rng.normal(size=(n, dim - 2))
        out.append(pts)
    return out


@pytest.mark.parametrize("options", [
    {},
    {"alpha": 0.0, "endconditions": "closed"},
    {"alpha": 1.0, "endconditions": "reflect", "tension": 0.3},
])
def test_arc_lengths_match_the_single_curve_path(options, seed):
    curves = _polygons(seed)
    one = np.array([crspline.CatmullRom(p, **options).arc_length() for p in curves])
    for workers in (1, 3, None):
        many = crspline.arc_lengths(curves, workers=workers, **options)
        assert many.shape == (len(curves),) and many.dtype == np.float64
        # The same computation on the same doubles: bit for bit, in input order.
        assert np.array_equal(many, one), f"seed {seed}, workers {workers}, first difference at " \
                                          f"{int(np.argmax(many != one))}"
    assert len(set(one.tolist())) == len(curves)  # distinct lengths: an order mix-up could not hide


def test_tessellate_many_matches_the_single_curve_path(seed):
    curves = _polygons(seed, 200)
    many = crspline.tessellate_many(curves, endconditions="closed", workers=4)
    assert len(many) == len(curves)
    for k, (p, got) in enumerate(zip(curves, many)):
        want = crspline.CatmullRom(p, endconditions="closed").tessellate()
        assert np.array_equal(got["points"], want["points"]), f"seed {seed}, curve {k}"
        assert np.array_equal(got["t"], want["t"]), f"seed {seed}, curve {k}"
    tol = 1e-2
    many = crspline.tessellate_many(curves[:20], tol)
    for k, p in enumerate(curves[:20]):
        assert np.array_equal(many[k]["points"], crspline.CatmullRom(p).tessellate(tol)["points"]), f"curve {k}"


def test_curves_as_one_array_and_as_a_generator():
    pts = np.random.default_rng(1).normal(size=(50, 6, 3))
    one = [crspline.CatmullRom(p).arc_length() for p in pts]
    assert np.array_equal(crspline.arc_lengths(pts), one)
    assert np.array_equal(crspline.arc_lengths(p for p in pts), one)
    assert crspline.arc_lengths([]).shape == (0,)


def test_errors_name_the_curve():
    curves = _polygons(7, 300)
    bad = [c.copy() for c in curves]
    bad[137][2, 0] = np.nan
    bad[250][1, 0] = np.inf
    for workers in (1, 2, 8):  # two bad curves: the lowest index is the one reported, whatever the threads
        with pytest.raises(crspline.SpecError) as info:
            crspline.arc_lengths(bad, workers=workers)
        e = info.value
        assert str(e) == "curve 137: point 2, coordinate 0 is not finite (nan)"
        assert (e.field, e.index, e.component, e.value) == ("points", 2, 0, "nan")
    bad[137][2, 0] = 0.5
    bad[250][1] = bad[250][0]  # coincident points: refused only in strict mode
    assert crspline.arc_lengths(bad).shape == (300,)
    with pytest.raises(crspline.InvalidInput, match=r"^curve 250: coincident consecutive points \(strict mode\): "
                                                    r"0 and 1$"):
        crspline.arc_lengths(bad, strict=True, workers=3)
    with pytest.raises(crspline.SpecError, match=r"^curve 3: a curve needs at least 2 points, got 1$"):
        crspline.arc_lengths(curves[:3] + [[[0, 0]]] + curves[3:])
    with pytest.raises(crspline.SpecError, match=r"^curve 1: dimension must be 1 to 16, got 17$"):
        crspline.arc_lengths([curves[0], np.zeros((3, 17))])
    with pytest.raises(TypeError, match=r"^curve 2: points must be real numbers"):
        crspline.arc_lengths(curves[:2] + [[["a", "b"], ["c", "d"]]])
    with pytest.raises(ValueError, match=r"^curve 1: points must be an N x dim array"):
        crspline.arc_lengths([curves[0], np.zeros((2, 2, 2))])
    with pytest.raises(crspline.InvalidInput, match=r"^curve 0: accuracy must be in \(0, 1\), got 2$"):
        crspline.arc_lengths(curves, accuracy=2)
    with pytest.raises(crspline.SpecError, match="start condition must be"):
        crspline.arc_lengths(curves, endconditions=("clamped", "natural"))
    with pytest.raises(ValueError, match="workers must be at least 1, got 0"):
        crspline.arc_lengths(curves, workers=0)
    with pytest.raises(TypeError, match="curves must be a list of point arrays"):
        crspline.arc_lengths(5)


def test_many_curves_release_the_gil():
    # As test_geometry's test of one curve: the main thread keeps running
    # Python while one call works through many curves in C++.
    rng = np.random.default_rng(3)
    curves = [rng.normal(size=(400, 3)) for _ in range(300)]
    assert_releases_the_gil(lambda k: crspline.arc_lengths(curves * k, workers=1))
