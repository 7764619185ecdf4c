// Tolerances and accuracies the coordinates cannot resolve (issue 20): the
// WASM module refuses a tessellation tolerance or an arc-length accuracy
// below the floor of include/crspline/resolution.hpp with an Error in the
// CLI's and Python's words, naming the smallest meaningful value; a value at
// the floor is accepted and finishes. Unit coordinates: doubles near 1 are
// 2^-52 apart, the tolerance floor is 64 * 2^-52 (about 1.4e-14), the
// accuracy floor 8 machine epsilons. Before the check, tessellate(1e-16)
// subdivided for minutes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadModule } from './support.mjs';

const M = await loadModule();
const UNIT = [[0, 0], [1, 0], [1, 1], [0, 1]];  // largest magnitude exactly 1
const SPACING = 2 ** -52;
const TOL_FLOOR = 64 * SPACING;
const ACC_FLOOR = 8 * Number.EPSILON;
// JavaScript's shortest round-trip form is Python's repr and the core's for
// these numbers ("1e-16", "2.220446049250313e-16", "1.4210854715202004e-14").
const tolMessage = (given, spacing = SPACING, floor = TOL_FLOOR) =>
  `tolerance: ${given} is below what the coordinates resolve (their largest magnitude is spaced ${spacing} ` +
  `apart); the smallest meaningful tolerance for this input is ${floor}`;
const accMessage = (given) =>
  `accuracy: ${given} is below what double arithmetic resolves; the smallest meaningful relative accuracy is ${ACC_FLOOR}`;

function withSpline(points, f) {
  const s = new M.Spline(points, 2, {});
  try {
    return f(s);
  } finally {
    s.delete();
  }
}

test('tessellate: a tolerance below the floor is refused naming it, one at the floor finishes', () => {
  withSpline(UNIT, (s) => {
    for (const given of [1e-16, 1e-300]) {
      assert.throws(() => s.tessellate(given), (e) => e instanceof Error && e.message === tolMessage(given),
        String(given));
    }
    const p = s.tessellate(TOL_FLOOR);
    assert.equal(p.points.length, 2 * p.t.length);
    assert.ok(p.t.length > 4, `${p.t.length} points`);
    assert.deepEqual(Array.from(p.points.subarray(-2)), UNIT[3]);
  });
  // The floor follows the coordinates: near 1e6 doubles are 2^-33 apart.
  withSpline(UNIT.map(([x, y]) => [x * 1e6, y * 1e6]), (s) => {
    // (C writes a two-digit exponent, e-09, where JavaScript writes e-9.)
    assert.equal(64 * 2 ** -33, 7.450580596923828e-9);
    assert.throws(() => s.tessellate(1e-10),
      (e) => e.message === tolMessage(1e-10, 2 ** -33, '7.450580596923828e-09'), 'near 1e6');
  });
  withSpline(UNIT, (s) => assert.ok(s.tessellate(1e-10).t.length > 4));
});

test('arcLength(accuracy) and sampleArcLength: an accuracy below the floor is refused naming it, at it finishes', () => {
  withSpline(UNIT, (s) => {
    for (const given of [1e-16, 1e-300]) {
      assert.throws(() => s.arcLength(given), (e) => e instanceof Error && e.message === accMessage(given));
      assert.throws(() => s.sampleArcLength(5, given), (e) => e instanceof Error && e.message === accMessage(given));
    }
    const exact = s.arcLength(ACC_FLOOR);
    assert.ok(Math.abs(exact - s.arcLength(1e-12)) <= 1e-11 * exact, `${exact}`);
    assert.equal(s.sampleArcLength(5, ACC_FLOOR).t.length, 5);
  });
});
