"""crspline fit (issue 40): the tolerance checked on the written curve (read
back by crspline sample, sampled densely, measured here in plain Python),
every input format and many curves per file, the three outputs, and bad
input as one line on stderr with exit status 2."""
import json
import math
import random

import pytest

from cli_support import run

SEED = 20261207


def noisy_line(seed, n=120, noise=0.1):
    rng = random.Random(seed)
    x = y = angle = 0.0
    pts = []
    for _ in range(n):
        pts.append([x + rng.uniform(-noise, noise), y + rng.uniform(-noise, noise)])
        angle += rng.gauss(0, 0.15)
        x += math.cos(angle)
        y += math.sin(angle)
    return pts


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    wx, wy = p[0] - a[0], p[1] - a[1]
    l2 = dx * dx + dy * dy
    f = min(1.0, max(0.0, (wx * dx + wy * dy) / l2)) if l2 > 0 else 0.0
    return math.hypot(wx - f * dx, wy - f * dy)


def poly_dist(p, poly):
    return min(seg_dist(p, poly[i], poly[i + 1]) for i in range(len(poly) - 1))


def ok(args, stdin=""):
    p = run(args, stdin)
    assert p.returncode == 0, p.stderr
    return p.stdout


def both_ways(samples, pts, closed):
    """Largest sampled distance curve -> input polyline, and input -> curve bounded
    below interval by interval (the nearer of two consecutive samples less 0.6 of
    their gap; the largest gap anywhere made the bound idle on closed lines)."""
    poly = pts + [pts[0]] if closed else pts
    c2i = max(poly_dist(s, poly) for s in samples)
    i2c = max(min(min(math.dist(p, samples[i]), math.dist(p, samples[i + 1])) - 0.6 * math.dist(samples[i], samples[i + 1])
                  for i in range(len(samples) - 1))
              for p in pts)
    return c2i, i2c


@pytest.mark.parametrize("mode", ["subset", "free"])
@pytest.mark.parametrize("closed", [False, True])
def test_curve_file_keeps_the_tolerance(mode, closed, tmp_path):
    pts = noisy_line(SEED + closed)
    tol = 0.2
    doc = {"points": pts, "closed": closed}
    curve = json.loads(ok(["fit", "--tolerance", str(tol), "--mode", mode, "-"], json.dumps(doc)))
    assert set(curve) <= {"points", "alpha", "closed", "start", "end", "tension", "kb"}
    assert len(curve["points"]) < len(pts) // 2
    if mode == "subset":
        assert all(p in pts for p in curve["points"])
    # The written curve file is a curve every command reads: sample it densely.
    f = tmp_path / "curve.json"
    f.write_text(json.dumps(curve))
    samples = json.loads(ok(["sample", str(f), "--count", str(60 * len(curve["points"]))]))["points"]
    c2i, i2c = both_ways(samples, pts, closed)
    assert c2i <= tol and i2c <= tol, (c2i, i2c)


def test_many_curves_every_format_and_outputs(tmp_path):
    lines = [noisy_line(SEED + k, n=60) for k in range(3)]
    tol = 0.25
    # A JSON list with ids and properties: the report lands in each item's properties.
    items = [{"id": f"c{k}", "points": p, "properties": {"k": k}} for k, p in enumerate(lines)]
    out = json.loads(ok(["fit", "--tolerance", str(tol), "-"], json.dumps(items)))
    assert [o["id"] for o in out] == ["c0", "c1", "c2"]
    for k, o in enumerate(out):
        props = o["properties"]
        assert props["k"] == k
        assert props["fit_control_points"] == len(o["points"])
        assert props["fit_input_points"] == 60
        assert 0 < props["fit_deviation"] <= tol
        assert [lines[k][i] for i in props["fit_indices"]] == o["points"]
    # The output list is itself an input every command reads.
    lst = tmp_path / "list.json"
    lst.write_text(json.dumps(out))
    assert len(json.loads(ok(["length", str(lst)]))) == 3
    # CSV blocks in, CSV out: the control points with the curve's id first.
    csv = "x,y\n" + "\n\n".join("\n".join(f"{x!r},{y!r}" for x, y in p) for p in lines) + "\n"
    table = ok(["fit", "--tolerance", str(tol), "--format", "csv", "--input-format", "csv", "-"], csv).splitlines()
    assert table[0] == "curve,x,y"
    assert len(table) - 1 == sum(len(o["points"]) for o in out)
    # GeoJSON in (a LineString and a Polygon ring), GeoJSON out.
    ring = noisy_line(SEED + 9, n=80, noise=0.05)
    gj = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "id": 7, "properties": {"name": "line"},
         "geometry": {"type": "LineString", "coordinates": lines[0]}},
        {"type": "Feature", "properties": {"name": "ring"},
         "geometry": {"type": "Polygon", "coordinates": [ring + [ring[0]]]}}]}
    fc = json.loads(ok(["fit", "--tolerance", str(tol), "--format", "geojson", "-"], json.dumps(gj)))
    assert fc["type"] == "FeatureCollection" and len(fc["features"]) == 2
    line_f, ring_f = fc["features"]
    assert line_f["id"] == 7 and line_f["properties"]["name"] == "line"
    assert line_f["geometry"]["type"] == "LineString"
    assert ring_f["geometry"]["type"] == "Polygon"
    r = ring_f["geometry"]["coordinates"][0]
    assert r[0] == r[-1]
    for f, src, closed in ((line_f, lines[0], False), (ring_f, ring, True)):
        props = f["properties"]
        assert props["tolerance"] == tol and props["mode"] == "subset"
        assert 0 < props["deviation"] <= tol and props["control_points"] >= 2
        coords = f["geometry"]["coordinates"] if not closed else f["geometry"]["coordinates"][0]
        # The polyline is within tolerance / 10 of the curve, so within 1.1 tolerance of the input.
        c2i = max(poly_dist(p, src + [src[0]] if closed else src) for p in coords)
        assert c2i <= 1.1 * tol
    # SVG path data: each subpath a curve.
    svg = "M 0 0 L 1 0.1 L 2 -0.1 L 3 0 L 4 0.05 M 0 5 L 1 5 L 2 5.2 L 3 5"
    svg_out = json.loads(ok(["fit", "--tolerance", "0.3", "--input-format", "svg", "-"], svg))
    assert len(svg_out) == 2


@pytest.mark.parametrize("args,stdin,message", [
    (["fit", "-"], '{"points": [[0, 0], [1, 1]]}', "crspline: --tolerance is required (usage: crspline fit"),
    (["fit", "--tolerance", "0", "-"], '{"points": [[0, 0], [1, 1]]}',
     "crspline: <stdin>: fit: tolerance must be a positive finite number, got 0"),
    (["fit", "--tolerance", "abc", "-"], "", "crspline: --tolerance: expected a number, got 'abc'"),
    (["fit", "--tolerance", "0.1", "--mode", "best", "-"], "", "crspline: --mode: expected subset or free, got 'best'"),
    (["fit", "--tolerance", "1e-9", "-"], '{"points": [[1000000, 0], [1000001, 1], [1000002, 0]]}',
     "crspline: <stdin>: fit: tolerance 1e-09 is at or below the rounding floor 5.6843532547645736e-08 of the coordinates "
     "(256 ulps of the largest, 1000002)"),
    (["fit", "--tolerance", "0.1", "-"], '{"points": [[0, 0]]}',
     "crspline: <stdin>: fit: needs at least 2 points, got 1"),
    (["fit", "--tolerance", "0.1", "--format", "svg", "-"], '{"points": [[0, 0], [1, 1]]}',
     "crspline: --format: expected one of json, csv, geojson for 'crspline fit', got 'svg'"),
])
def test_errors_one_line_exit_2(args, stdin, message):
    p = run(args, stdin)
    assert p.returncode == 2
    assert p.stdout == ""
    lines = p.stderr.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith(message), lines[0]
