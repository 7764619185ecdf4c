// The npm package's decision (issue 27): decide, decidePair, decideSet and
// clearance over catmullRom() curves, the report's "verdict" first.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { init, catmullRom, decide, decidePair, decideSet, clearance } from 'crspline';

await init();
const eight = [[0, 0], [1, 1], [2, 0], [1, -1], [0, 0.2], [-1, 1], [-2, 0], [-1, -1]];

test('one curve, every alpha: decide() and the report\'s verdict', () => {
  let n = 0;
  for (const alpha of [0, 0.5, 1]) {
    const c = catmullRom(eight, { alpha });
    const d = decide(c);
    assert.equal(d.verdict, 'crosses', `alpha ${alpha}`);
    assert.equal(d.crossings.length, 1);
    assert.deepEqual(c.decide(), d);
    const r = c.analyze();
    assert.equal(Object.keys(r)[0], 'verdict');
    assert.equal(r.verdict, 'crosses');
    c.dispose();
    n++;
  }
  assert.equal(n, 3);
  const ring = catmullRom([[1, 0], [0, 1], [-1, 0], [0, -1]], { closed: true });
  assert.equal(decide(ring).verdict, 'simple');
  ring.dispose();
});

test('pair and set, and clearance between curves', () => {
  const a = catmullRom([[0, 0], [2, 2]]), b = catmullRom([[0, 2], [2, 0]]), c = catmullRom([[5, 5], [6, 6]]);
  const d = decidePair(a, b);
  assert.equal(d.verdict, 'crosses');
  assert.deepEqual(d.crossings[0].curves, [0, 1]);
  assert.equal(decidePair(a, c).verdict, 'simple');
  const set = decideSet([c, a, b]);
  assert.deepEqual(set.crossings.map((x) => x.curves), [[1, 2]]);
  const far = clearance(a, c);
  // (2, 2) to (5, 5) at the default accuracy (1e-10 of the extent).
  assert.ok(Math.abs(far.distance - 3 * Math.SQRT2) <= 1e-9, `${far.distance}`);
  assert.throws(() => decideSet([a, 'b']), /curve 1 of the set: expected a curve made by catmullRom\(\)/);
  const c3 = catmullRom([[0, 0, 0], [1, 1, 1], [2, 0, 0], [0, 1, 0]]);
  assert.throws(() => decide(c3), /the decision needs plane curves \(dimension 2\), got dimension 3/);
  assert.ok(clearance(c3).distance > 0);
  assert.throws(() => clearance(a, c3), /dimensions 2 and 3/);
  for (const x of [a, b, c, c3]) x.dispose();
});
