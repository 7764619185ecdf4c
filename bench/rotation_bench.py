"""Rotation splines from Python (issue 28): batch evaluation per sample of
crspline.rotation.RotationSpline against SciPy's RotationSpline on the same
keys and times (goal: at least 20x less time on 10^6 samples), crspline's
C2 construction at 10^3..10^5 keys (time per key flat: linear), and
splines.quaternion where it is installed (goal: at least 1000x).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/rotation_bench.py [--samples N] [--reps R] [--out FILE.json]

Prints a table and, with --out, writes the medians (process CPU time) as
JSON. Timings on a loaded machine are not figures: BENCHMARKS.md records the
run that made them.

    python3 bench/rotation_bench.py --cpp RESULTS.json

reads the C++ benchmark's JSON (crspline_rotation_bench --benchmark_out=...)
instead and prints each class's time per sample against the 4-D Euclidean
batch of the same run (goal: at most 4x); this mode needs no NumPy.
"""
import argparse
import json
import statistics
import sys
import time


def random_keys(n, seed=28):
    """n unit quaternions [w, x, y, z], consecutive ones 0.2 to 1.2 rad apart (seeded)."""
    import numpy as np

    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(n, 3))
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    angles = rng.uniform(0.2, 1.2, n)
    steps = np.column_stack([np.cos(angles / 2), np.sin(angles / 2)[:, None] * axes])
    keys = np.empty((n, 4))
    keys[0] = [1, 0, 0, 0]
    for k in range(1, n):
        a, b = steps[k], keys[k - 1]
        keys[k] = [a[0] * b[0] - a[1:] @ b[1:], *(a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:]))]
    return keys


def best_of(reps, fn):
    """Median over reps of the process's CPU time (user + system) for fn():
    on a machine loaded by others, wall time counts their turns too. Both
    sides run on one thread (crspline releases the GIL but does not fan out)."""
    times = []
    for _ in range(reps):
        t0 = time.process_time()
        fn()
        times.append(time.process_time() - t0)
    return statistics.median(times)


def cpp_ratios(path):
    """The C++ rows of one run: ns per sample of each rotation batch and its
    ratio to rotation/euclid4/eval (medians when the run has repetitions)."""
    with open(path) as f:
        rows = json.load(f)["benchmarks"]
    ns = {}
    for r in rows:
        if r.get("run_type") == "aggregate" and r.get("aggregate_name") != "median":
            continue
        if "items_per_second" not in r:
            continue
        name = r.get("run_name", r["name"])
        if name not in ns or r.get("aggregate_name") == "median":
            ns[name] = 1e9 / r["items_per_second"]
    floor = ns.get("rotation/euclid4/eval")
    if floor is None:
        print("no rotation/euclid4/eval row in " + path, file=sys.stderr)
        return 1
    print("| batch, 10^6 random t | ns per sample | / euclid4 | goal <= 4x |")
    print("| --- | ---: | ---: | --- |")
    for name, v in ns.items():
        reference = name == "rotation/euclid4/eval" or name.endswith("/scalar") or name.endswith("/portable")
        goal = "" if reference else ("met" if v <= 4 * floor else "not met")
        print(f"| {name} | {v:.1f} | {v / floor:.2f} | {goal} |")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=1_000_000)
    ap.add_argument("--keys", type=int, default=100)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--construct", default="1000,10000,100000", help="key counts for the C2 construction")
    ap.add_argument("--out")
    ap.add_argument("--cpp", help="print the ratios of a C++ run's JSON instead (no NumPy needed)")
    args = ap.parse_args(argv)
    if args.cpp:
        return cpp_ratios(args.cpp)

    import numpy as np

    from crspline import rotation
    from scipy.spatial.transform import Rotation
    from scipy.spatial.transform import RotationSpline as ScipySpline

    keys = random_keys(args.keys)
    times = np.arange(args.keys, dtype=float)
    t = np.random.default_rng(1).uniform(0, times[-1], args.samples)
    xyzw = keys[:, [1, 2, 3, 0]]
    ours = rotation.RotationSpline(times, keys)
    theirs = ScipySpline(times, Rotation.from_quat(xyzw))
    # The two agree (crspline converged, SciPy after its 10 rounds) before
    # anything is timed: a benchmark of different curves would mean nothing.
    q_ours = np.asarray(ours(t[:1000]))
    q_theirs = theirs(t[:1000]).as_quat()[:, [3, 0, 1, 2]]
    gap = np.minimum(np.abs(q_ours - q_theirs).max(axis=1), np.abs(q_ours + q_theirs).max(axis=1)).max()
    results = {"samples": args.samples, "keys": args.keys, "agreement": float(gap)}
    # 1e-8: SciPy stops its fixed-point loop at 1e-9 in the rates; with steps
    # under 1.2 rad it converges there, and the rotations follow within 1e-8.
    if not gap <= 1e-8:
        print(f"crspline and SciPy disagree by {gap:.3g} on the benchmark's curve", file=sys.stderr)
        return 1
    rows = []
    for order in (0, 1):
        a = best_of(args.reps, lambda: ours(t, order))
        b = best_of(args.reps, lambda: theirs(t, order))
        results[f"eval{order}"] = {"crspline_s": a, "scipy_s": b, "ratio": b / a}
        rows.append((f"RotationSpline(t, {order}), {args.samples} samples", a, b))
    # SciPy's own currency: a Rotation in and out (crspline writes x, y, z, w
    # rows for it; Rotation.from_quat then normalizes them, SciPy's cost).
    ours_r = rotation.RotationSpline(times, Rotation.from_quat(xyzw))
    a = best_of(args.reps, lambda: ours_r(t))
    b = best_of(args.reps, lambda: theirs(t))
    results["eval0_rotation_objects"] = {"crspline_s": a, "scipy_s": b, "ratio": b / a}
    rows.append((f"RotationSpline(t) -> Rotation, {args.samples} samples", a, b))
    try:
        from splines.quaternion import CatmullRom, UnitQuaternion
    except ImportError:
        results["splines"] = "not installed"
    else:
        m = min(args.samples, 10_000)  # splines evaluates one t per Python call
        uq = [UnitQuaternion.from_unit_xyzw(q) for q in xyzw]
        theirs_cr = CatmullRom(uq, alpha=0.5)
        ours_cr = rotation.QuaternionSpline(keys, alpha=0.5, start="natural_splines", end="natural_splines")
        ts = np.random.default_rng(2).uniform(0, ours_cr.grid[-1], m)
        a = best_of(args.reps, lambda: ours_cr.evaluate(ts)) / m
        b = best_of(1, lambda: [theirs_cr.evaluate(x) for x in ts]) / m
        results["splines"] = {"crspline_s_per_sample": a, "splines_s_per_sample": b, "ratio": b / a}
        rows.append(("splines.quaternion CatmullRom, per sample", a, b))
    construct = {}
    for n in [int(x) for x in args.construct.split(",") if x]:
        k = random_keys(n)
        s = best_of(args.reps, lambda: rotation.C2RotationSpline(np.arange(n, dtype=float), k))
        construct[n] = {"s": s, "s_per_key": s / n}
        rows.append((f"C2 construction, {n} keys (per key)", s / n, float("nan")))
    results["construct"] = construct

    print(f"agreement with SciPy on 1000 samples: {gap:.2e}")
    print(f"| case | crspline (s) | peer (s) | peer / crspline |")
    print("| --- | ---: | ---: | ---: |")
    for name, a, b in rows:
        print(f"| {name} | {a:.3g} | {b:.3g} | {b / a:.1f} |")
    if args.out:
        with open(args.out, "w") as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
