#!/usr/bin/env bash
# Builds the npm package's contents: js/dist/crspline.{mjs,wasm}, copied from
# the WebAssembly module web/build.sh makes (built here only when web/dist is
# missing or older than the sources, so ./run test builds it once), then
# packs it: js/build.sh [PACK_DIR] writes PACK_DIR/crspline-<version>.tgz
# and prints its path.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
node -e "import('$root/web/test/support.mjs').then((m) => m.ensureBuilt())" >&2
mkdir -p "$here/dist"
cp "$root/web/dist/crspline.mjs" "$root/web/dist/crspline.wasm" "$here/dist/"
if [[ $# -gt 0 ]]; then
    # Absolute: npm pack runs in js/, and a relative PACK_DIR is the caller's.
    dest="$(mkdir -p "$1" && cd "$1" && pwd)"
    (cd "$here" && npm pack --silent --pack-destination "$dest") | tail -n 1 | sed "s|^|$dest/|"
fi
