"""crspline.geo on a Dask DataFrame whose geometry column holds WKB bytes.

``smooth(ddf, crs=..., tolerance=...)`` gives the rows that
``crspline.geo.smooth`` gives on the same layer in one process, byte for
byte (geometry as WKB out), with the same options and columns.

How the work is spread. No task holds the layer's vertices; each stage is
a set of tasks, and the stages meet by shuffles (every task of one stage
sends each task of the next the records whose key hashes to it, as Dask's
task-based shuffle does):

1. per partition: WKB decoded, parts cleaned (the core's step 1), and, on a
   geographic CRS, lines across the antimeridian unwrapped; a few numbers
   per partition (latitudes, boxes, the largest coordinate) make the
   layer-wide frame and rounding slack, as the single-process path has them;
2. shuffle by vertex (its exact coordinates): a vertex is a junction when
   its distinct neighbours over all partitions are not exactly two, or it
   ends a line; its first occurrence in layer order is kept, so the arcs'
   direction is the one the single-process path picks;
3. per partition: parts cut into arcs at the junctions, each arc keyed by
   its vertex sequence in canonical direction; shuffle by arc key, so the
   copies of a boundary shared by features in different partitions meet in
   one task and the arc is smoothed once;
4. the crossing proof pairs segments of different arcs, so arcs that may
   meet must be smoothed together. Each distinct arc's box holds its curve
   at every tension level (the box of its untensioned Bezier points:
   tension only pulls the inner points towards the segment's ends), and the
   core's proof looks at two segments only where the boxes of their Bezier
   points come within the rounding slack. Boxes padded by tolerance + 3
   slack link the arcs whose boxes overlap, and each connected group is
   smoothed in one task by the core's own rounds (detail::proof: tension
   raised where a pair is not proved). A pair of segments in two groups is
   never looked at by the single-process proof either, at any tension: the
   proof is complete, and every arc ends with the tension and the numbers
   the single-process run gives it. Only the boxes (four numbers per arc)
   meet in one task, to find the groups;
5. shuffle back: each partition gets the smoothed arcs its parts use, and
   rebuilds its rings and measures as crspline.geo.smooth does.

Groups go to the smoothing tasks largest first, each to the least loaded
task (by vertices), so no task holds more than the average plus the
largest group. What this does not spread: a group is one task, and in a
coverage (every country touching its neighbours) the touching features
form one group, so step 4 for Natural Earth's Eurasia and Africa is one
task (docs/geo.md says why cutting a group needs rounds across tasks).
Separate lines and islands spread over the workers.

``fit(ddf, crs=..., tolerance=...)`` (issue 40) is crspline.geo.fit's path
through the same stages: each distinct arc fitted in its group's task (the
fit of an arc depends on the arc alone), with boxes that hold every hull a
fitted arc can have (its input box grown by its diagonal, as the core's
proof takes them), so the rows are crspline.geo.fit's, byte for byte.
Stages 1-3 are in ``_dask_arcs.py``.

``write_partitions(result, directory, crs=...)`` writes one file per
partition (GeoJSON by default; any fiona driver), each by a task on a worker.
"""
from __future__ import annotations

import os

import numpy as np

from ._dask_arcs import (  # stages 1-3
    _prepare,
    _layer_info,
    _vertex_keys,
    _clean,
    _junctions,
    _cut,
    _arc_split,
    _distinct_arcs,
    _flat,
)

__all__ = ["smooth", "fit", "write_partitions", "arc_counts"]

_OUT_COLUMNS = ("length", "curve_length", "max_deviation", "verdict", "status")
_FIT_COLUMNS = ("length", "control_points", "deviation", "verdict", "status")


def _verdict(name):
    """The core's code of a verdict (crspline/geo/smooth.hpp's enum)."""
    from .. import _crspline

    return _crspline._geo_verdicts.index(name)


# --- 4. groups of arcs that may meet --------------------------------------------

def _slack(cleaned, tolerance):
    """geo::smooth's rounding slack: 64 eps times the layer's largest
    coordinate (or the tolerance, if larger)."""
    scale = max([c["scale"] for c in cleaned] + [0.0])
    return 64 * np.finfo(float).eps * max(scale, float(tolerance))


def _box_summary(d):
    """What step 4's one task needs of a bucket of distinct arcs: their
    boxes and vertex counts (not the arcs)."""
    return {"boxes": d["boxes"], "sizes": np.asarray([len(d["arcs"][k]["xy"]) for k in d["keys"]], dtype=np.int64)}


def _groups(slack, tolerance, buckets, *distinct):
    """Arcs linked when their boxes, padded by the largest flatness margin
    a piece may have, overlap; per distinct-arc bucket, the group task of
    each arc (groups spread over `buckets` tasks) and its group."""
    # The core's proof looks at two segments only where the boxes of their
    # Bezier points come within the slack; those points are inside the
    # arcs' boxes up to rounding (far below the slack). The tolerance is
    # added as a margin in case a proof ever looks farther (by its pieces'
    # flatness margins, at most the tolerance plus the slack).
    pad = float(tolerance) + 3 * slack
    boxes = np.concatenate([d["boxes"] for d in distinct]) if distinct else np.zeros((0, 4))
    n = len(boxes)
    lo = boxes[:, :2] - pad
    hi = boxes[:, 2:] + pad
    parent = np.arange(n)

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    # A sweep along x: box k (in order of low x) meets the boxes after it
    # that start before it ends and overlap it in y.
    order = np.argsort(lo[:, 0], kind="stable")
    lo_s, hi_s = lo[order], hi[order]
    ends = np.searchsorted(lo_s[:, 0], hi_s[:, 0], side="right")
    for k in range(n):
        cand = np.arange(k + 1, max(k + 1, ends[k]))
        cand = cand[(lo_s[cand, 1] <= hi_s[k, 1]) & (hi_s[cand, 1] >= lo_s[k, 1])]
        ri = root(order[k])
        for j in order[cand]:
            rj = root(j)
            if rj != ri:
                parent[max(ri, rj)] = min(ri, rj)
                ri = min(ri, rj)
    group = np.array([root(i) for i in range(n)], dtype=np.int64)
    # Groups to tasks by their work (vertices), largest first, each to the
    # least loaded task (ties: the lowest index): no task holds more than
    # the average load plus the largest group, and the largest group shares
    # its task only with groups that fit under the others' loads. Where a
    # group goes changes nothing in its result (each group is smoothed by
    # its own call of the core), only the balance.
    weight = np.concatenate([d["sizes"] for d in distinct] + [np.zeros(0)]).astype(np.int64)
    ids, inverse = np.unique(group, return_inverse=True)
    group_weight = np.bincount(inverse, weights=weight, minlength=len(ids)).astype(np.int64)
    group_arcs = np.bincount(inverse, minlength=len(ids)).astype(np.int64)
    load = [0] * buckets
    task_of = np.zeros(len(ids), dtype=np.int64)
    for gi in sorted(range(len(ids)), key=lambda i: (-group_weight[i], ids[i])):
        t = min(range(buckets), key=lambda j: (load[j], j))
        task_of[gi] = t
        load[t] += int(group_weight[gi])
    task = task_of[inverse] if n else np.zeros(0, dtype=np.int64)
    out, k = [], 0
    for d in distinct:
        m = len(d["boxes"])
        out.append({"group": group[k:k + m], "task": task[k:k + m]})
        k += m
    largest = int(np.argmax(group_weight)) if len(ids) else 0
    return {"assign": out, "groups": int(len(ids)), "task_vertices": load,
            "largest_group": {"arcs": int(group_arcs[largest]) if len(ids) else 0,
                              "vertices": int(group_weight[largest]) if len(ids) else 0}}


def _to_group_task(d, groups, d_index, task):
    a = groups["assign"][d_index]
    sel = np.flatnonzero(a["task"] == task)
    return [(int(a["group"][i]), d["keys"][i], d["arcs"][d["keys"][i]]) for i in sel]


def _smooth_groups(options, frame_domain, slack, groups, partitions, *pieces):
    """Each group of arcs smoothed by the core's rounds; per partition, the
    smoothed arcs its parts use."""
    from .. import _crspline

    by_group = {}
    for piece in pieces:
        for g, key, arc in piece:
            by_group.setdefault(g, []).append((key, arc))
    answers = [dict() for _ in range(partitions)]
    max_dev = options["max_deviation"]
    for g, members in by_group.items():
        # The core's arc order: first occurrence in layer order.
        members.sort(key=lambda m: m[1]["order"])
        arcs = [m[1] for m in members]
        xy, offs, closed = _flat(arcs)
        r = _crspline._geo_smooth_arcs(xy, offs, closed, float(options["alpha"]), float(options["tolerance"]),
                                       None if max_dev is None else float(max_dev), True, frame_domain, slack,
                                       fit=options.get("fit"))
        # Verdicts: an arc touches when several features use it or one of
        # its ends (a junction) is shared by several features' arcs: all
        # arcs ending at a vertex are in its group (their boxes meet there).
        at_end = {}
        for (key, arc) in members:
            if not arc["closed"]:
                for v in (arc["xy"][0], arc["xy"][-1]):
                    at_end.setdefault(_vertex_keys(v.reshape(1, 2)).tobytes(), set()).update(arc["features"])
        lo = r["offsets"]
        for i, (key, arc) in enumerate(members):
            touches = len(arc["features"]) > 1
            if not arc["closed"]:
                for v in (arc["xy"][0], arc["xy"][-1]):
                    touches = touches or len(at_end[_vertex_keys(v.reshape(1, 2)).tobytes()]) > 1
            crossing = int(r["crossing"][i])
            verdict = _verdict("crosses") if crossing == 2 else (
                _verdict("touches") if touches or crossing == 1 else _verdict("simple"))
            a, b = lo[i], lo[i + 1]
            result = {"xy": r["xy"][a:b], "vseg": r["vseg"][a:b], "vnext": r["vnext"][a:b], "vu": r["vu"][a:b],
                      "control_points": int(r["control_points"][i]),
                      "length": float(r["length"][i]), "max_deviation": float(r["max_deviation"][i]),
                      "verdict": verdict, "extra": arc["extra"], "n": len(arc["xy"]), "closed": arc["closed"]}
            for p in arc["partitions"]:
                answers[p][key] = result
    return answers


# --- 5. back to the partitions ------------------------------------------------

def _assemble_parts(b, arc_of, part_arcs):
    """The core's output layer (frame coordinates) for one partition, from
    the smoothed arcs of its clean parts: as geo::smooth's step 4 emits it."""
    prep, c, frame_xy = b["prep"], b["clean"], b["frame_xy"]
    E = 1 if prep.layer.has_z else 0
    nparts = len(prep.offsets) - 1
    clean_of = np.full(nparts, -1, dtype=np.int64)
    clean_of[c["parts"]] = np.arange(len(c["parts"]))
    nf = prep.layer.feature_count
    length = np.zeros(nf)
    dev = np.zeros(nf)
    verdict = np.zeros(nf, dtype=np.uint8)
    control = np.zeros(nf, dtype=np.int64)
    out_xy, out_z, offsets = [], [], [0]
    for p in range(nparts):
        s, e = int(prep.offsets[p]), int(prep.offsets[p + 1])
        q = clean_of[p]
        if q < 0:
            control[int(prep.features[p])] += e - s  # passed through
            out_xy.append(frame_xy[s:e])
            out_z.append(prep.z[s:e])
            offsets.append(offsets[-1] + (e - s))
            continue
        f = int(prep.features[p])
        chunks, zchunks = [], []
        if not c["rings"][q]:
            control[f] += 1  # a line's last point (as geo::smooth counts)
        for j, (key, reversed_) in enumerate(part_arcs[q]):
            a = arc_of[key]
            control[f] += a["control_points"] - (0 if a["closed"] else 1)
            length[f] += a["length"]
            dev[f] = max(dev[f], a["max_deviation"])
            verdict[f] = max(verdict[f], a["verdict"])
            idx = np.arange(len(a["xy"]))
            if reversed_:
                idx = idx[::-1]
            if j > 0:
                idx = idx[1:]  # the junction, already out
            chunks.append(a["xy"][idx])
            if E:
                seg = a["vseg"][idx]
                nxt = a["vnext"][idx]
                e0, e1 = a["extra"][seg, 0], a["extra"][nxt, 0]
                u = a["vu"][idx]
                zchunks.append(np.where(u == 0, e0, np.where(u == 1, e1, e0 + u * (e1 - e0))).reshape(-1, 1))
        part = np.concatenate(chunks)
        zpart = np.concatenate(zchunks) if E else np.zeros((len(part), 0))
        if c["rings"][q] and not (part[0, 0] == part[-1, 0] and part[0, 1] == part[-1, 1]):
            part = np.vstack((part, part[:1]))
            zpart = np.vstack((zpart, zpart[:1]))
        out_xy.append(part)
        out_z.append(zpart)
        offsets.append(offsets[-1] + len(part))
    # Invalid nesting of the input's rings (found by _geo_clean, as
    # geo::smooth finds it): the verdict says it, the message which parts.
    message = list(c["message"])
    for f, words in enumerate(c["nesting"]):
        if words:
            verdict[f] = max(verdict[f], _verdict("nested"))
            message[f] = words
    return {"xy": np.concatenate(out_xy) if out_xy else np.zeros((0, 2)),
            "extra": np.concatenate(out_z) if out_z else np.zeros((0, E)),
            "part_offsets": np.asarray(offsets, dtype=np.int64), "status": c["status"],
            "message": message, "verdict": verdict, "length": length, "max_deviation": dev,
            "control_points": control}


def _finish_partition(df, b, info, geometry, r, options):
    from . import _finish

    new, cols, _ = _finish(b["prep"], info["frame"], b["frame_xy"], r)
    cols["deviation"] = cols["max_deviation"]
    out = df.copy()
    out[geometry] = [None if g is None else g.wkb for g in new]
    for c in (_FIT_COLUMNS if options.get("fit") is not None else _OUT_COLUMNS):
        out[c] = cols[c]
    return out


def _assemble(df, b, cut, info, geometry, options, *answers):
    arc_of = {}
    for a in answers:
        arc_of.update(a)
    return _finish_partition(df, b, info, geometry, _assemble_parts(b, arc_of, cut["parts"]), options)


def _assemble_alone(df, b, info, geometry, options, slack):
    """topology="none": each part is its own arc, smoothed alone (no proof),
    with the layer's slack: no shuffle needed."""
    from .. import _crspline

    c = b["clean"]
    pts = b["frame_xy"][c["vertices"]]
    offs = np.asarray(c["offsets"], dtype=np.int64)
    closed = np.asarray(c["rings"], dtype=np.uint8)
    max_dev = options["max_deviation"]
    r = _crspline._geo_smooth_arcs(pts, offs, closed, float(options["alpha"]), float(options["tolerance"]),
                                   None if max_dev is None else float(max_dev), False, info["frame"].domain, slack,
                                   fit=options.get("fit"))
    prep = b["prep"]
    extra = prep.z[c["vertices"]] if prep.layer.has_z else None
    arc_of, parts = {}, []
    for q in range(len(offs) - 1):
        a, e = r["offsets"][q], r["offsets"][q + 1]
        arc_of[q] = {"xy": r["xy"][a:e], "vseg": r["vseg"][a:e], "vnext": r["vnext"][a:e], "vu": r["vu"][a:e],
                     "control_points": int(r["control_points"][q]), "length": float(r["length"][q]),
                     "max_deviation": float(r["max_deviation"][q]), "verdict": 0,
                     "extra": None if extra is None else extra[offs[q]:offs[q + 1]],
                     "n": int(offs[q + 1] - offs[q]), "closed": bool(closed[q])}
        parts.append([(q, False)])
    return _finish_partition(df, b, info, geometry, _assemble_parts(b, arc_of, parts), options)


def _check_frame(ddf, geometry, alpha, tolerance, max_deviation, topology, names=_OUT_COLUMNS):
    from . import _check

    for c in names:
        if c in ddf.columns:
            raise ValueError(f"the input already has a column named {c!r}; rename it first")
    if geometry not in ddf.columns:
        raise ValueError(f"no geometry column {geometry!r} in the Dask DataFrame (columns: {list(ddf.columns)})")
    _check(alpha, tolerance, max_deviation, topology)


def _stages(ddf, *, crs, geometry, alpha, tolerance, max_deviation, topology, buckets, fit=None):
    """The task graph, stage by stage (lazy Dask objects): "outs" (one
    pandas frame per partition) and, with topology "preserve", "distinct"
    (the distinct arcs per bucket) and "groups"."""
    import dask
    import pyproj

    geographic = crs is not None and pyproj.CRS.from_user_input(crs).is_geographic
    preserve = topology == "preserve"
    options = dict(alpha=alpha, tolerance=tolerance, max_deviation=max_deviation, fit=fit)
    delayed = dask.delayed
    frames = ddf.to_delayed()
    P = len(frames)
    B = int(buckets or P)
    if B < 1:
        raise ValueError(f"buckets must be at least 1, got {B}")
    # 1. Per partition, and the layer-wide numbers.
    prepared = [delayed(_prepare)(f, geometry, geographic) for f in frames]
    info = delayed(_layer_info)(prepared, geographic)
    cleaned = [delayed(_clean)(a, info, i, B, preserve) for i, a in enumerate(prepared)]
    slack = delayed(_slack)(cleaned, tolerance)
    if not preserve:
        return {"outs": [delayed(_assemble_alone)(f, c, info, geometry, options, slack)
                         for f, c in zip(frames, cleaned)]}
    # 2. Junctions, shuffled by vertex.
    junctions = [delayed(_junctions, nout=P)(*[c["vbuckets"][j] for c in cleaned]) for j in range(B)]
    # 3. Arcs, shuffled by arc key.
    cuts = [delayed(_cut)(c, info, B, *[junctions[j][i] for j in range(B)]) for i, c in enumerate(cleaned)]
    distinct = [delayed(_distinct_arcs)((alpha, fit), *[delayed(_arc_split)(cut, j) for cut in cuts])
                for j in range(B)]
    # 4. Groups of arcs that may meet (boxes only in one task), smoothed.
    groups = delayed(_groups)(slack, tolerance, B, *[delayed(_box_summary)(d) for d in distinct])
    domain = info["frame"].domain
    smoothed = [delayed(_smooth_groups, nout=P)(options, domain, slack, groups, P,
                                                *[delayed(_to_group_task)(d, groups, j, t)
                                                  for j, d in enumerate(distinct)])
                for t in range(B)]
    # 5. Back to the partitions.
    outs = [delayed(_assemble)(f, c, cut, info, geometry, options, *[smoothed[t][i] for t in range(B)])
            for i, (f, c, cut) in enumerate(zip(frames, cleaned, cuts))]
    return {"outs": outs, "distinct": distinct, "groups": groups}


def smooth(ddf, *, crs, geometry="geometry", alpha=0.5, tolerance=None, max_deviation=None, topology="preserve",
           buckets=None):
    """Smooth a Dask DataFrame's WKB geometry column (see crspline.geo.smooth
    for the options and columns). `crs`: the layer's CRS (anything pyproj
    takes). `buckets`: how many tasks each shuffle stage has (default: the
    number of partitions). Returns a lazy Dask DataFrame with the same
    partitions, index and columns, the geometry smoothed (WKB) and the four
    measure columns."""
    import dask.dataframe as dd
    import pandas as pd

    _check_frame(ddf, geometry, alpha, tolerance, max_deviation, topology)
    st = _stages(ddf, crs=crs, geometry=geometry, alpha=alpha, tolerance=tolerance, max_deviation=max_deviation,
                 topology=topology, buckets=buckets)
    meta = ddf._meta.copy()
    for c, dtype in zip(_OUT_COLUMNS, ("f8", "f8", "f8", "object", "object")):
        meta[c] = pd.Series([], dtype=dtype)
    return dd.from_delayed(st["outs"], meta=meta, divisions=ddf.divisions)


def fit(ddf, *, crs, geometry="geometry", alpha=0.5, tolerance=None, topology="preserve", buckets=None):
    """Fit a Dask DataFrame's WKB geometry column with few control points
    (see crspline.geo.fit for what is proved and the columns); the rows are
    crspline.geo.fit's on the same layer, byte for byte. Returns a lazy Dask
    DataFrame: the geometry (WKB) and the columns length, control_points,
    deviation, verdict and status."""
    import dask.dataframe as dd
    import pandas as pd

    _check_frame(ddf, geometry, alpha, tolerance, None, topology, _FIT_COLUMNS)
    if not (isinstance(tolerance, (int, float, np.floating, np.integer)) and np.isfinite(tolerance) and tolerance > 0):
        raise ValueError(f"tolerance must be a positive finite distance, got {tolerance!r}")
    st = _stages(ddf, crs=crs, geometry=geometry, alpha=alpha, tolerance=float(tolerance) / 10, max_deviation=None,
                 topology=topology, buckets=buckets, fit=float(tolerance))
    meta = ddf._meta.copy()
    for c, dtype in zip(_FIT_COLUMNS, ("f8", "i8", "f8", "object", "object")):
        meta[c] = pd.Series([], dtype=dtype)
    return dd.from_delayed(st["outs"], meta=meta, divisions=ddf.divisions)


def arc_counts(ddf, *, crs, geometry="geometry", alpha=0.5, tolerance=None, buckets=None):
    """What the arc stages of smooth() (topology "preserve") see, computed:
    {"arcs": distinct arcs (each smoothed once), "arcs_per_bucket": [...],
    "groups": groups of arcs that may meet (each smoothed in one task),
    "task_vertices": the arc vertices each smoothing task holds (groups
    placed largest first on the least loaded task), "largest_group":
    {"arcs", "vertices"}}."""
    import dask

    _check_frame(ddf, geometry, alpha, tolerance, None, "preserve")
    st = _stages(ddf, crs=crs, geometry=geometry, alpha=alpha, tolerance=tolerance, max_deviation=None,
                 topology="preserve", buckets=buckets)
    distinct, groups = dask.compute(st["distinct"], st["groups"])
    per = [len(d["keys"]) for d in distinct]
    return {"arcs": sum(per), "arcs_per_bucket": per, "groups": groups["groups"],
            "task_vertices": groups["task_vertices"], "largest_group": groups["largest_group"]}


def _write(df, path, crs, geometry, driver):
    import geopandas as gpd
    from shapely import wkb

    geoms = [None if b is None else wkb.loads(bytes(b)) for b in df[geometry]]
    gdf = gpd.GeoDataFrame(df.drop(columns=[geometry]), geometry=gpd.GeoSeries(geoms, index=df.index, crs=crs),
                           crs=crs)
    gdf.to_file(path, driver=driver)
    return path


def write_partitions(ddf, directory, *, crs, geometry="geometry", driver="GeoJSON", extension=None):
    """Write one file per partition (part-00000.geojson, ...) into
    `directory`, each by a task on a worker; returns the paths."""
    import dask

    ext = extension or {"GeoJSON": "geojson", "GPKG": "gpkg", "ESRI Shapefile": "shp"}.get(driver, "dat")
    os.makedirs(directory, exist_ok=True)
    tasks = [dask.delayed(_write)(p, os.path.join(directory, f"part-{i:05d}.{ext}"), crs, geometry, driver)
             for i, p in enumerate(ddf.to_delayed())]
    return list(dask.compute(*tasks))
