// One catalogue of bad curve specifications (tests/reference/bad_specs.json)
// fed to the WASM module, as tests/frontends/test_bad_specs.py feeds it to
// the CLI and Python: each case's Error carries the same words (the field's
// name, the index as a number, the core's message fragments), and where the
// core raised it (spec_error), error.field and error.index say which field
// and which index.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadModule, reference } from './support.mjs';

const M = await loadModule();
const { cases } = reference('bad_specs.json');

/// The Spline arguments for a curve file: points, the dimension of its
/// first point, and the options object in the module's words ("end":
/// "closed" is closed: true; a tangent [dx, dy] is {tangent: [...]}).
function splineArgs(spec) {
  const options = {};
  const end = (e) => (Array.isArray(e) ? { tangent: e } : e);
  for (const [k, v] of Object.entries(spec)) {
    if (k === 'points') continue;
    if (k !== 'end') options[k] = v;
    else if (v === 'closed') options.closed = true;
    else if (typeof v === 'string') { options.start = v; options.end = v; }
    else {
      if ('start' in v) options.start = end(v.start);
      if ('end' in v) options.end = end(v.end);
    }
  }
  const first = Array.isArray(spec.points) ? spec.points[0] : undefined;
  return [spec.points, Array.isArray(first) ? first.length : 2, options];
}

/// What the message lacks of the case's words (empty: it has them all).
export function lacks(message, c) {
  const missing = c.words.filter((w) => !message.includes(w));
  if (c.index !== null && !new RegExp(`(?<![\\d.])${c.index}(?![\\d.])`).test(message)) missing.push(`index ${c.index}`);
  return missing;
}

test('every bad spec: an Error with the catalogue\'s words, field and index', () => {
  assert.equal(cases.length, 25);
  let checked = 0, withField = 0;
  for (const c of cases) {
    const [points, dim, options] = splineArgs(c.spec);
    let error = null;
    try {
      new M.Spline(points, dim, options).delete();
    } catch (e) {
      error = e;
    }
    assert.ok(error instanceof Error, `${c.name}: no error`);
    assert.deepEqual(lacks(error.message, c), [], `${c.name}: ${error.message}`);
    if (c.core) {
      assert.equal(error.field, c.field, `${c.name}: field`);
      // The index where the catalogue has one; the core may name an index
      // the other front ends leave to the message (e.g. a tangent's coordinate).
      if (c.index !== null) assert.equal(error.index, c.index, `${c.name}: index`);
      withField++;
    }
    checked++;
  }
  assert.equal(checked, cases.length);
  assert.equal(withField, cases.filter((c) => c.core).length);
});

test('an unknown option is named, never dropped', () => {
  assert.throws(() => new M.Spline([[0, 0], [1, 1]], 2, { alpha: 0.5, colour: 'red' }),
    (e) => e.message.includes("unknown option 'colour'") && e.field === 'colour' && e.index === null);
});

test('the word check can fail', () => {
  const c = cases.find((x) => x.name === 'grid_not_finite');
  assert.deepEqual(lacks('grid[1] is not finite (inf)', c), []);
  assert.deepEqual(lacks('grid[11] is not finite', c), ['index 1']);
  assert.deepEqual(lacks('grid: bad', c), ['finite', 'index 1']);
});
