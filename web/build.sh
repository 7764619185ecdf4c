#!/usr/bin/env bash
# Build the crspline WebAssembly module: web/dist/crspline.mjs + crspline.wasm,
# an ES module usable in the browser and in node (give node the bytes:
# CrSpline({ wasmBinary: fs.readFileSync('dist/crspline.wasm') })).
# Needs Debian's emscripten (3.1.6). Usage: web/build.sh [--debug]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
out="$here/dist"
mkdir -p "$out"
# Debian's em++ needs Debian's node modules (acorn) at -O1 and above.
export NODE_PATH="${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs"
# A writable cache copy is not needed: the Debian package ships a frozen one.
opt=(-O2)
if [[ "${1:-}" == "--debug" ]]; then opt=(-O0 -g -sASSERTIONS=2); fi
em++ -std=c++20 "${opt[@]}" -fexceptions -Wall -Wextra \
    -I"$root/include" \
    "$here"/src/*.cpp \
    -lembind \
    -fexceptions \
    -sMODULARIZE -sEXPORT_ES6 -sEXPORT_NAME=CrSpline -sENVIRONMENT=web,worker \
    -sALLOW_MEMORY_GROWTH -sINITIAL_MEMORY=33554432 \
    -o "$out/crspline.mjs"
echo "built $out/crspline.mjs and $out/crspline.wasm"
