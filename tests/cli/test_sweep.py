"""crspline sweep and crspline stroke (issue 41): the mesh files parsed back
(OBJ, PLY, glTF 2.0 with its embedded buffer decoded), the report, strokes
as GeoJSON and SVG, and bad input as one line on stderr with exit status 2."""
import base64
import json
import math
import os
import struct
import tempfile

import pytest

from cli_support import run

KNOT = [[(2 + math.cos(3 * a)) * math.cos(2 * a), (2 + math.cos(3 * a)) * math.sin(2 * a), math.sin(3 * a)]
        for a in [2 * math.pi * k / 12 for k in range(12)]]
LINE3 = [[0, 0, 0], [1, 0.2, 0], [2, 0, 0.5], [3, 0.3, 0.2]]
LOOP2 = [[0, 0], [4, 0], [4, 3], [2, 4], [0, 3], [2, -1]]


def sweep_to(ext, doc, *flags):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "tube." + ext)
        p = run(["sweep", "-", "-o", out, *flags], json.dumps(doc))
        assert p.returncode == 0, p.stderr
        with open(out, "rb") as f:
            return f.read(), json.loads(p.stdout)


def test_obj_counts_and_report():
    data, report = sweep_to("obj", {"points": KNOT, "closed": True}, "--radius", "0.2", "--tubular-segments", "64",
                            "--radial-segments", "8")
    lines = data.decode().splitlines()
    v = [l for l in lines if l.startswith("v ")]
    f = [l for l in lines if l.startswith("f ")]
    assert len(v) == 65 * 9 and len(f) == 2 * 64 * 8
    assert len([l for l in lines if l.startswith("vn ")]) == len(v) == len([l for l in lines if l.startswith("vt ")])
    # Faces index the vertices from 1.
    idx = [int(x.split("/")[0]) for l in f for x in l.split()[1:]]
    assert min(idx) == 1 and max(idx) == len(v)
    r = report["reports"][0]
    assert r["self_intersects"] is False and r["bound"] > 0
    # The closing ring is the first: no seam.
    assert v[:9] == v[-9:]


def test_gltf_parses_back():
    data, report = sweep_to("gltf", {"points": LINE3}, "--radius", "0.1", "--tolerance", "1e-3")
    g = json.loads(data)
    assert g["asset"]["version"] == "2.0"
    buf = g["buffers"][0]
    prefix = "data:application/octet-stream;base64,"
    assert buf["uri"].startswith(prefix)
    raw = base64.b64decode(buf["uri"][len(prefix):])
    assert len(raw) == buf["byteLength"]
    prim = g["meshes"][0]["primitives"][0]
    pos = g["accessors"][prim["attributes"]["POSITION"]]
    nor = g["accessors"][prim["attributes"]["NORMAL"]]
    ind = g["accessors"][prim["indices"]]
    assert pos["componentType"] == 5126 and pos["type"] == "VEC3" and ind["componentType"] == 5125
    view = g["bufferViews"][pos["bufferView"]]
    xyz = struct.unpack(f"<{3 * pos['count']}f", raw[view["byteOffset"]:view["byteOffset"] + view["byteLength"]])
    for k in range(3):
        assert min(xyz[k::3]) == pytest.approx(pos["min"][k]) and max(xyz[k::3]) == pytest.approx(pos["max"][k])
    nview = g["bufferViews"][nor["bufferView"]]
    n = struct.unpack(f"<{3 * nor['count']}f", raw[nview["byteOffset"]:nview["byteOffset"] + nview["byteLength"]])
    assert all(abs(math.sqrt(n[3 * i] ** 2 + n[3 * i + 1] ** 2 + n[3 * i + 2] ** 2) - 1) < 1e-5 for i in range(nor["count"]))
    iview = g["bufferViews"][ind["bufferView"]]
    idx = struct.unpack(f"<{ind['count']}I", raw[iview["byteOffset"]:iview["byteOffset"] + iview["byteLength"]])
    assert ind["count"] % 3 == 0 and max(idx) == pos["count"] - 1
    assert report["reports"][0]["tolerance_met"] is True


def test_ply_header_and_counts():
    data, _ = sweep_to("ply", {"points": LINE3}, "--profile", "-0.1,0,0.1,0", "--profile-open", "--roll", "0,0.5,1,1.5")
    text = data.decode()
    head, body = text.split("end_header\n")
    nv = int(head.split("element vertex ")[1].split()[0])
    nf = int(head.split("element face ")[1].split()[0])
    rows = body.splitlines()
    assert len(rows) == nv + nf and all(r.startswith("3 ") for r in rows[nv:])
    assert nv % 2 == 0  # a ribbon: two vertices a ring


def test_stroke_geojson_and_svg():
    p = run(["stroke", "-", "--width", "0.4", "--cap", "round"], json.dumps({"points": LOOP2}))
    assert p.returncode == 0, p.stderr
    fc = json.loads(p.stdout)
    geom = fc["features"][0]["geometry"]
    assert geom["type"] == "MultiPolygon"
    rings = [r for poly in geom["coordinates"] for r in poly]
    assert all(r[0] == r[-1] for r in rings)  # closed rings
    assert sum(len(poly) - 1 for poly in geom["coordinates"]) >= 1  # a hole inside the loop

    def area(r):
        return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(r, r[1:])) / 2

    assert all(area(poly[0]) > 0 for poly in geom["coordinates"])  # exteriors counterclockwise (RFC 7946)
    p = run(["stroke", "-", "--width", "0.4", "--format", "svg"], json.dumps({"points": LOOP2}))
    assert p.returncode == 0 and p.stdout.startswith("<svg") and 'fill-rule="nonzero"' in p.stdout


@pytest.mark.parametrize("args, doc, line", [
    (["sweep", "-", "--radius", "0"], {"points": LINE3}, "crspline sweep: --radius: must be positive and finite, got 0"),
    (["sweep", "-", "--radius", "nan"], {"points": LINE3}, "crspline sweep: --radius: must be positive and finite, got nan"),
    (["sweep", "-", "--profile", "1,0"], {"points": LINE3}, "crspline sweep: --profile: needs at least 2 points, got 1"),
    (["sweep", "-"], {"points": LOOP2}, "crspline sweep: curve: sweep needs a 3-D curve, got a 2-D one"),
    (["stroke", "-", "--width", "1"], {"points": LINE3}, "crspline stroke: curve: stroke needs a 2-D curve, got a 3-D one"),
    (["stroke", "-", "--width", "-1"], {"points": LOOP2}, "crspline stroke: --width: must be positive and finite, got -1"),
    (["stroke", "-"], {"points": LOOP2}, "crspline stroke: --width: required"),
    (["stroke", "-", "--width", "1", "--join", "mitre"], {"points": LOOP2},
     "crspline stroke: --join: must be round, miter or bevel, got 'mitre'"),
    (["sweep", "-", "--roll", "0,1"], {"points": LINE3}, "crspline sweep: --roll: 2 angles for 4 knots (one per curve point)"),
])
def test_errors_one_line_exit_2(args, doc, line):
    p = run(args, json.dumps(doc))
    assert p.returncode == 2
    assert p.stdout == ""
    assert p.stderr == line + "\n"
