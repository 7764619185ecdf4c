"""crspline: cubic Catmull-Rom curves in any dimension, over NumPy.

The compiled core (``crspline._crspline``, pybind11) does the work; this
package turns Python arguments into its normalized form and its results into
plain ndarrays and dicts.

>>> import crspline
>>> c = crspline.CatmullRom([[0, 0], [1, 2], [3, 2], [4, 0]])   # centripetal
>>> c.evaluate(c.grid).tolist() == c.points.tolist()          # interpolates
True

What it does (each with its page under docs/):

* curves: ``CatmullRom``, ``KochanekBartels``: evaluation, derivatives, arc
  length, tessellation, the Bezier form, nearest points (docs/python.md)
* decision: ``decide``, ``decide_pair``, ``decide_set``, ``clearance``: a
  proved verdict on crossings, simple, crosses or touches (docs/analysis.md)
* rotations: ``crspline.rotation``: quaternion splines, SciPy's C2
  ``RotationSpline`` converged, pose curves (docs/rotation.md)
* GIS smoothing: ``crspline.geo.smooth``: GeoPandas layers smoothed with
  shared borders and containment kept, proved; Dask too (docs/geo.md)
* fit: ``fit``: the fewest control points within a proved tolerance of
  dense or noisy samples (docs/fit.md)
* sweeps/strokes: ``sweep``, ``stroke``: tubes and roads along a 3-D curve
  as meshes, a 2-D curve's outline as polygons (docs/sweep.md)
* rotation fit: ``crspline.rotation.fit``: the fewest keys within an angle of
  an orientation stream (docs/rotation.md)

Conventions (those of the C++ library and of the ``splines`` package):

* ``t`` is the curve parameter, running over ``grid[0] .. grid[-1]``; ``s`` is
  arc length. Segment ``i`` joins ``points[i]`` and ``points[i+1]`` on
  ``[grid[i], grid[i+1]]``; an interior knot belongs to the segment on its
  right, the last knot to the last segment.
* Knots from ``alpha``: ``t[0] = 0``, ``t[i+1] = t[i] + |x[i+1] - x[i]|**alpha``
  (0 uniform, 0.5 centripetal, 1 chordal). A closed curve does not repeat its
  first point and has one more knot than points.
* float32 points give a float32 curve (float32 results); anything else real
  gives float64. Dimensions 1 to ``max_dimension`` (16).
* Errors: bad values raise ``ValueError`` (``InvalidInput`` or, for a
  parameter outside the domain, ``OutOfDomain``, both subclasses of
  ``ValueError``) with the core's message; arguments of the wrong kind raise
  ``TypeError``.
* Batch work (evaluation, arc-length inversion, nearest points, ...) runs in
  C++ with the GIL released.

The package, one job a module: ``_constants`` (the named constants),
``_arguments`` (Python arguments to the core's form), ``_curve``
(``CatmullRom``), ``_kochanek_bartels`` (``KochanekBartels``),
``_curve_file`` (``from_spec``, ``load``, ``save``) and ``_many`` (the
many-curve calls); ``splines`` is the drop-in for the ``splines`` package.
"""
from . import _crspline
from ._crspline import InvalidInput, OutOfDomain, SpecError, __version__
from ._constants import centripetal, chordal, default_accuracy, max_dimension, uniform
# The private helpers stay importable from the package, where they were before it was split.
from ._arguments import (_DEFAULT_ALPHA, _DefaultAlpha, _as_points, _as_vector, _end,  # noqa: F401
                         _numeric_array, _parse_endconditions, _readonly, _real, _scalar_or_array)
from ._curve import CatmullRom
from ._kochanek_bartels import KochanekBartels
from ._curve_file import _FILE_FIELDS, _file_end, _file_kb, from_spec, load, save  # noqa: F401
from ._many import _curve_list, _shared, _workers, arc_lengths, tessellate_many  # noqa: F401
from ._decision import clearance, decide, decide_pair, decide_set  # noqa: F401  (issue 27)
from ._fit import FitResult, fit  # noqa: F401  (issue 40)
from ._sweep import stroke, sweep  # noqa: F401  (issue 41)

__all__ = [
    "CatmullRom",
    "KochanekBartels",
    "InvalidInput",
    "SpecError",
    "OutOfDomain",
    "load",
    "save",
    "from_spec",
    "arc_lengths",
    "tessellate_many",
    "uniform",
    "centripetal",
    "chordal",
    "default_accuracy",
    "max_dimension",
    "__version__",
]

# The public classes and functions say they are crspline's (help(), repr of
# the class, pickling), not the private module's that defines them.
for _obj in (CatmullRom, KochanekBartels, from_spec, load, save, arc_lengths, tessellate_many):
    _obj.__module__ = __name__
del _obj
