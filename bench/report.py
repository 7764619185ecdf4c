#!/usr/bin/env python3
"""Table of medians and ratios from one benchmark run (standard library only).

    report.py CPP.json [JS.json] [--cli CLI.json] > table.md

CPP.json: Google Benchmark's --benchmark_out (with repetitions: the
`_median` aggregates are used). JS.json: bench/js/threejs_bench.mjs output.
CLI.json: bench/cli_bench.py output (the command on 10^6 points).
Times are CPU time per item (the machine is shared: wall time includes
other processes' turns), and every ratio compares numbers of the same run.
"""
import json
import sys


def load_cpp(path):
    with open(path) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        name = b["run_name"]
        if b.get("run_type") == "iteration" and name in rows and rows[name].get("aggregate_name") == "median":
            continue
        rows[name] = b
    return data.get("context", {}), rows


def fmt_ns(ns):
    if ns >= 1e6:
        return f"{ns / 1e6:.3g} ms"
    if ns >= 1e3:
        return f"{ns / 1e3:.3g} µs"
    return f"{ns:.3g} ns"


def intersection_scaling(rows, ns, p):
    """certify/N and find_intersections/N: time per call and the fitted
    exponent (least squares of log time against log segments)."""
    import math
    cases = {}
    for name in rows:
        head, _, n = name.rpartition("/")
        if head in ("certify", "find_intersections") and n.isdigit() and ns(name):
            cases.setdefault(head, []).append((int(n), ns(name) * int(n) / 1e9))
    if not cases:
        return
    p("")
    p("Intersection-free spiral, CPU seconds per call, and the exponent b of a least-squares fit time ~ n^b:")
    p("")
    p("| segments | " + " | ".join(cases) + " |")
    p("|---:|" + "---:|" * len(cases))
    for n in sorted({n for v in cases.values() for n, _ in v}):
        p(f"| {n} | " + " | ".join(next((f"{t:.3g} s" for m, t in v if m == n), "") for v in cases.values()) + " |")
    fits = []
    for head, v in cases.items():
        if len(v) >= 2:
            x = [math.log(n) for n, _ in v]
            y = [math.log(t) for _, t in v]
            mx, my = sum(x) / len(x), sum(y) / len(y)
            b = sum((a - mx) * (c - my) for a, c in zip(x, y)) / sum((a - mx) ** 2 for a in x)
            fits.append(f"{b:.2f}")
        else:
            fits.append("")
    p("| exponent | " + " | ".join(fits) + " |")
    for n, goal in ((100000, 2), (1000000, 30)):
        t = next((t for m, t in cases.get("certify", []) if m == n), None)
        if t is not None:
            p(f"\ncertify {n} segments: {t:.3g} s, goal <= {goal} s: {'met' if t <= goal else f'MISSED by {t / goal:.2f}x'}")


def dimension_costs(rows, ns, p):
    """dimension/<op>/<path>/<d> (bench/dimension_bench.cpp): the front ends'
    run-time dimension path (runtime: exact for 1..4, zero-padded to 16 for
    5..16) and padding to 8 (pad8, measured only) against catmull_rom<d>."""
    cases = {}
    for name in rows:
        parts = name.split("/")
        if len(parts) == 4 and parts[0] == "dimension" and ns(name):
            cases.setdefault(parts[1], {})[(parts[2], int(parts[3]))] = ns(name)
    if not cases:
        return
    dims = sorted({d for v in cases.values() for _, d in v})
    p("")
    p("Run-time dimension (issue 14): time per item of the front ends' path / catmull_rom<d> used directly"
      " (runtime: d exactly for 1..4, zero-padded catmull_rom<16> for 5..16; pad8: padded to 8, not used,"
      " for comparison). Native time per item in brackets.")
    p("")
    p("| operation | " + " | ".join(f"{d}-D runtime" for d in dims) + " | " +
      " | ".join(f"{d}-D pad8" for d in dims if any(k == ("pad8", d) for v in cases.values() for k in v)) + " |")
    pad_dims = [d for d in dims if any(k == ("pad8", d) for v in cases.values() for k in v)]
    p("|---|" + "---:|" * (len(dims) + len(pad_dims)))
    for op, v in cases.items():
        cells = []
        for path, ds in (("runtime", dims), ("pad8", pad_dims)):
            for d in ds:
                nat, r = v.get(("native", d)), v.get((path, d))
                cells.append(f"{r / nat:.2f}x" + (f" ({fmt_ns(nat)})" if path == "runtime" else "") if nat and r else "")
        p(f"| {op} | " + " | ".join(cells) + " |")
    worst = max(((v[("runtime", d)] / v[("native", d)], op, d) for op, v in cases.items() for d in dims
                 if d >= 5 and ("runtime", d) in v and ("native", d) in v), default=None)
    if worst:
        p(f"\nLargest padded cost: {worst[1]} at {worst[2]}-D, {worst[0]:.2f}x native"
          f" ({'over' if worst[0] > 3 else 'within'} 3x).")


def cli_table(path, p):
    """bench/cli_bench.py output: the command on 10^6 points, time and peak
    memory per point, against reading the file and the issue-16 goals."""
    with open(path) as f:
        cli = json.load(f)
    n = cli["points"]
    rf = cli.get("read_file", {})
    p("")
    p(f"The crspline command on a {n}-point 2-D CSV ({cli['file_bytes'] / 1e6:.1f} MB; load average "
      f"{', '.join(f'{x:.1f}' for x in cli.get('load_avg', []))}); one run each, resources of the child "
      f"(getrusage). Reading the file (`cat`): {rf.get('wall_s', float('nan')):.3f} s wall, "
      f"{rf.get('peak_rss_bytes', 0) / 1e6:.1f} MB.")
    p("")
    p("| command | wall | user + sys CPU | peak memory | per point | goal | status |")
    p("|---|---:|---:|---:|---:|---|---|")
    for name, r in cli["cases"].items():
        if r.get("timed_out"):
            p(f"| `{name}` | > {r['wall_s']:.0f} s (stopped) | | | | | not measured |")
            continue
        if r.get("exit", 0) != 0:
            p(f"| `{name}` | | | | | | failed (exit {r['exit']}) |")
            continue
        cpu = r["user_s"] + r["sys_s"]
        bpp = r["peak_rss_bytes"] / n
        goals, missed = [], []
        if r.get("memory_goal"):
            goals.append(f"<= {GOAL_BPP} B/point")
            if bpp > GOAL_BPP:
                missed.append(f"memory by {bpp / GOAL_BPP:.2f}x")
        g = r.get("goal_wall_s")
        if g:
            goals.append(f"<= {g} s")
            # On a shared machine wall time includes other processes' turns:
            # the CPU time is what the command itself spent.
            if cpu > g:
                missed.append(f"time by {cpu / g:.2f}x")
        status = "" if not goals else ("met" if not missed else "MISSED " + ", ".join(missed))
        if g and not missed and r["wall_s"] > g:
            status += f" (CPU time; wall {r['wall_s']:.2f} s on the loaded machine)"
        goal_text = ", ".join(goals) if goals else "(info: prints per-point output)"
        p(f"| `{name}` | {r['wall_s']:.2f} s | {cpu:.2f} s | {r['peak_rss_bytes'] / 1e6:.0f} MB | {bpp:.0f} B "
          f"| {goal_text} | {status} |")
    ratios = cli.get("ratios")  # issue 26: the search's cost, pairs run back to back
    if ratios and ratios.get("median_wall") is not None:
        each = ", ".join(f"{r['ratio_wall']:.2f}" for r in ratios["runs"] if r["ratio_wall"] is not None)
        met = "met" if ratios["median_wall"] <= ratios["goal"] else "MISSED"
        p(f"\n`{ratios['of'][0]}` / `{ratios['of'][1]}`, back to back: {each} (wall; median "
          f"{ratios['median_wall']:.2f}, CPU {ratios['median_cpu']:.2f}); goal <= {ratios['goal']}: {met}.")


GOAL_BPP = 150


def main():
    args = sys.argv[1:]
    cli_path = None
    if "--cli" in args:
        k = args.index("--cli")
        cli_path = args[k + 1]
        del args[k:k + 2]
    ctx, rows = load_cpp(args[0])
    js = {}
    if len(args) > 1:
        with open(args[1]) as f:
            js = json.load(f)

    def ns(name):  # CPU ns per item
        b = rows.get(name)
        return 1e9 / b["items_per_second"] if b and b.get("items_per_second") else None

    def ctr(name, key):
        b = rows.get(name)
        return b.get(key) if b else None

    out = []
    p = out.append
    p(f"Machine: {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, "
      f"caches {', '.join(str(c['size'] // 1024) + ' KiB L' + str(c['level']) for c in ctx.get('caches', []) if c['type'] != 'Instruction')}; "
      f"load average {', '.join(f'{x:.1f}' for x in ctx.get('load_avg', []))}; {ctx.get('date', '')}")
    p(f"CPU: {ctx.get('cpu_model', 'not recorded')}. Kernels: {ctx.get('kernels', 'not recorded')}.")
    if ctx.get("eval_pages"):
        p(f"Evaluation buffers (t and outputs of the memory-bound cases): {ctx['eval_pages']} pages.")
    reps = next((b.get("repetitions") for b in rows.values() if b.get("repetitions")), 1)
    p(f"Medians of {reps} repetitions, CPU time per item.")
    p("")
    p("| case | per item | accuracy / counters |")
    p("|---|---:|---|")
    per = {"tessellate_walk20k/eval": "point", "tessellate_walk20k": "vertex", "construct": "control point", "arc_length": "segment", "tessellate": "segment",
           "nearest": "query", "nearest_scaling": "query", "t_at_arc_length": "query",
           "certify": "segment", "find_intersections": "segment"}
    per.update({"dimension/construct": "control point", "dimension/arc_length": "segment",
                "dimension/analyze": "segment", "dimension/intersections": "segment"})
    # eval_sorted/interleaved, eval_sorted_float/interleaved: one iteration
    # is the kernel and each of its floors over 10^7 points, in turn.
    per.update({"eval_sorted/interleaved": "point, all passes", "eval_sorted_float/interleaved": "point, all passes"})
    for name, b in rows.items():
        t = ns(name)
        if t is None:
            continue
        unit = next((v for k, v in per.items() if name.startswith(k)), "point")
        extra = []
        for k, v in b.items():
            if k in ("items_per_second", "bytes_per_second") or not isinstance(v, (int, float)):
                continue
            if k in ("real_time", "cpu_time", "iterations", "repetitions", "repetition_index",
                     "threads", "family_index", "per_family_instance_index"):
                continue
            extra.append(f"{k}={v:.3g}")
        p(f"| {name} | {fmt_ns(t)}/{unit} | {' '.join(extra)} |")
    for name, v in js.get("results", {}).items():
        if isinstance(v, dict) and "median_ns" in v:
            extra = f"rel_err={v['rel_err']:.3g}" if "rel_err" in v else ""
            if "arcLengthDivisions" in v:
                extra += f" (arcLengthDivisions={v['arcLengthDivisions']})"
            if "max_distance_to_three" in v:
                extra += f"max distance to three.js' getPoint={v['max_distance_to_three']:.2g}"
            p(f"| {name} (node {js.get('node')}, three {js.get('three')}) | {fmt_ns(v['median_ns'])}/point | {extra} |")
    if "wasm_error" in js.get("results", {}):
        p(f"| threejs_*/wasm | not run | {js['results']['wasm_error']} |")
    if "adapter_error" in js.get("results", {}):
        p(f"| threejs_*/adapter | not run | {js['results']['adapter_error']} |")

    p("")
    p("| target | measured (same run) | goal | status |")
    p("|---|---:|---:|---|")

    def target(label, value, goal, ok, how=""):
        if value is None:
            p(f"| {label} | n/a | {goal} | not measured |")
            return
        p(f"| {label} | {value} | {goal} | {'met' if ok else 'MISSED' + (' ' + how if how else '')} |")

    # The memory-bound targets (issue 30): from the interleaved cases, the
    # floor's time over the kernel's pass by pass, median of the pairs (and
    # the fastest pass of each beside it); the separate cases' medians,
    # seconds to minutes apart, only as information.
    def interleaved_target(case, label, floor):
        r, r_min = ctr(case, f"vs_{floor}"), ctr(case, f"vs_{floor}_min")
        if r is None:
            return False
        target(f"{label} throughput (interleaved, paired)", f"{r:.2f} (fastest passes {r_min:.2f})", ">= 0.8",
               r >= 0.8, f"by {0.8 / r:.2f}x")
        return True

    def interleaved_info(case, label, floor):
        r, r_min = ctr(case, f"vs_{floor}"), ctr(case, f"vs_{floor}_min")
        if r is not None:
            p(f"| (info) {label} throughput (interleaved, paired) | {r:.2f} (fastest passes {r_min:.2f}) | (info) | |")

    es, fl, ms = ns("eval_sorted/crspline"), ns("store_floor"), ns("store_floor/memset")
    il = "eval_sorted/interleaved"
    if not interleaved_target(il, "eval_sorted / store_floor/memset", "memset"):
        if es and ms:
            r = ms / es
            target("eval_sorted / store_floor/memset throughput", f"{r:.2f}", ">= 0.8", r >= 0.8, f"by {0.8 / r:.2f}x")
    elif es and ms:
        p(f"| (info) eval_sorted / store_floor/memset, separate cases | {ms / es:.2f} | (info) | |")
    if not interleaved_target(il, "eval_sorted / store_floor (plain loop)", "store_floor"):
        if es and fl:
            r = fl / es
            target("eval_sorted / store_floor (plain loop) throughput", f"{r:.2f}", ">= 0.8", r >= 0.8, f"by {0.8 / r:.2f}x")
    rw = ns("store_floor/read_write")
    if ctr(il, "vs_read_write") is not None:
        interleaved_info(il, "eval_sorted / store_floor/read_write (reads t too)", "read_write")
    elif es and rw:
        p(f"| (info) eval_sorted / store_floor/read_write throughput (reads t too) | {rw / es:.2f} | (info) | |")
    eb = ns("eval_sorted/boost")
    if es and eb:
        target("eval_sorted speed-up over Boost", f"{eb / es:.1f}x", ">= 10x", eb / es >= 10, f"by {10 / (eb / es):.2f}x")
    er, erb = ns("eval_random/crspline"), ns("eval_random/boost")
    if er and erb:
        target("eval_random speed-up over Boost", f"{erb / er:.1f}x", ">= 10x", erb / er >= 10, f"by {10 / (erb / er):.2f}x")
    ds = ns("deriv_sorted/crspline")
    if ds and es:
        target("deriv_sorted / eval_sorted time", f"{ds / es:.2f}", "<= 1.2", ds / es <= 1.2, f"by {ds / es / 1.2:.2f}x")
    for n in (1000, 1000000):
        c, cb = ns(f"construct/crspline/{n}"), ns(f"construct/boost/{n}")
        if c and cb:
            target(f"construct {n} points: crspline / Boost time per point", f"{c / cb:.2f}", "<= 1",
                   c / cb <= 1, f"by {c / cb:.2f}x")
    ta = ns("t_at_arc_length")
    if ta:
        err = ctr("t_at_arc_length", "rel_err")
        target("t_at_arc_length per query (rel. error)", f"{ta:.0f} ns ({err:.2g})", "< 100 ns at 1e-12",
               ta < 100 and err is not None and err <= 1e-12, f"by {ta / 100:.2f}x")
    # Issue 16: arc length against one 16-point rule per segment, and
    # tessellation per vertex against a sorted batch evaluation of as many
    # points, with its vertex count over the asymptotic optimum.
    al, gl = ns("arc_length_walk20k/crspline"), ns("arc_length_walk20k/gl16")
    if al and gl:
        err = ctr("arc_length_walk20k/crspline", "rel_err")
        target("arc_length (walk 20k, 1e-12) / one 16-point rule, time", f"{al / gl:.1f}x (error {err:.2g})",
               "<= 4x at <= 1e-12", al / gl <= 4 and err is not None and err <= 1e-12, f"by {al / gl / 4:.2f}x")
    for k, tol in ((3, "1e-3"), (5, "1e-5")):
        tv, ev = ns(f"tessellate_walk20k/crspline/{k}"), ns(f"tessellate_walk20k/eval/{k}")
        if tv and ev:
            target(f"tessellate (walk 20k, tol {tol}) per vertex / sorted evaluation per point", f"{tv / ev:.0f}x",
                   "<= 50x", tv / ev <= 50, f"by {tv / ev / 50:.2f}x")
        oo = ctr(f"tessellate_walk20k/crspline/{k}", "over_optimum")
        if oo is not None:
            target(f"tessellate (walk 20k, tol {tol}) vertices / asymptotic optimum", f"{oo:.3f}", "<= 1.2",
                   oo <= 1.2, f"by {oo / 1.2:.3f}x")
    ef, ff, efb = ns("eval_sorted_float/crspline"), ns("store_floor_float"), ns("eval_sorted_float/boost")
    ilf = "eval_sorted_float/interleaved"
    if not interleaved_target(ilf, "eval_sorted_float / store_floor_float", "memset"):
        if ef and ff:
            target("eval_sorted_float / store_floor_float throughput", f"{ff / ef:.2f}", ">= 0.8", ff / ef >= 0.8,
                   f"by {0.8 / (ff / ef):.2f}x")
    elif ef and ff:
        p(f"| (info) eval_sorted_float / store_floor_float, separate cases | {ff / ef:.2f} | (info) | |")
    rwf = ns("store_floor_float/read_write")
    if ctr(ilf, "vs_read_write") is not None:
        interleaved_info(ilf, "eval_sorted_float / store_floor_float/read_write (reads t too)", "read_write")
    elif ef and rwf:
        p(f"| (info) eval_sorted_float / store_floor_float/read_write throughput (reads t too) | {rwf / ef:.2f} | (info) | |")
    for case in (il, ilf):
        hp = ctr(case, "huge_pages")
        if hp is not None and hp < 0.9 and "2 MiB" in ctx.get("eval_pages", ""):
            p(f"| (info) {case}: output in 2 MiB pages | {hp:.0%} (THP refused: the ratios are 4 KiB-page ones) | (info) | |")
    if ef and efb:
        p(f"| (float) speed-up over Boost | {efb / ef:.1f}x | (info) | |")
    us, ug = ns("uniform_segment/crspline"), ns("uniform_segment/glm")
    if us and ug:
        p(f"| uniform_segment: speed-up over glm | {ug / us:.2f}x | (info) | |")
    for case in ("threejs_getPoint", "threejs_getPointAt"):
        v = js.get("results", {}).get(f"{case}/three")
        nat = ns(f"{case}/crspline")
        w = js.get("results", {}).get(f"{case}/wasm")
        if v and nat:
            p(f"| {case}: three.js / native crspline time | {v['median_ns'] / nat:.1f}x | (info) | |")
        if v and w:
            p(f"| {case}: three.js / crspline WASM time | {v['median_ns'] / w['median_ns']:.1f}x | (info) | |")
        ad = js.get("results", {}).get(f"{case}/adapter")
        if v and ad:
            p(f"| {case}: three.js / CRSplineCurve3 (crspline/three) time | {v['median_ns'] / ad['median_ns']:.1f}x | (info) | |")

    sc = [(int(k.split("/")[1]), k) for k in rows if k.startswith(("nearest_scaling/", "nearest/"))]
    if sc:
        p("")
        p("nearest_index scaling (10^5 queries within about one step of the curve):")
        p("")
        p("| segments | per query | nodes / query | segments solved / query | per segment solved |")
        p("|---:|---:|---:|---:|---:|")
        for n, k in sorted(sc):
            t, s = ns(k), ctr(k, "solved_per_query")
            p(f"| {n} | {fmt_ns(t)} | {ctr(k, 'nodes_per_query'):.1f} | {s:.2f} | {fmt_ns(t / s)} |")
    intersection_scaling(rows, ns, p)
    dimension_costs(rows, ns, p)
    if cli_path:
        cli_table(cli_path, p)
    print("\n".join(out))


if __name__ == "__main__":
    main()
