#!/usr/bin/env bash
# Instructions per item of the main kernels, counted by callgrind (stable on
# a shared machine, unlike times). Prints a Markdown table; used for the
# "what limits it" notes in BENCHMARKS.md. Part of `./run bench`.
#   bench/count_instructions.sh [build dir]   (default build-bench/bench)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-bench/bench}"
exe="$build/crspline_instructions"
[[ -x "$exe" ]] || { echo "count_instructions: $exe not built (needs the valgrind headers)" >&2; exit 1; }
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file="$dir/cg.out" "$exe" >"$dir/items.txt" 2>"$dir/valgrind.log" ||
    { cat "$dir/valgrind.log" >&2; exit 1; }
echo "| case | instructions per item (callgrind) |"
echo "|---|---:|"
# One dump per case (cg.out.1, .2, ...), in the order the driver printed them.
mapfile -t lines <"$dir/items.txt"
k=1
for line in "${lines[@]}"; do
    read -r name items <<<"$line"
    file="$dir/cg.out.$k"
    total="$(awk '/^totals:/ {print $2}' "$file")"
    awk -v n="$name" -v t="$total" -v i="$items" 'BEGIN { printf "| %s | %.1f |\n", n, t / i }'
    k=$((k + 1))
done
