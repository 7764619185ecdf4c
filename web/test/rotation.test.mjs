// The rotation and pose splines of the WASM module (issue 28,
// web/src/bind_rotation.cpp): SciPy's converged RotationSpline from
// tests/reference/rotation_spline_scipy.json (the numbers Python's
// tests/python/test_rotation.py checks too), unit norm and interpolation at
// the keys on seeded random keys, the pose curve, and the errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadModule, reference } from './support.mjs';

const M = await loadModule();
const seed = Number(process.env.CRSPLINE_SEED ?? 20260528);

// A small seeded generator (mulberry32): the seed is in every message.
function rng(s) {
  return () => {
    s |= 0; s = (s + 0x6D2B79F5) | 0;
    let t = Math.imul(s ^ (s >>> 15), 1 | s);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
function randomKeys(rand, n) {
  const out = [];
  for (let i = 0; i < n; ++i) {
    const q = [rand() - 0.5, rand() - 0.5, rand() - 0.5, rand() - 0.5];
    const r = Math.hypot(...q);
    out.push(...q.map((x) => x / r));
  }
  return out;
}
// |q - p| up to sign (q and -q are one rotation).
const upToSign = (q, p) => Math.min(Math.hypot(...q.map((x, i) => x - p[i])), Math.hypot(...q.map((x, i) => x + p[i])));
function use(o, f) {
  try { return f(o); } finally { o.delete(); }
}

test('C2 spline: SciPy\'s converged RotationSpline, rotations to 1e-12, body rates to 1e-10 of their scale', () => {
  const cases = reference('rotation_spline_scipy.json').cases.filter((c) => c.class === 'RotationSpline');
  assert.equal(cases.length, 8);
  let compared = 0;
  for (const c of cases) {
    use(M.RotationCurve.c2Spline(c.times, c.keys.flat(), {}), (s) => {
      const ref = c.converged;
      const rateScale = Math.max(1, ...ref.rate.flat().map(Math.abs));
      const accelScale = Math.max(1, ...ref.accel.flat().map(Math.abs));
      c.t.forEach((t, k) => {
        const j = s.evaluate(t, 2, 'body');
        // 1e-12 and 1e-10: the file's stated tolerances (tests/python uses the same).
        assert.ok(upToSign(Array.from(j.q), ref.q[k]) <= 1e-12, `${c.name} t=${t}: q ${Array.from(j.q)} vs ${ref.q[k]}`);
        for (let d = 0; d < 3; ++d) {
          assert.ok(Math.abs(j.omega[d] - ref.rate[k][d]) <= 1e-10 * rateScale, `${c.name} t=${t}: rate`);
          assert.ok(Math.abs(j.alpha[d] - ref.accel[k][d]) <= 1e-10 * accelScale, `${c.name} t=${t}: accel`);
        }
        compared++;
      });
      assert.ok(s.residual() <= 1e-9 * accelScale, `${c.name}: residual ${s.residual()}`);
      // The batch call gives the same rotations.
      const many = s.evaluateMany(c.t, 0, 'world').q;
      c.t.forEach((t, k) => assert.ok(upToSign(Array.from(many.subarray(4 * k, 4 * k + 4)), ref.q[k]) <= 1e-12));
    });
  }
  assert.equal(compared, cases.reduce((n, c) => n + c.t.length, 0));
});

test(`every kind: unit norm, the keys at the knots, world rate = R body rate (seed ${seed})`, () => {
  const rand = rng(seed);
  let checked = 0;
  for (const kind of ['catmull_rom', 'kochanek_bartels', 'piecewise_slerp', 'barry_goldman', 'squad']) {
    for (const closed of [false, true]) {
      const keys = randomKeys(rand, 6);
      use(M.RotationCurve.quaternionSpline(keys, { kind, closed, alpha: 0.5 }), (s) => {
        const g = Array.from(s.grid());
        assert.equal(g.length, closed ? 7 : 6, `${kind} closed=${closed} seed ${seed}`);
        const K = Array.from(s.keys());
        g.forEach((t, k) => {
          // At a knot: the key (after the sign rule) to a few ulps of slerp's rounding.
          const q = Array.from(s.evaluate(t).q);
          assert.ok(upToSign(q, K.slice(4 * k, 4 * k + 4)) <= 1e-14 * 16, `${kind} closed=${closed} key ${k} seed ${seed}`);
        });
        for (let i = 0; i < 20; ++i) {
          const t = g[0] + rand() * (g[g.length - 1] - g[0]);
          const w = s.evaluate(t, 1, 'world'), b = s.evaluate(t, 1, 'body');
          const q = Array.from(w.q);
          // Unit norm: products of unit quaternions, rounding only (1e-14).
          assert.ok(Math.abs(Math.hypot(...q) - 1) <= 1e-14, `${kind} t=${t} |q| = ${Math.hypot(...q)} seed ${seed}`);
          // world = R body: rotate the body rate by q.
          const [qw, qx, qy, qz] = q, v = Array.from(b.omega);
          const tx = 2 * (qy * v[2] - qz * v[1]), ty = 2 * (qz * v[0] - qx * v[2]), tz = 2 * (qx * v[1] - qy * v[0]);
          const r = [v[0] + qw * tx + (qy * tz - qz * ty), v[1] + qw * ty + (qz * tx - qx * tz), v[2] + qw * tz + (qx * ty - qy * tx)];
          const scale = 1 + Math.hypot(...w.omega);
          for (let d = 0; d < 3; ++d) assert.ok(Math.abs(r[d] - w.omega[d]) <= 1e-12 * scale, `${kind} t=${t} seed ${seed}`);
          checked++;
        }
      });
    }
  }
  assert.equal(checked, 5 * 2 * 20);
});

test('two keys: slerp, and the angle length is the angle between them', () => {
  const h = Math.SQRT1_2;
  use(M.RotationCurve.quaternionSpline([1, 0, 0, 0, h, 0, 0, h], {}), (s) => {
    const q = Array.from(s.evaluate(0.25).q);
    // slerp at 1/4 of a 90-degree turn about z: cos and sin of 11.25 degrees.
    const a = Math.PI / 16;
    assert.ok(upToSign(q, [Math.cos(a), 0, 0, Math.sin(a)]) <= 1e-15 * 8);
    assert.ok(Math.abs(s.angleLength(0) - Math.PI / 2) <= 1e-12 * Math.PI);
    const t = Array.from(s.constantAngularSpeedTimes(5, 0));
    t.forEach((x, k) => assert.ok(Math.abs(x - k / 4) <= 1e-12, `t ${t}`));
  });
});

test('pose curve: positions and orientations at the keys, rates in both frames', () => {
  const h = Math.SQRT1_2;
  const positions = [0, 0, 0, 1, 0, 0, 2, 1, 0, 3, 1, 1];
  const rotations = [1, 0, 0, 0, h, 0, 0, h, 0, 0, 0, 1, 0, 0, h, h];
  use(new M.PoseCurve(positions, rotations, {}), (p) => {
    const g = Array.from(p.grid());
    assert.equal(g.length, 4);
    g.forEach((t, k) => {
      const s = p.evaluate(t);
      for (let d = 0; d < 3; ++d) assert.ok(Math.abs(s.position[d] - positions[3 * k + d]) <= 1e-14 * 4);
      assert.ok(upToSign(Array.from(s.orientation), rotations.slice(4 * k, 4 * k + 4)) <= 1e-14);
    });
    const many = p.evaluateMany([g[1], g[2]]);
    assert.equal(many.positions.length, 6);
    assert.equal(many.orientations.length, 8);
    const u = Array.from(p.constantSpeedTimes(4, 1, 0, 0));
    assert.equal(u.length, 4);
    assert.equal(u[0], g[0]);
    assert.ok(Math.abs(u[3] - g[3]) <= 1e-12 * g[3]);
  });
});

test('errors name what is wrong', () => {
  // Keys are normalized, as SciPy's from_quat does (issue 42); zero is no rotation; a finite
  // unitTolerance refuses non-unit keys.
  assert.throws(() => M.RotationCurve.quaternionSpline([0, 0, 0, 0, 1, 0, 0, 0], {}), /key 0 \[0, 0, 0, 0\] has norm 0: not a rotation/);
  assert.throws(() => M.RotationCurve.quaternionSpline([2, 0, 0, 0, 1, 0, 0, 0], { unitTolerance: 1e-6 }), /key 0 .* is not a unit quaternion/);
  assert.throws(() => M.RotationCurve.quaternionSpline([1, 0, 0], {}), /keys has 3 numbers, not a multiple of 4/);
  assert.throws(() => M.RotationCurve.quaternionSpline([1, 0, 0, 0, 1, 0, 0, 0], { kind: 'cubic' }), /kind must be .* got 'cubic'/);
  assert.throws(() => M.RotationCurve.quaternionSpline([1, 0, 0, 0, 1, 0, 0, 0], { alphaa: 1 }), /unknown option 'alphaa'/);
  assert.throws(() => M.RotationCurve.c2Spline([0, 1], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0], {}), /times has 2 values for 3 keys/);
  use(M.RotationCurve.c2Spline([0, 1], [1, 0, 0, 0, 0, 1, 0, 0], {}), (s) => {
    assert.throws(() => s.evaluate(2, 0, 'world'), /t = 2 is outside the curve's domain \[0, 1\]/);
    assert.throws(() => s.evaluate(0.5, 1, 'space'), /frame must be 'world' or 'body', got 'space'/);
    assert.throws(() => s.evaluateMany([0, 3], 0, 'world'), /t = 3 \(index 1\) is outside/);
  });
  assert.throws(() => new M.PoseCurve([0, 0, 0, 1, 0, 0], [1, 0, 0, 0], {}), /2 positions but 1 rotations/);
});

test('Catmull-Rom family: the 40-digit q_exact and omega_exact of quaternion_splines.json (as Python\'s native API)', () => {
  // The cases' own tolerances (tol.q_exact, tol.omega_exact: float64 error
  // of the construction, from the file). The package's natural end
  // ('natural_splines') is the one those exact values are of.
  const cases = reference('quaternion_splines.json').cases.filter((c) => c.class === 'CatmullRom');
  assert.equal(cases.length, 17);
  let compared = 0;
  for (const c of cases) {
    const o = { closed: c.closed };
    if (c.alpha !== null) o.alpha = c.alpha;
    if (c.grid !== null) o.grid = c.grid;
    if (!c.closed) o.start = o.end = 'natural_splines';
    use(M.RotationCurve.quaternionSpline(c.keys.flat(), o), (s) => {
      const smp = c.samples;
      smp.t_exact.forEach((t, k) => {
        // t_exact is the decimal knot; the double grid may end an ulp short
        // of it (an ulp of t moves q by |omega| ulp, far under tol).
        const j = s.evaluate(Math.min(Math.max(t, s.tMin()), s.tMax()), 1, 'world');
        const dq = Math.max(...Array.from(j.q, (x, d) => Math.abs(x - smp.q_exact[k][d])));
        const dw = Math.max(...Array.from(j.omega, (x, d) => Math.abs(x - smp.omega_exact[k][d])));
        assert.ok(dq <= c.tol.q_exact, `${c.id} t=${t}: q off by ${dq}`);
        assert.ok(dw <= c.tol.omega_exact, `${c.id} t=${t}: omega off by ${dw}`);
        compared++;
      });
    });
  }
  assert.equal(compared, cases.reduce((n, c) => n + c.samples.t_exact.length, 0));
});
