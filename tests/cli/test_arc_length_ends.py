"""Issue 26 point 1: `crspline eval` with arc lengths at the ends of [0, total].

An arc length within the promised accuracy of either end is that end (a
length computed by another tool is only known to that accuracy): s =
total * (1 + 8e-15) is the last knot, s = -total * 8e-15 the first; further
out, s = total * (1 + 1e-9), it is still refused with the line naming the
index, the value and the range. The rule is the core's
(arc_length_table::in_range: max(accuracy, 4 eps) * total past either end),
so `eval` and the library agree. Standard library only."""
import json
import random

from cli_support import run, run_json


def fmt(x):
    """A number as the CLI's error lines print it (shortest round trip)."""
    r = repr(float(x))
    return r[:-2] if r.endswith(".0") else r


def total_of(points, accuracy=None):
    doc = {"points": points}
    if accuracy is not None:
        doc["accuracy"] = accuracy
    return run_json("length", doc)["total"]


def t_of_s(points, s, accuracy=None):
    doc = {"points": points, "s": s, "knots": True}
    if accuracy is not None:
        doc["accuracy"] = accuracy
    out = run_json("eval", doc)
    return out["t_of_s"], out["grid"]


def refused(points, s, index, accuracy=None):
    doc = {"points": points, "s": s}
    if accuracy is not None:
        doc["accuracy"] = accuracy
    p = run(["eval", "-"], json.dumps(doc))
    assert p.returncode == 2, (p.returncode, p.stdout[:200], p.stderr)
    assert p.stdout == "", p.stdout[:200]
    return p.stderr


# The README's curve: its length is not a round number.
POINTS = [[0, 0], [1, 2], [3, 3], [4, 0]]


def test_issue_case_at_the_end():
    total = total_of(POINTS)
    assert 7.8 < total < 7.9, total
    # 8e-15 relative past the end, as another tool's total for the same curve:
    # inside the 1e-12 promise, so the last knot.
    s = total * (1 + 8e-15)
    assert s > total
    t, grid = t_of_s(POINTS, [0, total / 2, s])
    assert t[0] == grid[0] and t[2] == grid[-1], (t, grid)
    assert grid[0] < t[1] < grid[-1]
    # And before the start by as much: the first knot.
    t, grid = t_of_s(POINTS, [-total * 8e-15, total])
    assert t == [grid[0], grid[-1]], (t, grid)
    # 1e-9 relative is outside the promise: refused, naming index and value.
    s = total * (1 + 1e-9)
    line = refused(POINTS, [0, total / 2, s], 2)
    assert line == f"crspline: s[2]: s = {fmt(s)} is outside the arc-length range [0, {fmt(total)}]\n", line
    s = -total * 1e-9
    line = refused(POINTS, [s], 0)
    assert line == f"crspline: s[0]: s = {fmt(s)} is outside the arc-length range [0, {fmt(total)}]\n", line


def test_slack_follows_the_accuracy(seed):
    """Seeded random curves at two accuracies: half the accuracy past either
    end maps to that end, twice it is refused (the slack is accuracy * total
    for accuracies above 4 eps)."""
    rng = random.Random(seed)
    checked = 0
    for trial in range(6):
        n = rng.randint(3, 7)
        points = [[rng.uniform(-10, 10), rng.uniform(-10, 10)] for _ in range(n)]
        for accuracy in (1e-6, 1e-12):
            total = total_of(points, accuracy)
            inside = [-0.5 * accuracy * total, total + 0.5 * accuracy * total]
            t, grid = t_of_s(points, inside, accuracy)
            assert t == [grid[0], grid[-1]], (trial, accuracy, t, grid)
            for s in (total + 2 * accuracy * total, -2 * accuracy * total):
                line = refused(points, [total / 3, s], 1, accuracy)
                assert line == (f"crspline: s[1]: s = {fmt(s)} is outside the arc-length range "
                                f"[0, {fmt(total)}]\n"), (trial, accuracy, line)
                checked += 1
    assert checked == 6 * 2 * 2
