"""Errors: ValueError (InvalidInput, OutOfDomain) with the core's messages,
TypeError for arguments of the wrong kind."""
import numpy as np
import pytest

import crspline

P = [[0, 0], [1, 2], [3, 2], [4, 0]]


@pytest.mark.parametrize("args, kwargs, exc, message", [
    (([[0, 0]],), {}, crspline.InvalidInput, "a curve needs at least 2 points, got 1"),
    (([[0, 0]],), {"endconditions": "closed"}, crspline.InvalidInput,
     "a closed curve needs at least 2 points, got 1"),
    (([[0, 0], [1, np.nan]],), {}, crspline.InvalidInput, "point 1, coordinate 1 is not finite (nan)"),
    (([[0, 0], [np.inf, 1]],), {}, crspline.InvalidInput, "point 1, coordinate 0 is not finite (inf)"),
    ((P,), {"alpha": 1.5}, crspline.InvalidInput, "alpha must be in [0, 1], got 1.5"),
    ((P,), {"alpha": -0.1}, crspline.InvalidInput, "alpha must be in [0, 1], got -0.1"),
    ((P,), {"alpha": 0.5, "grid": [0, 1, 2, 3]}, crspline.InvalidInput, "give alpha or grid, not both"),
    ((P,), {"grid": [0, 1, 2]}, crspline.InvalidInput, "grid has 3 values, expected 4 (one per point)"),
    ((P,), {"grid": [0, 1, 1, 3]}, crspline.InvalidInput,
     "grid must be strictly increasing: grid[2] = 1 is not greater than grid[1] = 1"),
    ((P,), {"grid": [0, 1, 2, 3], "endconditions": "closed"}, crspline.InvalidInput,
     "grid has 4 values, expected 5"),
    ((P,), {"tension": 2}, crspline.InvalidInput, "tension must be in [0, 1], got 2"),
    ((P,), {"endconditions": ([np.nan, 0], "natural")}, crspline.InvalidInput,
     "start tangent coordinate 0 is not finite (nan)"),
    ((np.zeros((3, 17)),), {}, crspline.SpecError, "dimension must be 1 to 16, got 17"),
    ((np.zeros((2, 2, 2)),), {}, ValueError, "points must be an N x dim array"),
    ((np.zeros((3, 0)),), {}, ValueError, "dimension must be 1 to 16, got 0"),
    ((P,), {"endconditions": "periodic"}, crspline.SpecError,
     "end conditions must be 'natural', 'reflect', 'closed' or one for each end, got 'periodic'"),
    ((P,), {"endconditions": ("natural", "closed")}, crspline.SpecError,
     "end condition must be 'natural', 'reflect' or a tangent, got 'closed'"),
    ((P,), {"endconditions": ("clamped", "natural")}, crspline.SpecError,
     "start condition must be 'natural', 'reflect' or a tangent, got 'clamped'"),
    ((P,), {"endconditions": ([1, 2, 3], "natural")}, crspline.SpecError,
     "start tangent has 3 coordinates, expected 2 like the points"),
    ((P,), {"endconditions": ([[1, 2]], "natural")}, ValueError, "start tangent must be one vector dx/dt"),
    ((P,), {"endconditions": {"start": "natural"}}, ValueError, "exactly the keys"),
    ((P,), {"endconditions": 5}, TypeError, "endconditions must be a string or a pair"),
    ((P,), {"endconditions": ("natural", "natural", "natural")}, TypeError, "a pair"),
    (([["a", "b"], ["c", "d"]],), {}, TypeError, "points must be real numbers"),
    (([[1j, 0], [0, 1]],), {}, TypeError, "complex"),
    ((P,), {"alpha": "0.5"}, TypeError, "alpha must be a real number"),
    ((P,), {"tension": None}, TypeError, "tension must be a real number"),
    ((P,), {"grid": ["a", "b", "c", "d"]}, TypeError, "grid must be real numbers"),
])
def test_construction_errors(args, kwargs, exc, message):
    with pytest.raises(exc) as info:
        crspline.CatmullRom(*args, **kwargs)
    assert message in str(info.value)


def test_strict_message_names_the_points():
    with pytest.raises(crspline.InvalidInput,
                       match=r"^coincident consecutive points \(strict mode\): 1 and 2$"):
        crspline.CatmullRom([[0, 0], [1, 1], [1, 1], [2, 0]], strict=True)


def test_evaluation_errors():
    c = crspline.CatmullRom(P, alpha=0)
    with pytest.raises(crspline.OutOfDomain, match=r"^t = 3.5 is outside the domain \[0, 3\]$"):
        c.evaluate(3.5)
    with pytest.raises(crspline.OutOfDomain, match=r"^t = -1 \(index 2\) is outside the domain \[0, 3\]$"):
        c.evaluate([0, 1, -1, 2])
    with pytest.raises(crspline.OutOfDomain, match=r"t = nan \(index 1\)"):
        c.evaluate([0, np.nan])
    with pytest.raises(crspline.InvalidInput, match="derivative order must be 0, 1, 2 or 3, got 4"):
        c.evaluate(1.0, 4)
    with pytest.raises(ValueError, match="derivative order"):
        c.evaluate(1.0, -1)
    with pytest.raises(TypeError):
        c.evaluate(1.0, 1.5)  # the order is an integer
    with pytest.raises(TypeError, match="t must be real numbers"):
        c.evaluate("1.0")
    with pytest.raises(TypeError):
        c.evaluate([1 + 1j])
    # ValueError catches both library errors.
    with pytest.raises(ValueError):
        c.evaluate(10)


def test_arc_length_errors():
    c = crspline.CatmullRom(P)
    L = c.arc_length()
    with pytest.raises(crspline.OutOfDomain, match=r"^s = -1 is outside the arc-length range \[0, "):
        c.t_at_arc_length(-1.0)
    with pytest.raises(crspline.OutOfDomain, match=r"\(index 1\) is outside the arc-length range"):
        c.t_at_arc_length([0.0, 2 * L])
    with pytest.raises(crspline.InvalidInput, match="accuracy must be in"):
        c.arc_length(accuracy=0)
    with pytest.raises(crspline.InvalidInput, match="is reversed"):
        c.arc_length(2.0, 1.0)
    with pytest.raises(crspline.OutOfDomain):
        c.arc_length(0.0, 100.0)
    with pytest.raises(ValueError, match="need at least 2 samples, got 1"):
        c.sample(1)
    with pytest.raises(ValueError, match="by must be"):
        c.sample(5, by="length")


def test_kochanek_bartels_errors():
    with pytest.raises(crspline.InvalidInput, match="give alpha or grid, not both"):
        crspline.KochanekBartels(P, grid=[0, 1, 2, 3], alpha=0.5)
    with pytest.raises(ValueError, match="tcb has 4 triples"):
        crspline.KochanekBartels(P, tcb=np.zeros((4, 3)))
    with pytest.raises(crspline.InvalidInput, match=r"kb tension\[1\] is not finite"):
        crspline.KochanekBartels(P, tcb=[(np.nan, 0, 0), (0, 0, 0)])
    with pytest.raises(TypeError):
        crspline.KochanekBartels(P, tcb="tcb")


def test_out_of_domain_messages_name_the_index_and_the_value():
    # Issue 31 point 7: every call taking an array of t names the first t
    # outside the domain, its index in t.ravel() and its value (evaluate's
    # words); a number gets the scalar message, which has no index.
    c = crspline.CatmullRom(P, alpha=0)  # domain [0, 3]
    space = crspline.CatmullRom([[0, 0, 0], [1, 2, 0], [3, 2, 1], [4, 0, 2]], alpha=0)
    calls = [("evaluate", c.evaluate), ("arc_length_at", c.arc_length_at), ("curvature", c.curvature),
             ("signed_curvature", c.signed_curvature), ("torsion", space.torsion),
             ("curvature (3-D)", space.curvature)]
    for name, f in calls:
        with pytest.raises(crspline.OutOfDomain, match=r"^t = 3.5 \(index 2\) is outside the domain \[0, 3\]$"):
            f([0.0, 1.5, 3.5, 2.0, -1.0])
        with pytest.raises(crspline.OutOfDomain, match=r"^t = -1 \(index 3\) is outside the domain \[0, 3\]$"):
            f([[0.0, 1.0], [2.0, -1.0]])  # the index in t.ravel()
        with pytest.raises(crspline.OutOfDomain, match=r"^t = nan \(index 1\) is outside the domain \[0, 3\]$"):
            f(np.array([0.0, np.nan]))
        with pytest.raises(crspline.OutOfDomain, match=r"^t = 3.5 is outside the domain \[0, 3\]$"):
            f(3.5)
        assert np.all(np.isfinite(f([0.0, 1.5, 3.0]))), name  # inside: no error
    # float32 curves name the value as float32 holds it.
    c32 = crspline.CatmullRom(np.array(P, dtype=np.float32), alpha=0)
    for f in (c32.arc_length_at, c32.curvature):
        with pytest.raises(crspline.OutOfDomain, match=r"^t = 4 \(index 1\) is outside the domain \[0, 3\]$"):
            f(np.array([1, 4], dtype=np.float32))
    # frames (the core's batch call) names it in its own words.
    with pytest.raises(crspline.OutOfDomain, match=r"^t\[2\] = 3.5 is outside the domain \[0, 3\]$"):
        c.frames([0.0, 1.0, 3.5])


def test_segment_index_clamps_outside_values_and_refuses_nan():
    # Issue 31 point 7: values outside the domain clamp to the first or last
    # segment (documented); NaN, which is on neither side, is refused by index.
    c = crspline.CatmullRom(P, alpha=0)  # segments [0, 1), [1, 2), [2, 3]
    t = [-np.inf, -1e300, -1.0, 0.0, 0.5, 1.0, 2.999, 3.0, 4.0, 1e300, np.inf]
    assert c.segment_index(t).tolist() == [0, 0, 0, 0, 0, 1, 2, 2, 2, 2, 2]
    assert c.segment_index(1e300) == 2 and c.segment_index(-1e300) == 0
    with pytest.raises(crspline.OutOfDomain, match=r"^t = nan \(index 2\) is not a number"):
        c.segment_index([0.0, 1.0, np.nan, np.nan])
    with pytest.raises(crspline.OutOfDomain, match=r"^t = nan \(index 3\) is not a number"):
        c.segment_index(np.array([[0.0, 1.0], [2.0, np.nan]], dtype=np.float32))
    with pytest.raises(crspline.OutOfDomain, match=r"^t = nan is not a number"):
        c.segment_index(float("nan"))


@pytest.mark.parametrize("alpha", [0.0, 0.5, 1.0])
def test_points_whose_differences_overflow_are_refused_at_construction(alpha):
    # Issue 31 point 3 (needs the core's refusal of non-finite chords, knot
    # intervals and Bezier points): the difference of these finite points
    # overflows; before, alpha 0 gave arc_length() 0.0, evaluate(0.5) NaN and
    # infinite Bezier points, alpha 1 the grid [0, inf].
    points = [[-1.5e308, 0.0], [1.5e308, 0.0]]
    with pytest.raises(ValueError, match=r"\bpoints 0 and 1\b"):
        crspline.CatmullRom(points, alpha=alpha)
    with pytest.raises(ValueError, match=r"\bpoints 0 and 1\b"):
        crspline.from_spec({"points": points, "alpha": alpha})
    with pytest.raises(ValueError, match=r"^curve 1: .*\bpoints 0 and 1\b"):
        crspline.arc_lengths([[[0.0, 0.0], [1.0, 1.0]], points], alpha=alpha)


def test_an_arc_length_within_the_accuracy_of_the_total_maps_to_the_end():
    # Issue 26 point 1: a length computed by another tool cannot be known
    # better than the accuracy promise (1e-12 relative): s within it of
    # either end maps to that end; further out is still an error.
    c = crspline.CatmullRom(P)
    total = c.arc_length()
    lo, hi = c.domain
    near = total * (1 + 8e-15)  # the case: 8e-15 relative, far inside 1e-12
    assert near > total
    assert c.t_at_arc_length(near) == hi
    assert c.t_at_arc_length([0.0, total / 2, near]).tolist()[-1] == hi
    assert c.t_at_arc_length(-total * 8e-15) == lo
    with pytest.raises(crspline.OutOfDomain, match=r"is outside the arc-length range \[0, "):
        c.t_at_arc_length(total * (1 + 1e-9))
    with pytest.raises(crspline.OutOfDomain, match=r"\(index 1\) is outside the arc-length range"):
        c.t_at_arc_length([0.0, total * (1 + 1e-9)])
    with pytest.raises(crspline.OutOfDomain, match=r"is outside the arc-length range"):
        c.t_at_arc_length(-total * 1e-9)
    # The promise is the table's own accuracy: at 1e-6, 1e-9 past the end is the end.
    assert c.t_at_arc_length(total * (1 + 1e-9), accuracy=1e-6) == hi
