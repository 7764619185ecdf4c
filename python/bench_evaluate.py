#!/usr/bin/python3
"""Benchmark: crspline's vectorized evaluate against a pure-NumPy
Barry-Goldman pyramid (the paper's three stages, vectorized over all t).

    PYTHONPATH=build-py/python /usr/bin/python3 python/bench_evaluate.py [--n 1000000]

Both evaluate the same closed centripetal curve (no end conditions to
reproduce) at n sorted parameters; the script checks that they agree and
prints the time of each and the ratio numpy / crspline (larger is faster for
crspline). Best of --repeat runs. The last line is machine-readable:
    ratio=<float>
"""
import argparse
import os
import sys
import time

# This file sits next to the package's sources (python/crspline, without the
# compiled module): import the built or installed package, not those.
_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != _HERE]

import numpy as np  # noqa: E402

import crspline  # noqa: E402


def barry_goldman_numpy(points, alpha, t):
    """Closed Catmull-Rom curve through `points` with knot exponent alpha,
    at the parameters t, by the Barry-Goldman pyramid in NumPy."""
    p = np.asarray(points, dtype=float)
    n = len(p)
    # Knots of the closed curve, extended by one interval on each side so
    # that every segment i has P(i-1), P(i), P(i+1), P(i+2) and their knots.
    h = np.linalg.norm(np.roll(p, -1, axis=0) - p, axis=1) ** alpha
    knots = np.concatenate([[0.0], np.cumsum(h)])                 # n + 1
    ext_t = np.concatenate([[-h[-1]], knots, [knots[-1] + h[0]]])  # index i + 1 is knot i
    ext_p = np.concatenate([p[-1:], p, p[:2]])                      # index i + 1 is P(i mod n)
    seg = np.clip(np.searchsorted(knots, t, side="right") - 1, 0, n - 1)
    t0, t1, t2, t3 = (ext_t[seg + k] for k in range(4))
    P0, P1, P2, P3 = (ext_p[seg + k] for k in range(4))
    x = t[:, None]
    t0, t1, t2, t3 = (v[:, None] for v in (t0, t1, t2, t3))
    # Work relative to P1 (as the library does) for precision far from 0.
    P0, P2, P3 = P0 - P1, P2 - P1, P3 - P1
    # Stage 1: linear interpolation along each polygon edge.
    A1 = (t1 - x) / (t1 - t0) * P0
    A2 = (x - t1) / (t2 - t1) * P2
    A3 = (t3 - x) / (t3 - t2) * P2 + (x - t2) / (t3 - t2) * P3
    # Stage 2: blend neighbouring edges.
    B1 = (t2 - x) / (t2 - t0) * A1 + (x - t0) / (t2 - t0) * A2
    B2 = (t3 - x) / (t3 - t1) * A2 + (x - t1) / (t3 - t1) * A3
    # Stage 3: blend over the segment's own interval.
    C = (t2 - x) / (t2 - t1) * B1 + (x - t1) / (t2 - t1) * B2
    return C + P1


def best_of(repeat, f):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000, help="parameters to evaluate (default 10^6)")
    ap.add_argument("--points", type=int, default=1000, help="control points (default 1000)")
    ap.add_argument("--dim", type=int, default=3, help="dimension (default 3)")
    ap.add_argument("--alpha", type=float, default=0.5, help="knot exponent (default 0.5)")
    ap.add_argument("--repeat", type=int, default=5, help="runs per method; the best counts (default 5)")
    ap.add_argument("--seed", type=int, default=20240601)
    args = ap.parse_args(argv)

    rng = np.random.default_rng(args.seed)
    print(f"seed {args.seed}: {args.points} points in {args.dim}-D, alpha {args.alpha}, n = {args.n}")
    points = rng.normal(size=(args.points, args.dim)).cumsum(axis=0)
    curve = crspline.CatmullRom(points, alpha=args.alpha, endconditions="closed")
    t = np.sort(rng.uniform(*curve.domain, args.n))
    unsorted = rng.permutation(t)

    t_cr, x_cr = best_of(args.repeat, lambda: curve.evaluate(t))
    t_cu, x_cu = best_of(args.repeat, lambda: curve.evaluate(unsorted))
    t_np, x_np = best_of(args.repeat, lambda: barry_goldman_numpy(points, args.alpha, t))

    # The two agree (relative to the coordinates' size).
    scale = np.abs(points).max()
    err = np.abs(x_cr - x_np).max() / scale
    ok = err <= 1e-11 and np.array_equal(x_cu, curve.evaluate(unsorted))
    print(f"max |crspline - numpy| / scale = {err:.2e}  ({'agree' if ok else 'DISAGREE'})")
    mpts = lambda s: args.n / s / 1e6
    print(f"crspline evaluate, sorted t:   {t_cr * 1e3:9.2f} ms  ({mpts(t_cr):7.1f} M points/s)")
    print(f"crspline evaluate, unsorted t: {t_cu * 1e3:9.2f} ms  ({mpts(t_cu):7.1f} M points/s)")
    print(f"numpy Barry-Goldman:           {t_np * 1e3:9.2f} ms  ({mpts(t_np):7.1f} M points/s)")
    ratio = t_np / t_cr
    print(f"speed ratio numpy / crspline (sorted): {ratio:.1f}x")
    print(f"ratio={ratio:.3f}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
