// The analysis report (docs/report.md) from the WASM module: the same tree
// as `crspline analyze` prints and Python's CatmullRom.analyze() returns.
// tests/reference/report_cases.json holds curves and the CLI's report of
// each (tests/reference/make_report_cases.py); tests/frontends checks the
// CLI and Python against the same file. Here: Spline.analyze() gives the
// same keys in the same order, the same types (numbers as plain numbers,
// lists as plain arrays, absent values as null), the same values.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadModule, reference } from './support.mjs';

const M = await loadModule();
const { cases } = reference('report_cases.json');

const kind = (v) => (v === null ? 'null' : Array.isArray(v) ? 'array' : typeof v);

/// Where two report trees differ: keys (and their order), kinds, lengths,
/// and numbers beyond rel relative (of 1 + |want|). Integers and floats are
/// both JavaScript numbers; JSON.parse reads the CLI's 0.0 as 0.
export function differences(got, want, rel, path = 'report') {
  if (kind(got) !== kind(want)) return [`${path}: ${kind(got)} ${JSON.stringify(got)} vs ${kind(want)} ${JSON.stringify(want)}`];
  if (kind(want) === 'object') {
    const gk = Object.keys(got), wk = Object.keys(want);
    if (gk.join() !== wk.join()) return [`${path}: keys ${gk} vs ${wk}`];
    return wk.flatMap((k) => differences(got[k], want[k], rel, `${path}.${k}`));
  }
  if (kind(want) === 'array') {
    if (got.length !== want.length) return [`${path}: ${got.length} items vs ${want.length}`];
    return want.flatMap((w, i) => differences(got[i], w, rel, `${path}[${i}]`));
  }
  if (kind(want) === 'number') return Math.abs(got - want) <= rel * (1 + Math.abs(want)) ? [] : [`${path}: ${got} vs ${want}`];
  return got === want ? [] : [`${path}: ${JSON.stringify(got)} vs ${JSON.stringify(want)}`];
}

function options(curve) {
  const o = { alpha: curve.alpha, closed: !!curve.closed };
  if (curve.tension !== undefined) o.tension = curve.tension;
  return o;
}

test('Spline.analyze() is the CLI\'s report, key for key and value for value', () => {
  assert.equal(cases.length, 9);
  let compared = 0;
  for (const c of cases) {
    const s = new M.Spline(c.curve.points, c.report.dimension, options(c.curve));
    try {
      // 1e-12 relative: the fixture was written by the CLI, built by g++
      // against glibc; emscripten's clang and musl libm may round pow, sin
      // and acos differently in the last bits, which the parameters and
      // distances inherit at a few ulps. A change of the analysis or of a
      // key moves far more.
      // Issue 27: the report carries "verdict" first (report.hpp writes it,
      // so the CLI's fixture has it too), decide()'s verdict for a plane
      // curve and null otherwise.
      const got = s.analyze();
      assert.equal(Object.keys(got)[0], 'verdict', c.name);
      assert.equal(got.verdict, c.report.dimension === 2 ? s.decide().verdict : null, c.name);
      assert.deepEqual(differences(got, c.report, 1e-12), [], c.name);
      // The parts are the report's parts.
      const search = s.intersections();
      assert.deepEqual(Object.keys(search), ['intersections', 'overlaps', 'folds', 'complete', 'any']);
      assert.deepEqual(differences(search.intersections, c.report.intersections, 1e-12), [], c.name);
      const cert = s.certify({ searchOnFailure: false });
      assert.deepEqual(Object.keys(cert), Object.keys(c.report.certificate));
      compared++;
    } finally {
      s.delete();
    }
  }
  assert.equal(compared, cases.length);
});

test('analyzeSegment() writes the report\'s segment object', () => {
  // The middle segment of the uniform loop, on its own: the same keys and
  // classification as the report's segment 1 (its t values are local: the
  // segment alone starts at t = 0).
  const c = cases.find((x) => x.name === 'uniform_loop');
  const want = c.report.segments[1];
  const a = M.analyzeSegment(c.curve.points, 2, 0, 0);
  assert.deepEqual(Object.keys(a), Object.keys(want));
  assert.equal(a.self_intersection_u.length, 1);
  assert.deepEqual(differences(a.self_intersection_u, want.self_intersection_u, 1e-12), []);
  assert.deepEqual(differences(a.bezier, want.bezier, 1e-12), []);
});

test('the comparison fails on a changed value, key or kind', () => {
  const want = cases[0].report;
  const copy = () => JSON.parse(JSON.stringify(want));
  let got = copy();
  got.segments[1].self_intersection_u[0][0] *= 1 + 1e-9;
  assert.notEqual(differences(got, want, 1e-12).length, 0);
  got = copy();
  got.certificate.failedRule = got.certificate.failed_rule;
  delete got.certificate.failed_rule;
  assert.notEqual(differences(got, want, 1e-12).length, 0);
  got = copy();
  got.complete = 1;
  assert.notEqual(differences(got, want, 1e-12).length, 0);
});
