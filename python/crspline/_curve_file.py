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


#: The fields of the curve file that crspline.load reads (docs/spec.md).
_FILE_FIELDS = ("points", "alpha", "grid", "end", "tension", "kb", "strict")


def _file_end(e, which):
    if isinstance(e, str):
        return e
    if isinstance(e, list):
        return e
    raise TypeError(f"'{which}' must be \"natural\", \"reflect\" or a tangent [dx/dt, ...], got {type(e).__name__}")


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

    A field that is not part of the curve file raises ``ValueError`` naming it
    (``unknown field 'foo'``, the command line's words); ``tangents`` (a
    Hermite curve, which the command line reads) is refused by name. The
    values are checked by the core (``SpecError``)."""
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
    end = spec.get("end", "natural")
    if isinstance(end, _Mapping):
        for key in end:
            if key not in ("start", "end"):
                raise ValueError(f"unknown field '{key}' in 'end' (expected \"start\" and \"end\")")
        end = (_file_end(end.get("start", "natural"), "end.start"), _file_end(end.get("end", "natural"), "end.end"))
    elif not isinstance(end, str):
        raise TypeError(f"'end' must be \"natural\", \"reflect\", \"closed\" or {{\"start\": ..., \"end\": ...}}, "
                        f"got {type(end).__name__}")
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
