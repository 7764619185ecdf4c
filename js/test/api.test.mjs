// The package's plain JavaScript API, imported from the installed tarball.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import * as crspline from 'crspline';
import { reference, maxAbs, seeded } from './support.mjs';

const { init, catmullRom, isReady, CatmullRom } = crspline;

test('init: curves need the module; init() loads it once and resolves to the API', async () => {
  assert.equal(isReady(), false);
  assert.throws(() => catmullRom([[0, 0], [1, 1]]), /call `await init\(\)`/);
  const [a, b] = await Promise.all([init(), init()]);
  assert.equal(a, b);
  assert.equal(a, crspline.default);
  assert.equal(isReady(), true);
  assert.match(a.version(), /^\d+\.\d+\.\d+/);
  // The package's version is the library's.
  const pkg = JSON.parse(fs.readFileSync(createRequire(import.meta.url).resolve('crspline/package.json'), 'utf8'));
  assert.equal(pkg.version, a.version());
});

test('a 7-D curve through the package gives the numbers of catmull_rom<7> (seven_d.json)', async () => {
  await init();
  const ref = reference('seven_d.json');
  const inp = ref.input;
  const curve = catmullRom(inp.points, { alpha: inp.alpha, tension: inp.tension, start: inp.end.start, end: { tangent: inp.end.end } });
  assert.equal(curve.dimension, 7);
  assert.deepEqual(Array.from(curve.grid), ref.grid);
  let n = 0;
  for (const order of inp.derivatives) {
    const want = ref.values[String(order)];
    // The batch path is the one the CLI wrote the file with: exact. The
    // one-t path: 8 eps * scale (see web/test/module.test.mjs for why).
    const tol = 8 * Number.EPSILON * Math.max(...want.flat().map(Math.abs));
    const out = new Float64Array(7 * inp.t.length);
    assert.equal(curve.evaluateMany(inp.t, order, out), out);
    inp.t.forEach((t, j) => {
      assert.deepEqual(Array.from(out.subarray(7 * j, 7 * j + 7)), want[j]);
      assert.ok(maxAbs(curve.evaluate(t, order), want[j]) <= tol, `order ${order}, t ${t}`);
      ++n;
    });
  }
  assert.equal(n, 63);
  curve.dispose();
});

test('points as arrays, {x, y, z} objects and flat coordinates make the same curve', async () => {
  await init();
  const pts = [[0, 0, 0], [1, 2, 0.5], [3, 1, -1], [4, 4, 2]];
  const a = catmullRom(pts);
  const b = catmullRom(pts.map(([x, y, z]) => ({ x, y, z })));
  const c = catmullRom(pts.flat(), { dimension: 3 });
  const d = catmullRom(pts.map(([x, y]) => ({ x, y })));
  assert.equal(d.dimension, 2);
  const ts = [0, 0.3, 1.7, a.tMax];
  for (const o of [b, c]) assert.deepEqual(o.evaluateMany(ts), a.evaluateMany(ts));
  assert.deepEqual(Array.from(a.points), pts.flat());
  assert.equal(a.pointCount, 4);
  assert.equal(a.segmentCount, 3);
  assert.equal(a.closed, false);
  for (const o of [a, b, c, d]) o.dispose();
});

test('identities: interpolation at the knots, Bézier ends, batch = one at a time, arc length round trip', async () => {
  await init();
  const rng = seeded();
  const msg = `seed ${rng.seed}`;
  for (const alpha of [0, 0.5, 1])
    for (const closed of [false, true]) {
      const pts = Array.from({ length: 7 }, () => [rng.uniform(-10, 10), rng.uniform(-10, 10)]);
      const curve = catmullRom(pts, { alpha, closed });
      const scale = 20 * Math.SQRT2;  // bounding box diagonal of the points' square
      const g = curve.grid;
      assert.equal(g.length, closed ? 8 : 7, msg);
      // Interpolation: exact up to the rounding of a few operations (8 eps * scale).
      pts.forEach((p, i) => assert.ok(maxAbs(curve.evaluate(g[i]), p) <= 8 * Number.EPSILON * scale, `${msg}: knot ${i}`));
      const all = curve.bezier();
      assert.equal(all.length, curve.segmentCount * 8, msg);
      for (let i = 0; i < curve.segmentCount; ++i) {
        const b = curve.bezier(i);
        assert.deepEqual(b, all.subarray(8 * i, 8 * i + 8));
        assert.ok(maxAbs(b.subarray(0, 2), pts[i]) <= 8 * Number.EPSILON * scale, msg);
        assert.ok(maxAbs(b.subarray(6, 8), pts[(i + 1) % pts.length]) <= 8 * Number.EPSILON * scale, msg);
      }
      const ts = Array.from({ length: 50 }, (_, k) => curve.tMin + (curve.tMax - curve.tMin) * (k / 49));
      ts[49] = curve.tMax;
      // Positions: the two paths agree exactly; first derivatives round
      // differently (the batch kernel's form), within 8 eps * their scale.
      const pos = curve.evaluateMany(ts), vel = curve.evaluateMany(ts, 1);
      const vscale = Math.max(...vel.map(Math.abs));
      ts.forEach((t, k) => {
        assert.deepEqual(curve.evaluate(t), pos.subarray(2 * k, 2 * k + 2), msg);
        assert.ok(maxAbs(curve.evaluate(t, 1), vel.subarray(2 * k, 2 * k + 2)) <= 8 * Number.EPSILON * vscale, msg);
      });
      // Arc length: the total is s at the end; t(s(t)) = t to 1e-9 of the
      // domain (the table's promise is 1e-12 relative in s; near a slow
      // point t moves more than s).
      const L = curve.arcLength();
      assert.ok(Math.abs(curve.sAt(curve.tMax) - L) <= 1e-12 * L, msg);
      assert.ok(Math.abs(curve.arcLength(1e-13) - L) <= 1e-11 * L, msg);
      for (const t of ts.slice(1, -1)) assert.ok(Math.abs(curve.tAtArcLength(curve.sAt(t)) - t) <= 1e-9 * curve.tMax, `${msg}: t ${t}`);
      curve.dispose();
    }
});

test('arc length of a straight line is its length; evenly spaced samples are evenly spaced', async () => {
  await init();
  // Collinear points with uneven spacing, chordal: the curve runs along
  // the line monotonically, so the length is exactly 10.
  const curve = catmullRom([[0, 0], [1, 0], [3, 0], [10, 0]].map(([x]) => [0.6 * x, 0.8 * x]), { alpha: 1 });
  assert.ok(Math.abs(curve.arcLength() - 10) <= 1e-12 * 10);
  const smp = curve.sampleArcLength(11);
  for (let k = 0; k <= 10; ++k) {
    assert.ok(Math.abs(smp.s[k] - k) <= 1e-11, `s[${k}] = ${smp.s[k]}`);
    assert.ok(Math.hypot(smp.points[2 * k], smp.points[2 * k + 1]) - k <= 1e-11);
  }
  curve.dispose();
});

test('tessellate(tol): every point of the curve between two vertices is within tol of their chord', async () => {
  await init();
  const rng = seeded();
  const pts = Array.from({ length: 9 }, () => [rng.uniform(-10, 10), rng.uniform(-10, 10)]);
  const curve = catmullRom(pts, { alpha: 0.5 });
  for (const tol of [1e-1, 1e-3, 1e-5]) {
    const { points, t } = curve.tessellate(tol);
    assert.equal(points.length, 2 * t.length);
    assert.equal(t[0], curve.tMin);
    assert.equal(t.at(-1), curve.tMax);
    let checked = 0;
    for (let k = 0; k + 1 < t.length; ++k) {
      const ax = points[2 * k], ay = points[2 * k + 1], bx = points[2 * k + 2], by = points[2 * k + 3];
      const ts = Array.from({ length: 15 }, (_, j) => t[k] + (t[k + 1] - t[k]) * (j + 1) / 16);
      const q = curve.evaluateMany(ts);
      for (let j = 0; j < 15; ++j) {
        // Distance to the chord segment.
        const dx = bx - ax, dy = by - ay, L2 = dx * dx + dy * dy;
        const w = L2 > 0 ? Math.min(1, Math.max(0, ((q[2 * j] - ax) * dx + (q[2 * j + 1] - ay) * dy) / L2)) : 0;
        const d = Math.hypot(q[2 * j] - ax - w * dx, q[2 * j + 1] - ay - w * dy);
        assert.ok(d <= tol * (1 + 1e-9), `seed ${rng.seed}: tol ${tol}, piece ${k}: ${d}`);
        ++checked;
      }
    }
    assert.equal(checked, 15 * (t.length - 1));
  }
  curve.dispose();
});

test('nearest(p): a point at distance h off the curve along the normal finds its foot', async () => {
  await init();
  // A convex arc: for h below the radius of curvature the foot is unique.
  const curve = catmullRom([[0, 0], [1, 1], [2, 1.5], [3, 1.6], [4, 1.5]]);
  for (const t of [0.5, 1.3, 2.2]) {
    const p = curve.evaluate(t), v = curve.evaluate(t, 1);
    const s = Math.hypot(v[0], v[1]);
    const h = 0.05;
    const q = [p[0] - h * v[1] / s, p[1] + h * v[0] / s];
    const n = curve.nearest(q);
    assert.ok(Math.abs(n.t - t) <= 1e-8, `t ${t}: ${n.t}`);
    assert.ok(Math.abs(n.distance - h) <= 1e-12, `t ${t}: ${n.distance}`);
    assert.equal(n.distanceSq, n.distance ** 2);
    assert.equal(n.segment, curve.locate(t));
    assert.ok(maxAbs(n.point, p) <= 1e-8);
  }
  curve.dispose();
});

test('analyze() and certify() pass the core report through', async () => {
  await init();
  // A uniform curve through a zig-zag folds back; the centripetal one never cusps.
  const pts = [[0, 0], [1, 0], [1.05, 1], [0, 1.1], [2, 2]];
  const c = catmullRom(pts, { alpha: 0.5 });
  const report = c.analyze();
  assert.ok(report !== null && typeof report === 'object');
  assert.deepEqual(JSON.parse(JSON.stringify(report)), JSON.parse(JSON.stringify(c.analyze())));
  const cert = c.certify();
  assert.equal(typeof cert.certified, 'boolean');
  assert.deepEqual(c.certify({ safeAngle: 0.5 }).certified, c.certify({ safeAngle: 0.5 }).certified);
  const box = c.boundingBox();
  assert.equal(box.lo.length, 2);
  c.dispose();
});

test('errors are Error objects with the core words and field / index / component / value', async () => {
  await init();
  const cases = [
    [() => catmullRom([[0, 0]]), /^a curve needs at least 2 points, got 1$/, { field: 'points', index: null, value: '1' }],
    [() => catmullRom([[0, 0], [1, NaN]]), /^point 1, coordinate 1 is not finite \(nan\)$/, { field: 'points', index: 1, component: 1, value: 'nan' }],
    [() => catmullRom([[0, 0], [1, 1]], { alpha: 1.5 }), /^alpha must be in \[0, 1\], got 1.5$/, { field: 'alpha', value: '1.5' }],
    [() => catmullRom([[0, 0], [1, 1], [2, 2]], { grid: [0, 2, 1] }), /^grid must be strictly increasing/, { field: 'grid', index: 2 }],
    [() => catmullRom([[0, 0], [1, 1]], { tension: 2 }), /^tension must be in \[0, 1\], got 2$/, { field: 'tension' }],
    [() => catmullRom([[0, 0], [1, 1]], { start: 'clamped' }), /^start condition must be 'natural', 'reflect' or a tangent, got 'clamped'$/, { field: 'start' }],
    [() => catmullRom([[0, 0], [1, 1]], { end: { tangent: [1, 2, 3] } }), /^end tangent has 3 coordinates, expected 2/, { field: 'end' }],
    [() => catmullRom([[0, 0], [1, 1]], { closed: true, start: 'reflect' }), /^a closed curve takes no end conditions$/, { field: 'start' }],
    // The ends are the table's words (issue 26): closed a boolean, start and
    // end one end each (a curve file's compact forms are named, not misread).
    [() => catmullRom([[0, 0], [1, 1]], { closed: 'yes' }), /^closed must be true or false, got "yes"$/, { field: 'closed', value: 'yes' }],
    [() => catmullRom([[0, 0], [1, 1]], { end: { start: 'reflect', end: 'natural' } }),
      /^end condition must be 'natural', 'reflect' or a tangent \(\[dx\/dt, \.\.\.\] or \{tangent: \[\.\.\.\]\}\), got \{"start":"reflect","end":"natural"\} \(a curve file's "end": \{"start": \.\.\., "end": \.\.\.\} is the options start and end\)$/, { field: 'end' }],
    [() => catmullRom([[0, 0], [1, 1]], { end: 'closed' }), /^end condition must be 'natural', 'reflect' or a tangent, got 'closed'$/, { field: 'end' }],
    [() => catmullRom([Array(17).fill(0), Array(17).fill(1)]), /^dimension must be 1 to 16, got 17$/, { field: 'dimension', value: '17' }],
    // What only JavaScript can get wrong, in the same shape.
    [() => catmullRom([[0, 0], [1, 1, 1]]), /^point 1 has 3 coordinates, point 0 has 2$/, { field: 'points', index: 1 }],
    [() => catmullRom([[0, 0], [1, 1]], { alhpa: 0.5 }), /^unknown option 'alhpa'/, { field: 'alhpa' }],
    [() => catmullRom('0,0 1,1'), /^points must be an array of points$/, { field: 'points' }],
    [() => catmullRom([0, 0, 1, 1]), /need options.dimension/, { field: 'points' }],
  ];
  for (const [f, message, props] of cases)
    assert.throws(f, (e) => {
      assert.ok(e instanceof Error, String(message));
      assert.match(e.message, message);
      for (const [k, v] of Object.entries(props)) assert.equal(e[k], v, `${message}: ${k}`);
      return true;
    });
  const c = catmullRom([[0, 0], [1, 1]]);
  assert.throws(() => c.evaluate(7), (e) => e instanceof Error && /t = 7 is outside the domain/.test(e.message) && e.field === undefined);
  assert.throws(() => c.evaluate(0.5, 4), /derivative order must be 0, 1, 2 or 3, got 4/);
  assert.throws(() => c.tAtArcLength(-1), /s = -1 is outside the arc-length range/);
  assert.throws(() => c.evaluateMany([0, 0.5], 0, new Float64Array(3)), /out has 3 numbers, 4 needed/);
  c.dispose();
  assert.equal(c.disposed, true);
  assert.throws(() => c.evaluate(0), /this curve was disposed/);
  c.dispose();  // twice is harmless
  assert.ok(c instanceof CatmullRom);
});

// Runs `code` (an ES module body) in a node with --expose-gc; returns its JSON output.
function runChild(code) {
  const file = fileURLToPath(new URL(`./gc-${process.pid}-${Math.random().toString(36).slice(2)}.mjs`, import.meta.url));
  fs.writeFileSync(file, code);
  try {
    const r = spawnSync(process.execPath, ['--expose-gc', file], { encoding: 'utf8', timeout: 120000 });
    assert.equal(r.status, 0, r.stderr);
    return JSON.parse(r.stdout);
  } finally {
    fs.unlinkSync(file);
  }
}

test('WASM memory: dispose() frees it now, and a dropped curve is freed by the garbage collector', () => {
  // Each curve of 2 10^4 3-D points holds about 6 MB of WASM memory (points,
  // segments, arc-length table; measured: 40 curves of 10^5 points kept
  // alive grew the heap to 1.17 GB); 40 of them kept alive would need about
  // 240 MB. Freed, the allocator reuses the same memory: the heap stays under
  // 100 MB (it starts at 32 MB).
  // memory is the WASM heap's size in bytes (it only grows).
  const out = runChild(`
    import { init, catmullRom, wasmMemoryBytes } from 'crspline';
    await init();
    const n = 20000, pts = new Float64Array(3 * n);
    for (let i = 0; i < 3 * n; ++i) pts[i] = Math.sin(i * 0.37) * 100 + i * 1e-3;
    const mode = { disposed: 0, collected: 0 };
    for (let k = 0; k < 40; ++k) {
      const c = catmullRom(pts, { dimension: 3 });
      c.arcLength();
      c.dispose();
    }
    mode.disposed = wasmMemoryBytes();
    for (let k = 0; k < 40; ++k) {
      (() => { const c = catmullRom(pts, { dimension: 3 }); c.arcLength(); })();
      globalThis.gc();
      await new Promise((r) => setTimeout(r, 0));  // finalizers run between tasks
    }
    mode.collected = wasmMemoryBytes();
    console.log(JSON.stringify(mode));
  `);
  assert.ok(out.disposed < 100e6, `after dispose: ${out.disposed} bytes`);
  assert.ok(out.collected < 100e6, `after collection: ${out.collected} bytes`);
});

test('init({ wasmBinary }): the bytes from elsewhere (here the exported crspline/crspline.wasm)', () => {
  const out = runChild(`
    import fs from 'node:fs';
    import { createRequire } from 'node:module';
    import { init, catmullRom } from 'crspline';
    const bytes = fs.readFileSync(createRequire(import.meta.url).resolve('crspline/crspline.wasm'));
    const api = await init({ wasmBinary: bytes });
    const c = catmullRom([[0, 0], [3, 4]]);
    console.log(JSON.stringify({ version: api.version(), length: c.arcLength() }));
  `);
  assert.match(out.version, /^\d+\.\d+\.\d+/);
  assert.equal(out.length, 5);
});
