// Shared by the web tests: build the WASM module if it is missing, load it
// in node, read the reference data.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const webDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const repoDir = path.resolve(webDir, '..');
const wasm = path.join(webDir, 'dist', 'crspline.wasm');
const mjs = path.join(webDir, 'dist', 'crspline.mjs');

/// Runs web/build.sh when dist/ lacks the module or is older than the
/// sources (the bindings or any header).
export function ensureBuilt() {
  const newest = (dir) => fs.readdirSync(dir, { withFileTypes: true, recursive: true })
    .filter((e) => e.isFile())
    .reduce((t, e) => Math.max(t, fs.statSync(path.join(e.parentPath ?? e.path, e.name)).mtimeMs), 0);
  const built = fs.existsSync(wasm) && fs.existsSync(mjs) ? Math.min(fs.statSync(wasm).mtimeMs, fs.statSync(mjs).mtimeMs) : 0;
  const sources = Math.max(newest(path.join(webDir, 'src')), newest(path.join(repoDir, 'include')));
  if (built < sources) execFileSync(path.join(webDir, 'build.sh'), { stdio: 'inherit' });
}

let module = null;
/// The module in node: the bytes are passed in (node's fetch cannot load a
/// file URL).
export async function loadModule() {
  if (!module) {
    ensureBuilt();
    const { default: CrSpline } = await import(mjs);
    module = await CrSpline({ wasmBinary: fs.readFileSync(wasm) });
  }
  return module;
}

export function reference(name) {
  return JSON.parse(fs.readFileSync(path.join(repoDir, 'tests', 'reference', name), 'utf8'));
}

export const maxAbs = (a, b) => {
  let m = 0;
  for (let i = 0; i < a.length; ++i) m = Math.max(m, Math.abs(a[i] - b[i]));
  if (a.length !== b.length) return Infinity;
  return m;
};
