// The WASM module in node: the core's rules reach JavaScript unchanged.
// Issue 26 point 1: an arc length within the promised accuracy (1e-12 of
// the total, the module's table) of either end is that end; further out it
// is refused with the core's message. Issue 31 point 3: a curve whose chord
// overflows is refused at construction, naming the points, in every alpha.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadModule } from './support.mjs';

const M = await loadModule();

function withSpline(points, dim, options, f) {
  const s = new M.Spline(points, dim, options);
  try {
    return f(s);
  } finally {
    s.delete();
  }
}

// A number as the core's messages print it (C's %g at the shortest
// precision that reads back: the same digits as JavaScript's, the exponent
// with at least two digits).
const cNum = (x) => String(x).replace(/e([+-])(\d)$/, 'e$10$2');

test('tAtArcLength: within the accuracy of an end is that end, further out an error', () => {
  // The README's curve: a length that is not a round number.
  withSpline([[0, 0], [1, 2], [3, 3], [4, 0]], 2, {}, (c) => {
    const total = c.arcLength();
    const grid = Array.from(c.grid());
    assert.ok(total > 7.8 && total < 7.9, String(total));
    // 8e-15 relative past the end (the case: another tool's total).
    const past = total * (1 + 8e-15);
    assert.ok(past > total);
    assert.equal(c.tAtArcLength(past), grid[grid.length - 1]);
    assert.equal(c.tAtArcLength(-total * 8e-15), grid[0]);
    assert.equal(c.tAtArcLength(total), grid[grid.length - 1]);
    // 1e-9 relative is outside the 1e-12 promise: the core's message.
    let checked = 0;
    for (const s of [total * (1 + 1e-9), -total * 1e-9]) {
      assert.throws(() => c.tAtArcLength(s),
        (e) => e instanceof Error && e.message === `s = ${cNum(s)} is outside the arc-length range [0, ${cNum(total)}]`,
        `s = ${s}`);
      ++checked;
    }
    assert.equal(checked, 2);
  });
});

test('a chord that overflows is refused at construction, naming the points', () => {
  let checked = 0;
  for (const alpha of [0, 0.5, 1]) {
    for (const closed of [false, true]) {
      assert.throws(() => new M.Spline([[-1.5e308, 0], [1.5e308, 0]], 2, { alpha, closed }),
        (e) => e instanceof Error && e.field === 'points' && e.index === 0 &&
          e.message === 'points 0 and 1: the chord between them overflows (|P1 - P0| is not finite)',
        `alpha ${alpha} closed ${closed}`);
      ++checked;
    }
  }
  assert.equal(checked, 6);
});
