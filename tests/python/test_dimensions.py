"""Any dimension 1 to 16: a 7-D curve gives the numbers of catmull_rom<7>
(tests/reference/seven_d.json, checked against the C++ API by
Reference.SevenDimensions); dimensions 5 to 16 (one zero-padded wide curve
inside the module) match a 1-D curve coordinate by coordinate."""
import numpy as np
import pytest

import crspline
from conftest import load_reference


def test_seven_d_matches_catmull_rom_7_exactly():
    ref = load_reference("seven_d.json")
    doc = ref["input"]
    c = crspline.CatmullRom(doc["points"], alpha=doc["alpha"], tension=doc["tension"],
                            endconditions=(doc["end"]["start"], doc["end"]["end"]))
    assert c.dim == 7 and c.points.shape == (6, 7)
    assert c.grid.tolist() == ref["grid"]
    for order in (0, 1, 2):
        got = c.evaluate(np.array(doc["t"]), order)
        assert got.shape == (len(doc["t"]), 7)
        assert got.tolist() == ref["values"][str(order)]  # exact, as the C++ batch call gives them


@pytest.mark.parametrize("dim", range(1, 17))
def test_every_dimension_matches_one_coordinate_at_a_time(dim):
    seed = 1000 + dim
    rng = np.random.default_rng(seed)
    pts = rng.uniform(-5, 5, (6, dim))
    c = crspline.CatmullRom(pts)
    t = np.linspace(*c.domain, 23)
    assert c.dim == dim
    # The knots fixed as an explicit grid for both (an alpha curve takes its
    # shape from the intervals as computed, not from the grid's differences:
    # docs/spec.md): every coordinate is then its own 1-D curve.
    on_grid = crspline.CatmullRom(pts, grid=c.grid)
    for order in (0, 1, 2):
        values = on_grid.evaluate(t, order)
        assert values.shape == (23, dim)
        for k in range(dim):
            one = crspline.CatmullRom(pts[:, k], grid=c.grid)
            np.testing.assert_array_equal(values[:, k], one.evaluate(t, order)[:, 0], err_msg=f"seed {seed}, k {k}")
    # Results that carry points come back with the curve's own coordinates.
    assert c.to_bezier().shape == (5, 4, dim)
    assert c.tangents().shape == (5, 2, dim)
    assert c.bounding_box().shape == (2, dim)
    assert c.tessellate(1e-3)["points"].shape[1] == dim
    assert c.sample(5)["points"].shape == (5, dim)
    near = c.nearest(pts[2] + 0.01)
    # The curve passes through pts[2], 0.01 * sqrt(dim) from the query.
    assert near["point"].shape == (dim,) and near["distance_sq"] <= dim * 1e-4 * (1 + 1e-9)
    report = c.analyze()
    assert report["dimension"] == dim and all(len(b) == dim for s in report["segments"] for b in s["bezier"])


def test_wide_curve_refuses_what_depends_on_the_dimension():
    c = crspline.CatmullRom(np.arange(14.0).reshape(2, 7) ** 2)
    with pytest.raises(crspline.InvalidInput, match="torsion needs a 3-D curve, this one is 7-D"):
        c.torsion(0.5)
    with pytest.raises(crspline.InvalidInput, match="rotation-minimizing frames need a 2-D or 3-D curve, this one is 7-D"):
        c.frames([0.0])
    with pytest.raises(crspline.SpecError, match=r"^end tangent has 16 coordinates, expected 7 like the points$"):
        crspline.CatmullRom(np.zeros((3, 7)) + np.arange(3)[:, None], endconditions=("natural", np.ones(16)))
