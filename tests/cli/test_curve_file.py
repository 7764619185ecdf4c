"""One curve file (docs/spec.md): the web editor's export (web/app/io.mjs,
run by node) is read unchanged by every crspline subcommand, with the same
curve; a command-line input opens in the editor with its options honoured."""
import json
import os
import shutil
import subprocess

import pytest

from cli_support import run, run_json

IO_MJS = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "web", "app", "io.mjs")
NODE = shutil.which("node")
pytestmark = pytest.mark.skipif(NODE is None, reason="node is needed to run the editor's io.mjs")


def node(script):
    """Runs an ES module snippet with io.mjs imported as `io`; returns its stdout."""
    code = f"import * as io from {json.dumps(os.path.abspath(IO_MJS))};\n{script}"
    p = subprocess.run([NODE, "--input-type=module", "-e", code], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    return p.stdout


POINTS = [0, 0, 1, 2, 3, 1, 4, 3, 2, 4]
OPTION_SETS = [
    {"alpha": 0.25, "tension": 0.1, "closed": False, "start": "reflect", "end": "zero"},
    {"alpha": 0, "tension": 0, "closed": True, "start": "natural", "end": "natural"},
    {"alpha": 1, "tension": 0.5, "closed": False, "start": "natural", "end": "natural"},
]


@pytest.mark.parametrize("opts", OPTION_SETS)
def test_editor_export_runs_through_every_subcommand(opts, tmp_path):
    text = node(f"process.stdout.write(io.pointsToJson(Float64Array.from({json.dumps(POINTS)}), {json.dumps(opts)}));")
    path = tmp_path / "export.json"
    path.write_text(text)
    for args in (["bezier"], ["length"], ["analyze"], ["eval", "--t", "0"], ["sample", "--count", "5"],
                 ["plot", "-o", str(tmp_path / "p.svg")]):
        p = run(args[:1] + [str(path)] + args[1:])
        assert p.returncode == 0, f"crspline {' '.join(args)} on the editor's export: {p.stderr}"
    # The same curve: the knots follow alpha, the domain its closure.
    grid = run_json("bezier", json.loads(text))["grid"]
    assert len(grid) == len(POINTS) // 2 + (1 if opts["closed"] else 0)
    if opts["alpha"] == 0:
        assert grid == list(range(len(grid)))
    # And the editor reads its own export back with the same options.
    back = json.loads(node(f"process.stdout.write(JSON.stringify(io.parsePoints({json.dumps(text)}, 'a.json').options));"))
    assert back == opts


def test_command_line_input_opens_in_the_editor_with_its_options():
    doc = {"points": [[0, 0], [1, 1], [2, 0], [3, 1]], "alpha": 0, "tension": 0.5, "end": "reflect"}
    opts = json.loads(node(f"process.stdout.write(JSON.stringify(io.parsePoints({json.dumps(json.dumps(doc))}, 'c.json').options));"))
    assert opts == {"alpha": 0, "tension": 0.5, "closed": False, "start": "reflect", "end": "reflect"}


def test_grid_kb_strict_and_end_tangents_go_through_the_editor_unchanged(tmp_path):
    doc = {"points": [[0, 0], [1, 1], [2, 0], [3, 1]], "grid": [0, 1, 2.5, 3], "tension": 0.1,
           "end": {"start": [1, -0.5], "end": "reflect"},
           "kb": {"tension": [None, 0.2, -0.1, None], "bias": [0, 0.1, 0, 0]}, "strict": True}
    text = node(f"const r = io.parsePoints({json.dumps(json.dumps(doc))}, 'c.json');"
                "process.stdout.write(io.pointsToJson(r.points, r.options, r.dimension));")
    # Written back in the table's words (issue 26): the compact "end" object is "closed", "start", "end".
    words = {k: v for k, v in doc.items() if k != "end"} | {"closed": False, "start": [1, -0.5], "end": "reflect"}
    assert json.loads(text) == words
    assert run_json("length", json.loads(text))["total"] == run_json("length", doc)["total"]


@pytest.mark.parametrize("text, message", [
    ('{"points": [[0, 0], [1, 1]], "tangents": [[1, 0], [1, 0]]}', "JSON: field 'tangents' is not supported by the editor"),
    ('{"points": [[0, 0], [1, 1]], "kb": {"tensions": [0, 0]}}', "JSON: kb: unknown field 'tensions'"),
    ('{"points": [[0], [1]]}', "JSON: point 0 has 1 coordinate; the editor draws curves of 2 to 16 coordinates"),
    # (A tangent of the wrong length is read, and refused by the library
    # when the editor builds the curve: web/test/module.test.mjs.)
    ('{"points": [[0, 0], [1, 1]], "end": {"start": "zero"}}', 'JSON: end.start: expected "natural", "reflect" or a tangent like [0, 0], got "zero"'),
    ('x,y\nNaN,1\n2,3\n', 'CSV line 2: "NaN,1" is not two finite numbers'),
    ('NaN,1\n2,3\n', 'CSV line 1: "NaN,1" is not two finite numbers'),
])
def test_the_editor_refuses_what_it_cannot_hold(text, message):
    out = node(f"try {{ io.parsePoints({json.dumps(text)}); process.stdout.write('accepted'); }}"
               f" catch (e) {{ process.stdout.write(e.message); }}")
    assert out.startswith(message), out


def test_a_3d_curve_opens_whole_and_its_export_is_the_same_curve(tmp_path):
    """A 3-D command-line input opens in the editor with all its coordinates
    (shown there as a projection) and its export is the same 3-D curve."""
    doc = {"points": [[0, 0, 1], [1, 2, -1], [3, 1, 0.5], [4, 3, 2]], "alpha": 0.25, "end": {"start": "reflect", "end": [0, 0, 0]}}
    text = node(f"const r = io.parsePoints({json.dumps(json.dumps(doc))}, 'c.json');"
                "process.stdout.write(io.pointsToJson(r.points, r.options, r.dimension));")
    back = json.loads(text)
    assert back["points"] == doc["points"]
    assert run_json("length", back)["total"] == run_json("length", doc)["total"]
