"""The curve file (docs/spec.md): a curve's specification as JSON, read by
``from_spec`` / ``load`` and written by ``save``."""
from collections.abc import Mapping as _Mapping
import json as _json
import numbers as _numbers
import os as _os

import numpy as _np

from ._arguments import _as_points, _readonly, _real
from ._curve import CatmullRom
from ._kochanek_bartels import KochanekBartels


#: The fields of the curve file that crspline.load reads (docs/spec.md's table).
_FILE_FIELDS = ("points", "alpha", "grid", "closed", "start", "end", "tension", "kb", "strict")


def _file_end(e, which):
    """One end as the file gives it: a name (the core checks it) or a tangent list."""
    if isinstance(e, str):
        return e
    if isinstance(e, list):
        return e
    raise TypeError(f"'{which}' must be \"natural\", \"reflect\" or a tangent [dx/dt, ...], got {type(e).__name__}")


def _file_ends(spec):
    """The ends of a curve file in the core's form: ``'closed'``, one name
    for both ends, or a pair (start, end).

    The table's words (docs/spec.md): ``"closed": true|false``, ``"start":
    E``, ``"end": E``, E ``"natural"``, ``"reflect"`` or a tangent list; a
    missing end is natural. The older compact forms stay readable: ``"end":
    "closed"``, ``"end": {"start": E, "end": E}``, and a name in ``end``
    given without ``start`` and ``closed`` applies to both ends. Fields that
    contradict each other are a ValueError naming them."""
    closed = spec.get("closed")
    if "closed" in spec and not isinstance(closed, bool):
        raise TypeError(f"'closed' must be true or false, got {type(closed).__name__}")
    has_start, end = "start" in spec, spec.get("end")
    if isinstance(end, str) and end == "closed":  # compact: "end": "closed"
        if closed is False:
            raise ValueError("fields 'closed' and 'end' contradict: \"closed\": false, but \"end\": \"closed\"")
        if has_start:
            raise ValueError("fields 'start' and 'end' contradict: \"end\": \"closed\" makes a closed curve, "
                             "which has no start condition")
        return "closed"
    if isinstance(end, _Mapping):  # compact: "end": {"start": E, "end": E}
        for key in end:
            if key not in ("start", "end"):
                raise ValueError(f"unknown field '{key}' in 'end' (expected \"start\" and \"end\")")
        if closed:
            raise ValueError("fields 'closed' and 'end' contradict: a closed curve has no end conditions")
        if has_start:
            raise ValueError("fields 'start' and 'end' contradict: both give the start condition (\"start\": E, "
                             "and \"end\": {\"start\": E, ...}); write \"start\": E, \"end\": E")
        return (_file_end(end.get("start", "natural"), "end.start"), _file_end(end.get("end", "natural"), "end.end"))
    if closed:
        given = [key for key in ("start", "end") if key in spec]
        if given:
            names = ", ".join(f"'{key}'" for key in ["closed"] + given[:-1]) + f" and '{given[-1]}'"
            raise ValueError(f"fields {names} contradict: a closed curve has no end conditions")
        return "closed"
    if isinstance(end, str) and not has_start and "closed" not in spec:
        return end  # compact: one name for both ends (the core checks it)
    if end is not None and not isinstance(end, (str, list)):
        raise TypeError(f"'end' must be \"natural\", \"reflect\", a tangent [dx/dt, ...], \"closed\" or "
                        f"{{\"start\": ..., \"end\": ...}}, got {type(end).__name__}")
    return (_file_end(spec.get("start", "natural"), "start"), _file_end(spec.get("end", "natural"), "end"))


def _file_kb(values, which):
    if not isinstance(values, (list, tuple)):
        raise TypeError(f"'kb.{which}' must be a list of numbers, one per point, got {type(values).__name__}")
    out = []
    for i, v in enumerate(values):
        if v is None:
            out.append(float("nan"))  # allowed only where the core ignores it (open ends)
        elif isinstance(v, bool) or not isinstance(v, _numbers.Real):
            raise TypeError(f"'kb.{which}[{i}]' must be a number or null, got {type(v).__name__}")
        else:
            out.append(float(v))
    return out


def from_spec(spec):
    """The curve a curve-file dict describes (the form ``CatmullRom.spec()``
    returns and ``crspline.load`` reads; docs/spec.md): a ``CatmullRom``, or
    a ``KochanekBartels`` when it has ``kb``. Always float64.

    The fields are the specification table's (``closed``, ``start``,
    ``end``, ...); the older compact ``end`` forms are read too (see
    ``_file_ends``), and fields that contradict each other are a
    ``ValueError`` naming them. A field that is not part of the curve file
    raises ``ValueError`` naming it (``unknown field 'foo'``, the command
    line's words); ``tangents`` (a Hermite curve, which the command line
    reads) is refused by name. The values are checked by the core
    (``SpecError``)."""
    if not isinstance(spec, _Mapping):
        raise TypeError(f"a curve file holds a JSON object {{\"points\": ...}}, got {type(spec).__name__}")
    for key in spec:
        if key == "tangents":
            raise ValueError("field 'tangents' (a Hermite curve) is not supported by crspline.load; "
                             "crspline.splines.CubicHermite builds one from tangents")
        if key not in _FILE_FIELDS:
            raise ValueError(f"unknown field '{key}'")
    if "points" not in spec:
        raise ValueError("missing field 'points'")
    pts = _as_points(spec["points"]).astype(_np.float64)
    alpha = spec.get("alpha")
    if alpha is not None:
        alpha = _real(alpha, "alpha")
    grid = spec.get("grid")
    end = _file_ends(spec)
    tension = _real(spec.get("tension", 0.0), "tension")
    strict = spec.get("strict", False)
    if not isinstance(strict, bool):
        raise TypeError(f"'strict' must be true or false, got {type(strict).__name__}")
    kb = spec.get("kb")
    if kb is not None:
        if not isinstance(kb, _Mapping):
            raise TypeError(f"'kb' must be an object {{\"tension\": [...], \"continuity\": [...], \"bias\": [...]}}, "
                            f"got {type(kb).__name__}")
        for key in kb:
            if key not in ("tension", "continuity", "bias"):
                raise ValueError(f"unknown field '{key}' in 'kb' (expected \"tension\", \"continuity\", \"bias\")")
        values = tuple(_file_kb(kb[k], k) if k in kb else [] for k in ("tension", "continuity", "bias"))
        curve = KochanekBartels.__new__(KochanekBartels)
        curve._build(pts, alpha, grid, end, tension, values, strict)
        closed = curve.closed
        n = len(pts)
        rows = range(n) if closed else range(1, n - 1)
        curve._tcb = _readonly(_np.array([[v[i] if v else 0.0 for v in values] for i in rows],
                                         dtype=_np.float64).reshape(-1, 3))
        return curve
    curve = CatmullRom.__new__(CatmullRom)
    curve._build(pts, alpha, grid, end, tension, ([], [], []), strict)
    return curve


def load(path):
    """The curve in a curve file (JSON, docs/spec.md; what ``crspline save``
    and the command line's inputs hold): ``from_spec`` of its object."""
    with open(path, encoding="utf-8") as f:
        try:
            spec = _json.load(f)
        except _json.JSONDecodeError as e:
            raise ValueError(f"{path}: not JSON: {e}") from None
    return from_spec(spec)


def save(path, curve):
    """Writes the curve's specification (``curve.spec()``) to a curve file,
    as JSON that ``crspline.load`` and the command line read (numbers
    written to round-trip exactly). The file is replaced whole or not at
    all (written beside it, then renamed)."""
    if not isinstance(curve, CatmullRom):
        raise TypeError(f"save takes a crspline.CatmullRom or KochanekBartels, got {type(curve).__name__}")
    text = _json.dumps(curve.spec(), allow_nan=False)
    path = _os.fspath(path)
    tmp = f"{path}.tmp{_os.getpid()}"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text + "\n")
        _os.replace(tmp, path)
    except BaseException:
        if _os.path.exists(tmp):
            _os.remove(tmp)
        raise
