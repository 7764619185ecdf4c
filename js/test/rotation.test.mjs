// The npm package's rotations (issue 28): quaternionSpline, rotationSpline
// and poseCurve in crspline's [w, x, y, z], and crspline/three's
// CRSplineQuaternionCurve and CRSplinePoseCurve, which take and give
// THREE.Quaternion ([x, y, z, w]) so that the user never reorders.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as THREE from 'three';
import { init, quaternionSpline, rotationSpline, poseCurve, toXYZW, fromXYZW } from 'crspline';
import { CRSplineQuaternionCurve, CRSplinePoseCurve } from 'crspline/three';
import { reference, seeded } from './support.mjs';

await init();
const upToSign = (q, p) => Math.min(Math.hypot(...q.map((x, i) => x - p[i])), Math.hypot(...q.map((x, i) => x + p[i])));

test('rotationSpline: SciPy\'s converged RotationSpline (the numbers Python and C++ reproduce), 1e-12', () => {
  const cases = reference('rotation_spline_scipy.json').cases.filter((c) => c.class === 'RotationSpline');
  let compared = 0;
  for (const c of cases) {
    const s = rotationSpline(c.times, c.keys);
    const many = s.evaluateMany(c.t, 1, 'body');
    c.t.forEach((t, k) => {
      // The file's tolerances: rotations 1e-12, body rates 1e-10 of their scale.
      assert.ok(upToSign(Array.from(s.quaternion(t)), c.converged.q[k]) <= 1e-12, `${c.name} t=${t}`);
      assert.ok(upToSign(Array.from(many.q.subarray(4 * k, 4 * k + 4)), c.converged.q[k]) <= 1e-12);
      const scale = Math.max(1, ...c.converged.rate.flat().map(Math.abs));
      for (let d = 0; d < 3; ++d) assert.ok(Math.abs(many.omega[3 * k + d] - c.converged.rate[k][d]) <= 1e-10 * scale);
      compared++;
    });
    assert.equal(s.kind, 'c2');
    s.dispose();
    assert.equal(s.disposed, true);
    assert.throws(() => s.quaternion(0), /this curve was disposed/);
  }
  assert.equal(cases.length, 8);
  assert.equal(compared, cases.reduce((n, c) => n + c.t.length, 0));
});

test('quaternionSpline: keys at the knots, unit norm in between (seeded)', () => {
  const { seed, uniform } = seeded();
  const keys = [];
  for (let i = 0; i < 7; ++i) {
    const q = [uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)];
    const r = Math.hypot(...q);
    keys.push(q.map((x) => x / r));
  }
  let checked = 0;
  for (const alpha of [0, 0.5, 1]) {
    const s = quaternionSpline(keys, { alpha });
    const g = s.grid, K = s.keys;
    assert.equal(g.length, 7, `seed ${seed}`);
    for (let k = 0; k < 7; ++k) {
      // A key is its sign-corrected input, up to slerp's rounding (a few eps).
      assert.ok(upToSign(Array.from(s.quaternion(g[k])), keys[k]) <= 1e-14, `alpha ${alpha} key ${k} seed ${seed}`);
      assert.ok(upToSign(Array.from(K.subarray(4 * k, 4 * k + 4)), keys[k]) <= 1e-15, `seed ${seed}`);
    }
    for (let i = 0; i < 50; ++i) {
      const q = s.quaternion(uniform(s.tMin, s.tMax));
      assert.ok(Math.abs(Math.hypot(...q) - 1) <= 1e-14, `alpha ${alpha}: |q| ${Math.hypot(...q)} seed ${seed}`);
      checked++;
    }
    s.dispose();
  }
  assert.equal(checked, 150);
});

test('order conversion: toXYZW / fromXYZW, and the three.js adapter reorders for the user', () => {
  assert.deepEqual(Array.from(toXYZW([1, 2, 3, 4])), [2, 3, 4, 1]);
  assert.deepEqual(Array.from(fromXYZW([2, 3, 4, 1])), [1, 2, 3, 4]);
  // A quarter turn about z and a half turn about x, as three.js writes them.
  const a = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 0, 1), Math.PI / 2);
  const b = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(1, 0, 0), Math.PI / 3);
  const curve = new CRSplineQuaternionCurve([new THREE.Quaternion(), a, b]);
  const mid = curve.getQuaternion(0.5);
  assert.ok(mid instanceof THREE.Quaternion);
  // u = 1/2 is the middle key (uniform grid 0, 1, 2 by default).
  assert.ok(Math.abs(Math.abs(mid.dot(a)) - 1) <= 1e-15 * 4, `${mid.toArray()}`);
  // Between keys: the adapter's rotation is the core's, reordered.
  const core = quaternionSpline([[1, 0, 0, 0], [a.w, a.x, a.y, a.z], [b.w, b.x, b.y, b.z]]);
  const q = curve.getQuaternion(0.3), c = core.quaternion(0.6);
  assert.deepEqual(q.toArray(), [c[1], c[2], c[3], c[0]]);
  // Arrays in three's own order are taken too.
  const fromArrays = new CRSplineQuaternionCurve([[0, 0, 0, 1], a.toArray(), b.toArray()]);
  assert.deepEqual(fromArrays.getQuaternion(0.3).toArray(), q.toArray());
  // Angular velocity per unit u: the middle of a two-key quarter turn about z.
  const two = new CRSplineQuaternionCurve([new THREE.Quaternion(), a]);
  const w = two.getAngularVelocity(0.5);
  assert.ok(Math.abs(w.z - Math.PI / 2) <= 1e-12 && Math.abs(w.x) <= 1e-15 && Math.abs(w.y) <= 1e-15, `${w.toArray()}`);
  // The C2 spline through the adapter.
  const c2 = new CRSplineQuaternionCurve([new THREE.Quaternion(), a, b], { times: [0, 1, 3] });
  assert.equal(c2.curve.kind, 'c2');
  assert.ok(Math.abs(Math.abs(c2.getQuaternion(1 / 3).dot(a)) - 1) <= 1e-14);
  assert.throws(() => new CRSplineQuaternionCurve([new THREE.Quaternion(), [1, 0, 0]]), /quaternions\[1\] must be a THREE.Quaternion or \[x, y, z, w\]/);
  for (const x of [curve, core, fromArrays, two, c2]) x.dispose();
});

test('CRSplinePoseCurve: an Object3D placed at the pose; a camera looks along the pose\'s -z', () => {
  const positions = [new THREE.Vector3(0, 0, 5), new THREE.Vector3(5, 0, 0), new THREE.Vector3(0, 0, -5), new THREE.Vector3(-5, 0, 0)];
  // Each key looks at the origin from its position.
  const look = (p) => new THREE.Quaternion().setFromRotationMatrix(new THREE.Matrix4().lookAt(p, new THREE.Vector3(), new THREE.Vector3(0, 1, 0)));
  const path = new CRSplinePoseCurve(positions, positions.map(look));
  const camera = new THREE.PerspectiveCamera();
  let n = 0;
  for (let k = 0; k < 4; ++k) {
    path.applyTo(camera, k / 3);
    camera.updateMatrixWorld();
    assert.ok(camera.position.distanceTo(positions[k]) <= 1e-14 * 5 * 4, `key ${k}: ${camera.position.toArray()}`);
    const dir = camera.getWorldDirection(new THREE.Vector3());
    const want = positions[k].clone().negate().normalize();
    assert.ok(dir.distanceTo(want) <= 1e-7, `key ${k}: looks along ${dir.toArray()}, not ${want.toArray()}`);  // three's Matrix4 is float64 but lookAt goes through Euler-free float math: 1e-7 covers it
    n++;
  }
  // Between keys: the adapter's pose is the core's (reordered), and the Curve
  // of positions is a three.js Curve (TubeGeometry takes it).
  const core = poseCurve(positions.map((p) => p.toArray()), positions.map(look).map((q) => [q.w, q.x, q.y, q.z]));
  const s = core.evaluate(core.tMin + 0.4 * (core.tMax - core.tMin));
  path.applyTo(camera, 0.4);
  assert.deepEqual(camera.position.toArray(), Array.from(s.position));
  assert.deepEqual(camera.quaternion.toArray(), [s.orientation[1], s.orientation[2], s.orientation[3], s.orientation[0]]);
  const tube = new THREE.TubeGeometry(path, 40, 0.1, 6, false);
  assert.equal(tube.attributes.position.count, 41 * 7);
  const u = path.constantSpeedU(5);
  assert.equal(u.length, 5);
  assert.ok(u[0] === 0 && Math.abs(u[4] - 1) <= 1e-12);
  assert.equal(n, 4);
  path.dispose();
  core.dispose();
});
