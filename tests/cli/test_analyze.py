"""`crspline analyze` against the 50-digit oracle (tests/reference/oracle.json)
and on curves whose loops, crossings and certificates are known.

Each oracle case is the middle segment (index 1) of the open curve through
its four points ("reflect" ends change only segments 0 and 2). Tolerances
are those of the library's own oracle test (tests/analysis/
test_segment_oracle.cpp): parameters to 1e-12, distances to 1e-13 of the
segment's size (max |P - P1|) plus one ulp of the coordinates (both sides
round to binary64), the Eq. 6 bound to 1e-14 relative (as the library test:
the curve keeps its knot intervals as computed).
"""
import json
import math

from cli_support import load_reference, run, run_json, ulp_of


def scale_of(points):
    return max(math.dist(p, points[1]) for p in points)


def test_every_oracle_case():
    cases = load_reference("oracle.json")["cases"]
    checked = {"cusp": 0, "loop": 0, "distances": 0, "bound": 0}
    for case in cases:
        out = run_json("analyze", {"points": case["points"], "alpha": case["alpha"],
                                   "tension": case["tension"], "end": "reflect"})
        seg = out["segments"][1]
        name = case["name"]
        assert seg["index"] == 1
        assert len(seg["cusp_u"]) == len(case["cusp_u"]), (name, seg["cusp_u"], case["cusp_u"])
        for got, want in zip(seg["cusp_u"], case["cusp_u"]):
            assert abs(got - want) <= 1e-12, (name, got, want)
        checked["cusp"] += bool(case["cusp_u"])
        assert len(seg["self_intersection_u"]) == len(case["self_intersection_uv"]), name
        for got, want in zip(seg["self_intersection_u"], case["self_intersection_uv"]):
            assert abs(got[0] - want[0]) <= 1e-12 and abs(got[1] - want[1]) <= 1e-12, (name, got, want)
        checked["loop"] += bool(case["self_intersection_uv"])
        assert seg["fold"] == case["fold_1d"], name
        tol = 1e-13 * max(scale_of(case["points"]), 1e-300) + ulp_of(case["points"])
        assert abs(seg["max_chord_line_distance"] - case["max_dist_to_chord_line"]) <= tol, name
        assert abs(seg["max_chord_distance"] - case["max_dist_to_chord_segment"]) <= tol, name
        checked["distances"] += 1
        if case["eq6_bound_two_sided"] is None:
            assert seg["distance_bound"] is None, name
        else:
            want = case["eq6_bound_two_sided"]
            # 1e-14, the library test's tolerance: the bounds use the knot
            # intervals as computed, not differences of the rounded knots.
            assert abs(seg["distance_bound"] - want) <= 1e-14 * want, (name, seg["distance_bound"], want)
            checked["bound"] += 1
        # Segment 1's Bezier points end at the segment's own points, exactly.
        assert seg["bezier"][0] == case["points"][1] and seg["bezier"][3] == case["points"][2]
    assert checked["distances"] == len(cases) == 38
    assert checked["cusp"] > 0 and checked["loop"] > 0 and checked["bound"] > 0, checked


# A short edge between two long ones: the uniform curve loops in the middle
# segment, the centripetal one does not (the paper's Figure 2).
LOOP = [[0, 0], [1, 1], [1.1, 1], [2, 0]]


def test_uniform_loop_and_centripetal_certificate():
    uniform = run_json("analyze", {"points": LOOP, "alpha": 0})
    # The keys of docs/report.md, in its order ("verdict" first: issue 27).
    assert list(uniform) == ["verdict", "dimension", "segments", "cusp_t", "has_cusp", "has_self_intersection",
                             "intersections", "overlaps", "folds", "complete", "certificate"]
    assert uniform["complete"] is True
    loops = [s for s in uniform["segments"] if s["self_intersection_u"]]
    assert [s["index"] for s in loops] == [1]
    u, v = loops[0]["self_intersection_u"][0]
    assert 0 < u < v < 1
    # The loop is reported among the curve's intersections as segments [1, 1].
    assert any(x["segments"] == [1, 1] for x in uniform["intersections"])
    assert uniform["has_self_intersection"] is True
    assert uniform["certificate"]["certified"] is False
    assert uniform["certificate"]["failed_rule"] == "not_centripetal"
    # The certificate ran without its own search; the report's found the loop.
    assert uniform["certificate"]["intersects"] is True and uniform["certificate"]["search"] is None

    centripetal = run_json("analyze", {"points": LOOP, "alpha": 0.5})
    assert all(not s["self_intersection_u"] and not s["cusp_u"] for s in centripetal["segments"])


def test_crossing_between_segments_and_certified_curve():
    # A figure-eight-like polygon: segments 0 and 2 cross.
    out = run_json("analyze", {"points": [[0, 0], [2, 2], [2, 0], [0, 2]]})
    cross = [x for x in out["intersections"] if x["segments"][0] != x["segments"][1]]
    assert len(cross) == 1 and cross[0]["segments"] == [0, 2]
    # A crossing, not a near miss: its distance is zero to rounding.
    assert 0 <= cross[0]["distance"] <= 1e-12
    # The reported point lies on both segments: evaluate through the CLI.
    grid = run_json("bezier", {"points": [[0, 0], [2, 2], [2, 0], [0, 2]]})["grid"]
    ts = [grid[i] + u * (grid[i + 1] - grid[i]) for i, u in zip(cross[0]["segments"], cross[0]["u"])]
    pos = run_json("eval", {"points": [[0, 0], [2, 2], [2, 0], [0, 2]], "t": ts})["values"]["0"]
    assert math.dist(pos[0], pos[1]) <= 1e-9 and math.dist(pos[0], cross[0]["point"]) <= 1e-9
    # A gentle centripetal arc is certified intersection-free.
    arc = [[math.cos(a / 10), math.sin(a / 10)] for a in range(0, 20)]
    out = run_json("analyze", {"points": arc})
    assert out["certificate"] == {"certified": True, "failed_rule": None, "detail": "", "vertex": None,
                                  "segment": None, "segments": None, "angle": None, "intersects": None,
                                  "search": None}
    assert out["intersections"] == []


def test_analyze_from_csv_with_options(tmp_path):
    path = tmp_path / "loop.csv"
    path.write_text("x,y\n" + "".join(f"{x},{y}\n" for x, y in LOOP))
    p = run(["analyze", "--uniform", str(path)])
    assert p.returncode == 0, p.stderr
    assert '"self_intersection_u":[[' in p.stdout


def test_given_start_tangent_that_crosses_is_not_certified():
    # Issue 13: the end segment shaped by a given tangent crosses its
    # neighbour twice; the angle rule never covered it, and the certificate
    # now names the pair it could not prove apart.
    doc = {"points": [[0, 0], [1, 0], [1, 1]], "alpha": 0.5, "end": {"start": [10, 10]}}
    out = run_json("analyze", doc)
    cross = sorted(x["u"] for x in out["intersections"] if x["segments"] == [0, 1])
    assert len(cross) == 2
    assert math.isclose(cross[0][0], 0.1274, abs_tol=1e-4) and math.isclose(cross[1][0], 0.8523, abs_tol=1e-4)
    free = out["certificate"]
    assert free["certified"] is False and free["failed_rule"] == "adjacent_pair"
    assert "segments 0 and 1" in free["detail"] and "end condition" in free["detail"]
    # The same with the command-line tangent.
    p = run(["analyze", "--start=10,10", "-"], json.dumps({"points": doc["points"]}))
    assert p.returncode == 0, p.stderr
    assert '"failed_rule":"adjacent_pair"' in p.stdout


# --- issue 27, point 5: the proved verdict at the top of the report ---------------------------


def test_the_verdict_is_first_and_decides_every_alpha():
    # The uniform curve loops in its middle segment (crosses); the chordal
    # one does not, and the certificate cannot say so (not centripetal):
    # the verdict can. The figure eight crosses at every alpha, searched or
    # not; a 3-D curve has no verdict (null). tests/analysis/
    # test_decision_report.cpp checks the verdict against decide() itself,
    # tests/frontends the CLI's report against Python's decide().
    want = {0: "crosses", 0.5: "simple", 1: "simple"}
    for alpha, verdict in want.items():
        out = run_json("analyze", {"points": LOOP, "alpha": alpha})
        assert list(out)[0] == "verdict"
        assert out["verdict"] == verdict, alpha
    assert run_json("analyze", {"points": LOOP, "alpha": 1})["certificate"]["certified"] is False
    for alpha in (0, 0.5, 1):
        for search in (True, False):
            out = run_json("analyze", {"points": FIGURE_EIGHT, "alpha": alpha, "end": "closed", "search": search})
            assert out["verdict"] == "crosses", (alpha, search)
    out = run_json("analyze", {"points": [[0, 0, 0], [1, 1, 0], [2, 0, 1], [0, 0.5, 0]]})
    assert list(out)[0] == "verdict" and out["verdict"] is None
    # --summary: the same key, first.
    p = run(["analyze", "--summary", "--uniform", "-"], json.dumps({"points": LOOP}))
    assert p.returncode == 0, p.stderr
    summary = json.loads(p.stdout)
    assert list(summary)[0] == "verdict" and summary["verdict"] == "crosses"


# --- issue 31, point 5: what was not searched for is unknown ---------------------------------

FIGURE_EIGHT = [[0, 0], [1, 1], [2, 0], [1, -1], [0, 0.2], [-1, 1], [-2, 0], [-1, -1]]


def test_has_self_intersection_is_null_when_the_search_did_not_run():
    # A closed figure eight crosses itself between segments (the search
    # finds it); without the search that is unknown, not false. A loop
    # inside a segment is known without the search: true either way.
    searched = run_json("analyze", {"points": FIGURE_EIGHT, "end": "closed"})
    assert searched["has_self_intersection"] is True
    assert any(x["segments"][0] != x["segments"][1] for x in searched["intersections"])
    assert all(not s["has_self_intersection"] for s in searched["segments"])
    quick = run_json("analyze", {"points": FIGURE_EIGHT, "end": "closed", "search": False})
    assert quick["has_self_intersection"] is None and quick["intersections"] is None
    p = run(["analyze", "--no-intersections", "-"], json.dumps({"points": FIGURE_EIGHT, "closed": True}))
    assert p.returncode == 0 and json.loads(p.stdout)["has_self_intersection"] is None
    # A uniform segment that loops (test_uniform_loop_and_centripetal_certificate's).
    looped = run_json("analyze", {"points": LOOP, "alpha": 0, "search": False})
    assert any(s["self_intersection_u"] for s in looped["segments"])
    assert looped["has_self_intersection"] is True
    # Searched and clean: false.
    clean = run_json("analyze", {"points": [[0, 0], [1, 1], [2, 0], [3, 1]]})
    assert clean["has_self_intersection"] is False and clean["intersections"] == []


# --- issue 26, point 4: analyze holds no more than the curve needs --------------------------

def random_walk(rng, n):
    """A 2-D random walk of unit steps: about as many crossings as points."""
    x = y = 0.0
    pts = []
    for _ in range(n):
        a = rng.uniform(0, 2 * math.pi)
        x, y = x + math.cos(a), y + math.sin(a)
        pts.append([round(x, 9), round(y, 9)])
    return pts


PEAK = (
    "import resource, subprocess, sys\n"
    "with open(sys.argv[1], 'wb') as out:\n"
    "    subprocess.run(sys.argv[2:], stdout=out, check=True)\n"
    "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
)


def peak_kib(args, out):
    """Peak resident memory (KiB) of one crspline run writing to the file
    `out`, measured in a fresh Python process whose only child is that run."""
    import subprocess
    import sys
    from cli_support import binary
    p = subprocess.run([sys.executable, "-c", PEAK, str(out), binary(), *args], capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stderr
    return int(p.stdout)


def test_analyze_memory_stays_near_length_whatever_the_output(tmp_path, seed):
    """Each segment's record is written as it is analysed and each crossing
    as it is found; --summary keeps counts only. So the peak memory of
    analyze (about 150 MB of text here) and of --summary stays within twice
    that of `length` on the same file, which holds the input and the curve
    (about 18 MB at 10^5 points; the fixed costs of analyze, the held-back
    first MiB of output and of the crossings, are a few MB). Holding the
    whole analysis until written, as before, took about 5 times length's
    here (10 times at 10^6 points). Memory, not time: a peak does not
    depend on the machine's load."""
    import random
    rng = random.Random(seed)
    n = 100_000
    path = tmp_path / "walk.json"
    path.write_text(json.dumps({"points": random_walk(rng, n)}))
    length = peak_kib(["length", str(path)], tmp_path / "length.json")
    full = peak_kib(["analyze", str(path)], tmp_path / "analyze.json")
    summary = peak_kib(["analyze", "--summary", str(path)], tmp_path / "summary.json")
    counts = json.loads((tmp_path / "summary.json").read_text())
    # The walk crosses itself often: the output is large, not just the curve.
    assert counts["segment_count"] == n - 1 and counts["intersections"] > n, counts
    assert (tmp_path / "analyze.json").stat().st_size > 100 * n
    assert full <= 2 * length, (full, length)
    assert summary <= 2 * length, (summary, length)
