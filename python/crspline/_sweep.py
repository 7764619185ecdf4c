"""Sweeps and strokes (issue 41; C++ ``crspline/sweep.hpp``, ``crspline/stroke.hpp``).

``sweep`` carries a cross-section along a 3-D curve and returns a triangle
mesh within a proved distance (``tolerance``) of the swept surface, as
arrays ready for a renderer::

    >>> import crspline, numpy as np
    >>> a = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    >>> knot = crspline.CatmullRom(np.c_[(2 + np.cos(3 * a)) * np.cos(2 * a),
    ...                                  (2 + np.cos(3 * a)) * np.sin(2 * a), np.sin(3 * a)],
    ...                            endconditions="closed")
    >>> m = crspline.sweep(knot, radius=0.3)
    >>> m["positions"].shape[1], m["indices"].shape[1], m["report"]["self_intersects"]
    (3, 3, False)

``stroke`` gives the region within ``width / 2`` of a 2-D curve (a line
buffer) as polygons: lists of rings, the exterior counterclockwise first,
then the holes (clockwise), or as a Shapely geometry with ``shapely=True``.

Errors name the field (``radius``, ``profile``, ``roll``, ``scale``, ``up``,
``tolerance``, ``width``, ``join``, ``cap``, ``miter_limit``, ``curve``) and
raise ``ValueError`` (``SpecError``).
"""
import numpy as np

from . import _crspline
from ._curve import CatmullRom


def _curve(c, what):
    if not isinstance(c, CatmullRom):
        raise TypeError(f"{what}: curve must be a crspline curve (CatmullRom, KochanekBartels), got {type(c).__name__}")
    return c._c


def _floats(x, field):
    try:
        a = np.asarray(x, dtype=float).ravel()
    except (TypeError, ValueError):
        raise TypeError(f"{field}: expected numbers, got {type(x).__name__}") from None
    return [float(v) for v in a]


def _keys(keys, field):
    """(positions, values) as two lists of floats."""
    try:
        s, v = keys
    except (TypeError, ValueError):
        raise TypeError(f"{field}: expected (arc_lengths, values)") from None
    return _floats(s, field), _floats(v, field)


def sweep(curve, *, radius=1.0, profile=None, profile_closed=True, roll=None, up=None, scale=None, tolerance=None,
          tubular_segments=None, radial_segments=None, seamless=True, clearance=True):
    """The sweep of a cross-section along a 3-D curve, as a triangle mesh.

    profile: None (a circle of ``radius``), an (n, 2) array (a polyline in
        the plane of the frame's normal and binormal, closed when
        ``profile_closed``) or a 2-D CatmullRom (a curve profile).
    roll: angles (radians) about the tangent, one per knot (a sequence), or
        ``(arc_lengths, angles)``; interpolated by the rotation splines.
    up: a 3-vector the normal follows (its projection; never flipped; within
        5 degrees of it, the rotation-minimizing frame blended onto it).
    scale: ``(arc_lengths, factors)``: the profile's scale along the curve.
    tolerance: the mesh's distance to the swept surface (default 1e-3 of the
        curve's size); or tubular_segments / radial_segments: three.js' counts.
    seamless: False leaves a closed curve's holonomy unspread (the seam that
        other libraries have; for comparison).

    Returns a dict: positions, normals (n, 3), uvs (n, 2; v along arc
    length), indices (m, 3, uint32), t and s of each ring, rings, ring_size,
    and report (tolerance, bound, tolerance_met, proved, holonomy,
    frame_drift, length, largest_radius, clearance, min_radius_of_curvature,
    far_contact, local_fold, self_intersects, seam_gap, seam_normal_gap).
    """
    c = _curve(curve, "sweep")
    kind, points, closed, alpha = "circle", None, True, 0.5
    if profile is not None:
        if isinstance(profile, CatmullRom):
            kind, points, closed = "curve", np.asarray(profile.points, dtype=float), profile.closed
            alpha = profile.spec().get("alpha", 0.5)
            if alpha is None:
                alpha = 0.5
        else:
            kind, points, closed = "polyline", np.asarray(profile, dtype=float), bool(profile_closed)
            if points.ndim != 2 or (points.size and points.shape[1] != 2):
                raise ValueError(f"profile: expected an (n, 2) array of points, got shape {points.shape}")
            points = points.reshape(-1, 2)
    roll_at, roll_s, roll_v = "knots", [], []
    if roll is not None:
        if isinstance(roll, tuple) and len(roll) == 2:
            roll_at = "arc_length"
            roll_s, roll_v = _keys(roll, "roll")
        else:
            roll_v = _floats(roll, "roll")
    scale_s, scale_v = ([], []) if scale is None else _keys(scale, "scale")
    up_v = None if up is None else _floats(up, "up")
    if radius is None or not np.isscalar(radius):
        raise TypeError(f"radius: expected a number, got {type(radius).__name__}")
    return _crspline._sweep(c, kind, float(radius), points, closed, float(alpha), roll_v, roll_at, roll_s, scale_v,
                            scale_s, up_v, 0.0 if tolerance is None else float(tolerance),
                            int(tubular_segments or 0), int(radial_segments or 0), bool(seamless), bool(clearance))


def stroke(curve, width, *, join="round", cap="butt", miter_limit=4.0, tolerance=None, shapely=False):
    """The region within width / 2 of a 2-D curve, as simple polygons.

    join: 'round', 'miter' (with miter_limit, SVG's rule) or 'bevel', at the
    curve's corners; cap: 'butt', 'round' or 'square'. Within tolerance
    (default 1e-3 of the curve's size plus the width) of the true stroke.

    Returns a list of polygons, each a list of (n, 2) rings (exterior
    counterclockwise, then holes clockwise; first vertex not repeated), or
    with shapely=True a shapely Polygon / MultiPolygon.
    """
    c = _curve(curve, "stroke")
    polys, _tol, _n = _crspline._stroke(c, float(width), str(join), str(cap), float(miter_limit),
                                        0.0 if tolerance is None else float(tolerance))
    if not shapely:
        return polys
    from shapely.geometry import MultiPolygon, Polygon

    shapes = [Polygon(rings[0], rings[1:]) for rings in polys]
    return shapes[0] if len(shapes) == 1 else MultiPolygon(shapes)
