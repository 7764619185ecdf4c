"""crspline.sweep and crspline.stroke (issue 41) from Python: the mesh's
arrays and seam, the report, strokes against Shapely (is_valid, the area of
Shapely's buffer of the curve's tessellation within the tolerance times the
perimeter, fewer vertices), and the errors, each naming its field."""
import math

import numpy as np
import pytest
from shapely.geometry import LinearRing, LineString, Point, Polygon
from shapely.ops import unary_union

import crspline


def knot(n=12):
    a = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.c_[(2 + np.cos(3 * a)) * np.cos(2 * a), (2 + np.cos(3 * a)) * np.sin(2 * a), np.sin(3 * a)]


def test_sweep_arrays_and_the_seam():
    c = crspline.CatmullRom(knot(), endconditions="closed")
    m = crspline.sweep(c, radius=0.3, tolerance=1e-3)
    n = m["rings"] * m["ring_size"]
    assert m["positions"].shape == (n, 3) and m["normals"].shape == (n, 3) and m["uvs"].shape == (n, 2)
    assert m["indices"].dtype == np.uint32 and m["indices"].shape == (6 * (m["rings"] - 1) * (m["ring_size"] - 1) // 3, 3)
    assert m["indices"].max() == n - 1
    np.testing.assert_allclose(np.linalg.norm(m["normals"], axis=1), 1, atol=1e-12)
    r = m["report"]
    assert r["tolerance_met"] and r["bound"] <= 1e-3 * (1 + 1e-12) and r["proved"]
    assert not r["self_intersects"] and r["clearance"] > 0.6
    # The rings' frames against the exact rotation-minimizing frame: a
    # bound in radians, finite and small, its share (twice: the spread
    # holonomy's) inside the bound.
    assert 0 < r["frame_drift"] < 1e-5
    assert r["bound"] >= 2 * r["largest_radius"] * r["frame_drift"]
    # No seam: the computed closing ring met the first to rounding; the
    # stored one is the first (v runs 0 to 1).
    assert r["seam_gap"] < 1e-9 and r["seam_normal_gap"] < 1e-9
    k = m["ring_size"]
    assert np.array_equal(m["positions"][-k:], m["positions"][:k])
    assert np.array_equal(m["normals"][-k:], m["normals"][:k])
    assert np.array_equal(m["uvs"][-k:, 0], m["uvs"][:k, 0]) and np.all(m["uvs"][-k:, 1] == 1)
    # Without the spread holonomy: a seam as wide as the twist says.
    bad = crspline.sweep(c, radius=0.3, tolerance=1e-3, seamless=False)
    assert bad["report"]["seam_gap"] > 0.3 * 0.5 * abs(r["holonomy"]) > 0


def test_sweep_counts_roll_scale_up_and_profiles():
    c = crspline.CatmullRom([[0, 0, 0], [1, 0.2, 0], [2, 0, 0.5], [3, 0.3, 0.2]])
    m = crspline.sweep(c, radius=0.1, tubular_segments=64, radial_segments=8)
    assert (m["rings"], m["ring_size"]) == (65, 9) and len(m["positions"]) == 65 * 9
    L = m["report"]["length"]
    # c's tangents stay far from vertical: the up frame's bound is proved;
    # a loop through vertical (a pole) too, its rings placed for it (the
    # cone's crossings are rings); at three.js' counts the rings next to
    # the cone are too far apart for the up frame to be bounded there.
    m = crspline.sweep(c, radius=0.1, roll=[0, 0.5, 1.0, 1.5], scale=([0, L], [1, 2]), up=[0, 0, 1])
    assert m["report"]["tolerance_met"] and m["report"]["proved"]
    loop = crspline.CatmullRom([[0, 0, 0], [1, 0, 1], [0, 0, 2], [-1, 0, 1], [0, 0.01, 0.1], [1, 0.02, 0]])
    m = crspline.sweep(loop, radius=0.1, up=[0, 0, 1])
    assert m["report"]["tolerance_met"] and m["report"]["proved"]
    m = crspline.sweep(loop, radius=0.1, up=[0, 0, 1], tubular_segments=64, radial_segments=8)
    assert not m["report"]["proved"]
    m = crspline.sweep(c, roll=([0, L / 2, L], [0, 1, 0]), profile=[[-0.1, 0], [0.1, 0]], profile_closed=False)
    assert m["ring_size"] == 2
    oval = crspline.CatmullRom([[0.1, 0], [0, 0.05], [-0.1, 0], [0, -0.05]], endconditions="closed")
    m = crspline.sweep(c, profile=oval, tolerance=1e-4)
    assert m["ring_size"] > 8 and m["report"]["bound"] <= 1e-4 * (1 + 1e-12)


def test_sweep_report_sees_a_thick_tube_meet_itself():
    c = crspline.CatmullRom(knot(), endconditions="closed")
    assert crspline.sweep(c, radius=0.8)["report"]["far_contact"]


def minkowski_reference(line, d, cap, closed):
    """The stroke of a polyline built from simple convex pieces (one flat-ended
    buffer per edge, a wedge of the disc on the outer side of each turn, the
    caps), merged by unary_union. Not
    GEOS's buffer of the line itself: on a tight hook with a wide stroke that
    drops covered regions (seen here: a point 0.25 from the line, stroke half
    width 1.3, left out), which the union of pieces does not."""
    pieces = [LineString([line[i], line[i + 1]]).buffer(d, cap_style=2) for i in range(len(line) - 1)]
    m = len(line) - 1 if closed else len(line)  # a closed line repeats its first point
    for k in range(m) if closed else range(1, m - 1):
        a, p, b = line[(k - 1) % m], line[k], line[(k + 1) % m]
        n0, n1 = [np.array([-(v[1]), v[0]]) / np.linalg.norm(v) for v in (p - a, b - p)]
        if np.cross(p - a, b - p) > 0:  # a left turn: the wedge is on the right
            n0, n1 = -n0, -n1
        a0, a1 = math.atan2(n0[1], n0[0]), math.atan2(n1[1], n1[0])
        turn = math.remainder(a1 - a0, 2 * math.pi)
        arc = [p + d * np.array([math.cos(a0 + turn * i / 64), math.sin(a0 + turn * i / 64)]) for i in range(65)]
        if abs(turn) > 1e-12:
            pieces.append(Polygon([p] + arc))  # the join: the disc's wedge on the outer side
    if not closed and cap != "butt":
        for p, q in ((line[0], line[1]), (line[-1], line[-2])):
            e = (p - q) / np.linalg.norm(p - q)
            n = np.array([-e[1], e[0]])
            pieces.append(Point(p).buffer(d, resolution=64) if cap == "round" else
                          Polygon([p + d * n, p + d * n + d * e, p - d * n + d * e, p - d * n]))
    return unary_union(pieces)


def random_curve(rng, closed):
    n = int(rng.integers(3, 10))
    return crspline.CatmullRom(rng.uniform(0, 10, (n, 2)), endconditions="closed" if closed else "natural")


@pytest.mark.parametrize("cap", ["butt", "round", "square"])
def test_strokes_are_valid_and_match_shapelys_buffer(cap, seed):
    """The reference: the stroke of the curve's tessellation at tol / 10
    (minkowski_reference, its joins' arcs in 64 steps: within d (1 - cos(pi /
    256)) of the true stroke at turns below pi / 2, which the tessellation's
    are by far). The areas agree within the
    tolerance times the perimeter (a region within distance tol of another
    has an area within tol x perimeter of it, to first order), Shapely's
    is_valid holds, and the stroke has fewer vertices than Shapely's default
    buffer of the same tessellation the stroke used."""
    rng = np.random.default_rng(seed)
    shapely_cap = {"butt": 2, "round": 1, "square": 3}[cap]
    checked = fewer = 0
    for trial in range(12):
        closed = trial % 3 == 0
        c = random_curve(rng, closed)
        w = float(rng.uniform(0.05, 3))
        tol = 1e-3 * (np.linalg.norm(np.ptp(c.points, axis=0)) + w)
        g = crspline.stroke(c, w, cap=cap, join="round", shapely=True)
        assert g.is_valid, f"trial {trial}"
        dense = c.tessellate(tol / 10)["points"]
        ref = minkowski_reference(dense, w / 2, cap, closed)
        ref_error = w / 2 * (1 - math.cos(math.pi / 256)) + tol / 10
        assert abs(g.area - ref.area) <= (tol + ref_error) * ref.length, f"trial {trial}"
        coarse = c.tessellate(tol / 2)["points"]
        cline = LinearRing(coarse[:-1]) if closed else LineString(coarse)
        default = cline.buffer(w / 2, cap_style=shapely_cap, join_style=1)
        ours = sum(len(p.exterior.coords) + sum(len(h.coords) for h in p.interiors) for p in getattr(g, "geoms", [g]))
        theirs = sum(len(p.exterior.coords) + sum(len(h.coords) for h in p.interiors)
                     for p in getattr(default, "geoms", [default]))
        fewer += ours < theirs
        checked += 1
    assert checked == 12
    assert fewer == 12


def test_stroke_arrays_and_joins():
    c = crspline.CatmullRom([[0, 0], [4, 0], [4, 3], [2, 4], [0, 3], [2, -1]])
    polys = crspline.stroke(c, 0.4)
    assert all(r.shape[1] == 2 for p in polys for r in p)
    assert sum(len(p) - 1 for p in polys) >= 1  # the loop encloses a hole
    for join in ("round", "miter", "bevel"):
        assert crspline.stroke(c, 0.4, join=join, shapely=True).is_valid


@pytest.mark.parametrize("call, words", [
    (lambda c3, c2: crspline.sweep(c3, radius=0), "radius: must be positive and finite, got 0"),
    (lambda c3, c2: crspline.sweep(c3, radius=-1.5), "radius: must be positive and finite, got -1.5"),
    (lambda c3, c2: crspline.sweep(c3, radius=float("nan")), "radius: must be positive and finite, got nan"),
    (lambda c3, c2: crspline.sweep(c3, profile=[[0, 1]]), "profile: needs at least 2 points, got 1"),
    (lambda c3, c2: crspline.sweep(c2), "curve: sweep needs a 3-D curve, got a 2-D one"),
    (lambda c3, c2: crspline.stroke(c3, 1.0), "curve: stroke needs a 2-D curve, got a 3-D one"),
    (lambda c3, c2: crspline.stroke(c2, 0.0), "width: must be positive and finite, got 0"),
    (lambda c3, c2: crspline.stroke(c2, 1.0, join="mitre"), "join: must be 'round', 'miter' or 'bevel'"),
    (lambda c3, c2: crspline.sweep(c3, roll=[0, 1]), "roll: 2 angles for 4 knots"),
    (lambda c3, c2: crspline.sweep(c3, up=[0, 0, 0]), "up: must not be the zero vector"),
    (lambda c3, c2: crspline.sweep(c3, scale=([0, 1], [1, 0])), "scale[1]: value 0 must be positive"),
])
def test_errors_name_the_field(call, words):
    c3 = crspline.CatmullRom([[0, 0, 0], [1, 0, 0], [2, 1, 0], [3, 1, 1]])
    c2 = crspline.CatmullRom([[0, 0], [1, 0], [2, 1]])
    with pytest.raises(ValueError) as e:
        call(c3, c2)
    assert words in str(e.value)
    assert isinstance(e.value, crspline.SpecError)
