#!/usr/bin/env bash
# The whole benchmark run (`./run bench`): Release build of bench/ (the
# project's normal flags, no -march), the Google Benchmark suite with
# repetitions, the three.js peer in node, the rotation splines' batches
# against the 4-D Euclidean one (issue 28), the crspline command on 10^6
# points (time and peak memory), then the table of medians and ratios.
#   apt: libbenchmark-dev libboost-math-dev libglm-dev nodejs npm; for bench/geo_bench.py
#        the Python packages of ./run (python3-geopandas, python3-dask, ...)
#   npm: three (bench/js/package.json, installed with `npm ci`); crspline's
#        own npm package (js/build.sh) for its three.js adapter
# Environment: BUILD (default build-bench/bench), REPS (default 5),
# FILTER (a --benchmark_filter regex, default all), GEO_SIZES (bench/geo_bench.py).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
build="${BUILD:-build-bench/bench}"
reps="${REPS:-5}"
results="bench/results"
mkdir -p "$results"

cmake -S bench -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j2
if [[ ! -d bench/js/node_modules/three ]]; then (cd bench/js && npm ci --no-audit --no-fund); fi
# crspline's npm package (CRSplineCurve3 against CatmullRomCurve3), packed
# from web/dist and installed without touching bench/js's lock file.
tgz="$(js/build.sh "$build/pack")"
(cd bench/js && npm install --no-save --offline --no-audit --no-fund --loglevel=error "$tgz")

stamp="$(date -u +%Y%m%dT%H%M%SZ)"
"$build/crspline_bench" --dump-points="$results/walk1000.json"
"$build/crspline_bench" --benchmark_repetitions="$reps" --benchmark_min_time=0.2 \
    --benchmark_filter="${FILTER:-.}" \
    --benchmark_out="$results/cpp-$stamp.json" --benchmark_out_format=json
node bench/js/threejs_bench.mjs "$results/walk1000.json" "$results/js-$stamp.json" "$reps"
# Issue 28: rotation splines. Each class's batch and the 4-D Euclidean batch
# in one run, back to back, so their ratio holds even on a loaded machine.
"$build/crspline_rotation_bench" --benchmark_repetitions="$reps" --benchmark_min_time=0.2 \
    --benchmark_out="$results/rotation-$stamp.json" --benchmark_out_format=json
python3 bench/rotation_bench.py --cpp "$results/rotation-$stamp.json" | tee "$results/latest-rotation.md"
# The crspline command on a 10^6-point CSV: time and peak memory of each
# subcommand (getrusage of the child), against reading the file.
cli_build="${CLI_BUILD:-build-bench/cli}"
cmake -S . -B "$cli_build" -DCMAKE_BUILD_TYPE=Release -DCRSPLINE_BUILD_TESTS=OFF -DCRSPLINE_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$cli_build" -j2 --target crspline_cli
python3 bench/cli_bench.py "$cli_build/cli/crspline" "$results/cli-$stamp.json"
python3 bench/report.py "$results/cpp-$stamp.json" "$results/js-$stamp.json" --cli "$results/cli-$stamp.json" |
    tee "$results/table-$stamp.md"
cp "$results/cpp-$stamp.json" "$results/latest-cpp.json"
cp "$results/js-$stamp.json" "$results/latest-js.json"
cp "$results/cli-$stamp.json" "$results/latest-cli.json"
cp "$results/table-$stamp.md" "$results/latest-table.md"
# Each CPU's results kept beside the others' (issue 30): bench/results/cpu/
# <model and widest kernel>/, so a regression on either machine shows.
cpu="$(python3 -c 'import json,re,sys; c=json.load(open(sys.argv[1]))["context"]; m=c.get("cpu_model","unknown"); k=c.get("kernels",""); w="avx512" if "AVX-512" in k else "avx2" if "AVX2" in k else "sse2"; print(re.sub(r"[^a-z0-9]+","-",(m.split(" (")[0]+" "+w).lower()).strip("-"))' "$results/cpp-$stamp.json")"
mkdir -p "$results/cpu/$cpu"
cp "$results/table-$stamp.md" "$results/cpu/$cpu/table.md"
cp "$results/cpp-$stamp.json" "$results/cpu/$cpu/cpp.json"
# Construction at 10^6 points: user-mode vs kernel time and page faults.
echo
{ "$build/crspline_construct_rusage"; "$build/crspline_construct_rusage_4k"; } | tee "$results/latest-construct.md"
cp "$results/latest-construct.md" "$results/cpu/$cpu/construct.md"
# GIS (issue 29): crspline.geo's lines per second per core at 10^4 and
# 10^5 lines, and the lengths alone at 10^6 (smoothing 10^6 lines in one
# call needs about 16 GB; bench/geo_bench.py; the Python module in the tree
# that ./run bench's Python step uses too). GEO_SIZES overrides the sizes.
py_build="${PY_BUILD:-build/bench-python}"
cmake -S . -B "$py_build" -DCMAKE_BUILD_TYPE=Release -DCRSPLINE_BUILD_PYTHON=ON -DCRSPLINE_BUILD_TESTS=OFF \
    -DCRSPLINE_BUILD_EXAMPLES=OFF -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$py_build" -j2 --target _crspline
echo
PYTHONPATH="$py_build/python" /usr/bin/python3 bench/geo_bench.py --sizes "${GEO_SIZES:-10000,100000}" \
    --out "$results/geo-$stamp.json" | tee "$results/latest-geo.txt"
PYTHONPATH="$py_build/python" /usr/bin/python3 bench/geo_bench.py --sizes 1000000 --rows length --frame-sizes "" \
    --dask-lines 0 --reps 1 --out "$results/geo-1e6-$stamp.json" | tee -a "$results/latest-geo.txt"
# Fit (issue 40): counts against Ramer-Douglas-Peucker and speed on the real
# corpus, and the peers (simplify-js, paper.js) on the same lines with their
# measured deviation.
echo
# --max 1e7: the issue's growth range, 10^4 to 10^7 points (about 2 minutes).
"$build/crspline_fit_bench" --max 1e7 | tee "$results/latest-fit.txt"
if [[ ! -d bench/js/fit/node_modules ]]; then (cd bench/js/fit && npm ci --no-audit --no-fund); fi
node bench/js/fit_peers.mjs tests/reference/fit/*.txt | tee "$results/latest-fit-peers.json"
# Sweeps (issue 41): a 10^6-vertex tube against the memory floor, and three.js'
# TubeGeometry at the same counts.
echo
"$build/crspline_sweep_bench" --dump-points="$results/knot48.json" | tee "$results/latest-sweep.json"
node bench/js/tube_bench.mjs "$results/knot48.json" "$reps" | tee "$results/latest-tube-threejs.json"
# Instruction counts (callgrind): stable where the times above are not.
if [[ -x "$build/crspline_instructions" ]] && command -v valgrind >/dev/null; then
    echo
    bench/count_instructions.sh "$build" | tee "$results/latest-instructions.md"
fi
