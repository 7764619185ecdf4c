"""The curve file (docs/spec.md) from Python: crspline.save / load / from_spec
and CatmullRom.spec(), round trips through Python and through the command
line (which reads what Python saved), unknown fields named, and the core's
words for a bad specification (SpecError with field, index, value)."""
import json
import os
import random
import subprocess

import numpy as np
import pytest

import crspline


def _random_spec(rng, dim):
    """A random curve description covering every field of the curve file."""
    n = rng.randint(2, 7)
    closed = rng.random() < 0.3
    pts = [[rng.uniform(-5, 5) for _ in range(dim)] for _ in range(n)]
    spec = {"points": pts}
    if rng.random() < 0.3:
        steps = [rng.uniform(0.2, 2) for _ in range(n + (1 if closed else 0) - 1)]
        spec["grid"] = [0.0] + list(np.cumsum(steps))
    else:
        spec["alpha"] = rng.choice([0.0, 0.5, 1.0, rng.random()])
    # The ends in the table's words (docs/spec.md) or in the older compact
    # form of "end", which stays readable.
    table_words = rng.random() < 0.5
    if closed:
        spec.update({"closed": True} if table_words else {"end": "closed"})
    else:
        ends = [rng.choice(["natural", "reflect", [rng.uniform(-2, 2) for _ in range(dim)]]) for _ in range(2)]
        spec.update({"start": ends[0], "end": ends[1]} if table_words else {"end": {"start": ends[0], "end": ends[1]}})
    spec["tension"] = rng.choice([0.0, 0.25])
    if rng.random() < 0.4:
        spec["kb"] = {k: [rng.uniform(-0.5, 0.5) for _ in range(n)] for k in ("tension", "continuity", "bias")}
        if not closed:
            for v in spec["kb"].values():
                v[0] = v[-1] = None  # ignored at the ends of an open curve: null in the file
    return spec


def _cases(seed):
    rng = random.Random(seed)
    return [(dim, _random_spec(rng, dim)) for dim in list(range(1, 17)) + [2, 2, 3, 3, 2, 3] for _ in range(2)]


def _t_inside(c, per=5):
    g = c.grid
    return np.concatenate([np.linspace(g[i], g[i + 1], per, endpoint=False) for i in range(len(g) - 1)] + [g[-1:]])


def test_save_and_load_round_trip(tmp_path, seed):
    cases = _cases(seed)
    for k, (dim, spec) in enumerate(cases):
        c = crspline.from_spec(spec)
        path = tmp_path / f"c{k}.json"
        crspline.save(path, c)
        back = crspline.load(path)
        assert type(back) is type(c), f"seed {seed}, case {k}"
        assert back.dim == dim and back.closed == c.closed
        # The same doubles go in, so the same doubles come out.
        assert np.array_equal(back.grid, c.grid), f"seed {seed}, case {k}: {spec}"
        t = _t_inside(c)
        for n in range(3):
            assert np.array_equal(back.evaluate(t, n), c.evaluate(t, n)), f"seed {seed}, case {k}, order {n}"
        assert back.spec() == c.spec(), f"seed {seed}, case {k}"
        # And the file says what was asked for, in the table's words (issue
        # 26: one spelling): "closed": true, or "start" and "end".
        written = json.loads(path.read_text())
        assert written["points"] == spec["points"]
        if c.closed:
            assert written["closed"] is True and "start" not in written and "end" not in written, written
        else:
            ends = spec["end"] if isinstance(spec["end"], dict) else spec
            assert "closed" not in written and (written["start"], written["end"]) == (ends["start"], ends["end"])
        assert written.get("grid") == (list(map(float, spec["grid"])) if "grid" in spec else None)
        if "kb" in spec:
            assert written["kb"] == {key: [None if x is None else x for x in v] for key, v in spec["kb"].items()}


def test_spec_of_a_constructed_curve():
    c = crspline.CatmullRom([[0, 0], [1, 2], [3, 1]], endconditions=([1, 0], "reflect"), tension=0.5)
    # The table's words (issue 26): "closed": true for a closed curve, "start"
    # and "end" for an open one (both always, each a name or a tangent).
    assert c.spec() == {"points": [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]], "alpha": 0.5,
                        "start": [1.0, 0.0], "end": "reflect", "tension": 0.5}
    u = crspline.CatmullRom([[0], [1], [3]], alpha=None, strict=True)
    assert u.spec() == {"points": [[0.0], [1.0], [3.0]], "alpha": 0.0, "start": "natural", "end": "natural",
                        "tension": 0.0, "strict": True}
    g = crspline.CatmullRom([[0, 0], [1, 2], [3, 1]], grid=[0, 1, 3, 4.5], endconditions="closed")
    assert g.spec() == {"points": [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]], "grid": [0.0, 1.0, 3.0, 4.5],
                        "closed": True, "tension": 0.0}
    k = crspline.KochanekBartels([[0, 0], [1, 2], [3, 1], [4, 0]], tcb=[(0.1, 0.2, 0.3), (0, 0, 0)])
    spec = k.spec()
    assert spec["alpha"] == 0.0 and spec["kb"] == {"tension": [0.0, 0.1, 0.0, 0.0],
                                                     "continuity": [0.0, 0.2, 0.0, 0.0],
                                                     "bias": [0.0, 0.3, 0.0, 0.0]}
    np.testing.assert_array_equal(crspline.from_spec(spec).tcb, k.tcb)


@pytest.mark.skipif(not os.environ.get("CRSPLINE_BIN"), reason="CRSPLINE_BIN (the command line tool) not set")
def test_the_command_line_reads_what_python_saved(tmp_path, seed):
    cases = _cases(seed)
    checked = 0
    for k, (dim, spec) in enumerate(cases):
        c = crspline.from_spec(spec)
        path = tmp_path / f"c{k}.json"
        crspline.save(path, c)
        t = _t_inside(c, 3)
        p = subprocess.run([os.environ["CRSPLINE_BIN"], "eval", "--t", ",".join(repr(float(x)) for x in t),
                            "--derivatives", "0,1", "--knots", str(path)], capture_output=True, text=True, timeout=60)
        assert p.returncode == 0, f"seed {seed}, case {k}: {p.stderr}"
        out = json.loads(p.stdout)
        assert out["grid"] == c.grid.tolist(), f"seed {seed}, case {k}"
        for n in (0, 1):
            # One core computes both; the CLI prints shortest round-trip decimals.
            assert np.array_equal(np.array(out["values"][str(n)]), c.evaluate(t, n)), f"seed {seed}, case {k}"
        p = subprocess.run([os.environ["CRSPLINE_BIN"], "length", str(path)], capture_output=True, text=True,
                           timeout=60)
        assert p.returncode == 0, p.stderr
        assert json.loads(p.stdout)["total"] == pytest.approx(c.arc_length(), rel=1e-12)
        checked += 1
    assert checked == len(cases)


@pytest.mark.skipif(not os.environ.get("CRSPLINE_BIN"), reason="CRSPLINE_BIN (the command line tool) not set")
def test_the_command_line_and_python_refuse_the_same_unknown_field(tmp_path):
    path = tmp_path / "typo.json"
    path.write_text(json.dumps({"points": [[0, 0], [1, 1]], "alpah": 0.5}))
    p = subprocess.run([os.environ["CRSPLINE_BIN"], "length", str(path)], capture_output=True, text=True, timeout=60)
    assert p.returncode == 2 and "unknown field 'alpah'" in p.stderr
    with pytest.raises(ValueError, match="^unknown field 'alpah'$"):
        crspline.load(path)


def test_fields_python_cannot_read_are_named(tmp_path):
    with pytest.raises(ValueError, match="^unknown field 'dimension'$"):
        crspline.from_spec({"points": [[0, 0], [1, 1]], "dimension": 2})
    with pytest.raises(ValueError, match="field 'tangents'"):
        crspline.from_spec({"points": [[0, 0], [1, 1]], "tangents": [[1, 0], [1, 0]]})
    with pytest.raises(ValueError, match="unknown field 'middle' in 'end'"):
        crspline.from_spec({"points": [[0, 0], [1, 1]], "end": {"start": "natural", "middle": "natural"}})
    with pytest.raises(ValueError, match="unknown field 'tenson' in 'kb'"):
        crspline.from_spec({"points": [[0, 0], [1, 1]], "kb": {"tenson": [0, 0]}})
    with pytest.raises(ValueError, match="^missing field 'points'$"):
        crspline.from_spec({"alpha": 0.5})
    with pytest.raises(TypeError, match="'strict' must be true or false"):
        crspline.from_spec({"points": [[0, 0], [1, 1]], "strict": 1})
    path = tmp_path / "bad.json"
    path.write_text("{\"points\": [[0, 0], [1, 1]")
    with pytest.raises(ValueError, match="not JSON"):
        crspline.load(path)
    with pytest.raises(TypeError, match="save takes a crspline.CatmullRom"):
        crspline.save(tmp_path / "x.json", object())


@pytest.mark.parametrize("spec, field, index, component, value, message", [
    ({"points": [[0, 0], [1, float("nan")]]}, "points", 1, 1, "nan", "point 1, coordinate 1 is not finite (nan)"),
    ({"points": [[0, 0], [1, 1]], "alpha": 2}, "alpha", None, None, "2", "alpha must be in [0, 1], got 2"),
    ({"points": [[0, 0], [1, 1], [2, 0]], "grid": [0, 2, 1]}, "grid", 2, None, "1",
     "grid must be strictly increasing: grid[2] = 1 is not greater than grid[1] = 2"),
    ({"points": [[0, 0], [1, 1]], "end": {"start": "clamped"}}, "start", None, None, "clamped",
     "start condition must be 'natural', 'reflect' or a tangent, got 'clamped'"),
    ({"points": [[0, 0], [1, 1]], "end": "periodic"}, "end", None, None, "periodic",
     "end conditions must be 'natural', 'reflect', 'closed' or one for each end, got 'periodic'"),
    ({"points": [[0, 0], [1, 1]], "end": {"end": [1, 2, 3]}}, "end", None, None, "3",
     "end tangent has 3 coordinates, expected 2 like the points"),
    ({"points": [[0, 0], [1, 1], [2, 0]], "kb": {"bias": [None, None, 0]}}, "kb.bias", 1, None, "nan",
     "kb bias[1] is not finite (nan)"),
    ({"points": [[0, 0], [1, 1]], "tension": 1.5}, "tension", None, None, "1.5", "tension must be in [0, 1], got 1.5"),
])
def test_spec_errors_carry_the_core_words_and_parts(spec, field, index, component, value, message):
    with pytest.raises(crspline.SpecError) as info:
        crspline.from_spec(spec)
    e = info.value
    assert isinstance(e, crspline.InvalidInput) and isinstance(e, ValueError)
    assert str(e) == message
    assert (e.field, e.index, e.component, e.value) == (field, index, component, value)


# --- issue 26: one spelling, the table's (docs/spec.md) ------------------------
P3 = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]]
P4 = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 3.0]]

#: One curve per row of the specification's table, its field away from the
#: default; `dimension` is the points' own length (the file has no such field).
TABLE_ROWS = {
    "dimension": {"points": [[float(i), float(i * i % 5), 0.5 * i, 1.0, -2.0, 0.25 * i, 3.0] for i in range(4)]},
    "points": {"points": P3},
    "alpha": {"points": P3, "alpha": 0.25},
    "grid": {"points": P3, "grid": [0.0, 1.0, 3.0]},
    "closed": {"points": P3, "closed": True},
    "start, end (names)": {"points": P3, "start": "reflect", "end": "natural"},
    "start, end (tangents)": {"points": P3, "start": [0.5, 1.0], "end": [1.0, -2.0]},
    "tension": {"points": P3, "tension": 0.25},
    "kb.tension, kb.continuity, kb.bias": {"points": P4, "kb": {"tension": [None, 0.1, 0.2, None],
                                                                  "continuity": [None, -0.3, 0.0, None],
                                                                  "bias": [None, 0.0, 0.4, None]}},
    "strict": {"points": P3, "strict": True},
}


def _canonical(spec):
    """What spec() writes for a table-word spec: the defaults filled in
    (alpha 0.5 without a grid, tension 0, both ends of an open curve)."""
    out = {"points": spec["points"]}
    out.update({"grid": spec["grid"]} if "grid" in spec else {"alpha": spec.get("alpha", 0.5)})
    if spec.get("closed"):
        out["closed"] = True
    else:
        out.update({"start": spec.get("start", "natural"), "end": spec.get("end", "natural")})
    out["tension"] = spec.get("tension", 0.0)
    for key in ("kb", "strict"):
        if key in spec:
            out[key] = spec[key]
    return out


@pytest.mark.parametrize("row", sorted(TABLE_ROWS))
def test_every_row_of_the_table_round_trips(row, tmp_path):
    spec = TABLE_ROWS[row]
    c = crspline.from_spec(spec)
    written = c.spec()
    assert written == _canonical(spec), row
    assert len(written["points"][0]) == len(spec["points"][0])
    again = crspline.from_spec(written)
    assert again.spec() == written and type(again) is type(c) and again.closed == c.closed
    t = _t_inside(c)
    assert np.array_equal(again.evaluate(t), c.evaluate(t)), row
    path = tmp_path / "row.json"
    crspline.save(path, c)
    assert json.loads(path.read_text()) == written, row  # the file holds exactly the table's words
    back = crspline.load(path)
    assert back.spec() == written and np.array_equal(back.evaluate(t), c.evaluate(t)), row


def test_the_spec_method_writes_one_spelling(seed):
    # Whatever form a curve was built from, spec() has no compact 'end'
    # (a string for both ends, "closed", or an object) and 'closed' only when true.
    for k, (dim, spec) in enumerate(_cases(seed)):
        written = crspline.from_spec(spec).spec()
        if written.get("closed"):
            assert written["closed"] is True and "start" not in written and "end" not in written
        else:
            assert "closed" not in written, f"seed {seed}, case {k}"
            for key in ("start", "end"):
                e = written[key]
                assert e in ("natural", "reflect") or (isinstance(e, list) and len(e) == dim), (seed, k, written)


#: The older compact forms (and table words that leave a default) against the
#: same curve in the table's words.
COMPACT_FORMS = [
    ({"end": "closed"}, {"closed": True}),
    ({"closed": True, "end": "closed"}, {"closed": True}),
    ({"end": "natural"}, {"start": "natural", "end": "natural"}),
    ({"end": "reflect"}, {"start": "reflect", "end": "reflect"}),  # a name alone: both ends
    ({"end": {"start": "reflect", "end": [1, 0]}}, {"start": "reflect", "end": [1.0, 0.0]}),
    ({"end": {"end": "reflect"}}, {"start": "natural", "end": "reflect"}),
    ({"end": {}}, {"start": "natural", "end": "natural"}),
    ({}, {"start": "natural", "end": "natural"}),
    ({"closed": False}, {"start": "natural", "end": "natural"}),
    ({"closed": False, "end": "reflect"}, {"start": "natural", "end": "reflect"}),  # table words: the end only
    ({"start": "reflect"}, {"start": "reflect", "end": "natural"}),
    ({"start": "natural", "end": "reflect"}, {"start": "natural", "end": "reflect"}),
    ({"end": [1, 0]}, {"start": "natural", "end": [1.0, 0.0]}),
]


@pytest.mark.parametrize("given, table", COMPACT_FORMS)
def test_compact_forms_read_as_the_table_words(given, table):
    c = crspline.from_spec({"points": P3, **given})
    expected = crspline.from_spec({"points": P3, **table})
    assert c.spec() == expected.spec() == _canonical({"points": P3, **table}), given
    t = _t_inside(c)
    assert np.array_equal(c.evaluate(t, 1), expected.evaluate(t, 1))


@pytest.mark.parametrize("given, exc, message", [
    ({"closed": True, "end": "natural"}, ValueError,
     "^fields 'closed' and 'end' contradict: a closed curve has no end conditions$"),
    ({"closed": True, "start": "reflect"}, ValueError,
     "^fields 'closed' and 'start' contradict: a closed curve has no end conditions$"),
    ({"closed": True, "start": "natural", "end": [1, 0]}, ValueError,
     "^fields 'closed', 'start' and 'end' contradict: a closed curve has no end conditions$"),
    ({"closed": True, "end": {"start": "natural"}}, ValueError,
     "^fields 'closed' and 'end' contradict: a closed curve has no end conditions$"),
    ({"closed": False, "end": "closed"}, ValueError, "^fields 'closed' and 'end' contradict: "),
    ({"start": "reflect", "end": "closed"}, ValueError, "^fields 'start' and 'end' contradict: "),
    ({"start": "reflect", "end": {"end": "natural"}}, ValueError,
     "^fields 'start' and 'end' contradict: both give the start condition"),
    ({"closed": 1}, TypeError, "^'closed' must be true or false, got int$"),
    ({"closed": None}, TypeError, "^'closed' must be true or false, got NoneType$"),
    ({"start": 5}, TypeError, "^'start' must be \"natural\", \"reflect\" or a tangent"),
    ({"start": "natural", "end": {"x": 1}}, ValueError, "^unknown field 'x' in 'end'"),
])
def test_contradicting_end_fields_are_named(given, exc, message):
    with pytest.raises(exc, match=message):
        crspline.from_spec({"points": P3, **given})


def test_end_names_in_the_table_words_get_the_core_words():
    with pytest.raises(crspline.SpecError) as info:
        crspline.from_spec({"points": P3, "start": "clamped", "end": "natural"})
    assert str(info.value) == "start condition must be 'natural', 'reflect' or a tangent, got 'clamped'"
    assert info.value.field == "start"
    with pytest.raises(crspline.SpecError) as info:
        crspline.from_spec({"points": P3, "start": "natural", "end": "closed?"})
    assert info.value.field == "end" and info.value.value == "closed?"


@pytest.mark.skipif(not os.environ.get("CRSPLINE_BIN"), reason="CRSPLINE_BIN (the command line tool) not set")
@pytest.mark.parametrize("row", sorted(TABLE_ROWS))
def test_the_command_line_reads_every_row_python_saved(row, tmp_path):
    c = crspline.from_spec(TABLE_ROWS[row])
    path = tmp_path / "row.json"
    crspline.save(path, c)
    t = _t_inside(c, 3)
    p = subprocess.run([os.environ["CRSPLINE_BIN"], "eval", "--t", ",".join(repr(float(x)) for x in t),
                        "--derivatives", "0,1", "--knots", str(path)], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, f"{row}: {p.stderr}"
    out = json.loads(p.stdout)
    assert out["grid"] == c.grid.tolist(), row
    for n in (0, 1):
        # One core computes both; the CLI prints shortest round-trip decimals.
        assert np.array_equal(np.array(out["values"][str(n)]), c.evaluate(t, n)), f"{row}, order {n}"
