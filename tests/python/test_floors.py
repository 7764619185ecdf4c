"""Tolerances and accuracies the coordinates cannot resolve (issue 20): every
call that takes a distance tolerance or a relative accuracy refuses a value
below the floor of include/crspline/resolution.hpp with a ValueError that
names the smallest meaningful value, in the CLI's words; a value at the floor
is accepted and finishes.

Unit coordinates: doubles near 1 are 2**-52 apart, so the tolerance floor is
64 * 2**-52 (about 1.4e-14); the accuracy floor is 8 machine epsilons for
any input. Before the check, tessellate(1e-16) on such a curve ran for
minutes (the CLI's sample --tolerance 1e-16 ran past 60 s)."""
import numpy as np
import pytest

import crspline

UNIT = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]  # largest magnitude exactly 1
SPACING = 2.0 ** -52
TOL_FLOOR = 64 * SPACING
ACC_FLOOR = 8 * np.finfo(float).eps


def tolerance_message(given, spacing=SPACING, floor=TOL_FLOOR):
    return (f"tolerance: {given!r} is below what the coordinates resolve (their largest magnitude is spaced "
            f"{spacing!r} apart); the smallest meaningful tolerance for this input is {floor!r}")


def accuracy_message(given):
    return (f"accuracy: {given!r} is below what double arithmetic resolves; the smallest meaningful relative "
            f"accuracy is {ACC_FLOOR!r}")


@pytest.mark.parametrize("tolerance", [1e-16, 1e-300, np.nextafter(TOL_FLOOR, 0)])
def test_tessellate_below_the_floor_is_refused_naming_it(tolerance):
    c = crspline.CatmullRom(UNIT)
    with pytest.raises(ValueError) as e:
        c.tessellate(tolerance)
    assert str(e.value) == tolerance_message(tolerance)
    with pytest.raises(ValueError) as e:
        crspline.tessellate_many([UNIT, UNIT], tolerance)
    assert tolerance_message(tolerance) in str(e.value)


def test_tessellate_at_the_floor_finishes():
    c = crspline.CatmullRom(UNIT)
    p = c.tessellate(TOL_FLOOR)
    # A polyline within 1.4e-14 of three unit segments: many points, but a
    # finite run; it starts and ends at the curve's ends.
    points, t = p["points"], p["t"]
    assert len(points) == len(t) > 4
    assert np.array_equal(points[0], UNIT[0]) and np.array_equal(points[-1], UNIT[-1])
    many = crspline.tessellate_many([UNIT], TOL_FLOOR)
    assert len(many) == 1 and np.array_equal(many[0]["points"], points)


def test_the_floor_scales_with_the_coordinates():
    # Near 1e6 doubles are 2**-33 apart: 1e-10 is fine on unit coordinates
    # and refused here.
    big = [[x * 1e6 for x in p] for p in UNIT]
    crspline.CatmullRom(UNIT).tessellate(1e-10)
    with pytest.raises(ValueError) as e:
        crspline.CatmullRom(big).tessellate(1e-10)
    assert str(e.value) == tolerance_message(1e-10, 2.0 ** -33, 64 * 2.0 ** -33)


def test_float32_curves_have_the_float32_floor():
    c = crspline.CatmullRom(np.array(UNIT, dtype=np.float32))
    floor = 64 * 2.0 ** -23
    with pytest.raises(ValueError) as e:
        c.tessellate(1e-10)
    assert str(e.value) == tolerance_message(1e-10, 2.0 ** -23, floor)
    assert len(c.tessellate(floor)["points"]) > 4


@pytest.mark.parametrize("call", [
    lambda c, a: c.arc_length(accuracy=a),
    lambda c, a: c.arc_length(0.5, 2.5, accuracy=a),
    lambda c, a: c.arc_length_at(1.5, accuracy=a),
    lambda c, a: c.sample(5, accuracy=a),
    lambda c, a: crspline.arc_lengths([UNIT, UNIT], accuracy=a),
], ids=["arc_length", "arc_length_between", "arc_length_table", "sample_arc_length", "arc_lengths"])
def test_accuracy_below_the_floor_is_refused_and_at_it_finishes(call):
    c = crspline.CatmullRom(UNIT)
    for given in (1e-16, 1e-300):
        with pytest.raises(ValueError) as e:
            call(c, given)
        assert str(e.value) == accuracy_message(given)
    call(c, ACC_FLOOR)  # accepted, and returns


def test_non_positive_values_keep_their_own_messages():
    c = crspline.CatmullRom(UNIT)
    with pytest.raises(ValueError, match="accuracy must be in"):
        c.arc_length(accuracy=0.0)
    with pytest.raises(ValueError) as e:
        c.tessellate(0.0)
    assert "smallest meaningful" not in str(e.value)
