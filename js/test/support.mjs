// Shared by the package tests. They run in a scratch project where js/test.sh
// installed the packed tarball (import 'crspline' resolves to
// node_modules/crspline, as in a user's project); the reference data is read
// from the repository named by CRSPLINE_REPO.
import fs from 'node:fs';
import path from 'node:path';

export const repo = process.env.CRSPLINE_REPO;
if (!repo) throw new Error('CRSPLINE_REPO must name the crspline repository (js/test.sh sets it)');

export function reference(name) {
  return JSON.parse(fs.readFileSync(path.join(repo, 'tests', 'reference', name), 'utf8'));
}

export const maxAbs = (a, b) => {
  if (a.length !== b.length) return Infinity;
  let m = 0;
  for (let i = 0; i < a.length; ++i) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
};

/// A seeded generator (the seed is printed by the tests that use it on
/// failure): CRSPLINE_SEED or a random one.
export function seeded() {
  const seed = Number(process.env.CRSPLINE_SEED ?? Math.floor(Math.random() * 2 ** 31));
  let s = seed >>> 0 || 1;
  const next = () => {
    // xorshift32
    s ^= s << 13; s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5; s >>>= 0;
    return s / 2 ** 32;
  };
  return { seed, uniform: (a, b) => a + (b - a) * next() };
}
