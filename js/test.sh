#!/usr/bin/env bash
# The npm package's tests, as a user meets the package: js/build.sh packs it
# (reusing web/dist when it is current), the tarball is installed with npm
# into a scratch project next to the pinned test dependencies
# (js/test/package-lock.json: three, d3-shape, typescript, playwright-core;
# installed once into js/test/node_modules and copied), and node's test
# runner runs js/test/*.test.mjs there: the API, the d3 and three.js
# adapters, the .d.ts check (tsc --noEmit on a typed consumer), a
# Chromium page drawing a d3 chart and a three.js tube, and the camera
# example (examples/camera_path.html) flown in Chromium.
# Usage: js/test.sh [node --test arguments]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tgz="$("$here/build.sh" "$work/pack")"
if [[ ! -d "$here/test/node_modules/three" || "$here/test/package-lock.json" -nt "$here/test/node_modules/.package-lock.json" ]]; then
    (cd "$here/test" && npm ci --no-audit --no-fund)
fi
scratch="$work/project"
mkdir -p "$scratch"
cp "$here/test/package.json" "$here/test/package-lock.json" "$here"/test/tsconfig*.json "$here/test/consumer.ts" "$scratch/"
cp "$here"/test/*.mjs "$scratch/"
cp -r "$here/test/browser" "$scratch/"
cp -r "$here/examples" "$scratch/"
cp -a "$here/test/node_modules" "$scratch/"
rm -rf "$scratch/node_modules/crspline"
(cd "$scratch" && npm install --no-save --offline --no-audit --no-fund --loglevel=error "$tgz")
cd "$scratch"
# Test files named in the arguments run alone; otherwise all of them.
files=(./*.test.mjs)
for a in "$@"; do [[ "$a" == *.test.mjs ]] && files=() && break; done
CRSPLINE_REPO="$root" node --test "$@" "${files[@]}"
