// The decision of issue 27 in the WASM module (web/src/bindings.cpp:
// Spline.decide, decidePair, decideSet, clearance, and "verdict" at the top
// of Spline.analyze()). The verdicts themselves are proved and checked
// against an exact oracle in tests/analysis; here: that the module carries
// them for every alpha, in the report's shape, for one curve, a pair and a
// set, and refuses what it cannot decide with a message.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadModule } from './support.mjs';

const M = await loadModule();
function use(o, f) {
  try { return f(o); } finally { o.delete(); }
}

// A figure eight (crosses once near the middle, at every alpha) and a
// convex closed curve (simple at every alpha).
const eight = [[0, 0], [1, 1], [2, 0], [1, -1], [0, 0.2], [-1, 1], [-2, 0], [-1, -1]];
const ring = [[1, 0], [0, 1], [-1, 0], [0, -1]];

test('every alpha: the verdict at the top of the report, and decide() gives the decision', () => {
  let n = 0;
  for (const alpha of [0, 0.25, 0.5, 0.75, 1]) {
    for (const [points, closed, want] of [[eight, false, 'crosses'], [ring, true, 'simple']]) {
      use(new M.Spline(points, 2, { alpha, closed }), (s) => {
        const r = s.analyze();
        assert.equal(Object.keys(r)[0], 'verdict');
        assert.equal(r.verdict, want, `alpha ${alpha}`);
        const d = s.decide();
        assert.deepEqual(Object.keys(d), ['verdict', 'fast_path', 'floor', 'crossings', 'touches', 'pairs']);
        assert.equal(d.verdict, want);
        if (want === 'crosses') {
          assert.equal(d.crossings.length, 1, `alpha ${alpha}`);
          const c = d.crossings[0];
          // The proved interval holds the crossing: both curves' points at the
          // middles of the intervals agree to the interval's width.
          assert.ok(c.u[0][1] - c.u[0][0] < 1e-9 && c.u[0][0] <= c.u[0][1]);
          const p = s.evaluate(s.grid()[c.segments[0]] + (c.u[0][0] + c.u[0][1]) / 2 * (s.grid()[c.segments[0] + 1] - s.grid()[c.segments[0]]), 0);
          assert.ok(Math.hypot(p[0] - c.point[0], p[1] - c.point[1]) <= 1e-12);
        }
        assert.equal(s.decide({ recordPairs: false }).pairs.length, 0);
        assert.equal(s.analyze({ decision: false }).verdict, null);
        n++;
      });
    }
  }
  assert.equal(n, 10);
});

test('a curve that is not plane: verdict null in the report, decide() refuses, clearance answers', () => {
  use(new M.Spline([[0, 0, 0], [1, 1, 0], [2, 0, 1], [0, 0.5, 0]], 3), (s) => {
    const r = s.analyze();
    assert.equal(Object.keys(r)[0], 'verdict');
    assert.equal(r.verdict, null);
    assert.throws(() => s.decide(), /the decision needs plane curves \(dimension 2\), got dimension 3/);
    const c = s.clearance();
    assert.ok(c.distance > 0 && c.lowerBound <= c.distance && c.distance - c.lowerBound <= 1e-9);
    assert.equal(c.points[0].length, 3);
  });
});

test('pair and set: crossings name both curves; clearance between two curves', () => {
  const a = new M.Spline([[0, 0], [2, 2]], 2), b = new M.Spline([[0, 2], [2, 0]], 2), c = new M.Spline([[5, 5], [6, 6]], 2);
  try {
    const d = M.Spline.decidePair(a, b, {});
    assert.equal(d.verdict, 'crosses');
    assert.deepEqual(d.crossings[0].curves, [0, 1]);
    // Two straight segments cross at (1, 1), at u = 1/2 on each.
    assert.ok(d.crossings[0].u[0][0] <= 0.5 && d.crossings[0].u[0][1] >= 0.5);
    assert.equal(M.Spline.decidePair(a, c, {}).verdict, 'simple');
    const set = M.Spline.decideSet([c, a, b], {});
    assert.equal(set.verdict, 'crosses');
    assert.deepEqual(set.crossings.map((x) => x.curves), [[1, 2]]);
    assert.equal(M.Spline.decideSet([a, c], {}).verdict, 'simple');
    const far = M.Spline.clearancePair(a, c, 0);
    // (2, 2) to (5, 5): 3 sqrt(2), to the default accuracy 1e-10 of the extent.
    assert.ok(Math.abs(far.distance - 3 * Math.SQRT2) <= 1e-9, `${far.distance}`);
    assert.deepEqual(far.curves, [0, 1]);
    assert.throws(() => M.Spline.clearance(a, c, -1), /./);
    assert.throws(() => a.clearance(-1), /clearance accuracy must be a finite distance >= 0/);
    assert.throws(() => a.decide({ budget: -2 }), /budget must be a non-negative integer, got -2/);
  } finally {
    a.delete(); b.delete(); c.delete();
  }
});

test('the editor\'s whole-curve pass (overlays.mjs, run in the worker) carries the verdict for every alpha', async () => {
  const { computeGlobal } = await import('../app/overlays.mjs');
  // A straight run with a small bump: the uniform curve loops there, the
  // centripetal and chordal ones do not (the certificate speaks only for
  // centripetal: "not centripetal" for the other two).
  const pts = Float64Array.from([100, 400, 400, 400, 420, 380, 440, 400, 740, 400]);
  const got = {};
  for (const alpha of [0, 0.5, 1]) {
    const out = computeGlobal(M, { version: 1, points: pts.slice(), dimension: 2, options: { alpha } });
    assert.equal(out.error, null);
    got[alpha] = out.decision.verdict;
    if (alpha !== 0.5) assert.equal(out.cert.failed_rule, 'not_centripetal');
  }
  assert.deepEqual(got, { 0: 'crosses', 0.5: 'simple', 1: 'simple' });
  const out3 = computeGlobal(M, { version: 1, points: Float64Array.from([0, 0, 0, 1, 1, 0, 2, 0, 1]), dimension: 3, options: {} });
  assert.equal(out3.decision, null);
});
