"""Geometry through the Python API: tessellation, bounding boxes, nearest
points, curvature and frames, analysis; and that batch work releases the GIL."""
import json

import numpy as np
import pytest
from hypothesis import given, strategies as st

import crspline
from conftest import assert_releases_the_gil
from test_properties import alphas, polygons

WAVE = [[0, 0], [1, 2], [3, 2], [4, 0], [6, -1]]
HELIX = [[np.cos(a), np.sin(a), 0.3 * a] for a in np.linspace(0, 4 * np.pi, 13)]


def dense(c, n=4001):
    t = np.linspace(*c.domain, n)
    return t, c.evaluate(t)


def distance_to_polyline(x, poly):
    """Distance from each row of x to the polyline (brute force)."""
    a, b = poly[:-1], poly[1:]
    d = b - a
    L2 = np.maximum((d * d).sum(axis=1), 1e-300)
    w = np.clip(((x[:, None, :] - a[None]) * d[None]).sum(axis=2) / L2, 0, 1)
    foot = a[None] + w[..., None] * d[None]
    return np.sqrt(((x[:, None, :] - foot) ** 2).sum(axis=2)).min(axis=1)


@given(polygons(dim=2, min_points=3), alphas, st.sampled_from([1e-1, 1e-2, 1e-3]))
def test_tessellation_meets_its_tolerance(p, alpha, rel):
    c = crspline.CatmullRom(p, alpha=alpha)
    box = c.bounding_box()
    tol = rel * np.linalg.norm(box[1] - box[0])
    r = c.tessellate(tol)
    assert np.array_equal(r["points"], c.evaluate(r["t"]))  # vertices on the curve, exactly
    assert np.all(np.diff(r["t"]) > 0)
    assert set(c.grid.tolist()) <= set(r["t"].tolist())  # every knot is a vertex
    _, x = dense(c, 3001)
    # Dense sampling proves the promise (both ways would need the other
    # direction too; curve -> polyline is the one dense samples can check).
    assert distance_to_polyline(x, r["points"]).max() <= tol * (1 + 1e-9) + 1e-12 * np.abs(p).max()


def test_tessellate_default_tolerance():
    c = crspline.CatmullRom(WAVE)
    r = c.tessellate()
    box = c.bounding_box()
    tol = 1e-3 * np.linalg.norm(box[1] - box[0])
    _, x = dense(c)
    assert distance_to_polyline(x, r["points"]).max() <= tol * (1 + 1e-9)
    assert len(r["t"]) < len(c.tessellate(tol / 100)["t"])
    with pytest.raises(ValueError, match="tolerance must be positive"):
        c.tessellate(0)


@given(polygons(), alphas)
def test_bounding_box_brackets_the_curve_and_is_tight(p, alpha):
    c = crspline.CatmullRom(p, alpha=alpha)
    lo, hi = c.bounding_box()
    _, x = dense(c, 2001)
    scale = np.abs(p).max()
    assert np.all(x >= lo - 1e-13 * scale) and np.all(x <= hi + 1e-13 * scale)
    # Tight: dense samples come within the sampling error of every face.
    size = hi - lo
    assert np.all(x.min(axis=0) - lo <= 1e-3 * size + 1e-12 * scale)
    assert np.all(hi - x.max(axis=0) <= 1e-3 * size + 1e-12 * scale)
    clo, chi = c.bounding_box(tight=False)  # Bézier control points: contains the tight box
    # (up to the rounding of the interior extrema the tight box evaluates)
    assert np.all(clo <= lo + 1e-14 * scale) and np.all(chi >= hi - 1e-14 * scale)


@given(polygons(dim=2, min_points=3), alphas)
def test_nearest_beats_brute_force(p, alpha):
    c = crspline.CatmullRom(p, alpha=alpha)
    rng = np.random.default_rng(len(p))
    lo, hi = c.bounding_box()
    q = rng.uniform(lo - 1, hi + 1, size=(20, 2))
    r = c.nearest(q)
    assert r["t"].shape == (20,) and r["point"].shape == (20, 2) and r["segment"].dtype == np.int64
    _, x = dense(c, 20001)
    brute = ((q[:, None, :] - x[None]) ** 2).sum(axis=2).min(axis=1)
    scale = np.abs(p).max() + 1
    assert np.all(r["distance_sq"] <= brute + 1e-12 * scale**2)
    assert np.allclose(r["point"], c.evaluate(r["t"]), atol=1e-12 * scale)
    assert np.allclose(((r["point"] - q) ** 2).sum(axis=1), r["distance_sq"], rtol=1e-9, atol=1e-24)


def test_nearest_shapes():
    c = crspline.CatmullRom(WAVE)
    one = c.nearest([2.0, 3.0])
    assert np.ndim(one["t"]) == 0 and one["point"].shape == (2,)
    grid = np.zeros((3, 4, 2))
    r = c.nearest(grid)
    assert r["t"].shape == (3, 4) and r["point"].shape == (3, 4, 2)
    on = c.nearest(c.points)  # the points themselves: distance 0 (to rounding) at their knots
    assert np.all(on["distance_sq"] <= (1e-15 * 6) ** 2) and np.allclose(on["t"], c.grid, rtol=0, atol=1e-12)
    with pytest.raises(ValueError, match="shape"):
        c.nearest([1, 2, 3])
    with pytest.raises(crspline.InvalidInput, match="not finite"):
        c.nearest([np.nan, 0])


def test_curvature_of_a_circle_like_curve():
    a = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    c = crspline.CatmullRom(np.c_[3 * np.cos(a), 3 * np.sin(a)], endconditions="closed")
    t = np.linspace(*c.domain, 200)
    k = c.curvature(t)
    # A C1 cubic approximation: its curvature wobbles about 1/3 by ~1%.
    assert k.shape == (200,) and np.allclose(k, 1 / 3, rtol=2e-2)
    s = c.signed_curvature(t)
    assert np.allclose(s, k)  # counterclockwise: turning left
    rev = crspline.CatmullRom(np.c_[3 * np.cos(a), 3 * np.sin(a)][::-1], endconditions="closed")
    assert np.all(rev.signed_curvature(t[:50] * rev.domain[1] / c.domain[1]) < 0)
    assert np.ndim(c.curvature(0.5)) == 0
    with pytest.raises(ValueError, match="2-D"):
        crspline.CatmullRom(HELIX).signed_curvature(0.5)


def test_curvature_and_torsion_of_the_twisted_cubic_in_closed_form():
    # (t, t^2, t^3) on [a, b] is the first segment of a uniform 3-point curve
    # with the start tangent given and P2 = P0 + 2h x'(b) (the Catmull-Rom
    # tangent at b is then x'(b)): the segment is the cubic itself, so
    # kappa = 2 sqrt(q) / (1 + 4t^2 + 9t^4)^(3/2) and tau = 3 / q with
    # q = 9t^4 + 9t^2 + 1 (x' x x'' = (6t^2, -6t, 2), det(x', x'', x''') = 12).
    def x(t):
        return np.array([t, t * t, t ** 3])

    def dx(t):
        return np.array([1.0, 2 * t, 3 * t * t])

    for a, b in [(0.0, 1.0), (-1.0, 0.5)]:
        h = b - a
        c = crspline.CatmullRom([x(a), x(b), x(a) + 2 * h * dx(b)], grid=[a, b, b + h],
                                endconditions=(dx(a), "natural"))
        t = a + h * np.arange(40) / 40  # [a, b): b belongs to the next segment
        q = 9 * t ** 4 + 9 * t ** 2 + 1
        # 1e-12 relative: a few roundings of coefficients of size <= 3 (C++
        # Frames.TwistedCubicCurvatureAndTorsionInClosedForm explains).
        assert np.allclose(c.curvature(t), 2 * np.sqrt(q) / (1 + 4 * t ** 2 + 9 * t ** 4) ** 1.5, rtol=1e-12, atol=0)
        assert np.allclose(c.torsion(t), 3 / q, rtol=1e-12, atol=0)


def test_torsion_and_frames_of_a_helix():
    c = crspline.CatmullRom(HELIX, alpha=0)
    t = np.linspace(1, 11, 50)  # away from the natural ends
    tau = c.torsion(t)
    # det(x', x'', x''') / |x' ^ x''|^2 from the derivatives themselves; a
    # right-handed helix has positive torsion (the natural end segments are
    # planar: 0 there).
    d1, d2, d3 = (c.evaluate(t, n) for n in (1, 2, 3))
    cr = np.cross(d1, d2)
    want = np.einsum("ij,ij->i", cr, d3) / np.einsum("ij,ij->i", cr, cr)
    interior = (t > 1) & (t < 11)
    assert np.allclose(tau[interior], want[interior], rtol=1e-9)
    assert np.all(tau[interior] > 0) and np.all(tau[~interior] >= 0)
    for kind in ("frenet", "rotation_minimizing"):
        f = c.frames(t, kind=kind)
        T, N, B = f["tangent"], f["normal"], f["binormal"]
        assert np.array_equal(f["position"], c.evaluate(t))
        for v in (T, N, B):
            assert np.allclose(np.linalg.norm(v, axis=1), 1, atol=1e-12)
        assert np.allclose((T * N).sum(axis=1), 0, atol=1e-12)
        assert np.allclose(np.cross(T, N), B, atol=1e-12)
        d1 = c.evaluate(t, 1)
        assert np.allclose(T, d1 / np.linalg.norm(d1, axis=1)[:, None], atol=1e-12)
    n0 = [0.0, 0.0, 1.0]
    f = c.frames(t, initial_normal=n0)
    assert np.dot(f["normal"][0], n0) > 0
    with pytest.raises(ValueError, match="kind must be"):
        c.frames(t, kind="bishop")
    with pytest.raises(ValueError, match="3-D"):
        crspline.CatmullRom(WAVE).frames([0.5], kind="frenet")


def test_frames_in_2d():
    c = crspline.CatmullRom(WAVE)
    f = c.frames(np.linspace(*c.domain, 9))
    T, N = f["tangent"], f["normal"]
    assert np.allclose(N, np.c_[-T[:, 1], T[:, 0]])  # the left normal
    assert np.all(f["binormal"] == 0)
    right = c.frames(np.linspace(*c.domain, 9), initial_normal=[T[0, 1], -T[0, 0]])
    assert np.allclose(right["normal"], -N)


def test_analysis_finds_the_uniform_cusp_and_none_for_centripetal():
    p = [(-5, 1), (0, 0), (1, 0), (6, 1)]  # SOURCES.md: exact cusp at u = 1/2 of the middle segment
    uni = crspline.CatmullRom(p, alpha=0).analyze()
    assert uni["has_cusp"] and len(uni["segments"]) == 3
    mid = uni["segments"][1]
    assert np.allclose(mid["cusp_u"], [0.5], atol=1e-6) and np.allclose(uni["cusp_t"], [1.5], atol=1e-6)
    assert mid["cusp_t"] == uni["cusp_t"]
    assert mid["bounds"] is not None and uni["segments"][0]["bounds"] is None  # end segments: no Eq. 5-8
    assert mid["distance_bound"] == mid["bounds"]["eq6"]
    cen = crspline.CatmullRom(p).analyze()
    assert not cen["has_cusp"] and not cen["has_self_intersection"]
    assert cen["intersections"] == [] and cen["folds"] == [] and cen["complete"] is True
    for s in cen["segments"]:
        assert s["max_chord_line_distance"] <= s["bezier_bound"] * (1 + 1e-12)
        if s["bounds"] is not None:
            assert s["max_chord_line_distance"] <= s["bounds"]["eq6"] * (1 + 1e-12)
    quick = crspline.CatmullRom(p).analyze(intersections=False)
    assert quick["intersections"] is None and quick["complete"] is None and quick["certificate"]["certified"]


def test_intersections_and_certificate():
    # A figure eight crosses itself; a convex closed curve is certified.
    eight = [(0, 0), (1, 1), (2, 0), (1, -1), (0, 0.2), (-1, 1), (-2, 0), (-1, -1)]
    c = crspline.CatmullRom(eight, endconditions="closed")
    r = c.intersections()
    assert r["any"] and r["intersections"] and r["complete"]
    for x in r["intersections"]:
        assert len(x["segments"]) == len(x["u"]) == len(x["t"]) == 2 and x["distance"] <= 1e-9
        ta, tb = x["t"]
        assert np.allclose(c.evaluate(ta), x["point"], atol=1e-9) and np.allclose(c.evaluate(tb), x["point"], atol=1e-9)
    cert = c.certify_intersection_free()
    assert not cert["certified"] and cert["intersects"] is True and cert["failed_rule"] is not None
    assert cert["detail"] and cert["search"] == r
    a = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    circle = crspline.CatmullRom(np.c_[np.cos(a), np.sin(a)], endconditions="closed")
    ok = circle.certify_intersection_free()
    assert ok["certified"] and ok["failed_rule"] is None and ok["search"] is None
    # Uniform knots break rule 1.
    no = crspline.CatmullRom(np.c_[np.cos(a), np.sin(a)], endconditions="closed", alpha=0)
    r = no.certify_intersection_free(search_on_failure=False)
    assert r["failed_rule"] == "not_centripetal" and r["intersects"] is None


def test_batch_work_releases_the_gil():
    # A long arc-length inversion runs in a thread; the main thread keeps
    # running Python meanwhile. Were the GIL held, the main loop would stall
    # for the whole call.
    rng = np.random.default_rng(5)
    c = crspline.CatmullRom(rng.normal(size=(2000, 3)))
    c.t_at_arc_length(0.0)  # build the table first
    L = c.arc_length()
    s = rng.uniform(0, L, 400_000)
    assert_releases_the_gil(lambda k: c.t_at_arc_length(np.tile(s, k)))


def test_analysis_without_the_search_says_unknown_not_false():
    # Issue 31 point 5: analyze(intersections=False) cannot know whether two
    # segments cross: has_self_intersection is None (JSON null), like the
    # search's own fields, unless a segment loops or folds by itself.
    eight = [(0, 0), (1, 1), (2, 0), (1, -1), (0, 0.2), (-1, 1), (-2, 0), (-1, -1)]
    c = crspline.CatmullRom(eight, endconditions="closed")
    full = c.analyze()
    assert full["has_self_intersection"] is True and full["intersections"]
    assert not any(s["has_self_intersection"] for s in full["segments"])  # crossings between segments only
    quick = c.analyze(intersections=False)
    assert quick["has_self_intersection"] is None
    for key in ("intersections", "overlaps", "folds", "complete"):
        assert quick[key] is None, key
    assert '"has_self_intersection": null' in json.dumps(quick)
    # A curve that does not cross itself: False from the search, None without it.
    plain = crspline.CatmullRom([[0, 0], [1, 2], [3, 2], [4, 0]])
    assert plain.analyze()["has_self_intersection"] is False
    assert plain.analyze(intersections=False)["has_self_intersection"] is None
    # A loop inside one segment is known without the search (docs/report.md's
    # example: uniform knots, the short middle edge makes segment 1 loop).
    loop = crspline.CatmullRom([[0, 0], [1, 1], [1.1, 1], [2, 0]], alpha=0).analyze(intersections=False)
    assert loop["segments"][1]["has_self_intersection"] and loop["has_self_intersection"] is True
