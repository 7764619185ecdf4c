"""Type stubs of the crspline package (the public API)."""
import os
from collections.abc import Mapping, Sequence
from typing import Any, Literal, TypedDict, Union

import numpy as np
import numpy.typing as npt

__version__: str
__all__: list[str]

uniform: float
centripetal: float
chordal: float
default_accuracy: float
max_dimension: int

class InvalidInput(ValueError):
    """Bad input: non-finite coordinates, too few points, bad alpha or grid, ... (a ValueError)."""

class SpecError(InvalidInput):
    """A curve specification the core rejects, with the core's words and its parts."""

    field: str
    index: Union[int, None]
    component: Union[int, None]
    value: str

class OutOfDomain(ValueError):
    """A parameter t or arc length s outside the curve's domain (a ValueError)."""

_Float = np.floating[Any]
_Array = npt.NDArray[_Float]
_ArrayLike = npt.ArrayLike
_Tangent = Union[float, Sequence[float], npt.NDArray[Any]]
_End = Union[Literal["natural", "reflect"], _Tangent]
_EndConditions = Union[
    Literal["natural", "closed", "reflect"],
    tuple[_End, _End],
    Sequence[_End],
    Mapping[str, _End],
    npt.NDArray[Any],
]

class ArcLengthSample(TypedDict):
    t: _Array
    s: _Array
    points: _Array

class Polyline(TypedDict):
    points: _Array
    t: _Array

class Nearest(TypedDict):
    t: Union[_Array, _Float]
    distance_sq: Union[_Array, _Float]
    segment: Union[npt.NDArray[np.int64], np.int64]
    point: _Array

class Frames(TypedDict):
    position: _Array
    tangent: _Array
    normal: _Array
    binormal: _Array

# The analysis report: docs/report.md (the same keys and values as
# `crspline analyze` prints; plain lists, not arrays).
_Pair = list[float]

class Intersection(TypedDict):
    segments: list[int]
    u: _Pair
    t: _Pair
    point: list[float]
    distance: float

class Overlap(TypedDict):
    segments: list[int]
    u: _Pair
    v: _Pair

class Intersections(TypedDict):
    intersections: list[Intersection]
    overlaps: list[Overlap]
    folds: list[int]
    complete: bool
    any: bool

class ChordProjection(TypedDict):
    bezier: _Pair
    theorem2: bool
    derivative_min: float
    derivative_min_u: float
    range: _Pair

class PaperBounds(TypedDict):
    d1: float
    d2: float
    d3: float
    theta1: float
    theta2: float
    h1: float
    h2: float
    eq6_one_sided: float
    eq6: float
    eq8_start: float
    eq8_end: float

class SegmentReport(TypedDict):
    index: int
    rank: int
    bezier: list[list[float]]
    zero_speed_u: list[float]
    cusp_u: list[float]
    cusp_t: list[float]
    self_intersection_u: list[_Pair]
    self_intersection_t: list[_Pair]
    fold: bool
    has_cusp: bool
    has_self_intersection: bool
    projection: Union[ChordProjection, None]
    bezier_height: _Pair
    bezier_bound: float
    max_chord_line_distance: float
    max_chord_line_distance_u: float
    max_chord_distance: float
    max_chord_distance_u: float
    overshoot: _Pair
    distance_bound: Union[float, None]
    bounds: Union[PaperBounds, None]

class Certificate(TypedDict):
    certified: bool
    failed_rule: Union[Literal["not_centripetal", "coincident_points", "adjacent_angle", "overlapping_boxes", "adjacent_pair"], None]
    detail: str
    vertex: Union[int, None]
    segment: Union[int, None]
    segments: Union[list[int], None]
    angle: Union[float, None]
    intersects: Union[bool, None]
    search: Union[Intersections, None]

class Analysis(TypedDict):
    dimension: int
    segments: list[SegmentReport]
    cusp_t: list[float]
    has_cusp: bool
    has_self_intersection: Union[bool, None]  # None: not searched, and no segment loops or folds
    intersections: Union[list[Intersection], None]
    overlaps: Union[list[Overlap], None]
    folds: Union[list[int], None]
    complete: Union[bool, None]
    certificate: Union[Certificate, None]

class CatmullRom:
    """A cubic Catmull-Rom curve. Default alpha = 0.5 (centripetal), NOT uniform as in `splines`."""

    def __init__(
        self,
        points: _ArrayLike,
        *,
        alpha: Union[float, None] = 0.5,
        grid: Union[_ArrayLike, None] = None,
        endconditions: _EndConditions = "natural",
        tension: float = 0.0,
        strict: bool = False,
    ) -> None: ...
    def spec(self) -> dict[str, Any]:
        """How the curve was built, in the curve file's form (docs/spec.md)."""
    @property
    def grid(self) -> _Array:
        """The knots (read-only)."""
    @property
    def points(self) -> _Array:
        """The control points, shape (N, dim) (read-only)."""
    @property
    def dim(self) -> int:
        """Dimension of the points."""
    @property
    def closed(self) -> bool:
        """True for a closed curve."""
    @property
    def dtype(self) -> np.dtype[Any]:
        """float32 or float64."""
    @property
    def segment_count(self) -> int:
        """Number of cubic segments."""
    @property
    def domain(self) -> tuple[float, float]:
        """(t_min, t_max)."""
    def evaluate(self, t: _ArrayLike, n: int = 0) -> _Array:
        """Position or n-th derivative at t; shape t.shape + (dim,)."""
    def __call__(self, t: _ArrayLike, n: int = 0) -> _Array:
        """Same as evaluate."""
    def evaluate_unchecked(self, t: _ArrayLike, n: int = 0) -> _Array:
        """Like evaluate, extrapolating outside the domain."""
    def to_bezier(self) -> _Array:
        """Bézier control points, shape (segment_count, 4, dim)."""
    def tangents(self) -> _Array:
        """dx/dt at both ends of every segment, shape (segment_count, 2, dim)."""
    def segment_index(self, t: _ArrayLike) -> Union[npt.NDArray[np.int64], np.int64]:
        """Segment owning each t."""
    def arc_length(
        self, t0: Union[float, None] = None, t1: Union[float, None] = None, *, accuracy: float = 1e-12
    ) -> float:
        """Arc length over [t0, t1] (default: the whole curve)."""
    def arc_length_at(self, t: _ArrayLike, *, accuracy: float = 1e-12) -> Union[_Array, _Float]:
        """Arc length from the start to t."""
    def t_at_arc_length(self, s: _ArrayLike, *, accuracy: float = 1e-12) -> Union[_Array, _Float]:
        """Parameter at arc length s."""
    def knot_arc_lengths(self, *, accuracy: float = 1e-12) -> _Array:
        """Cumulative arc length at every knot."""
    def sample(
        self, n: int, *, by: Literal["arc_length", "t"] = "arc_length", accuracy: float = 1e-12
    ) -> dict[str, _Array]:
        """n points evenly spaced in arc length ({'t', 's', 'points'}) or in t ({'t', 'points'})."""
    def tessellate(self, tolerance: Union[float, None] = None) -> Polyline:
        """Adaptive polyline within tolerance of the curve."""
    def bounding_box(self, *, tight: bool = True) -> _Array:
        """[lo, hi], shape (2, dim)."""
    def nearest(self, points: _ArrayLike) -> Nearest:
        """Nearest curve point to each query point."""
    def curvature(self, t: _ArrayLike) -> Union[_Array, _Float]:
        """Curvature at t."""
    def signed_curvature(self, t: _ArrayLike) -> Union[_Array, _Float]:
        """Signed curvature at t (2-D)."""
    def torsion(self, t: _ArrayLike) -> Union[_Array, _Float]:
        """Torsion at t (3-D)."""
    def frames(
        self,
        t: _ArrayLike,
        *,
        kind: Literal["rotation_minimizing", "frenet"] = "rotation_minimizing",
        initial_normal: Union[_ArrayLike, None] = None,
    ) -> Frames:
        """Moving frames at t."""
    def analyze(self, *, intersections: bool = True) -> Analysis:
        """Per-segment analysis and whole-curve intersections."""
    def intersections(self, tolerance: Union[float, None] = None) -> Intersections:
        """Every meeting of the curve with itself."""
    def certify_intersection_free(
        self,
        *,
        safe_angle: Union[float, None] = None,
        search_on_failure: bool = True,
        tolerance: Union[float, None] = None,
    ) -> Certificate:
        """Section 5's certificate that the curve does not intersect itself."""

class KochanekBartels(CatmullRom):
    """A Kochanek-Bartels (TCB) spline; alpha=None (default) is uniform, as in `splines`."""

    def __init__(
        self,
        vertices: _ArrayLike,
        grid: Union[_ArrayLike, None] = None,
        *,
        tcb: _ArrayLike = (0, 0, 0),
        alpha: Union[float, None] = None,
        endconditions: _EndConditions = "natural",
    ) -> None: ...
    @property
    def tcb(self) -> _Array:
        """The (tension, continuity, bias) triples, one per interior vertex (read-only)."""

def from_spec(spec: Mapping[str, Any]) -> CatmullRom:
    """The curve a curve-file dict describes (KochanekBartels when it has 'kb')."""

def load(path: Union[str, os.PathLike[str]]) -> CatmullRom:
    """The curve in a curve file (JSON, docs/spec.md)."""

def save(path: Union[str, os.PathLike[str]], curve: CatmullRom) -> None:
    """Writes curve.spec() to a curve file that load and the command line read."""

def arc_lengths(
    curves: Union[Sequence[_ArrayLike], npt.NDArray[Any]],
    *,
    alpha: Union[float, None] = 0.5,
    endconditions: _EndConditions = "natural",
    tension: float = 0.0,
    strict: bool = False,
    accuracy: float = 1e-12,
    workers: Union[int, None] = None,
) -> _Array:
    """Arc length of every curve, in one call on many threads (GIL released)."""

def tessellate_many(
    curves: Union[Sequence[_ArrayLike], npt.NDArray[Any]],
    tolerance: Union[float, None] = None,
    *,
    alpha: Union[float, None] = 0.5,
    endconditions: _EndConditions = "natural",
    tension: float = 0.0,
    strict: bool = False,
    workers: Union[int, None] = None,
) -> list[Polyline]:
    """Tessellation of every curve, in one call on many threads (GIL released)."""

# The decision (issue 27, crspline/_decision.py): the report's "decision"
# object (docs/report.md), and clearance.
Verdict = Literal["simple", "crosses", "touches"]

class ProvedCrossing(TypedDict):
    curves: list[int]
    segments: list[int]
    u: list[_Pair]  # [[lo, hi] in segments[0], [lo, hi] in segments[1]]
    point: list[float]

class Contact(TypedDict):
    curves: list[int]
    segments: list[int]
    u: _Pair
    distance: float
    budget_exhausted: bool

class DecidedPair(TypedDict):
    curves: list[int]
    segments: list[int]
    arguments: list[str]  # 'paper_rule', 'separation', 'joint', 'monotone', 'crossing', 'unresolved'

class Decision(TypedDict):
    verdict: Verdict
    fast_path: bool
    floor: float
    crossings: list[ProvedCrossing]
    touches: list[Contact]
    pairs: list[DecidedPair]

class Clearance(TypedDict):
    distance: float
    lower_bound: float
    curves: tuple[int, int]
    segments: tuple[int, int]
    u: tuple[float, float]
    points: _Array
    exhausted: bool

def decide(
    curve: CatmullRom, *, fast_path: bool = True, budget: Union[int, None] = None,
    pair_budget: Union[int, None] = None, record_pairs: bool = True,
) -> Decision:
    """Does the plane curve cross itself? (proved: docs/analysis.md)"""

def decide_pair(
    a: CatmullRom, b: CatmullRom, *, budget: Union[int, None] = None, pair_budget: Union[int, None] = None,
    record_pairs: bool = True,
) -> Decision:
    """Do two plane curves cross each other? (curve 0 is a, 1 is b)"""

def decide_set(
    curves: Sequence[CatmullRom], *, self: bool = False, budget: Union[int, None] = None,
    pair_budget: Union[int, None] = None, record_pairs: bool = True,
) -> Decision:
    """Do any two curves of the set cross? (self: each curve's own crossings too; GIL released)"""

def clearance(
    curve_or_a: CatmullRom, b: Union[CatmullRom, None] = None, *, accuracy: float = 0.0,
    budget: Union[int, None] = None,
) -> Clearance:
    """The least distance between non-adjacent segments of a curve, or between two curves (any dimension)."""

# crspline.fit (issue 40)
class FitResult:
    """What fit() returns: the curve and what was proved about it."""

    curve: CatmullRom
    deviation: float
    curve_to_input: float
    input_to_curve: float
    indices: Union[npt.NDArray[np.int64], None]
    count: int
    tensioned: int
    rounding_floor: float

def fit(
    points: _ArrayLike, *, tolerance: float, alpha: float = 0.5, closed: bool = False,
    mode: Literal["subset", "free"] = "subset", tension: float = 0.0,
    endconditions: Union[Literal["natural", "reflect"], tuple[str, str]] = "natural",
) -> FitResult:
    """A curve with few control points within a proved tolerance of the points, both ways (GIL released)."""

# crspline.sweep, crspline.stroke (issue 41)
class SweepReport(TypedDict):
    tolerance: float
    bound: float
    tolerance_met: bool
    proved: bool
    holonomy: float
    frame_drift: float
    length: float
    largest_radius: float
    clearance: float
    min_radius_of_curvature: float
    far_contact: bool
    local_fold: bool
    self_intersects: bool
    seam_gap: float
    seam_normal_gap: float

class SweepMesh(TypedDict):
    positions: _Array
    normals: _Array
    uvs: _Array
    indices: npt.NDArray[np.uint32]
    t: _Array
    s: _Array
    rings: int
    ring_size: int
    report: SweepReport

def sweep(
    curve: CatmullRom, *, radius: float = 1.0, profile: Union[_ArrayLike, CatmullRom, None] = None,
    profile_closed: bool = True, roll: Union[_ArrayLike, tuple[_ArrayLike, _ArrayLike], None] = None,
    up: Union[_ArrayLike, None] = None, scale: Union[tuple[_ArrayLike, _ArrayLike], None] = None,
    tolerance: Union[float, None] = None, tubular_segments: Union[int, None] = None,
    radial_segments: Union[int, None] = None, seamless: bool = True, clearance: bool = True,
) -> SweepMesh:
    """A cross-section swept along a 3-D curve: a mesh within the tolerance of the surface (GIL released)."""

def stroke(
    curve: CatmullRom, width: float, *, join: Literal["round", "miter", "bevel"] = "round",
    cap: Literal["butt", "round", "square"] = "butt", miter_limit: float = 4.0,
    tolerance: Union[float, None] = None, shapely: bool = False,
) -> Any:
    """The region within width / 2 of a 2-D curve: polygons as lists of rings, or a Shapely geometry."""
