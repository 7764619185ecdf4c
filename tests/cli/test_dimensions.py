"""Any dimension 1 to 16: a 7-D curve through `crspline eval` gives the numbers
of catmull_rom<7> (tests/reference/seven_d.json, checked against the C++ API
by Reference.SevenDimensions), and dimensions 5 to 16 match the exact 1-D path
coordinate by coordinate."""
import json
import random

from cli_support import load_reference, run, run_json


def test_seven_d_matches_catmull_rom_7_exactly():
    ref = load_reference("seven_d.json")
    out = run_json("eval", dict(ref["input"], knots=True))
    assert out["grid"] == ref["grid"]
    assert out["values"] == ref["values"]  # exact: shortest round-trip decimals of the same doubles


def test_every_dimension_matches_one_coordinate_at_a_time(seed):
    rng = random.Random(seed)
    for dim in range(1, 17):
        pts = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(5)]
        grid = run_json("bezier", {"points": pts})["grid"]
        t = [grid[0] + (grid[-1] - grid[0]) * k / 10 for k in range(10)] + [grid[-1]]
        # The knots fixed as an explicit grid for both (an alpha curve takes
        # its shape from the intervals as computed, not from the printed
        # knots' differences: docs/spec.md): every coordinate is then its own
        # 1-D curve.
        out = run_json("eval", {"points": pts, "grid": grid, "t": t, "derivatives": [0, 1]})
        assert len(out["values"]["0"][0]) == dim, f"seed {seed}, dimension {dim}"
        for k in range(dim):
            one = run_json("eval", {"points": [[p[k]] for p in pts], "grid": grid, "t": t, "derivatives": [0, 1]})
            for order in ("0", "1"):
                assert [v[k] for v in out["values"][order]] == [v[0] for v in one["values"][order]], \
                    f"seed {seed}, dimension {dim}, coordinate {k}, order {order}"


def test_seventeen_is_refused():
    p = run(["length", "-"], json.dumps({"points": [[0] * 17, [1] * 17]}))
    assert p.returncode == 2
    assert p.stderr == "crspline: <stdin>: dimension must be 1 to 16, got 17\n"
