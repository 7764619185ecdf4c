// fit (issue 40), sweep and stroke (issue 41) through the installed package:
// the WASM bindings web/src/bind_fit.cpp and bind_sweep.cpp behind
// crspline's fit(), sweep() and stroke().
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { init, catmullRom, fit, sweep, stroke } from 'crspline';
import { seeded } from './support.mjs';

await init();

// Distance from p to the polyline (flat, dim per point).
function toPolyline(p, flat, dim, closed = false) {
  const n = flat.length / dim;
  let best = Infinity;
  for (let i = 0; i < (closed ? n : n - 1); ++i) {
    const j = (i + 1) % n;
    let ab = 0, ap = 0;
    for (let k = 0; k < dim; ++k) {
      const d = flat[j * dim + k] - flat[i * dim + k];
      ab += d * d;
      ap += d * (p[k] - flat[i * dim + k]);
    }
    const u = ab > 0 ? Math.min(1, Math.max(0, ap / ab)) : 0;
    let d2 = 0;
    for (let k = 0; k < dim; ++k) {
      const q = flat[i * dim + k] + u * (flat[j * dim + k] - flat[i * dim + k]) - p[k];
      d2 += q * q;
    }
    best = Math.min(best, d2);
  }
  return Math.sqrt(best);
}

// A noisy stroke: a wavy line of n samples, noise of amplitude `noise`.
function noisyStroke(rng, n, noise) {
  const flat = new Float64Array(2 * n);
  for (let i = 0; i < n; ++i) {
    const x = (i / (n - 1)) * 100;
    flat[2 * i] = x + rng.uniform(-noise, noise);
    flat[2 * i + 1] = 20 * Math.sin(x / 15) + rng.uniform(-noise, noise);
  }
  return flat;
}

// Both directions, measured: 64 samples per segment against the input
// polyline, and every input point against the curve (nearest, exact).
function measured(r, flat, dim, closed) {
  let curveToInput = 0, inputToCurve = 0;
  const c = r.curve, t0 = c.tMin, t1 = c.tMax, N = 64 * c.segmentCount;
  for (let k = 0; k <= N; ++k) curveToInput = Math.max(curveToInput, toPolyline(c.evaluate(k === N ? t1 : t0 + ((t1 - t0) * k) / N), flat, dim, closed));
  for (let i = 0; i < flat.length / dim; ++i) inputToCurve = Math.max(inputToCurve, c.nearest(flat.subarray(i * dim, (i + 1) * dim)).distance);
  return { curveToInput, inputToCurve };
}

test('fit: a noisy 400-sample stroke -> few control points, within the tolerance both ways (measured), subset indices', () => {
  const rng = seeded();
  let checked = 0;
  for (const [mode, noise, tol] of [['subset', 0.05, 0.25], ['free', 0.2, 0.5], ['subset', 0, 0.05]]) {
    const flat = noisyStroke(rng, 400, noise);
    const r = fit(flat, { dimension: 2, tolerance: tol, mode });
    const why = `seed ${rng.seed}, ${mode}, noise ${noise}, tolerance ${tol}`;
    assert.equal(r.count, r.curve.pointCount, why);
    assert.ok(r.count >= 2 && r.count <= 40, `${why}: ${r.count} control points of 400`);
    assert.ok(r.deviation <= tol && r.deviation === Math.max(r.curveToInput, r.inputToCurve), why);
    const m = measured(r, flat, 2, false);
    // Sampling can only find less than the proved bound (plus rounding, 1e-12 of the scale 100).
    assert.ok(m.curveToInput <= r.curveToInput + 1e-10, `${why}: curve to input ${m.curveToInput} > ${r.curveToInput}`);
    assert.ok(m.inputToCurve <= r.inputToCurve + 1e-10, `${why}: input to curve ${m.inputToCurve} > ${r.inputToCurve}`);
    if (mode === 'subset') {
      const idx = Array.from(r.indices), pts = r.curve.points;
      assert.equal(idx[0], 0);
      assert.equal(idx[idx.length - 1], 399);
      idx.forEach((k, j) => {
        assert.ok(j === 0 || k > idx[j - 1], why);
        assert.equal(pts[2 * j], flat[2 * k]);  // real vertices, bit for bit
        assert.equal(pts[2 * j + 1], flat[2 * k + 1]);
      });
    } else {
      assert.equal(r.indices, null);
    }
    r.curve.dispose();
    ++checked;
  }
  assert.equal(checked, 3);
});

test('fit: closed rings, 3-D points, {x, y} objects; where the fit raises tension the curve carries it (kb)', () => {
  const ring = Array.from({ length: 200 }, (_, i) => [30 * Math.cos((2 * Math.PI * i) / 200), 20 * Math.sin((2 * Math.PI * i) / 200)]);
  // 200 samples of an ellipse: a tenth of a unit keeps 14 (measured), where
  // the samples' own chords sag by 0.003.
  const r = fit(ring, { tolerance: 0.1, closed: true });
  assert.equal(r.curve.closed, true);
  assert.ok(r.count < 30, `${r.count}`);
  const flat = Float64Array.from(ring.flat());
  const m = measured(r, flat, 2, true);
  assert.ok(m.curveToInput <= r.deviation + 1e-10 && m.inputToCurve <= r.deviation + 1e-10, JSON.stringify(m));
  const helix = Array.from({ length: 300 }, (_, i) => ({ x: Math.cos(i / 20), y: Math.sin(i / 20), z: i / 100 }));
  const h = fit(helix, { tolerance: 1e-3 });
  assert.equal(h.curve.dimension, 3);
  assert.ok(h.count < 100, `${h.count}`);  // measured: 77 of 300
  // A staircase (marching-squares contour): a curve through its corners
  // bulges past a tenth of a step, so the fit raises tension there.
  const stairs = [];
  for (let i = 0; i < 40; ++i) stairs.push([i, i], [i + 1, i]);
  const s = fit(stairs, { tolerance: 0.05 });
  assert.ok(s.tensioned > 0, `tensioned ${s.tensioned}`);
  const ms = measured(s, Float64Array.from(stairs.flat()), 2, false);
  assert.ok(ms.curveToInput <= 0.05 + 1e-10 && ms.inputToCurve <= 0.05 + 1e-10, JSON.stringify(ms));
  for (const c of [r, h, s]) c.curve.dispose();
});

test('fit: bad input gets the core\'s errors', () => {
  const pts = [[0, 0], [1, 1], [2, 0]];
  assert.throws(() => fit(pts, { tolerance: 0 }), /tolerance must be a positive finite number, got 0/);
  assert.throws(() => fit(pts, { tolerance: -1 }), /tolerance must be a positive finite number/);
  assert.throws(() => fit(pts, {}), /tolerance is missing/);
  assert.throws(() => fit([[0, 0], [NaN, 1], [2, 0]], { tolerance: 0.1 }), /point 1 has a non-finite coordinate 0/);
  assert.throws(() => fit([[0, 0]], { tolerance: 0.1 }), /needs at least 2 points, got 1/);
  assert.throws(() => fit([[1e6, 0], [1e6 + 1, 1]], { tolerance: 1e-12 }), /at or below the rounding floor 5\.\d+e-08/);
  assert.throws(() => fit(pts, { tolerance: 0.1, mode: 'exact' }), /mode must be 'subset' or 'free', got 'exact'/);
  assert.throws(() => fit(pts, { tolerance: 0.1, smooth: true }), /unknown option 'smooth'/);
  assert.throws(() => fit(pts, { tolerance: 0.1, alpha: 2 }), /alpha must be in \[0, 1\], got 2/);
});

// A trefoil knot through 12 points, closed.
const knot = Array.from({ length: 12 }, (_, i) => {
  const a = (2 * Math.PI * i) / 12;
  return [Math.sin(a) + 2 * Math.sin(2 * a), Math.cos(a) - 2 * Math.cos(2 * a), -Math.sin(3 * a)];
});

const ring = (a, k, m, w) => a.subarray(k * m * w, (k + 1) * m * w);

test('sweep: a closed knot closes with no seam (positions, normals, u equal; v 0 and 1); without the spread it does not', () => {
  const c = catmullRom(knot, { closed: true });
  const m = sweep(c, { radius: 0.3, tubularSegments: 120, radialSegments: 16 });
  assert.equal(m.rings, 121);
  assert.equal(m.ringSize, 17);
  assert.equal(m.positions.length, 121 * 17 * 3);
  assert.equal(m.normals.length, m.positions.length);
  assert.equal(m.uvs.length, 121 * 17 * 2);
  assert.equal(m.indices.length, 120 * 16 * 6);
  assert.deepEqual(ring(m.positions, 120, 17, 3), ring(m.positions, 0, 17, 3));
  assert.deepEqual(ring(m.normals, 120, 17, 3), ring(m.normals, 0, 17, 3));
  for (let j = 0; j < 17; ++j) {
    assert.equal(m.uvs[2 * (120 * 17 + j)], m.uvs[2 * j]);
    assert.equal(m.uvs[2 * j + 1], 0);
    assert.equal(m.uvs[2 * (120 * 17 + j) + 1], 1);
  }
  // The computed closing ring met the first to rounding (the report).
  assert.ok(m.report.seamGap < 1e-9 && m.report.seamNormalGap < 1e-9, JSON.stringify(m.report));
  assert.ok(Math.abs(m.report.holonomy) > 0.01, `holonomy ${m.report.holonomy}`);
  // The rings' frames against the exact rotation-minimizing frame: finite, inside the bound.
  assert.ok(m.report.frameDrift > 0 && m.report.bound >= 2 * 0.3 * m.report.frameDrift, JSON.stringify(m.report));
  for (let v = 0; v < m.normals.length; v += 3)
    assert.ok(Math.abs(Math.hypot(m.normals[v], m.normals[v + 1], m.normals[v + 2]) - 1) < 1e-6);
  // Without the spread twist the closing ring misses the first by the holonomy.
  const seam = sweep(c, { radius: 0.3, tubularSegments: 120, radialSegments: 16, spreadHolonomy: false });
  assert.ok(seam.report.seamNormalGap > 0.01, JSON.stringify(seam.report));
  c.dispose();
});

test('sweep: the rings sit on the curve the package holds (tension, kb, given tangents): the curve crosses as its Bezier form', () => {
  const curves = [catmullRom(knot, { closed: true, tension: 0.3 }),
    catmullRom(knot.slice(0, 7), { kb: { tension: [0, 0.5, -0.3, 0.8, 0.2, 0.1, 0], bias: [0, 0.2, 0, 0, -0.4, 0, 0] } }),
    // Continuity: incoming and outgoing tangents differ at the knots.
    catmullRom(knot.slice(0, 7), { kb: { continuity: [0, 0.6, -0.5, 0.4, 0, -0.7, 0] } }),
    catmullRom(knot.slice(0, 4), { alpha: 1, start: 'reflect' })];
  let rings = 0;
  for (const c of curves) {
    const m = sweep(c, { radius: 0.1, radialSegments: 8, clearance: false });
    for (let k = 0; k < m.rings; ++k) {
      // The ring's centre: the mean of its 8 distinct vertices.
      const x = c.evaluate(m.t[k]), ctr = [0, 0, 0];
      for (let j = 0; j < 8; ++j) for (let i = 0; i < 3; ++i) ctr[i] += m.positions[3 * (k * 9 + j) + i] / 8;
      // Float32 positions around |x| <= 3: 1e-6.
      assert.ok(Math.hypot(ctr[0] - x[0], ctr[1] - x[1], ctr[2] - x[2]) < 1e-6, `ring ${k}`);
      ++rings;
    }
    assert.ok(m.report.toleranceMet);
    c.dispose();
  }
  assert.ok(rings > 30, `${rings}`);
});

test('sweep: profiles, scale, roll, up; bad input names the field', () => {
  const c = catmullRom(knot, { closed: true });
  const square = sweep(c, { profile: [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]], tubularSegments: 50 });
  assert.equal(square.ringSize, 4);
  const closedSquare = sweep(c, { profile: { points: [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]], closed: true }, tubularSegments: 50 });
  assert.equal(closedSquare.ringSize, 5);
  const L = sweep(c, { radius: 0.2, tubularSegments: 10, radialSegments: 6 }).report.length;
  // A closed curve's scale keys are periodic: in [0, L).
  const scaled = sweep(c, { radius: 0.2, scale: [1, 2], scaleS: [0, L / 2], tubularSegments: 10, radialSegments: 6 });
  assert.ok(Math.abs(scaled.report.largestRadius - 0.4) < 1e-9, `${scaled.report.largestRadius}`);
  // An up vector: proved where every tangent stays clear of it (the knot's
  // stay more than 30 degrees from vertical) and through a loop's vertical
  // passes (the poles) too; at three.js' counts the rings next to the cone
  // around vertical are too far apart for the up frame to be bounded there.
  const withUp = sweep(c, { radius: 0.2, up: { x: 0, y: 0, z: 1 } });
  assert.ok(withUp.report.proved && withUp.report.toleranceMet);
  const vertical = catmullRom([[0, 0, 0], [1, 0, 1], [0, 0, 2], [-1, 0, 1], [0, 0.01, 0.1], [1, 0.02, 0]]);
  const overPole = sweep(vertical, { radius: 0.1, up: [0, 0, 1] });
  assert.ok(overPole.report.proved && overPole.report.toleranceMet, JSON.stringify(overPole.report));
  const coarse = sweep(vertical, { radius: 0.1, up: [0, 0, 1], tubularSegments: 64, radialSegments: 8 });
  assert.ok(!coarse.report.proved);
  const err = (f, field, re) => assert.throws(f, (e) => re.test(e.message) && e.field === field);
  err(() => sweep(c, { radius: 0 }), 'radius', /radius: must be positive and finite, got 0/);
  err(() => sweep(c, { radius: NaN }), 'radius', /radius: must be positive/);
  err(() => sweep(c, { profile: [[0, 0]] }), 'profile', /profile/);
  err(() => sweep(c, { roll: [0, 1] }), 'roll', /roll: 2 angles for 12 knots/);
  err(() => sweep(c, { up: [0, 0, 0] }), 'up', /up: must not be the zero vector/);
  const flat = catmullRom([[0, 0], [1, 1], [2, 0]]);
  err(() => sweep(flat, {}), 'curve', /curve: sweep needs a 3-D curve, got a 2-D one/);
  assert.throws(() => sweep(c, { radiu: 1 }), (e) => /unknown option 'radiu'/.test(e.message) && e.field === 'radiu');
  c.dispose();
  flat.dispose();
});

// Area of a ring (flat x, y) by the shoelace formula.
function area(r) {
  let a = 0;
  for (let i = 0, n = r.length / 2; i < n; ++i) {
    const j = (i + 1) % n;
    a += r[2 * i] * r[2 * j + 1] - r[2 * j] * r[2 * i + 1];
  }
  return a / 2;
}

test('stroke: a gentle open curve at width w covers w x its length (within tolerance x perimeter); joins, caps and errors', () => {
  const c = catmullRom([[0, 0], [30, 10], [60, 0], [90, 10]]);
  const w = 4, L = c.arcLength();
  const s = stroke(c, w, { tolerance: 0.01 });
  assert.equal(s.polygons.length, 1);
  const [exterior, ...holes] = s.polygons[0];
  assert.equal(holes.length, 0);
  const perimeter = 2 * L + 2 * w;
  assert.ok(Math.abs(Math.abs(area(exterior)) - w * L) <= 0.01 * perimeter, `${area(exterior)} vs ${w * L}`);
  // Round caps add a disc of diameter w.
  const round = stroke(c, w, { cap: 'round', tolerance: 0.01 });
  assert.ok(Math.abs(Math.abs(area(round.polygons[0][0])) - (w * L + Math.PI * w * w / 4)) <= 0.01 * (perimeter + Math.PI * w));
  // A curve through a corner: the joins differ.
  const corner = catmullRom([[0, 0], [10, 0], [10, 10]], { tension: 1 });
  const areas = ['round', 'miter', 'bevel'].map((join) => Math.abs(area(stroke(corner, 2, { join, tolerance: 0.001 }).polygons[0][0])));
  assert.ok(areas[1] > areas[0] && areas[0] > areas[2], JSON.stringify(areas));
  // A loop that overlaps itself: one polygon, the union (a hole inside the loop).
  const loop = catmullRom([[0, 0], [20, 0], [20, 10], [10, 10], [10, -10]]);
  const lp = stroke(loop, 1, { tolerance: 0.01 });
  assert.equal(lp.polygons.length, 1);
  assert.equal(lp.polygons[0].length, 2);
  const err = (f, field, re) => assert.throws(f, (e) => re.test(e.message) && e.field === field);
  err(() => stroke(c, 0), 'width', /width: must be positive and finite, got 0/);
  err(() => stroke(c, 1, { join: 'sharp' }), 'join', /join: must be 'round', 'miter' or 'bevel', got 'sharp'/);
  err(() => stroke(c, 1, { miterLimit: 0.5 }), 'miter_limit', /miter_limit: must be at least 1/);
  const k = catmullRom(knot, { closed: true });
  err(() => stroke(k, 1), 'curve', /curve: stroke needs a 2-D curve, got a 3-D one/);
  for (const x of [c, corner, loop, k]) x.dispose();
});
