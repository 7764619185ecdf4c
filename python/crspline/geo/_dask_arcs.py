"""crspline.geo.dask's first three stages (see crspline.geo.dask's docstring):
per partition, the parts decoded and cleaned; shuffled by vertex, the
junctions; per partition, the parts cut into arcs, shuffled by arc key into
the distinct arcs with their boxes. Functions run as Dask tasks."""
from __future__ import annotations

import copy
import zlib

import numpy as np

_POS_BITS = 40  # a vertex's place in layer order: partition << 40 | index in the partition


# --- 1. per partition --------------------------------------------------------

def _decode(df, geometry):
    """A partition's WKB column as Shapely geometries (None stays None)."""
    from shapely import wkb

    return [None if b is None else wkb.loads(bytes(b)) for b in df[geometry]]


def _prepare(df, geometry, geographic):
    from . import _Prepared

    prep = _Prepared(_decode(df, geometry), geographic)
    return {"prep": prep, "stats": prep.frame_stats() if geographic else None, "has_z": prep.layer.has_z,
            "features": prep.layer.feature_count}


def _layer_info(prepared, geographic):
    """Layer-wide numbers: the frame, Z or not, each partition's first
    feature (in layer order)."""
    from . import _Frame

    frame = _Frame(geographic, [p["stats"] for p in prepared])
    first = np.concatenate(([0], np.cumsum([p["features"] for p in prepared])))
    return {"frame": frame, "has_z": any(p["has_z"] for p in prepared), "first_feature": first}


def _vertex_keys(xy):
    """Exact coordinates as integer keys (-0 is 0), one row per vertex."""
    a = np.where(xy == 0, 0.0, xy)
    return np.ascontiguousarray(a).view(np.int64).reshape(-1, 2)


def _bucket_of_keys(keys, buckets):
    h = (keys[:, 0].astype(np.uint64) * np.uint64(0x9E3779B97F4A7C15)) ^ keys[:, 1].astype(np.uint64)
    h ^= h >> np.uint64(29)
    return (h % np.uint64(buckets)).astype(np.int64)


def _clean(a, info, index, buckets, preserve):
    """Frame coordinates, the core's cleaning, and the vertex records for
    the junction shuffle (bucketed by vertex key)."""
    from .. import _crspline

    prep = a["prep"]
    if info["has_z"] and not prep.layer.has_z:
        # Z somewhere in the layer: every part gets it (0 where it had none).
        prep = copy.copy(prep)
        prep.layer = copy.copy(prep.layer)
        prep.layer.has_z = True
        prep.z = np.zeros((len(prep.xy), 1))
    frame = info["frame"]
    frame_xy = frame.forward(prep.lonlat)
    c = _crspline._geo_clean(frame_xy, prep.offsets, prep.kinds, prep.features, prep.layer.feature_count,
                             part_roles=prep.roles)
    verts = c["vertices"]
    pts = frame_xy[verts]
    scale = float(np.max(np.abs(pts))) if len(pts) else 0.0
    out = {"prep": prep, "frame_xy": frame_xy, "clean": c, "scale": scale, "index": index}
    if not preserve:
        return out
    keys = _vertex_keys(pts)
    offs = c["offsets"]
    n = len(verts)
    ring = c["rings"].astype(bool)
    # Each vertex's neighbours along its part (both ways; a ring closes).
    nxt = np.arange(1, n + 1)
    prv = np.arange(-1, n - 1)
    starts, ends = offs[:-1], offs[1:] - 1
    nxt[ends] = np.where(ring, starts, -1)
    prv[starts] = np.where(ring, ends, -1)
    line_end = np.zeros(n, dtype=bool)
    line_end[starts[~ring]] = True
    line_end[ends[~ring]] = True
    pos = (np.int64(index) << _POS_BITS) + np.arange(n, dtype=np.int64)
    rec_v, rec_n = [], []
    for nb in (nxt, prv):
        has = nb >= 0
        rec_v.append(np.flatnonzero(has))
        rec_n.append(nb[has])
    v = np.concatenate(rec_v)
    nbr = np.concatenate(rec_n)
    b_vertex = _bucket_of_keys(keys, buckets)
    # Per bucket: every vertex once (key, place, line end) and its edges.
    out["keys"] = keys
    out["vbuckets"] = []
    for b in range(buckets):
        mine = np.flatnonzero(b_vertex == b)
        edges = v[b_vertex[v] == b]
        nbs = nbr[b_vertex[v] == b]
        out["vbuckets"].append({"vertex": mine, "key": keys[mine], "pos": pos[mine], "line_end": line_end[mine],
                                "edge_key": keys[edges], "edge_nbr": keys[nbs]})
    return out


# --- 2. junctions, by vertex ---------------------------------------------------

def _junctions(*records):
    """One bucket of vertices from every partition: junction flag and first
    place in layer order per vertex key, answered to each partition for the
    vertices it sent."""
    keys = np.concatenate([r["key"] for r in records]).reshape(-1, 2)
    uniq, inv = np.unique(keys, axis=0, return_inverse=True)
    inv = inv.reshape(-1)
    first = np.full(len(uniq), np.iinfo(np.int64).max, dtype=np.int64)
    np.minimum.at(first, inv, np.concatenate([r["pos"] for r in records]))
    junction = np.zeros(len(uniq), dtype=bool)
    np.logical_or.at(junction, inv, np.concatenate([r["line_end"] for r in records]))
    # Distinct neighbours per vertex.
    ek = np.concatenate([r["edge_key"] for r in records]).reshape(-1, 2)
    en = np.concatenate([r["edge_nbr"] for r in records]).reshape(-1, 2)
    if len(ek):
        pairs = np.unique(np.hstack((ek, en)), axis=0)
        vk = pairs[:, :2]
        idx = _rows_in(uniq, vk)
        count = np.bincount(idx, minlength=len(uniq))
    else:
        count = np.zeros(len(uniq), dtype=np.int64)
    junction |= count != 2
    answers, k = [], 0
    for r in records:
        m = len(r["key"])
        sel = inv[k:k + m]
        answers.append({"vertex": r["vertex"], "junction": junction[sel], "first": first[sel]})
        k += m
    return answers


def _rows_in(table, rows):
    """Index in `table` (unique rows, sorted as np.unique sorts them) of each
    row of `rows` (all present)."""
    t = np.ascontiguousarray(table).view([("x", np.int64), ("y", np.int64)]).reshape(-1)
    r = np.ascontiguousarray(rows).view([("x", np.int64), ("y", np.int64)]).reshape(-1)
    return np.searchsorted(t, r)


# --- 3. arcs, by key -----------------------------------------------------------

def _cut(b, info, buckets, *answers):
    """The partition's parts cut into arcs at the layer's junctions, each in
    the canonical direction geo::smooth gives it (by first occurrence in
    layer order), bucketed by arc key."""
    c = b["clean"]
    n = len(c["vertices"])
    junction = np.zeros(n, dtype=bool)
    first = np.zeros(n, dtype=np.int64)
    for a in answers:
        junction[a["vertex"]] = a["junction"]
        first[a["vertex"]] = a["first"]
    keys, offs = b["keys"], c["offsets"]
    pts = b["frame_xy"][c["vertices"]]
    prep = b["prep"]
    extra = prep.z[c["vertices"]] if prep.layer.has_z else None
    p_index = b["index"]
    feature0 = int(info["first_feature"][p_index])
    parts = []  # per clean part: [(arc key, reversed)]
    abuckets = [dict() for _ in range(buckets)]
    for q in range(len(offs) - 1):
        s, e = int(offs[q]), int(offs[q + 1])
        ids = first[s:e]
        jn = junction[s:e]
        m = e - s
        runs = []  # (local indices in the part, closed)
        if c["rings"][q]:
            jidx = np.flatnonzero(jn)
            if len(jidx) == 0:
                runs.append((np.arange(m), True))
            else:
                walk = (jidx[0] + np.arange(m + 1)) % m
                cuts = np.flatnonzero(jn[walk])
                for u, w in zip(cuts[:-1], cuts[1:]):
                    runs.append((walk[u:w + 1], False))
        else:
            cuts = np.flatnonzero(jn)
            for u, w in zip(cuts[:-1], cuts[1:]):
                runs.append((np.arange(u, w + 1), False))
        arcs = []
        for k, (seq, closed) in enumerate(runs):
            sid = ids[seq]
            reversed_ = False
            if closed:
                r = int(np.argmin(sid))
                seq = np.roll(seq, -r)
                sid = ids[seq]
                if sid[-1] < sid[1]:
                    seq = np.concatenate((seq[:1], seq[1:][::-1]))
                    reversed_ = True
            else:
                diff = np.flatnonzero(sid != sid[::-1])
                if len(diff) and sid[::-1][diff[0]] < sid[diff[0]]:
                    seq = seq[::-1]
                    reversed_ = True
            g = s + seq
            key = keys[g].tobytes() + (b"c" if closed else b"o")
            arcs.append((key, reversed_))
            bucket = zlib.crc32(key) % buckets
            rec = abuckets[bucket].get(key)
            order = (p_index, q, k)
            feature = feature0 + int(c["features"][q])
            if rec is None:
                abuckets[bucket][key] = {"order": order, "xy": pts[g], "closed": closed,
                                         "extra": None if extra is None else extra[g],
                                         "features": {feature}, "partitions": {p_index}}
            else:
                rec["features"].add(feature)
        parts.append(arcs)
    return {"parts": parts, "abuckets": abuckets}


def _arc_split(cut, bucket):
    return cut["abuckets"][bucket]


def _distinct_arcs(spec, *records):
    alpha, fit = spec
    """One bucket of arc records from every partition: each distinct arc
    once (its first occurrence's coordinates and Z, all its features and
    partitions) and the box that holds it at every tension."""
    from .. import _crspline

    arcs = {}
    for r in records:
        for key, rec in r.items():
            have = arcs.get(key)
            if have is None:
                arcs[key] = dict(rec, features=set(rec["features"]), partitions=set(rec["partitions"]))
            else:
                if rec["order"] < have["order"]:
                    for f in ("order", "xy", "extra"):
                        have[f] = rec[f]
                have["features"] |= rec["features"]
                have["partitions"] |= rec["partitions"]
    keys = sorted(arcs, key=lambda k: arcs[k]["order"])
    xy, offs, closed = _flat([arcs[k] for k in keys])
    boxes = _crspline._geo_arc_boxes(xy, offs, closed, float(alpha), fit is not None) if keys else np.zeros((0, 4))
    return {"keys": keys, "arcs": arcs, "boxes": boxes}


def _flat(arcs):
    xy = np.concatenate([a["xy"] for a in arcs]) if arcs else np.zeros((0, 2))
    offs = np.concatenate(([0], np.cumsum([len(a["xy"]) for a in arcs]))).astype(np.int64)
    closed = np.asarray([a["closed"] for a in arcs], dtype=np.uint8)
    return xy, offs, closed
