#!/usr/bin/env python3
"""The crspline command on a 10^6-point 2-D CSV: time and peak memory.

    cli_bench.py CRSPLINE OUT.json [POINTS]

Writes a seeded 2-D random walk of POINTS (default 10^6) points as CSV (the
walk of bench/walk.hpp in 2-D: unit directions, log-normal steps), then runs
each subcommand once as a child process and reads its resources with
os.wait4 (getrusage of the child): wall time, user and system CPU time, and
peak resident memory (ru_maxrss). The baseline is reading the file
(`cat FILE > /dev/null`, same measurement). Standard library only.
Output goes to a temporary file (-o), as a user's would.

Then the ratio of issue 26: `analyze --summary` (the intersection search,
counts only) against `analyze --no-intersections` (the same analysis and
certificate without the search), run back to back RATIO_RUNS times so that
both sides of each ratio see the same load; the ratios of wall and of CPU
time go to "ratios" and to stderr, with the goal (<= 2) and the median.
"""
import json
import math
import os
import random
import sys
import tempfile
import time

# (name, arguments before the input file, goal in seconds of wall time or None)
CASES = [
    ("length", ["length"], 1.5),
    ("eval --t 0", ["eval", "--t", "0"], None),
    ("sample --count 1000 --spacing arc_length", ["sample", "--count", "1000", "--spacing", "arc_length"], None),
    ("sample --tolerance 0.1", ["sample", "--tolerance", "0.1"], None),
    ("analyze", ["analyze"], None),
]
# Subcommands that print per-point output are exempt from the memory goal:
# tessellation prints every vertex (the walk's steps are about 1 long), and
# analyze prints records per segment.
# eval --t 0 (parse, build, one evaluation) is the baseline of the others;
# it echoes per-point data too (18 bytes a point).
PER_POINT_OUTPUT = {"eval --t 0", "sample --tolerance 0.1", "analyze"}
GOAL_BYTES_PER_POINT = 150
TIMEOUT_S = float(os.environ.get("CLI_BENCH_TIMEOUT", 300))  # seconds per command
# The search's cost: --summary over --no-intersections, each pair back to back.
RATIO_CASES = (("analyze --summary", ["analyze", "--summary"]),
               ("analyze --no-intersections", ["analyze", "--no-intersections"]))
RATIO_RUNS = 3
RATIO_GOAL = 2.0


def write_walk(path, n, seed=20240601):
    rng = random.Random(seed)
    x = y = 0.0
    with open(path, "w") as f:
        f.write("x,y\n")
        for _ in range(n):
            f.write(f"{x!r},{y!r}\n")
            a = rng.uniform(0, 2 * math.pi)
            step = math.exp(rng.gauss(0, 1))
            x += step * math.cos(a)
            y += step * math.sin(a)


def measure(argv):
    t0 = time.monotonic()
    with open(os.devnull, "wb") as out:
        pid = os.fork()
        if pid == 0:
            os.dup2(out.fileno(), 1)
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, 2)
            try:
                os.execv(argv[0], argv)
            finally:
                os._exit(127)
        deadline = t0 + TIMEOUT_S
        while True:
            done, status, ru = os.wait4(pid, os.WNOHANG)
            if done:
                break
            if time.monotonic() > deadline:
                os.kill(pid, 9)
                _, status, ru = os.wait4(pid, 0)
                return {"timed_out": True, "wall_s": time.monotonic() - t0}
            time.sleep(0.005)
    return {
        "exit": os.waitstatus_to_exitcode(status),
        "wall_s": time.monotonic() - t0,
        "user_s": ru.ru_utime,
        "sys_s": ru.ru_stime,
        "peak_rss_bytes": ru.ru_maxrss * 1024,
    }


def search_ratios(exe, csv, sink):
    """RATIO_RUNS pairs of RATIO_CASES, back to back: each pair's ratio of
    wall time and of user + sys CPU time, and their medians."""
    (num_name, num_args), (den_name, den_args) = RATIO_CASES
    runs = []
    for k in range(RATIO_RUNS):
        num = measure([exe] + num_args + [csv, "-o", sink])
        den = measure([exe] + den_args + [csv, "-o", sink])
        if num.get("timed_out") or den.get("timed_out") or num["exit"] or den["exit"]:
            runs.append({num_name: num, den_name: den, "ratio_wall": None, "ratio_cpu": None})
            print(f"ratio run {k}: not measured ({num_name}: {num}, {den_name}: {den})", file=sys.stderr)
            continue
        wall = num["wall_s"] / den["wall_s"]
        cpu = (num["user_s"] + num["sys_s"]) / (den["user_s"] + den["sys_s"])
        runs.append({num_name: num, den_name: den, "ratio_wall": wall, "ratio_cpu": cpu})
        print(f"ratio run {k}: {num_name} {num['wall_s']:.2f} s, {den_name} {den['wall_s']:.2f} s wall: "
              f"{wall:.2f}x wall, {cpu:.2f}x CPU (goal <= {RATIO_GOAL})", file=sys.stderr)
    walls = sorted(r["ratio_wall"] for r in runs if r["ratio_wall"] is not None)
    cpus = sorted(r["ratio_cpu"] for r in runs if r["ratio_cpu"] is not None)
    median = (lambda v: v[len(v) // 2] if v else None)
    out = {"of": [num_name, den_name], "goal": RATIO_GOAL, "runs": runs,
           "median_wall": median(walls), "median_cpu": median(cpus)}
    print(f"{num_name} / {den_name}: median {out['median_wall']} wall, {out['median_cpu']} CPU over "
          f"{len(walls)} of {RATIO_RUNS} runs (goal <= {RATIO_GOAL})", file=sys.stderr)
    return out


def main():
    exe = os.path.abspath(sys.argv[1])
    out_json = sys.argv[2]
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 1_000_000
    with tempfile.TemporaryDirectory() as tmp:
        csv = os.path.join(tmp, "walk.csv")
        write_walk(csv, n)
        sink = os.path.join(tmp, "out")
        results = {"points": n, "file_bytes": os.path.getsize(csv),
                   "load_avg": list(os.getloadavg()), "cases": {}}
        results["read_file"] = measure(["/bin/cat", csv])
        for name, args, goal in CASES:
            r = measure([exe] + args + [csv, "-o", sink])
            r["goal_wall_s"] = goal
            r["memory_goal"] = name not in PER_POINT_OUTPUT
            r["output_bytes"] = os.path.getsize(sink) if os.path.exists(sink) else 0
            results["cases"][name] = r
            print(f"{name}: {json.dumps(r)}", file=sys.stderr)
        results["ratios"] = search_ratios(exe, csv, sink)
    with open(out_json, "w") as f:
        json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
