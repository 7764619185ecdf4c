#!/usr/bin/env bash
# All web tests: the WASM module in node (test/module.test.mjs; test/report.test.mjs:
# the analysis report of docs/report.md; test/bad_specs.test.mjs: the catalogue
# of bad curve files; test/floors.test.mjs: tolerances and accuracies below what
# the coordinates resolve) and the
# editor in headless Chromium (test/browser.test.mjs; test/editor.test.mjs:
# the defects of issue 17, desktop and touch; test/designer.test.mjs: the
# designer's keys and gestures; test/curvefile.test.mjs: the docs' command-line
# examples and 3-D files in the editor, against the crspline command when it is
# built; test/perf.test.mjs: frame times at 10^3 to
# 10^5 points, reported, never asserted), with node's test runner (TAP output). Builds the module first if it is missing or stale;
# installs playwright-core from package-lock.json if node_modules lacks it.
# Needs: emscripten (apt), chromium (apt, /usr/bin/chromium or $CHROMIUM), node >= 18, npm.
set -euo pipefail
cd "$(dirname "$0")"
[[ -d node_modules/playwright-core ]] || npm ci --no-audit --no-fund
node -e "import('./test/support.mjs').then((m) => m.ensureBuilt())"
exec node --test "$@" test/module.test.mjs test/report.test.mjs test/bad_specs.test.mjs test/floors.test.mjs test/decision.test.mjs test/rotation.test.mjs test/core_refusals.test.mjs test/browser.test.mjs test/editor.test.mjs test/designer.test.mjs test/curvefile.test.mjs test/perf.test.mjs
