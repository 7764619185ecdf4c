"""`crspline plot` and `crspline demo`: SVG (cairo's SVG surface) and PNG
files that parse, with the overlays asked for; the demo's table."""
import json
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
    if not os.path.exists(example):
        return
    num = r"\{\{?(-?[\d.]+), (-?[\d.]+)\}\}?"
    ex = re.findall(num, open(example).read().split("polygon = {")[1].split("};")[0])
    de = re.findall(num, open(demo).read().split("demo_polygon[][2] = {")[1].split("};")[0])
    assert ex and ex == de
