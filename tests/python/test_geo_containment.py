"""Issue 39: smoothing keeps every relation between parts and features, not
only "no new crossings": an island near a coast stays outside it, a hole
near its shell stays inside, a line stays on its side of a ring; an output
is never less valid than its input; invalid nesting in the input is
reported (verdict "nested").

The layers: the issue's reproduction (a municipality and a small island,
EPSG:30166), seeded coasts with islands scattered outside at 0.1 to 10
tolerances from them, holes inside near the shell, lines on both sides,
as one MultiPolygon and as separate features; Natural Earth and nybb.
Relations are Shapely's (disjoint, touches, contains, within, or other),
compared pair by pair before and after for every pair whose input or
output boxes meet (other pairs are disjoint both times); counts asserted.
"""
import math

import numpy as np
import pytest

gpd = pytest.importorskip("geopandas")
shapely = pytest.importorskip("shapely")

import shapely.affinity  # noqa: E402

from shapely.geometry import LineString, MultiPolygon, Polygon  # noqa: E402

import crspline.geo as cg  # noqa: E402

pytestmark = [pytest.mark.filterwarnings("ignore:Geometry is in a geographic CRS"),
              pytest.mark.filterwarnings("ignore:STRtree will be changed"),
              pytest.mark.filterwarnings("ignore::DeprecationWarning")]

BIG = Polygon([(331182.2446295512, -90932.11309471469), (329332.18576206244, -90590.18590042497),
               (329276.59843904525, -90032.82945142474), (330473.11491476354, -90078.18625929175),
               (331187.31649087527, -90913.47959470267)])
ISLAND = Polygon([(329829.8956738626, -90715.57166108617), (329829.8996499169, -90715.68092214887),
                  (329829.80846243614, -90715.68424049778)])
REPRO_TOLERANCE = 14.51937002765435


def relation(a, b):
    if a.disjoint(b):
        return "disjoint"
    if a.touches(b):
        return "touches"
    if a.contains(b):
        return "contains"
    if a.within(b):
        return "within"
    return "other"


def boxes_meet(a, b):
    ax0, ay0, ax1, ay1 = a.bounds
    bx0, by0, bx1, by1 = b.bounds
    return not (ax0 > bx1 or bx0 > ax1 or ay0 > by1 or by0 > ay1)


def changed_relations(before, after):
    """Pairs (i, j) whose relation changed, and the number of pairs compared
    (those whose input or output boxes meet)."""
    changed, compared = [], 0
    n = len(before)
    for i in range(n):
        for j in range(i + 1, n):
            if not (boxes_meet(before[i], before[j]) or boxes_meet(after[i], after[j])):
                continue
            compared += 1
            r0, r1 = relation(before[i], before[j]), relation(after[i], after[j])
            if r0 != r1:
                changed.append((i, j, r0, r1))
    return changed, compared


def parts(g):
    return list(g.geoms) if g.geom_type.startswith("Multi") else [g]


def test_reproduction_one_multipolygon():
    layer = gpd.GeoDataFrame(geometry=[MultiPolygon([BIG, ISLAND])], crs="EPSG:30166")
    assert layer.is_valid.all()
    one = cg.smooth(layer, tolerance=REPRO_TOLERANCE)
    assert one.is_valid.all(), one.geometry[0].wkt[:200]
    big, island = parts(one.geometry[0])
    assert relation(big, island) == "disjoint"
    assert one.verdict[0] == "simple" and one.status[0] == "ok"
    # The new proof acted: the island's vertices lay in the big ring's bulge
    # before tension was raised there.
    assert one.attrs["crspline_stats"]["swept_vertices"] > 0


def test_reproduction_two_features():
    layer = gpd.GeoDataFrame(geometry=[BIG, ISLAND], crs="EPSG:30166")
    two = cg.smooth(layer, tolerance=REPRO_TOLERANCE)
    assert not two.geometry[0].contains(two.geometry[1])
    assert relation(two.geometry[0], two.geometry[1]) == "disjoint"
    assert two.is_valid.all()
    assert list(two.verdict) == ["simple", "simple"]


def coast(rng, n, radius, jitter):
    """A star-shaped ring of n vertices: convex and concave stretches, so
    the curve bulges out in some places and in in others."""
    ang = np.sort(rng.uniform(0, 2 * math.pi, n))
    r = radius * (1 + jitter * rng.uniform(-1, 1, n))
    return np.column_stack((r * np.cos(ang), r * np.sin(ang)))


def small_triangle(rng, centre, size):
    a = rng.uniform(0, 2 * math.pi)
    pts = [centre + size * np.array([math.cos(a + k * 2.1), math.sin(a + k * 2.1)]) for k in range(3)]
    return Polygon(pts)


def near_chords(rng, ring, tolerance, count, side):
    """Points at 0.1 to 10 tolerances (log-uniform) from random points of
    the ring's chords, on the outer (side +1) or inner (side -1) side."""
    n = len(ring)
    out = []
    for _ in range(count):
        k = rng.integers(n)
        p, q = ring[k], ring[(k + 1) % n]
        f = rng.uniform(0.15, 0.85)
        d = tolerance * 10 ** rng.uniform(-1, 1)
        t = q - p
        normal = np.array([t[1], -t[0]]) / np.linalg.norm(t)  # outward for a counter-clockwise ring
        out.append((p + f * t + side * d * normal, d))
    return out


def island_layer(seed, tolerance=5.0):
    """A coast with holes near its shell, islands outside near it and lines
    on both sides; every part disjoint from the others (checked)."""
    rng = np.random.default_rng(seed)
    ring = coast(rng, int(rng.integers(10, 20)), 1000.0, 0.12)
    shell = Polygon(ring)
    assert shell.is_valid
    islands, holes, lines = [], [], []
    taken = []

    def free(g):
        return all(g.disjoint(o) for o in taken)

    for centre, d in near_chords(rng, ring, tolerance, 60, +1):
        g = small_triangle(rng, centre, min(0.4 * d, tolerance))
        if g.disjoint(shell) and free(g):
            islands.append(g)
            taken.append(g)
    for centre, d in near_chords(rng, ring, tolerance, 40, -1):
        g = small_triangle(rng, centre, min(0.4 * d, tolerance))
        if shell.contains(g) and g.exterior.disjoint(shell.exterior) and free(g):
            holes.append(g)
            taken.append(g)
    for side in (+1, -1):
        for centre, d in near_chords(rng, ring, tolerance, 20, side):
            a = rng.uniform(0, 2 * math.pi)
            h = min(0.4 * d, tolerance)
            g = LineString([centre - h * np.array([math.cos(a), math.sin(a)]), centre,
                            centre + h * np.array([math.cos(a + 0.5), math.sin(a + 0.5)])])
            if g.disjoint(shell.exterior) and free(g):
                lines.append(g)
                taken.append(g)
    land = Polygon(ring, [h.exterior.coords for h in holes])
    assert land.is_valid
    return land, islands, holes, lines


def test_islands_holes_lines_keep_their_sides(seed):
    """Separate features: the land (with its holes), each island, each line."""
    total_compared = total_swept = 0
    for k in range(4):
        land, islands, holes, lines = island_layer(seed + k)
        assert len(islands) >= 20 and len(holes) >= 10 and len(lines) >= 10, (len(islands), len(holes), len(lines))
        before = [land] + islands + lines
        for kw in ({}, {"max_deviation": 20.0}):
            out = cg.smooth(gpd.GeoDataFrame(geometry=before, crs="EPSG:3857"), tolerance=5.0, **kw)
            after = list(out.geometry)
            assert all(out.is_valid[i] for i in range(len(before)) if before[i].is_valid), kw
            changed, compared = changed_relations(before, after)
            assert not changed, (kw, changed[:5])
            # Holes: still inside the shell, disjoint from its boundary.
            shell_out = Polygon(after[0].exterior)
            assert all(shell_out.contains(Polygon(h)) for h in after[0].interiors)
            total_compared += compared
            total_swept += out.attrs["crspline_stats"]["swept_vertices"]
    assert total_compared >= 4 * 2 * 40, total_compared
    # Islands 0.1 to 10 tolerances from the chords lie where the curves
    # bulge: the proof must have raised tension for some of them.
    assert total_swept > 0


def test_islands_in_one_multipolygon(seed):
    for k in range(4):
        land, islands, holes, _ = island_layer(seed + 100 + k)
        mp = MultiPolygon([land] + islands)
        assert mp.is_valid
        out = cg.smooth(gpd.GeoDataFrame(geometry=[mp], crs="EPSG:3857"), tolerance=5.0)
        assert out.is_valid[0], k
        assert out.verdict[0] == "simple", out.status[0]
        changed, compared = changed_relations(parts(mp), parts(out.geometry[0]))
        assert not changed, changed[:5]
        assert compared >= 20, compared  # most islands lie in the land's box


def test_invalid_nesting_is_reported():
    """An input that already nests invalidly is reported (verdict nested,
    the status naming the parts) and kept so: never less valid, never
    silently passed."""
    outer = Polygon([(0, 0), (100, 0), (100, 100), (0, 100)])
    inner = Polygon([(40, 40), (60, 40), (50, 60)])
    nested_shells = MultiPolygon([outer, inner])  # invalid: "Nested shells"
    assert not nested_shells.is_valid
    hole_outside = Polygon(outer.exterior.coords, [[(140, 40), (160, 40), (150, 60)]])
    assert not hole_outside.is_valid
    hole_in_hole = Polygon(outer.exterior.coords, [[(10, 10), (90, 10), (90, 90), (10, 90)],
                                                   [(40, 40), (60, 40), (50, 60)]])
    assert not hole_in_hole.is_valid
    # Valid: an island in a lake (away from the others: no shared rings).
    shell_in_hole = shapely.affinity.translate(
        MultiPolygon([Polygon(outer.exterior.coords, [[(10, 10), (90, 10), (90, 90), (10, 90)]]), inner]), 300, 0)
    assert shell_in_hole.is_valid
    layer = gpd.GeoDataFrame(geometry=[nested_shells, hole_outside, hole_in_hole, shell_in_hole])
    out = cg.smooth(layer, tolerance=0.5)
    assert list(out.verdict) == ["nested", "nested", "nested", "simple"], list(out.status)
    assert out.status[0] == "ok: part 1 (an outer ring) lies inside the polygon of part 0 (an outer ring) (nested shells)"
    assert out.status[1] == "ok: part 1 (an inner ring) lies outside its outer ring, part 0"
    assert out.status[2] == "ok: part 2 (an inner ring) lies inside another inner ring of its polygon, part 1"
    assert out.is_valid[3]
    # Kept as it was: the same relations between the parts.
    for g_in, g_out in zip(layer.geometry[:1], out.geometry[:1]):
        assert relation(*parts(g_in)) == relation(*parts(g_out)) == "contains"


@pytest.fixture(scope="module")
def world():
    return gpd.read_file(gpd.datasets.get_path("naturalearth_lowres"))


@pytest.mark.parametrize("kw", [{}, {"max_deviation": 3000.0}], ids=["plain", "max_deviation"])
def test_world_relations_and_validity(world, kw):
    out = cg.smooth(world, tolerance=50.0, **kw)
    before, after = list(world.geometry), list(out.geometry)
    invalid = [i for i in range(len(before)) if before[i].is_valid and not after[i].is_valid]
    assert not invalid, [world.name[i] for i in invalid]
    changed, compared = changed_relations(before, after)
    assert not changed, changed[:5]
    assert compared >= 300, compared  # 177 countries: the neighbours' pairs at least
    # Parts of each multi-polygon too.
    pairs = 0
    for g0, g1 in zip(before, after):
        if g0.geom_type == "MultiPolygon":
            c, n = changed_relations(parts(g0), parts(g1))
            assert not c, c[:5]
            pairs += n
    assert pairs > 0


def test_nybb_relations_and_validity():
    nybb = gpd.read_file(gpd.datasets.get_path("nybb"))
    out = cg.smooth(nybb, tolerance=10.0)
    before, after = list(nybb.geometry), list(out.geometry)
    assert all(a.is_valid for b, a in zip(before, after) if b.is_valid)
    changed, compared = changed_relations(before, after)
    assert not changed and compared >= 4, (changed, compared)
    for g0, g1 in zip(before, after):
        c, _ = changed_relations(parts(g0), parts(g1))
        assert not c, c[:5]


@pytest.mark.parametrize("kw", [{}, {"max_deviation": 0.05}], ids=["plain", "max_deviation"])
def test_contour_rings_keep_their_nesting(seed, kw):
    """The contour corpus of test_geo.py, its closed contours as polygons:
    rings nested close to each other where the field is steep. Every pair
    keeps its relation (contains / within / disjoint), every output valid."""
    from test_geo import random_field_contours

    compared = 0
    for k in range(12):  # fields until 20 pairs of nearby rings are compared
        if compared >= 20:
            break
        lines = random_field_contours(seed + k, levels=16)
        rings = [Polygon(g.coords) for g in lines if g.is_ring and len(g.coords) >= 4]
        rings = [r for r in rings if r.is_valid]
        if len(rings) < 2:
            continue
        out = cg.smooth(gpd.GeoDataFrame(geometry=rings, crs="EPSG:3857"), tolerance=1e-3, **kw)
        assert out.is_valid.all(), (seed + k, list(out.status))
        changed, n = changed_relations(rings, list(out.geometry))
        assert not changed, (seed + k, changed[:5])
        compared += n
    assert compared >= 20, compared
