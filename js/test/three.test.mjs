// crspline/three: CRSplineCurve3 against three.js r187's CatmullRomCurve3
// (tests/reference/threejs_d3.json, provenance in tests/reference/SOURCES.md)
// and inside three.js' own geometry code (TubeGeometry, ExtrudeGeometry).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as THREE from 'three';
import { init } from 'crspline';
import { CRSplineCurve3 } from 'crspline/three';
import { reference } from './support.mjs';

await init();
const data = reference('threejs_d3.json');
const vec3 = (p) => new THREE.Vector3(p[0], p[1], p[2] ?? 0);
const scaleOf = (pts) => Math.max(1, ...pts.flat().map(Math.abs));

test('getPoint: the numbers of CatmullRomCurve3 (r187) on every reference case three.js computes exactly', () => {
  let checked = 0, skipped = 0, variants = 0;
  for (const c of data.cases)
    for (const v of c.three) {
      // guardFired: three.js replaced a knot interval under 1e-4 by a
      // constant, which is not the Catmull-Rom curve (SOURCES.md): crspline
      // differs there on purpose (checked below for being finite and interpolating).
      if (v.guardFired === true) {
        ++skipped;
        continue;
      }
      const curve = new CRSplineCurve3(c.points.map(vec3), v.closed, v.curveType, v.tension);
      // As tests/reference/test_reference.cpp: 1e-12 of the coordinate scale
      // (SOURCES.md: three.js' own arithmetic is good to ~1e-9 near 1e3).
      const tol = 1e-12 * scaleOf(c.points);
      const target = new THREE.Vector3();
      v.getPoint.forEach((want, j) => {
        const u = j / 100;
        const got = curve.getPoint(u, target);
        assert.equal(got, target);
        const err = Math.max(Math.abs(got.x - want[0]), Math.abs(got.y - want[1]), Math.abs(got.z - want[2]));
        assert.ok(err <= tol, `${c.id} ${v.curveType} tension ${v.tension} closed ${v.closed} u ${u}: ${err} > ${tol}`);
        ++checked;
      });
      ++variants;
      curve.dispose();
    }
  assert.equal(skipped, 10);  // the guarded variants: near-coincident, duplicate and repeated points
  assert.equal(variants, 46);
  assert.equal(checked, 46 * 101);
});

test('where three.js guards a tiny knot interval, CRSplineCurve3 gives the exact curve: finite, through every point', () => {
  let checked = 0;
  for (const c of data.cases)
    for (const v of c.three) {
      if (v.guardFired !== true) continue;
      const curve = new CRSplineCurve3(c.points.map(vec3), v.closed, v.curveType, v.tension);
      const nseg = v.closed ? c.points.length : c.points.length - 1;
      for (let i = 0; i <= nseg; ++i) {
        const p = curve.getPoint(i / nseg), want = c.points[i % c.points.length];
        assert.ok(Math.abs(p.x - want[0]) + Math.abs(p.y - want[1]) + Math.abs(p.z - (want[2] ?? 0)) <= 1e-12 * scaleOf(c.points), `${c.id} ${i}`);
      }
      for (let j = 0; j <= 100; ++j) {
        const p = curve.getPoint(j / 100), t = curve.getTangent(j / 100);
        assert.ok([p.x, p.y, p.z, t.x, t.y, t.z].every(Number.isFinite), `${c.id} u ${j / 100}`);
      }
      ++checked;
      curve.dispose();
    }
  assert.equal(checked, 10);
});

test('getLength and getPointAt: arc length to 1e-9, where three.js is off by 1e-5 to 1e-3', () => {
  let checked = 0;
  for (const c of data.cases)
    for (const v of c.three) {
      if (v.guardFired === true) continue;
      const curve = new CRSplineCurve3(c.points.map(vec3), v.closed, v.curveType, v.tension);
      const L = curve.getLength();
      // lengthRef: 2^20 chords of three's curve; the chord sum falls short by
      // about L (h kappa)^2 / 24, under 1e-9 L on these cases.
      assert.ok(Math.abs(L - v.lengthRef) <= 1e-9 * v.lengthRef, `${c.id} ${v.curveType}: ${L} vs ${v.lengthRef}`);
      // An independent arc length: 2^15 chords per segment of our own
      // getPoint (so every knot, where three's t changes speed, is a
      // sample: a chord across one would interpolate s wrongly), then
      // |s(getUtoTmapping(u)) / L - u| for u = k / 50. The polyline's own
      // error is ~1e-9 relative; three.js' is v.getPointAtArcErr.
      const nseg = v.closed ? c.points.length : c.points.length - 1;
      const N = nseg << 15, cum = new Float64Array(N + 1);
      const a = new THREE.Vector3(), b = new THREE.Vector3();
      curve.getPoint(0, a);
      for (let k = 1; k <= N; ++k) {
        curve.getPoint(k / N, b);
        cum[k] = cum[k - 1] + a.distanceTo(b);
        a.copy(b);
      }
      let worst = 0;
      for (let k = 0; k <= 50; ++k) {
        const u = k / 50, t = curve.getUtoTmapping(u);
        const x = t * N, i = Math.min(N - 1, Math.floor(x));
        const s = cum[i] + (cum[i + 1] - cum[i]) * (x - i);
        worst = Math.max(worst, Math.abs(s / cum[N] - u));
      }
      assert.ok(worst <= 1e-7, `${c.id} ${v.curveType}: ${worst}`);
      assert.ok(worst < v.getPointAtArcErr / 100, `${c.id} ${v.curveType}: ours ${worst}, three.js ${v.getPointAtArcErr}`);
      // getPointAt is getPoint at that t; distance mode agrees with u mode.
      assert.deepEqual(curve.getPointAt(0.3), curve.getPoint(curve.getUtoTmapping(0.3)));
      assert.equal(curve.getUtoTmapping(0, 0.4 * L), curve.getUtoTmapping(0.4));
      const lengths = curve.getLengths(10);
      assert.equal(lengths.length, 11);
      assert.ok(Math.abs(lengths[10] - L) <= 1e-12 * L);
      ++checked;
      curve.dispose();
    }
  assert.equal(checked, 46);
});

test('getTangent: the exact unit tangent (central differences of getPoint agree to 1e-6)', () => {
  const pts = data.cases.find((c) => c.id === 'rand3d_5').points.map(vec3);
  for (const closed of [false, true])
    for (const type of ['centripetal', 'chordal', 'catmullrom']) {
      const curve = new CRSplineCurve3(pts, closed, type);
      const ref = new THREE.CatmullRomCurve3(pts, closed, type);
      for (let k = 0; k < 100; ++k) {
        // Off the knots: there three.js' t changes speed (each segment an
        // equal share of t), and a difference across it is not the tangent.
        const u = (k + 0.5) / 100, h = 1e-7;
        const tan = curve.getTangent(u);
        assert.ok(Math.abs(tan.length() - 1) <= 1e-15 * 4);
        const fd = curve.getPoint(u + h).sub(curve.getPoint(u - h)).normalize();
        // Central difference: error h^2 |x'''| / |x'| plus rounding eps |x| / h,
        // about 1e-8 here.
        assert.ok(tan.distanceTo(fd) <= 1e-6, `${type} closed ${closed} u ${u}: ${tan.distanceTo(fd)}`);
        // three.js' own tangent (a difference with delta 1e-4) points the same way.
        assert.ok(tan.distanceTo(ref.getTangent(u)) <= 1e-3, `${type} closed ${closed} u ${u}`);
      }
      curve.dispose();
    }
});

test('TubeGeometry and ExtrudeGeometry built from a CRSplineCurve3: rings of the radius around getPointAt', () => {
  const pts = data.cases.find((c) => c.id === 'rand3d_5').points.map(vec3);
  const curve = new CRSplineCurve3(pts, false, 'centripetal');
  const tubular = 64, radial = 8, radius = 0.25;
  const tube = new THREE.TubeGeometry(curve, tubular, radius, radial, false);
  const pos = tube.attributes.position;
  assert.equal(pos.count, (tubular + 1) * (radial + 1));
  const v = new THREE.Vector3();
  let checked = 0;
  for (let i = 0; i <= tubular; ++i) {
    const center = curve.getPointAt(i / tubular);
    const tangent = curve.getTangentAt(i / tubular);
    for (let j = 0; j <= radial; ++j) {
      v.fromBufferAttribute(pos, i * (radial + 1) + j).sub(center);
      // On the circle of the radius, in the plane normal to the tangent
      // (three.js computes in float32 buffers: 1e-6 relative).
      assert.ok(Math.abs(v.length() - radius) <= 1e-6, `ring ${i}, vertex ${j}: ${v.length()}`);
      assert.ok(Math.abs(v.dot(tangent)) <= 1e-6, `ring ${i}, vertex ${j}`);
      ++checked;
    }
  }
  assert.equal(checked, pos.count);
  const shape = new THREE.Shape([new THREE.Vector2(0, 0), new THREE.Vector2(0.3, 0), new THREE.Vector2(0, 0.3)]);
  const ext = new THREE.ExtrudeGeometry(shape, { steps: 40, extrudePath: curve });
  const epos = ext.attributes.position.array;
  assert.ok(epos.length > 0);
  assert.ok(epos.every(Number.isFinite));
  tube.dispose();
  ext.dispose();
  curve.dispose();
});

test('drop-in: constructor defaults, updateArcLengths after moving points, copy, clone and JSON', () => {
  const pts = [new THREE.Vector3(0, 0, 0), new THREE.Vector3(1, 2, 0), new THREE.Vector3(3, 1, 1), new THREE.Vector3(4, 3, 0)];
  const a = new CRSplineCurve3(pts);
  const b = new THREE.CatmullRomCurve3(pts);
  assert.equal(a.curveType, b.curveType);
  assert.equal(a.closed, b.closed);
  assert.equal(a.tension, b.tension);
  assert.ok(a instanceof THREE.Curve);
  assert.ok(a.getPoint(0.4).distanceTo(b.getPoint(0.4)) <= 1e-12 * 4);
  const before = a.getPoint(0.5).clone();
  pts[2].set(3, -1, 2);
  a.updateArcLengths();
  b.updateArcLengths();
  assert.ok(a.getPoint(0.5).distanceTo(before) > 0.1);
  assert.ok(a.getPoint(0.5).distanceTo(b.getPoint(0.5)) <= 1e-12 * 4);
  // A new points array is picked up without a call.
  a.points = pts.map((p) => p.clone().setZ(p.z + 1));
  assert.ok(Math.abs(a.getPoint(0.5).z - b.getPoint(0.5).z - 1) <= 1e-12 * 4);
  a.points = pts;
  const c = a.clone();
  assert.ok(c instanceof CRSplineCurve3);
  assert.deepEqual(c.getPoint(0.7), a.getPoint(0.7));
  const d = new CRSplineCurve3().fromJSON(JSON.parse(JSON.stringify(a.toJSON())));
  assert.deepEqual(d.getPoint(0.7), a.getPoint(0.7));
  assert.equal(d.type, 'CRSplineCurve3');
  // Closed: t = 1 is t = 0.
  const loop = new CRSplineCurve3(pts, true, 'chordal');
  assert.ok(loop.getPoint(1).distanceTo(loop.getPoint(0)) === 0);
  assert.throws(() => new CRSplineCurve3(pts, false, 'catmullrom', 0.7).getPoint(0.5),
    (e) => /tension must be in \[0, 0.5\] for curveType 'catmullrom'/.test(e.message) && e.field === 'tension');
  assert.throws(() => new CRSplineCurve3(pts, false, 'bspline').getPoint(0.5), /curveType must be/);
  assert.throws(() => new CRSplineCurve3([pts[0]]).getPoint(0.5), /a curve needs at least 2 points, got 1/);
  for (const x of [a, c, d, loop]) x.dispose();
});
