#!/usr/bin/env python3
"""Independent exact check of crspline's crossing decision (issue 27).

Written apart from the library: no code or constants shared with
include/crspline/decision.hpp. Standard library only (any python3 runs it).

Input: a corpus JSON written by the C++ test (tests/analysis/test_decision.cpp,
CRSPLINE_WRITE_DECISION_CORPUS=path): curves as piecewise cubic Bézier
control points (doubles printed with 17 significant digits, which read back
to the same doubles). Every double is an integer times a power of two, so
each curve is scaled to integer coordinates exactly, and halving a cubic
(de Casteljau at 1/2) stays integer after multiplying by 8: every predicate
below is evaluated exactly, on Python integers.

The decision, per curve:
  * segments whose four control points coincide are dropped (a point; its
    neighbours meet through it);
  * each segment is cut into pieces monotone in some direction d (every
    nonzero hodograph control point has d . h > 0): a monotone piece is
    injective;
  * consecutive pieces (sharing an end point exactly) are apart except at
    that point when a direction d puts every control point of the first,
    other than the shared point J, strictly behind J and of the second
    strictly ahead;
  * any two pieces are apart when a separating axis (x, y, either chord's
    normal) puts their control polygons strictly apart;
  * two pieces cross when, in the affine frame of their two chords, one
    piece lies in a horizontal strip and runs from left of the other's
    vertical slab to right of it, while the other lies in that slab and
    runs from below the strip to above it (two such paths in a rectangle
    must meet: the crossing lemma);
  * otherwise the larger piece is halved, down to a depth limit, where the
    pair is undecided (a contact).
Verdict: crosses if any crossing is proved, else touches if any pair is
undecided, else simple.

Usage: exact_decision.py corpus.json out.json
Writes the corpus back with, per curve, "exact": {"verdict", "crossing_pairs",
"crossing_keys", "undecided"}. exact_decision.py --check corpus.json
recomputes a written corpus and fails when any verdict differs (a CTest
case: analysis.exact_decision_reproduces).
"""
import json
import sys
from fractions import Fraction

MAX_DEPTH = 48  # levels of halving per segment before a pair is undecided


def to_int_curve(segments):
    """Scale a curve's double coordinates to integers: returns int segments."""
    fr = [[[Fraction(float(c)) for c in p] for p in seg] for seg in segments]
    den = 1
    for seg in fr:
        for p in seg:
            for c in p:
                den = max(den, c.denominator)  # all powers of two: the max is their lcm
    return [[tuple(int(c * den) for c in p) for p in seg] for seg in fr]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


class Piece:
    """Control points as integers over 2**shift (shift relative to the curve's scale)."""
    __slots__ = ("b", "shift", "seg", "depth", "at_start", "at_end")

    def __init__(self, b, shift, seg, depth, at_start=True, at_end=True):
        self.b, self.shift, self.seg, self.depth = b, shift, seg, depth
        self.at_start, self.at_end = at_start, at_end  # touches its segment's u = 0 / u = 1


def halve(p):
    b0, b1, b2, b3 = p.b
    f = lambda *t: tuple(sum(x[k] * w for x, w in t) for k in range(2))
    l = [f((b0, 8)), f((b0, 4), (b1, 4)), f((b0, 2), (b1, 4), (b2, 2)), f((b0, 1), (b1, 3), (b2, 3), (b3, 1))]
    r = [l[3], f((b1, 2), (b2, 4), (b3, 2)), f((b2, 4), (b3, 4)), f((b3, 8))]
    return (Piece(l, p.shift + 3, p.seg, p.depth + 1, p.at_start, False),
            Piece(r, p.shift + 3, p.seg, p.depth + 1, False, p.at_end))


def common(p, q):
    """Both pieces' points on one integer scale."""
    s = max(p.shift, q.shift)
    up = lambda x, k: (x[0] << k, x[1] << k)
    return [up(x, s - p.shift) for x in p.b], [up(x, s - q.shift) for x in q.b]


def monotone(b):
    hs = [sub(b[k + 1], b[k]) for k in range(3)]
    nz = [h for h in hs if h != (0, 0)]
    if not nz:
        return False
    cands = [sub(b[3], b[0]), nz[0], nz[-1], (nz[0][0] + nz[-1][0], nz[0][1] + nz[-1][1])]
    return any(d != (0, 0) and all(dot(d, h) > 0 for h in nz) for d in cands)


def separated(a, b):
    axes = [(1, 0), (0, 1)]
    for c in (sub(a[3], a[0]), sub(b[3], b[0])):
        if c != (0, 0):
            axes.append((-c[1], c[0]))
    for n in axes:
        pa = [dot(n, x) for x in a]
        pb = [dot(n, x) for x in b]
        if max(pa) < min(pb) or max(pb) < min(pa):
            return True
    return False


def joint_apart(a, b):
    """a ends at J = b's start: do they meet only at J?"""
    J = a[3]
    ra = [x for x in a[:3] if x != J]
    rb = [x for x in b[1:] if x != J]
    if not ra or not rb:
        return False
    da, db = sub(J, ra[-1]), sub(rb[0], J)
    na, nb = abs(da[0]) + abs(da[1]), abs(db[0]) + abs(db[1])
    for d in (da, db, (da[0] * nb + db[0] * na, da[1] * nb + db[1] * na)):
        if d == (0, 0):
            continue
        j = dot(d, J)
        if all(dot(d, x) < j for x in ra) and all(dot(d, x) > j for x in rb):
            return True
    return False


def crossing_lemma(a, b):
    """The rectangle argument in the frame of the two chords (exact). a and b
    are control points of paths (one Bézier piece, or two end to end): each
    path lies in the hull of its points and runs from the first to the last."""
    dA, dB = sub(a[-1], a[0]), sub(b[-1], b[0])
    D = cross(dA, dB)
    if D == 0:
        return False
    sg = 1 if D > 0 else -1
    S = lambda x: cross(sub(x, a[0]), dB) * sg  # along A's chord: a0 -> 0, a3 -> |D|
    T = lambda x: cross(dA, sub(x, a[0])) * sg  # along B's chord
    sB = [S(x) for x in b]
    tA = [T(x) for x in a]
    x0, x1 = min(sB), max(sB)
    y0, y1 = min(tA), max(tA)
    if not (S(a[0]) < x0 and S(a[-1]) > x1):
        return False
    tb0, tb3 = T(b[0]), T(b[-1])
    return (tb0 < y0 and tb3 > y1) or (tb3 < y0 and tb0 > y1)


def chained(p, ctx):
    """p's path continued through the vertex at its segment's end or start
    into the neighbouring segment's piece of the same depth, as a list of
    control points (two Bézier pieces, end to end), or None."""
    segs, nxt, prv = ctx
    return chained_with_key(p, ctx)[0]


def chained_with_key(p, ctx):
    """(chained(p), the vertex it passes through as "v<segment starting there>")."""
    segs, nxt, prv = ctx
    if p.at_end and nxt.get(p.seg) is not None:
        q = Piece(list(segs[nxt[p.seg]]), 0, nxt[p.seg], 0)
        while q.depth < p.depth:
            q = halve(q)[0]
        a, b = common(p, q)
        return a + b, "v%d" % nxt[p.seg]
    if p.at_start and prv.get(p.seg) is not None:
        q = Piece(list(segs[prv[p.seg]]), 0, prv[p.seg], 0)
        while q.depth < p.depth:
            q = halve(q)[1]
        a, b = common(q, p)
        return a + b, "v%d" % p.seg
    return None, None


def decide_pair(p, q, corner, out, ctx=None):
    """out: dict with 'crossing' (bool) and 'undecided' (int)."""
    stack = [(p, q, corner)]
    crossed = set()  # keys of the crossings: ("s<segment>" or "v<vertex>") pairs
    while stack:
        a, b, c = stack.pop()
        pa, pb = common(a, b)
        if separated(pa, pb):
            continue
        if c and joint_apart(pa, pb):
            continue
        if not c and crossing_lemma(pa, pb):
            crossed.add(tuple(sorted(("s%d" % a.seg, "s%d" % b.seg))))
            continue
        if a.depth >= MAX_DEPTH and b.depth >= MAX_DEPTH:
            # A crossing at a vertex: the paths through it, chained (both
            # pieces are at the same depth, so on the same integer scale).
            if not c and ctx is not None:
                (ca, ka), (cb, kb) = chained_with_key(a, ctx), chained_with_key(b, ctx)
                if (ca is not None or cb is not None) and crossing_lemma(ca or a.b, cb or b.b):
                    crossed.add(tuple(sorted((ka or "s%d" % a.seg, kb or "s%d" % b.seg))))
                    continue
            out["undecided"] += 1
            continue
        ea = max(max(x[k] for x in pa) - min(x[k] for x in pa) for k in range(2))
        eb = max(max(x[k] for x in pb) - min(x[k] for x in pb) for k in range(2))
        if (ea >= eb and a.depth < MAX_DEPTH) or b.depth >= MAX_DEPTH:
            l, r = halve(a)
            stack.append((l, b, False))
            stack.append((r, b, c))
        else:
            l, r = halve(b)
            stack.append((a, l, c))
            stack.append((a, r, False))
    return crossed


def box(p):
    s = p.shift
    return [min(x[k] for x in p.b) for k in range(2)], [max(x[k] for x in p.b) for k in range(2)], s


def boxes_meet(p, q):
    (lp, hp, sp), (lq, hq, sq) = box(p), box(q)
    s = max(sp, sq)
    f = lambda v, t: [x << (s - t) for x in v]
    lp, hp, lq, hq = f(lp, sp), f(hp, sp), f(lq, sq), f(hq, sq)
    return all(lp[k] <= hq[k] and lq[k] <= hp[k] for k in range(2))


def decide_curve(segments, closed):
    segs = to_int_curve(segments)
    pieces, undecided_self = [], 0
    for i, g in enumerate(segs):
        if g[0] == g[1] == g[2] == g[3]:
            continue
        stack = [Piece(list(g), 0, i, 0)]
        while stack:
            p = stack.pop()
            if monotone(p.b):
                pieces.append(p)
                continue
            if p.depth >= MAX_DEPTH:
                undecided_self += 1
                pieces.append(p)
                continue
            l, r = halve(p)
            stack.append(r)
            stack.append(l)
    # Neighbouring segments through a shared point (point segments skipped), for vertex crossings.
    live = [i for i, g in enumerate(segs) if not (g[0] == g[1] == g[2] == g[3])]
    nxt, prv = {}, {}
    for k, i in enumerate(live):
        if k + 1 == len(live) and not closed:
            break
        j = live[(k + 1) % len(live)]
        if i != j and segs[i][3] == segs[j][0]:
            nxt[i], prv[j] = j, i
    ctx = (segs, nxt, prv)
    if closed and len(pieces) == 2:  # two pieces would be adjacent at both ends: halve them
        pieces = [h for p in pieces for h in halve(p)]
    n = len(pieces)
    out = {"undecided": undecided_self}
    crossing_pairs, crossing_keys = set(), set()

    def same_point(p, k, q, m):
        s = max(p.shift, q.shift)
        x, y = p.b[k], q.b[m]
        return (x[0] << (s - p.shift), x[1] << (s - p.shift)) == (y[0] << (s - q.shift), y[1] << (s - q.shift))

    for i in range(n):
        for j in range(i + 1, n):
            p, q = pieces[i], pieces[j]
            if not boxes_meet(p, q):
                continue
            if j == i + 1 and same_point(p, 3, q, 0):
                a, b, corner = p, q, True
            elif closed and i == 0 and j == n - 1 and n > 2 and same_point(q, 3, p, 0):
                a, b, corner = q, p, True
            else:
                a, b, corner = p, q, False
            keys = decide_pair(a, b, corner, out, ctx)
            crossing_keys |= keys
            if any(k[0][0] == "s" and k[1][0] == "s" for k in keys):
                crossing_pairs.add((min(p.seg, q.seg), max(p.seg, q.seg)))
    verdict = "crosses" if crossing_keys else "touches" if out["undecided"] else "simple"
    return {"verdict": verdict, "crossing_pairs": sorted([list(x) for x in crossing_pairs]),
            "crossing_keys": sorted([list(x) for x in crossing_keys]), "undecided": out["undecided"]}


def check(path):
    """Recompute every verdict of a corpus that holds them; exit 1 on any difference."""
    corpus = json.load(open(path))
    bad = 0
    for c in corpus["curves"]:
        got = decide_curve(c["segments"], c["closed"])
        if got != c["exact"]:
            bad += 1
            print("differs: %s %d: %s, recorded %s" % (c["kind"], c["index"], got, c["exact"]))
    print("%d curves, %d differ from the recorded verdicts" % (len(corpus["curves"]), bad))
    if not corpus["curves"]:
        bad = 1
    sys.exit(1 if bad else 0)


def main():
    if sys.argv[1] == "--check":
        check(sys.argv[2])
    corpus = json.load(open(sys.argv[1]))
    counts = {}
    for c in corpus["curves"]:
        segs = c["segments"]
        c["exact"] = decide_curve(segs, c["closed"])
        counts[c["exact"]["verdict"]] = counts.get(c["exact"]["verdict"], 0) + 1
    corpus["exact_checker"] = "tests/analysis/exact_decision.py (integer arithmetic, max depth %d)" % MAX_DEPTH
    with open(sys.argv[2], "w") as f:
        json.dump(corpus, f, separators=(",", ":"))
        f.write("\n")
    print(len(corpus["curves"]), "curves:", counts)


if __name__ == "__main__":
    main()
