"""Smoothing and measuring whole GIS layers (GeoPandas / Shapely 1.8).

``smooth(gdf, tolerance=...)`` returns a GeoDataFrame with the same index,
columns and CRS, the smoothed geometry and five columns:

- ``length``: of the output geometry the user holds (a polygon's perimeter,
  all rings), measured as GIS measures it: planar in the CRS's units on a
  projected CRS (what ``out.length`` gives), geodesic on the WGS 84
  ellipsoid in metres on a geographic one (pyproj.Geod); one definition
  for both;
- ``curve_length``: the arc length of the smoothed curves themselves (the
  output polylines are chords of them, so never longer): in the CRS's units
  on a projected CRS; on a geographic CRS in metres of the conservative
  frame below (an upper bound of the curves' true length);
- ``max_deviation``: a proved bound on the distance of the curves from the
  input boundary;
- ``verdict``: ``simple``, ``touches`` (shares a boundary or a junction with
  another feature, as in a coverage), ``nested`` (the input's rings nest
  invalidly: a hole outside its shell or inside another hole, a shell
  inside another polygon of the feature; the status says which parts; the
  output keeps that nesting, as it keeps every relation) or ``crosses``
  (the input crossed itself or another feature there; those input
  segments are output as they are);
- ``status``: ``ok``, or ``empty``, ``degenerate: ...``, ``invalid: ...``
  naming the part and vertex (such features come back unchanged, never
  dropped).

The work is the C++ core's (crspline/geo/smooth.hpp): the layer is cut
into arcs between junctions, each shared boundary smoothed once, every
input vertex kept exactly, no output crossing another unless the input
did (proved piece by piece, tension raised locally where a proof fails),
and no vertex of one part in the region another part's smoothing sweeps
(so every part keeps its side of every ring: islands stay out, holes in).

Units. On a projected CRS, tolerance, max_deviation and lengths are in its
units (feet for EPSG:2263). On a geographic CRS (EPSG:4326) they are in
metres: the core works in an equirectangular frame in metres, x = R cos(phi0)
lambda, y = R phi, with R = a^2 / b of the ellipsoid (no radius of curvature
of it is larger) and phi0 the layer's latitude nearest the equator, so a
distance in the frame is never less than the true one: the tolerance and
the reported deviations are upper bounds in true metres. `length` is
geodesic on the ellipsoid (pyproj.Geod) along the output polylines. The
frame's inverse is not used for the input vertices: they come back bit for
bit. The curves are kept within the poles and the antimeridian (tension
where they would leave). A line or ring that crosses the antimeridian (a
step of more than 180 degrees of longitude between neighbours) is unwrapped
first: its longitudes made continuous (179, 181, ...), smoothed so, and
brought back into [-180, 180] on output (input vertices bit for bit).
"""
from __future__ import annotations

import math

import numpy as np

from .. import _crspline

__all__ = ["smooth", "measure", "fit", "geographic_frame"]

_COLUMNS = ("length", "curve_length", "max_deviation", "verdict", "status")
_FIT_COLUMNS = ("length", "control_points", "deviation", "verdict", "status")
_TOPOLOGIES = ("preserve", "none")


def _as_geoseries(data):
    import geopandas as gpd

    if isinstance(data, gpd.GeoDataFrame):
        return data, data.geometry
    if isinstance(data, gpd.GeoSeries):
        return None, data
    raise TypeError(f"expected a GeoDataFrame or GeoSeries, got {type(data).__name__}")


class _Layer:
    """Flat arrays of the parts of a GeoSeries, with the recipe to rebuild it."""

    def __init__(self, geoms):
        self.coords = []          # one (n, 2 or 3) array per part
        self.kinds = []           # 0 line, 1 ring
        self.roles = []           # 0 line, 1 outer ring (a polygon's shell), 2 inner ring (a hole)
        self.features = []        # feature of each part
        self.recipes = []         # per feature: (type name, structure) or None (pass through)
        self.unsupported = {}     # feature -> message
        self.has_z = False
        for i, g in enumerate(geoms):
            self.recipes.append(self._add(i, g))
        self.feature_count = len(self.recipes)

    def _part(self, i, coords, ring, role=0):
        self.roles.append(role)
        a = np.asarray(coords, dtype=float)
        if a.ndim != 2 or a.shape[0] == 0:
            a = np.zeros((0, 2))
        if a.shape[1] > 2:
            self.has_z = True
        self.coords.append(a)
        self.kinds.append(1 if ring else 0)
        self.features.append(i)

    def _add(self, i, g):
        if g is None or g.is_empty:
            return ("empty", None)
        t = g.geom_type
        if t == "Polygon":
            polys = [g]
        elif t == "MultiPolygon":
            polys = list(g.geoms)
        elif t in ("LineString", "LinearRing"):
            self._part(i, g.coords, t == "LinearRing")
            return (t, g.has_z)
        elif t == "MultiLineString":
            lines = list(g.geoms)
            for line in lines:
                self._part(i, line.coords, False)
            return (t, g.has_z, len(lines))
        else:
            self.unsupported[i] = f"unsupported geometry type {t}: passed through unchanged"
            return None
        structure = []
        for p in polys:
            self._part(i, p.exterior.coords, True, 1)
            holes = list(p.interiors)
            for h in holes:
                self._part(i, h.coords, True, 2)
            structure.append(1 + len(holes))
        return (t, g.has_z, structure)

    def arrays(self):
        n = sum(len(c) for c in self.coords)
        xy = np.empty((n, 2))
        z = np.zeros((n, 1 if self.has_z else 0))
        offsets = np.zeros(len(self.coords) + 1, dtype=np.int64)
        k = 0
        for p, c in enumerate(self.coords):
            xy[k:k + len(c)] = c[:, :2]
            if self.has_z and c.shape[1] > 2:
                z[k:k + len(c), 0] = c[:, 2]
            k += len(c)
            offsets[p + 1] = k
        return xy, z, offsets, np.asarray(self.kinds, dtype=np.uint8), np.asarray(self.features, dtype=np.int64)


# WGS 84: a^2 / b bounds both radii of curvature (meridian and prime vertical).
_A = 6378137.0
_F = 1 / 298.257223563
_B = _A * (1 - _F)
_R_MAX = _A * _A / _B


def _frame_stats(lonlat, original=None):
    """What the geographic frame needs from some vertices: (latitude min,
    max, smallest |latitude|, lo, hi of the finite rows of `lonlat` (the
    longitudes unwrapped), lo, hi of those of `original` (as given)),
    combined over partitions by _frame_from_stats."""
    def box(a):
        a = np.asarray(a, dtype=float).reshape(-1, 2)
        finite = np.isfinite(a).all(axis=1)
        return (a[finite].min(axis=0), a[finite].max(axis=0)) if finite.any() else (None, None)

    lonlat = np.asarray(lonlat, dtype=float).reshape(-1, 2)
    lat = lonlat[:, 1]
    lat = lat[np.isfinite(lat)]
    boxes = box(lonlat) + box(lonlat if original is None else original)
    if lat.size == 0:
        return (None, None, None) + boxes
    return (float(lat.min()), float(lat.max()), float(np.min(np.abs(lat)))) + boxes


def _frame_from_stats(stats, index=3):
    """(scale_x, scale_y, lo, hi): metres per degree of the conservative
    frame and the box (degrees) the curves stay in, from _frame_stats of
    every piece of the layer (index 5: the box of the input as given)."""
    lats = [s for s in stats if s[0] is not None]
    if not lats or (min(s[0] for s in lats) <= 0 <= max(s[1] for s in lats)):
        phi0 = 0.0
    else:
        phi0 = min(s[2] for s in lats)
    k = _R_MAX * math.pi / 180
    # The box: the globe's, grown to hold the input.
    lo, hi = np.array([-180.0, -90.0]), np.array([180.0, 90.0])
    for s in stats:
        if s[index] is not None:
            lo = np.minimum(lo, s[index])
            hi = np.maximum(hi, s[index + 1])
    return k * math.cos(math.radians(phi0)), k, lo, hi


def geographic_frame(lonlat):
    """(scale_x, scale_y) in metres per degree of the conservative frame for
    these longitudes and latitudes (see the module's doc)."""
    sx, sy, _, _ = _frame_from_stats([_frame_stats(lonlat)])
    return sx, sy


def _unwrap(xy, offsets, kinds):
    """Longitudes made continuous along each line or ring that crosses the
    antimeridian (a step of more than 180 degrees between neighbours is
    taken as the short way across +-180): returns the unwrapped (n, 2) array
    (the input when nothing crosses) and a flag per part. A ring whose
    steps add up to a turn round the pole is left as it is (it has no
    continuous longitude)."""
    n = len(xy)
    unwrapped = np.zeros(len(offsets) - 1, dtype=bool)
    if n < 2:
        return xy, unwrapped
    lon = xy[:, 0]
    with np.errstate(invalid="ignore"):
        step = np.diff(lon)
        jump = np.where(step > 180, -360.0, np.where(step < -180, 360.0, 0.0))
    part_of = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))
    jump[part_of[:-1] != part_of[1:]] = 0.0  # no step between parts
    if not jump.any():
        return xy, unwrapped
    shift = np.concatenate(([0.0], np.cumsum(jump)))
    starts = np.asarray(offsets[:-1], dtype=np.int64)
    nonempty = np.diff(offsets) > 0
    base = np.zeros(len(offsets) - 1)
    base[nonempty] = shift[starts[nonempty]]
    shift = shift - base[part_of]  # from each part's first vertex
    ends = np.asarray(offsets[1:], dtype=np.int64) - 1
    moved = np.zeros(len(offsets) - 1, dtype=bool)
    np.logical_or.at(moved, part_of, shift != 0)
    for p in np.flatnonzero(moved):
        if kinds[p] == 1:
            # The closing step, last vertex to first, unwrapped too: a ring
            # round a pole does not come back to its start.
            with np.errstate(invalid="ignore"):
                close = lon[starts[p]] - (lon[ends[p]] + shift[ends[p]])
            if not (abs(close) <= 180):
                shift[starts[p]:ends[p] + 1] = 0.0
                continue
        unwrapped[p] = True
    if not unwrapped.any():
        return xy, unwrapped
    out = xy.copy()
    out[:, 0] = lon + shift
    return out, unwrapped


def _restore_inputs(out_xy, frame_in, original):
    """Output vertices equal to a (framed) input vertex get the input's own
    coordinates back, bit for bit; the others are mapped back by the caller."""
    key_in = frame_in[:, 0] + 1j * frame_in[:, 1]
    order = np.argsort(key_in, kind="stable")
    sorted_keys = key_in[order]
    key_out = out_xy[:, 0] + 1j * out_xy[:, 1]
    pos = np.searchsorted(sorted_keys, key_out)
    pos = np.minimum(pos, len(sorted_keys) - 1) if len(sorted_keys) else pos
    hit = np.zeros(len(out_xy), dtype=bool)
    if len(sorted_keys):
        hit = sorted_keys[pos] == key_out
    return hit, order[pos]


class _Prepared:
    """A layer's flat arrays and, on a geographic CRS, its unwrapped
    longitudes (the frame itself is layer-wide: see _Frame)."""

    def __init__(self, geoms, geographic, has_z=None):
        self.geoms = geoms
        self.layer = _Layer(geoms)
        if has_z is not None:
            self.layer.has_z = has_z
        self.xy, self.z, self.offsets, self.kinds, self.features = self.layer.arrays()
        self.roles = np.asarray(self.layer.roles, dtype=np.uint8)
        self.geographic = geographic
        self.unwrapped = np.zeros(len(self.offsets) - 1, dtype=bool)
        self.lonlat = self.xy
        if geographic:
            self.lonlat, self.unwrapped = _unwrap(self.xy, self.offsets, self.kinds)

    def frame_stats(self):
        return _frame_stats(self.lonlat, self.xy)


class _Frame:
    """The layer's frame: identity on a projected CRS; on a geographic one
    the conservative equirectangular frame in metres and the box the curves
    stay in (see the module doc)."""

    def __init__(self, geographic, stats=()):
        self.geographic = geographic
        if geographic:
            # The curves stay in lo..hi (the globe's box grown to hold the
            # unwrapped input); the output is brought back into clip_lo..
            # clip_hi (grown to hold the input as given).
            self.sx, self.sy, self.lo, self.hi = _frame_from_stats(stats)
            _, _, self.clip_lo, self.clip_hi = _frame_from_stats(stats, 5)
            self.domain = (self.lo[0] * self.sx, self.lo[1] * self.sy, self.hi[0] * self.sx, self.hi[1] * self.sy)
        else:
            self.domain = None

    def forward(self, lonlat):
        if not self.geographic:
            return lonlat
        return np.column_stack((lonlat[:, 0] * self.sx, lonlat[:, 1] * self.sy))


def _run(series, *, alpha, tolerance, max_deviation, preserve, fit=None):
    geoms = list(series.values)
    crs = series.crs
    prep = _Prepared(geoms, crs is not None and crs.is_geographic)
    frame = _Frame(prep.geographic, [prep.frame_stats()])
    frame_xy = frame.forward(prep.lonlat)
    r = _crspline._geo_smooth(frame_xy, prep.z, prep.offsets, prep.kinds, prep.features, prep.layer.feature_count,
                              float(alpha), float(tolerance), None if max_deviation is None else float(max_deviation),
                              bool(preserve), frame.domain, part_roles=prep.roles,
                              fit=None if fit is None else float(fit))
    return _finish(prep, frame, frame_xy, r)


def _finish(prep, frame, frame_xy, r):
    """The geometries and measures from the core's result `r` (frame
    coordinates; the same keys as _crspline._geo_smooth returns)."""
    from shapely.geometry import LinearRing, LineString, MultiLineString, MultiPolygon, Polygon

    geoms, layer, xy, features = prep.geoms, prep.layer, prep.xy, prep.features
    out = r["xy"]
    offs = r["part_offsets"]
    if frame.geographic:
        back = np.column_stack((out[:, 0] / frame.sx, out[:, 1] / frame.sy))
        hit, idx = _restore_inputs(out, frame_xy, xy)
        lo, hi = frame.clip_lo, frame.clip_hi
        if frame.hi[0] > hi[0] or frame.lo[0] < lo[0]:
            # A part was unwrapped across the antimeridian, so curves may go
            # past +-180: they come back by a turn.
            lon = back[:, 0]
            back[:, 0] = np.where(lon > hi[0], lon - 360, np.where(lon < lo[0], lon + 360, lon))
        # The curves were kept inside the frame's box; the division may round
        # past it. (Input vertices come back as they were, even a longitude
        # of 180.00000000000006 as Natural Earth has.)
        np.clip(back[:, 0], lo[0], hi[0], out=back[:, 0])
        np.clip(back[:, 1], lo[1], hi[1], out=back[:, 1])
        back[hit] = xy[idx[hit]]
        out = back
    oz = r["extra"]
    statuses = _crspline._geo_statuses
    verdicts = _crspline._geo_verdicts
    status = []
    for i in range(layer.feature_count):
        s = statuses[r["status"][i]]
        msg = r["message"][i]
        if i in layer.unsupported:
            s, msg = "invalid", layer.unsupported[i]
        status.append(s if not msg or s == "empty" else f"{s}: {msg}")
    # Rebuild the geometries part by part (no loop over vertices).
    parts_of = {}
    for p, f in enumerate(features):
        parts_of.setdefault(int(f), []).append(p)

    def coords(p):
        a, b = offs[p], offs[p + 1]
        c = out[a:b]
        if layer.has_z:
            c = np.column_stack((c, oz[a:b, 0]))
        return c

    new = []
    for i, g in enumerate(geoms):
        recipe = layer.recipes[i]
        code = r["status"][i]
        if recipe is None or recipe[0] == "empty" or statuses[code] == "invalid":
            new.append(g)
            continue
        ps = parts_of.get(i, [])
        try:
            t = recipe[0]
            if t == "LineString":
                geom = LineString(coords(ps[0]))
            elif t == "LinearRing":
                geom = LinearRing(coords(ps[0]))
            elif t == "MultiLineString":
                geom = MultiLineString([coords(p) for p in ps])
            else:
                polys, k = [], 0
                for count in recipe[2]:
                    rings = [coords(p) for p in ps[k:k + count]]
                    polys.append(Polygon(rings[0], rings[1:]))
                    k += count
                geom = polys[0] if t == "Polygon" else MultiPolygon(polys)
        except ValueError as e:  # a degenerate ring Shapely will not build: keep the input
            geom = g
            if statuses[code] == "ok":
                status[i] = f"degenerate: {e}: passed through unchanged"
        new.append(geom)
    # length: of the output polylines the user holds, measured as GIS
    # measures them (geodesic on a geographic CRS, planar on a projected
    # one); curve_length: the core's arc length of the curves (in the frame's
    # metres on a geographic CRS: an upper bound, see the module doc).
    curve_length = np.array(r["length"], dtype=float)
    if frame.geographic:
        length = _geodesic_lengths(out, offs, features, layer.feature_count)
    else:
        length = _planar_lengths(out, offs, features, layer.feature_count)
    for i in range(layer.feature_count):
        if i in layer.unsupported or statuses[r["status"][i]] == "invalid":
            length[i] = curve_length[i] = 0.0  # passed through unmeasured (coordinates may be NaN)
    verdict = [verdicts[v] for v in r["verdict"]]
    cols = {"length": length, "curve_length": curve_length, "max_deviation": np.asarray(r["max_deviation"], dtype=float),
            "verdict": verdict, "status": status,
            "control_points": np.asarray(r["control_points"], dtype=np.int64)}
    return new, cols, r.get("stats", {})


def _feature_sums(seg, offsets, features, feature_count):
    """Per feature, the sum of the lengths `seg` of its output polylines'
    segments (segment k joins vertices k and k + 1; it belongs to a part
    when both do)."""
    lengths = np.zeros(feature_count)
    part_of_vertex = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))
    inside = part_of_vertex[:-1] == part_of_vertex[1:]
    seg = np.where(inside, seg, 0.0)
    feature_of_segment = np.asarray(features, dtype=np.int64)[part_of_vertex[:-1]]
    np.add.at(lengths, feature_of_segment, seg)
    return lengths


def _geodesic_lengths(lonlat, offsets, features, feature_count):
    """Geodesic length (metres, WGS 84) of each feature's output polylines,
    summed over its parts: one pyproj call for all segments."""
    from pyproj import Geod

    if len(lonlat) < 2:
        return np.zeros(feature_count)
    seg = np.asarray(Geod(ellps="WGS84").line_lengths(lonlat[:, 0], lonlat[:, 1]), dtype=float)
    return _feature_sums(seg, offsets, features, feature_count)


def _planar_lengths(xy, offsets, features, feature_count):
    """Planar length of each feature's output polylines (the CRS's units),
    summed over its parts."""
    if len(xy) < 2:
        return np.zeros(feature_count)
    return _feature_sums(np.hypot(np.diff(xy[:, 0]), np.diff(xy[:, 1])), offsets, features, feature_count)


def _units(crs):
    if crs is None:
        return "units of the coordinates (no CRS)"
    if crs.is_geographic:
        return "metre (geodesic on the ellipsoid; frame distances bound true ones)"
    try:
        return crs.axis_info[0].unit_name
    except (IndexError, AttributeError):
        return "units of the CRS"


def _check(alpha, tolerance, max_deviation, topology):
    if topology not in _TOPOLOGIES:
        raise ValueError(f"topology must be one of {', '.join(map(repr, _TOPOLOGIES))}, got {topology!r}")
    if tolerance is None:
        raise ValueError("tolerance is required (a distance in the layer's units, metres on a geographic CRS)")


def _frame(data, series, new_geoms, columns, names=_COLUMNS):
    import geopandas as gpd

    if data is None:
        out = gpd.GeoDataFrame({"geometry": gpd.GeoSeries(new_geoms, index=series.index, crs=series.crs)},
                               geometry="geometry", crs=series.crs)
        out.index = series.index
    else:
        for c in names:
            if c in data.columns:
                raise ValueError(f"the input already has a column named {c!r}; rename it first")
        out = data.copy()
        out[data.geometry.name] = gpd.GeoSeries(new_geoms, index=data.index, crs=series.crs)
    for name, values in columns.items():
        out[name] = values
    out.attrs["crspline_units"] = _units(series.crs)
    return out


def smooth(data, *, alpha=0.5, tolerance=None, max_deviation=None, topology="preserve"):
    """Smooth every line and ring of a GeoDataFrame or GeoSeries.

    alpha: the knot exponent (0.5 centripetal: no cusps or loops in a
    segment). tolerance: the output polylines are within it of the curves
    (required; in the layer's units, metres on a geographic CRS).
    max_deviation: if given, no curve point is farther than this from the
    input boundary. topology: "preserve" (shared boundaries smoothed once,
    no new crossings, proved) or "none" (each part alone, unchecked).
    Returns a GeoDataFrame with the same index, columns and CRS and the
    columns length, curve_length, max_deviation, verdict and status (see the
    module doc);
    `.attrs["crspline_units"]` names the unit.
    """
    _check(alpha, tolerance, max_deviation, topology)
    data, series = _as_geoseries(data)
    new, cols, stats = _run(series, alpha=alpha, tolerance=tolerance, max_deviation=max_deviation,
                            preserve=topology == "preserve")
    out = _frame(data, series, new, {c: cols[c] for c in _COLUMNS})
    out.attrs["crspline_stats"] = dict(stats)
    return out


def measure(data, *, alpha=0.5, tolerance=None):
    """Lengths and verdicts without smoothing: the geometry is unchanged;
    `length` is that of the Catmull-Rom curves' polylines through the
    vertices (each part alone, no tension; planar or geodesic as smooth()
    measures), `curve_length` the curves' arc length, `max_deviation` their
    proved distance from the input, `verdict`
    how the input features meet (shared boundaries, input crossings) and
    `status` as smooth() gives it."""
    _check(alpha, tolerance, None, "none")
    data, series = _as_geoseries(data)
    _, cols, _ = _run(series, alpha=alpha, tolerance=tolerance, max_deviation=None, preserve=False)
    _, topo, _ = _run(series, alpha=alpha, tolerance=tolerance, max_deviation=None, preserve=True)
    cols["verdict"] = topo["verdict"]
    return _frame(data, series, list(series.values), {c: cols[c] for c in _COLUMNS})


def fit(data, *, tolerance=None, alpha=0.5, topology="preserve"):
    """Fit every line and ring of a GeoDataFrame or GeoSeries with few
    control points (issue 40): each arc of the coverage (each shared border
    once, its junctions kept) becomes a Catmull-Rom curve through a subset of
    its vertices, proved within `tolerance` of the input both ways (every
    curve point near the input line, every input vertex near the curve),
    with the smoothing's proof on the fitted curves: no new crossings, no
    changed containment within or between features; where a proof fails,
    the vertices left out there come back. The geometry is the fitted
    curves' polylines (within tolerance / 10 of the curves). Columns:
    `control_points` (the vertices kept, all parts), `deviation` (the proved
    distance, <= tolerance), `length` (of the output, as smooth()),
    `verdict`, `status`. Units as smooth(): metres on a geographic CRS.
    topology: "preserve" (the default) or "none" (each part alone, fitted
    and proved within the tolerance, no crossing proof)."""
    _check(alpha, tolerance, None, topology)
    if not (isinstance(tolerance, (int, float, np.floating, np.integer)) and math.isfinite(tolerance) and tolerance > 0):
        raise ValueError(f"tolerance must be a positive finite distance, got {tolerance!r}")
    data, series = _as_geoseries(data)
    new, cols, stats = _run(series, alpha=alpha, tolerance=float(tolerance) / 10, max_deviation=None,
                            preserve=topology == "preserve", fit=float(tolerance))
    out = _frame(data, series, new, {c: (cols["max_deviation"] if c == "deviation" else cols[c])
                                     for c in _FIT_COLUMNS}, _FIT_COLUMNS)
    out.attrs["crspline_stats"] = dict(stats)
    return out
