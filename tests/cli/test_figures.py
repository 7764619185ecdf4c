"""`crspline plot` and `crspline demo`: SVG (cairo's SVG surface) and PNG
files that parse, with the overlays asked for; the demo's table."""
import json
import math
import os
import re
import struct
import xml.etree.ElementTree as ET

from cli_support import run

LOOP = [[0, 0], [1, 1], [1.1, 1], [2, 0], [3, 3]]


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n", data[:8]
    return struct.unpack(">II", data[16:24])


def ok(args, stdin=""):
    p = run(args, stdin)
    assert p.returncode == 0, p.stderr
    assert p.stderr == ""
    return p.stdout


def test_plot_svg_and_png(tmp_path):
    doc = json.dumps({"points": LOOP})
    svg, png = tmp_path / "f.svg", tmp_path / "f.png"
    assert ok(["plot", "--alpha", "0,0.5,1", "--all", "--title", "Three curves", "-o", str(svg), "--png", str(png)], doc) == ""
    root = ET.parse(svg).getroot()
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    assert root.get("width").startswith("900")
    assert png_size(png.read_bytes()) == (900, 640)
    # Three curve colours are drawn (uniform red, centripetal blue, chordal green).
    text = svg.read_text()
    for colour in ["stroke:rgb(84%,15%,16%)", "stroke:rgb(12%,47%,71%)", "stroke:rgb(17%,63%,17%)"]:
        assert colour in text, colour
    assert sorted(os.listdir(tmp_path)) == ["f.png", "f.svg"]


def test_plot_formats_and_size(tmp_path):
    doc = json.dumps({"points": LOOP})
    out = run(["plot", "--cusps"], doc)
    assert out.returncode == 0 and out.stdout.lstrip().startswith("<?xml")
    png = tmp_path / "x.png"
    assert ok(["plot", "--size", "400x300", "--comb", "--ticks", "--handles", "--volumes", "-o", str(png)], doc) == ""
    assert png_size(png.read_bytes()) == (400, 300)
    p = subprocess_bytes(["plot", "--format", "png"], doc)
    assert png_size(p) == (900, 640)


# The overlays, each drawn where it belongs. SOURCES.md: the uniform curve
# through (-5,1),(0,0),(1,0),(6,1) has an exact cusp at the middle of its one
# segment; with Hermite tangents m1 = (P2-P0)/2 = (3,-1/2), m2 = (P3-P1)/2 =
# (3,1/2) the cusp is at (1/2, -1/8), and the Bezier handles' inner points
# are P1 + m1/3 = (1,-1/6) and P2 - m2/3 = (0,-1/6).
CUSP = [[-5, 1], [0, 0], [1, 0], [6, 1]]
CURVE_STROKE = "stroke:rgb(84%,15%,16%)"  # the uniform curve's colour


def svg_paths(text):
    return re.findall(r'<path style="([^"]*)" d="([^"]*)"', text)


def subpaths(d):
    """The coordinate pairs of each M-started subpath of an SVG path."""
    out = []
    for part in re.split(r"(?=M )", d.strip()):
        nums = [float(x) for x in re.findall(r"-?[\d.]+(?:e-?\d+)?", part)]
        if nums:
            out.append(list(zip(nums[0::2], nums[1::2])))
    return out


def overlay_paths(option):
    plain = svg_paths(ok(["plot", "--uniform"], json.dumps({"points": CUSP})))
    full = svg_paths(ok(["plot", "--uniform", option], json.dumps({"points": CUSP})))
    added = list(full)
    for p in plain:
        if p in added:
            added.remove(p)
    return full, added  # the figure's own map: an overlay can widen the view


def pixel_map(plain):
    """x -> pixel from the dashed control polygon, whose vertices are CUSP."""
    # (the legend's dashed swatch is a single stroke)
    poly = [d for style, d in plain if "stroke-dasharray" in style and d.count("L") == len(CUSP) - 1]
    assert len(poly) == 1, poly
    v = subpaths(poly[0])[0]
    assert len(v) == len(CUSP)
    sx = (v[3][0] - v[0][0]) / (CUSP[3][0] - CUSP[0][0])
    sy = (v[3][1] - v[1][1]) / (CUSP[3][1] - CUSP[1][1])
    for (px, py), (x, y) in zip(v, CUSP):  # one affine map for all four vertices
        assert abs(px - (v[1][0] + sx * x)) < 0.01 and abs(py - (v[1][1] + sy * y)) < 0.01
    return lambda x, y: (v[1][0] + sx * x, v[1][1] + sy * y)


def curve_pixels(to_px):
    t = [3 * k / 2000 for k in range(2001)]
    pts = json.loads(ok(["eval"], json.dumps({"points": CUSP, "alpha": 0, "t": t})))["values"]["0"]
    return [to_px(*p) for p in pts]


def near_curve(q, curve, tol=1.0):
    return min(math.dist(q, c) for c in curve) <= tol


def test_plot_overlays_are_drawn_where_they_belong():
    # Cusps: one cross of 12 px at the cusp, in the colour of its curve.
    full, added = overlay_paths("--cusps")
    to_px = pixel_map(full)
    crosses = [d for style, d in added
               if CURVE_STROKE in style and "stroke-width:2.4" in style and "stroke-linejoin:round" in style]
    assert len(crosses) == 1, added
    ends = [q for sp in subpaths(crosses[0]) for q in sp]
    assert len(ends) == 4
    centre = (sum(q[0] for q in ends) / 4, sum(q[1] for q in ends) / 4)
    # cairo's SVG coordinates are fixed point in 1/256 px: 0.02 px is a few of them.
    assert math.dist(centre, to_px(0.5, -0.125)) <= 0.02, (centre, to_px(0.5, -0.125))
    # Comb: teeth from points on the curve, and the line through their tips.
    full, added = overlay_paths("--comb")
    curve = curve_pixels(pixel_map(full))
    comb = [d for style, d in added if "stroke-width:0.7" in style and CURVE_STROKE in style]
    assert len(comb) == 2, added
    teeth = subpaths(comb[0])
    assert len(teeth) >= 20
    for tooth in teeth:
        assert len(tooth) == 2 and near_curve(tooth[0], curve), tooth
    # Arc-length ticks: short strokes centred on the curve.
    full, added = overlay_paths("--ticks")
    curve = curve_pixels(pixel_map(full))
    ticks = [d for style, d in added if "stroke-width:1.2" in style and CURVE_STROKE in style]
    assert len(ticks) == 1, added
    strokes = subpaths(ticks[0])
    assert len(strokes) >= 5
    for a, b in strokes:
        assert near_curve(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), curve) and 9 <= math.dist(a, b) <= 11, (a, b)
    # Handles: squares at the Bezier handles' inner points, among them those
    # of the middle segment.
    full, added = overlay_paths("--handles")
    to_px = pixel_map(full)
    squares = [d for style, d in added if "fill-opacity:0.8" in style and "stroke:none" in style]
    assert len(squares) == 1, added
    centres = [(sum(q[0] for q in sp[:4]) / 4, sum(q[1] for q in sp[:4]) / 4) for sp in subpaths(squares[0])]
    for x, y in [(1, -1 / 6), (0, -1 / 6)]:
        assert min(math.dist(c, to_px(x, y)) for c in centres) <= 0.02, (x, y, centres)
    # Volumes: filled shapes of the curve's colour that together hold every
    # point of the curve (each point inside some shape's box).
    full, added = overlay_paths("--volumes")
    curve = curve_pixels(pixel_map(full))
    vols = [d for style, d in added if "fill-opacity:0.08" in style and CURVE_STROKE in style]
    assert len(vols) == 1, added
    boxes = [(min(q[0] for q in sp), min(q[1] for q in sp), max(q[0] for q in sp), max(q[1] for q in sp))
             for sp in subpaths(vols[0])]
    for q in curve[::20]:
        assert any(b[0] - 1 <= q[0] <= b[2] + 1 and b[1] - 1 <= q[1] <= b[3] + 1 for b in boxes), q


def subprocess_bytes(args, stdin):
    import subprocess
    from cli_support import binary
    p = subprocess.run([binary()] + args, input=stdin.encode(), capture_output=True, timeout=60)
    assert p.returncode == 0, p.stderr
    return p.stdout


def test_plot_from_csv_columns(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("id,x,y\n" + "".join(f"{i},{x},{y}\n" for i, (x, y) in enumerate(LOOP)))
    out = tmp_path / "p.svg"
    assert ok(["plot", "--columns", "x,y", "--uniform", "--chordal", str(path), "-o", str(out)]) == ""
    ET.parse(out)


def test_demo_writes_figures_and_table(tmp_path):
    out = ok(["demo", "-o", str(tmp_path / "figs")])
    assert sorted(os.listdir(tmp_path / "figs")) == ["demo.png", "demo.svg"]
    ET.parse(tmp_path / "figs" / "demo.svg")
    assert png_size((tmp_path / "figs" / "demo.png").read_bytes()) == (900, 640)
    lines = out.splitlines()
    header = next(i for i, l in enumerate(lines) if l.startswith("curve"))
    assert "arc length" in lines[header] and "cusps" in lines[header] and "self-intersections" in lines[header]
    assert "max distance to polygon" in lines[header] and "intersection-free" in lines[header]
    table = {}
    for l in lines[header + 1:header + 4]:
        f = l.split()
        table[f[0]] = {"alpha": float(f[1]), "length": float(f[2]), "cusps": int(f[3]), "meets": int(f[4]),
                       "distance": float(f[5]), "certified": " ".join(f[6:])}
    assert list(table) == ["uniform", "centripetal", "chordal"]
    # What the paper shows: the uniform curve loops, the centripetal one does not.
    assert table["uniform"]["meets"] >= 1
    assert table["centripetal"]["meets"] == 0 and table["centripetal"]["cusps"] == 0
    assert all(r["length"] > 0 for r in table.values())
    # The table's lengths are the CLI's own.
    polygon = [[0.0, 0.0], [1.0, 5.0], [7.0, 6.0], [7.6, 5.9], [14.0, 5.0], [15.0, 0.5], [10.5, 1.8], [11.0, 0.0]]
    for name, alpha in [("uniform", 0), ("centripetal", 0.5), ("chordal", 1)]:
        total = json.loads(ok(["length"], json.dumps({"points": polygon, "alpha": alpha})))["total"]
        assert abs(total - table[name]["length"]) <= 1e-4


def test_demo_polygon_is_the_example_polygon():
    """The demo's embedded polygon is examples/comparison.cpp's (the README figure)."""
    here = os.path.dirname(os.path.abspath(__file__))
    example = os.path.join(here, "..", "..", "examples", "comparison.cpp")
    demo = os.path.join(here, "..", "..", "cli", "demo.cpp")
    assert os.path.exists(example), example
    num = r"\{\{?(-?[\d.]+), (-?[\d.]+)\}\}?"
    ex = re.findall(num, open(example).read().split("polygon = {")[1].split("};")[0])
    de = re.findall(num, open(demo).read().split("demo_polygon[][2] = {")[1].split("};")[0])
    assert ex and ex == de


# A 3-D curve is drawn as its projection on two coordinates (--pair, from 1;
# default 1,2). Each coordinate of a Catmull-Rom curve is its own 1-D curve
# on the same knots, so the plane curve through the projected points on the
# 3-D curve's knots is the projection: checked on the Bézier points, then
# the plot draws exactly that plane curve.
CURVE_3D = {"points": [[0, 0, 1], [1, 2, -1], [3, 1, 0.5], [4, 3, 2], [5, 0, 0], [6, 1, -2]], "alpha": 0.5,
            "tension": 0.2, "end": {"start": [1, 0, 0.5], "end": "reflect"}}


def plane_of(doc, pair):
    knots = json.loads(ok(["eval", "--t", "0", "--knots", "-"], json.dumps(doc)))["grid"]
    plane = {"points": [[p[pair[0]], p[pair[1]]] for p in doc["points"]], "grid": knots, "tension": doc["tension"],
             "end": {"start": [doc["end"]["start"][pair[0]], doc["end"]["start"][pair[1]]], "end": "reflect"}}
    return plane


def test_a_3d_curve_is_plotted_as_its_projection(tmp_path):
    pair = (0, 2)
    plane = plane_of(CURVE_3D, pair)
    full = json.loads(ok(["bezier", "-"], json.dumps(CURVE_3D)))["segments"]
    flat = json.loads(ok(["bezier", "-"], json.dumps(plane)))["segments"]
    assert len(full) == len(flat) == 5
    # The knots' running sums are rounded once more in the plane curve's
    # intervals: 1e-14 of the coordinates' scale (a few ulps of 6).
    for a, b in zip(full, flat):
        for p, q in zip(a, b):
            assert math.dist([p[pair[0]], p[pair[1]]], q) <= 1e-14, (p, q)
    svg3, svg2 = tmp_path / "p3.svg", tmp_path / "p2.svg"
    ok(["plot", "--pair", "1,3", "--handles", "--ticks", "-o", str(svg3), "-"], json.dumps(CURVE_3D))
    ok(["plot", "--handles", "--ticks", "-o", str(svg2), "-"], json.dumps(plane))
    # The two figures differ in layout (the projection's subtitle takes room),
    # so the map from one to the other is a scale and a shift (equal aspect),
    # found from the extent of the curve's path (its 16 Bézier points, drawn
    # in centripetal blue, and in the first palette colour for the plane
    # curve on its explicit grid); then every point agrees within 0.05 px
    # (cairo writes 1/256 px; the plane curve through the projected points
    # with alpha 0.5 instead of the 3-D knots is up to 10 px away).
    def drawn(path, colour):
        pts = []
        for style, d in re.findall(r'<path style="([^"]*)" d="([^"]*)"', path.read_text()):
            if f"stroke:rgb({colour})" in style:
                nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", d)]
                if " C " in d:  # the curve (ticks and the legend's line keep their pixel size)
                    pts += list(zip(nums[0::2], nums[1::2]))
        return pts
    a3, a2 = drawn(svg3, "12%,47%,71%"), drawn(svg2, "58%,40%,74%")
    assert len(a3) == len(a2) == 16  # 5 cubic pieces
    lo3, lo2 = [min(p[k] for p in a3) for k in (0, 1)], [min(p[k] for p in a2) for k in (0, 1)]
    scale = (max(p[0] for p in a3) - lo3[0]) / (max(p[0] for p in a2) - lo2[0])
    worst = max(math.dist(p, [lo3[0] + scale * (q[0] - lo2[0]), lo3[1] + scale * (q[1] - lo2[1])]) for p, q in zip(a3, a2))
    assert worst <= 0.05, worst
    text = svg3.read_text()
    assert "3-D curve shown as its projection on x, z (coordinates 1 and 3)" in text


def test_plot_pair_errors():
    doc = json.dumps(CURVE_3D)
    for args, line in [(["--pair", "1,4"], "--pair: expected two different coordinates I,J from 1 to 3, got '1,4'"),
                       (["--pair", "2,2"], "--pair: expected two different coordinates I,J from 1 to 3, got '2,2'")]:
        p = run(["plot"] + args + ["-"], doc)
        assert p.returncode == 2 and p.stderr == f"crspline: {line}\n", p.stderr
    p = run(["plot", "--pair", "1,2", "-"], json.dumps({"points": LOOP}))
    assert p.returncode == 2 and p.stderr == "crspline: --pair: for points of 3 or more coordinates; these have 2\n"
    p = run(["plot", "-"], json.dumps({"points": [[0], [1], [3]]}))
    assert p.returncode == 2 and p.stderr == "crspline: plot: needs 2 or more coordinates per point, got 1 (choose two with --columns)\n"
