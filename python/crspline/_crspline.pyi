"""Type stubs of the compiled module crspline._crspline (private: use crspline.CatmullRom)."""
from typing import Any, Union

import numpy as np
import numpy.typing as npt

__version__: str
max_dimension: int
default_accuracy: float
default_tessellation_tolerance: float
default_intersection_tolerance: float
safe_adjacent_angle: float

class InvalidInput(ValueError):
    """Bad input to a constructor or method (a ValueError)."""

class SpecError(InvalidInput):
    """A curve specification the core rejects (field, index, component, value)."""

    field: str
    index: Union[int, None]
    component: Union[int, None]
    value: str

class OutOfDomain(ValueError):
    """A parameter outside the curve's domain (a ValueError)."""

_A = npt.NDArray[Any]

_EndArg = Union[str, list[float]]

def _make_curve(
    points: _A,
    alpha: Union[float, None],
    grid: Union[list[float], None],
    ends: Union[str, tuple[_EndArg, _EndArg]],
    tension: float,
    kb_tension: list[float],
    kb_continuity: list[float],
    kb_bias: list[float],
    strict: bool,
) -> _Curve:
    """Build a curve from its specification, validated by the core."""

def _check_grid(grid: list[float]) -> None:
    """The core's check of a given grid's values (finite, strictly increasing)."""

def _make_hermite(
    points: _A,
    outgoing: _A,
    incoming: Union[_A, None],
    grid: list[float],
    closed: bool,
) -> _Curve: ...

class _ArcLengthTable:
    """Cumulative arc length of a curve, and its inverse."""

    @property
    def total(self) -> float:
        """Total length."""
    @property
    def accuracy(self) -> float:
        """Relative accuracy."""
    @property
    def knot_lengths(self) -> _A:
        """Cumulative length at every knot."""
    @property
    def segment_lengths(self) -> _A:
        """Length of every segment."""
    def t_at(self, s: _A) -> _A:
        """t at every arc length s."""
    def s_at(self, t: _A) -> _A:
        """Arc length at every t."""

class _Curve:
    """A Catmull-Rom curve of run-time dimension and scalar type."""

    def spec(self) -> dict[str, Any]:
        """The specification the curve was built from (crspline::to_spec)."""
    @property
    def dim(self) -> int:
        """Dimension."""
    @property
    def dtype(self) -> np.dtype[Any]:
        """float32 or float64."""
    @property
    def closed(self) -> bool:
        """Closed curve?"""
    @property
    def segment_count(self) -> int:
        """Number of segments."""
    @property
    def grid(self) -> _A:
        """The knots."""
    @property
    def points(self) -> _A:
        """The control points."""
    def evaluate(self, t: _A, order: int = 0) -> _A:
        """Checked evaluation (releases the GIL)."""
    def evaluate_unchecked(self, t: _A, order: int = 0) -> _A:
        """Unchecked evaluation (extrapolates)."""
    def bezier(self) -> _A:
        """Bézier control points."""
    def tangents(self) -> _A:
        """Segment end tangents."""
    def locate(self, t: _A) -> _A:
        """Owning segment of each t."""
    def arc_length(self, accuracy: float = ...) -> float:
        """Whole length."""
    def arc_length_between(self, t0: float, t1: float, accuracy: float = ...) -> float:
        """Length over [t0, t1]."""
    def arc_length_table(self, accuracy: float = ...) -> _ArcLengthTable:
        """The arc-length table."""
    def sample_arc_length(self, n: int, accuracy: float = ...) -> tuple[_A, _A, _A]:
        """(t, s, points) evenly spaced in arc length."""
    def tessellate(self, tolerance: Union[float, None] = None) -> tuple[_A, _A]:
        """(points, t) of the adaptive polyline."""
    def bounding_box(self, tight: bool = True) -> _A:
        """[lo, hi]."""
    def nearest(self, queries: _A) -> tuple[_A, _A, _A, _A]:
        """(t, distance_sq, segment, point)."""
    def curvature(self, t: _A) -> _A:
        """Curvature."""
    def signed_curvature(self, t: _A) -> _A:
        """Signed curvature (2-D)."""
    def torsion(self, t: _A) -> _A:
        """Torsion (3-D)."""
    def frames(self, t: _A, kind: str = "rotation_minimizing", initial_normal: Union[list[float], None] = None) -> tuple[_A, _A, _A, _A]:
        """(position, tangent, normal, binormal)."""
    def analyze(self, search: bool = True, tolerance: Union[float, None] = None, dimension: Union[int, None] = None) -> dict[str, Any]:
        """The analysis report (docs/report.md)."""
    def intersections(self, tolerance: Union[float, None] = None, dimension: Union[int, None] = None) -> dict[str, Any]:
        """Whole-curve self-intersections (the report's search object)."""
    def certify_intersection_free(self, safe_angle: float = ..., search_on_failure: bool = True, tolerance: Union[float, None] = None, dimension: Union[int, None] = None) -> dict[str, Any]:
        """Section 5's certificate."""

def _arc_lengths(
    curves: list[_A],
    alpha: Union[float, None],
    ends: Union[str, tuple[_EndArg, _EndArg]],
    tension: float,
    strict: bool,
    accuracy: float,
    workers: int,
) -> _A: ...
def _tessellate_many(
    curves: list[_A],
    alpha: Union[float, None],
    ends: Union[str, tuple[_EndArg, _EndArg]],
    tension: float,
    strict: bool,
    tolerance: Union[float, None],
    workers: int,
) -> list[tuple[_A, _A]]: ...
