#!/bin/sh
# Builds the libFuzzer target with clang (ASan + UBSan, coverage on every CLI
# source) and fuzzes the input parsers for SECONDS (default 180), growing the
# kept corpus in fuzz/corpus/input. Findings go to fuzz/findings/ (ignored).
#
#   fuzz/run_fuzz.sh [SECONDS] [BUILD_DIR]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-180}
build=${2:-$root/build-fuzz}
jobs=${JOBS:-2}
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCRSPLINE_BUILD_EXAMPLES=OFF -DCRSPLINE_BUILD_FUZZER=ON \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j"$jobs" --target crspline_fuzz_input
mkdir -p "$root/fuzz/findings" "$build/fuzz-new"
# New inputs land in a scratch folder first; then merged (minimised) into the kept corpus.
"$build/tests/cli/fuzz/crspline_fuzz_input" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
    -artifact_prefix="$root/fuzz/findings/" -dict="$root/fuzz/crspline.dict" \
    "$build/fuzz-new" "$root/fuzz/corpus/input"
"$build/tests/cli/fuzz/crspline_fuzz_input" -merge=1 "$root/fuzz/corpus/input" "$build/fuzz-new" >/dev/null 2>&1
echo "corpus: $(ls "$root/fuzz/corpus/input" | wc -l) files"
