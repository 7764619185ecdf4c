"""The curve file holds exactly what docs/spec.md's table says (issue 26,
point 2): the table is read out of the page, a file is written for every
row (and for every form its type column names), and `crspline eval` reads
each; the curve must be the one the same description gives in the older
compact form, or through the command line's flags, and must differ from the
default curve where the row's value differs from the default (so a field
that was read and dropped would be caught). Contradictions between the
words are errors naming the fields."""
import json
import os
import random
import re

import pytest

from cli_support import run

SPEC = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "docs", "spec.md")


def table_fields():
    """The field names of the first column of docs/spec.md's table, in order."""
    with open(SPEC, encoding="utf-8") as f:
        lines = f.read().splitlines()
    start = lines.index("| field | type | default | rule |")
    rows = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        first = line.split("|")[1]
        rows.append(tuple(re.findall(r"`([^`]+)`", first)))
    return rows


def eval_curve(doc, args=()):
    """Positions and first derivatives at the knots and between them, and the
    knots: the curve as `crspline eval` reads it. Fails with the error line."""
    p = run(["eval", "--knots", *args, "-"], json.dumps(doc))
    assert p.returncode == 0, (p.stderr, doc)
    return json.loads(p.stdout)


def sample_t(doc, seed):
    """Parameter values inside the curve's domain: the knots and random points between."""
    grid = eval_curve({**doc, "t": []})["grid"]
    rng = random.Random(seed)
    return grid + [rng.uniform(grid[0], grid[-1]) for _ in range(7)]


def bezier_of(doc):
    p = run(["bezier", "-"], json.dumps(doc))
    assert p.returncode == 0, (p.stderr, doc)
    return json.loads(p.stdout)


def same_curve(a, b, seed, args_a=(), args_b=()):
    t = sample_t(a, seed)
    ra = eval_curve({**a, "t": t, "derivatives": [0, 1]}, args_a)
    rb = eval_curve({**b, "t": t, "derivatives": [0, 1]}, args_b)
    return ra == rb, ra


P4 = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.5], [4.0, 4.0]]
P7D = [[float(i), float(i * i % 5), 0.5 * i, 1.0, -2.0, 0.25 * i, 3.0] for i in range(4)]

#: Per row of the table: (file in the table's words, the same curve another
#: way: a dict for the compact form or a list of flags on the bare points).
#: Each row's value differs from the default.
ROWS = {
    ("dimension",): [({"points": P7D}, ["--alpha", "0.5"])],
    ("points",): [({"points": P4}, ["--alpha", "0.5"])],
    ("alpha",): [({"points": P4, "alpha": 0.25}, ["--alpha", "0.25"])],
    ("grid",): [({"points": P4, "grid": [0, 1, 3, 3.5]}, ["--grid", "0,1,3,3.5"])],
    ("closed",): [({"points": P4, "closed": True}, {"points": P4, "end": "closed"}),
                  ({"points": P4, "closed": True}, ["--closed"]),
                  ({"points": P4, "closed": False, "end": "reflect"}, {"points": P4, "end": {"start": "natural", "end": "reflect"}})],
    ("start",): [({"points": P4, "start": "reflect"}, {"points": P4, "end": {"start": "reflect", "end": "natural"}}),
                 ({"points": P4, "start": [1.0, -1.0]}, ["--start", "1,-1"])],
    ("end",): [({"points": P4, "start": "natural", "end": "reflect"}, ["--end", "reflect"]),
               ({"points": P4, "end": [2.0, 0.5]}, {"points": P4, "end": {"end": [2.0, 0.5]}}),
               ({"points": P4, "end": "reflect"}, {"points": P4, "start": "reflect", "end": "reflect"}),  # compact: both
               ({"points": P4, "end": "closed"}, {"points": P4, "closed": True}),
               ({"points": P4, "end": {"start": [0.5, 0.5], "end": "reflect"}}, ["--start", "0.5,0.5", "--end", "reflect"])],
    ("tension",): [({"points": P4, "tension": 0.25}, ["--tension", "0.25"])],
    ("kb.tension", "kb.continuity", "kb.bias"): [
        ({"points": P4, "kb": {"tension": [None, 0.1, 0.2, None], "continuity": [None, -0.3, 0.0, None],
                               "bias": [None, 0.0, 0.4, None]}},
         ["--kb-tension", "0,0.1,0.2,0", "--kb-continuity", "0,-0.3,0,0", "--kb-bias", "0,0,0.4,0"])],
    ("strict",): [({"points": P4, "strict": True}, ["--strict"])],
    ("tangents",): [({"points": P4, "tangents": [[1, 0], [1, 1], [0, 1], [1, 0]]},
                     {"points": P4, "tangents": {"in": [[1, 0], [1, 1], [0, 1], [1, 0]],
                                                 "out": [[1, 0], [1, 1], [0, 1], [1, 0]]}})],
}


def test_the_table_is_read_and_every_row_has_a_file():
    rows = table_fields()
    # The table as the page shows it: eleven rows, each with a case here
    # and no case for a row the page does not have.
    assert len(rows) == 11, rows
    assert set(rows) == set(ROWS), (set(rows) ^ set(ROWS))


@pytest.mark.parametrize("row", list(ROWS), ids=[", ".join(r) for r in ROWS])
def test_every_row_is_read_as_the_same_curve(row, seed):
    default_points = None
    checked = 0
    for words, other in ROWS[row]:
        if isinstance(other, dict):
            same, result = same_curve(words, other, seed)
        else:
            same, result = same_curve(words, {"points": words["points"]}, seed, args_b=other)
        assert same, (row, words, other)
        # The dimension is the points' own length: 7 coordinates back.
        assert {len(x) for x in result["values"]["0"]} == {len(words["points"][0])}
        # The row's value is not the default: the curve differs from the
        # bare points' (strict only refuses, so it cannot differ), so a
        # field read and then dropped would fail here.
        if row not in (("strict",), ("points",), ("dimension",)):
            assert bezier_of({"points": words["points"]}) != bezier_of(words), (row, words)
        default_points = words["points"]
        checked += 1
    assert checked == len(ROWS[row]) and default_points is not None


def test_a_tangent_end_is_the_derivative_there():
    # "start" and "end" tangents are dx/dt at the curve's ends, exactly.
    out = eval_curve({"points": P4, "start": [1.0, -1.0], "end": [2.0, 0.5], "t": []})
    t = [out["grid"][0], out["grid"][-1]]
    d = eval_curve({"points": P4, "start": [1.0, -1.0], "end": [2.0, 0.5], "t": t, "derivatives": [1]})
    # At t_min the derivative is the tangent as given (u = 0: c1 / h); at
    # t_max it is (c1 + 2 c2 + 3 c3) / h, sums of rounded terms the size of
    # the points (about 4): a few ulps, 1e-15. 1e-13 is far below any
    # misreading of the tangent (the natural end's dx/dt here is about 1).
    got = d["values"]["1"]
    assert got[0] == [1.0, -1.0]
    assert max(abs(a - b) for a, b in zip(got[1], [2.0, 0.5])) <= 1e-13, got


def test_strict_in_the_table_words_refuses_coincident_points():
    p = run(["bezier", "-"], json.dumps({"points": [[0, 0], [1, 1], [1, 1], [2, 0]], "strict": True, "closed": False}))
    assert p.returncode == 2 and "coincident" in p.stderr


CONTRADICTIONS = [
    ({"closed": True, "start": "reflect"}, 'start: a closed curve ("closed": true) has no start condition'),
    ({"closed": True, "end": [1, 0]}, 'end: a closed curve ("closed": true) has no end condition'),
    ({"closed": False, "end": "closed"}, 'end: "end": "closed" contradicts "closed": false'),
    ({"start": "natural", "end": "closed"}, 'start: a closed curve ("end": "closed") has no start condition'),
    ({"start": "reflect", "end": {"start": "natural", "end": "natural"}},
     'start: given twice: in "start" and in "end": {"start": ...}'),
    ({"start": "reflect", "end": {"end": "natural"}}, 'start: given twice: in "start" and in "end": {"start": ...}'),
    ({"closed": "yes"}, 'closed: expected true or false, got "yes"'),
    ({"start": "clamped"}, "<stdin>: start condition must be 'natural', 'reflect' or a tangent, got 'clamped'"),
    ({"start": 3}, 'start: expected "natural", "reflect" or a tangent [dx/dt, ...], got 3'),
    ({"end": 3}, 'end: expected "natural", "reflect", a tangent [dx/dt, ...], "closed" or {"start": ..., "end": ...}, got 3'),
]


@pytest.mark.parametrize("fields,line", CONTRADICTIONS, ids=[json.dumps(c[0]) for c in CONTRADICTIONS])
def test_contradictions_name_the_fields(fields, line):
    p = run(["bezier", "-"], json.dumps({"points": P4, **fields}))
    assert p.returncode == 2 and p.stdout == ""
    assert p.stderr == f"crspline: {line}\n"


def test_a_contradiction_in_a_file_names_the_file(tmp_path):
    path = tmp_path / "curve.json"
    path.write_text(json.dumps({"points": P4, "closed": False, "end": "closed"}))
    p = run(["bezier", str(path)])
    assert p.returncode == 2
    assert p.stderr == f'crspline: {path}: end: "end": "closed" contradicts "closed": false\n'


def test_flags_still_override_the_file():
    # --closed over "start"/"end" words, --end over "closed": false: the
    # command line's flags replace the file's ends, as before.
    same, _ = same_curve({"points": P4, "start": "reflect"}, {"points": P4, "closed": True}, 1, args_a=["--closed"])
    assert same
