// The JavaScript peer: three.js CatmullRomCurve3 (centripetal) on the same
// 1000-point walk as the C++ suite (written by `crspline_bench
// --dump-points=FILE`), and crspline's WebAssembly module on the same input
// when web/dist/crspline.mjs has been built (web/build.sh).
//
//   node bench/js/threejs_bench.mjs POINTS.json OUT.json [repetitions]
//
// Cases (per point, median over the repetitions, one warm-up run first):
//   threejs_getPoint/three     getPoint(u, target) for 10^6 increasing u
//   threejs_getPointAt/three   getPointAt(u, target), arc-length parameter
//   threejs_getPoint/wasm      Spline.evaluateMany(t) on 10^6 increasing t
//   threejs_getPointAt/wasm    Spline.sampleArcLength(10^6) (builds its table)
//   threejs_getPoint/adapter   crspline's CRSplineCurve3 (the npm package,
//   threejs_getPointAt/adapter installed in bench/js by run_bench.sh), the
//                              same calls as three.js, same three
// Accuracy of getPointAt: how far three's arc-length parameter is from
// true arc length, |s(point) - u L| / L, s from a 2*10^6-chord polyline.
import fs from 'node:fs';
import path from 'node:path';
import process from 'node:process';
import { fileURLToPath } from 'node:url';
import * as THREE from 'three';

const here = path.dirname(fileURLToPath(import.meta.url));
const [pointsFile, outFile, repsArg] = process.argv.slice(2);
if (!pointsFile || !outFile) {
    console.error('usage: node threejs_bench.mjs POINTS.json OUT.json [repetitions]');
    process.exit(2);
}
const reps = Number(repsArg ?? 5);
const pts = JSON.parse(fs.readFileSync(pointsFile, 'utf8'));  // [[x, y, z], ...]
const n = 1_000_000;

function median(a) {
    const s = [...a].sort((x, y) => x - y);
    const m = s.length >> 1;
    return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

// Times fn() (which handles n items) reps times after one warm-up; ns per item.
function time(fn) {
    fn();
    const ns = [];
    for (let r = 0; r < reps; ++r) {
        const t0 = process.hrtime.bigint();
        fn();
        ns.push(Number(process.hrtime.bigint() - t0) / n);
    }
    return { median_ns: median(ns), ns };
}

const results = {};
const curve = new THREE.CatmullRomCurve3(pts.map(([x, y, z]) => new THREE.Vector3(x, y, z)), false, 'centripetal');
const target = new THREE.Vector3();
const out = new Float64Array(3 * n);
let sink = 0;

results['threejs_getPoint/three'] = time(() => {
    for (let k = 0; k < n; ++k) {
        curve.getPoint(k / (n - 1), target);
        out[3 * k] = target.x; out[3 * k + 1] = target.y; out[3 * k + 2] = target.z;
    }
    sink += out[3 * (n >> 1)];
});
results['threejs_getPointAt/three'] = time(() => {
    for (let k = 0; k < n; ++k) {
        curve.getPointAt(k / (n - 1), target);
        out[3 * k] = target.x; out[3 * k + 1] = target.y; out[3 * k + 2] = target.z;
    }
    sink += out[3 * (n >> 1)];
});

// Accuracy of getPointAt: the reference arc length s(t) of three's own curve
// from a dense polyline in its parameter t (chord error ~ (L/N)^2 curvature,
// far below what is measured).
function getPointAtError(curve) {
    // About 2*10^6 chords, a whole number per segment: every knot (where
    // three's t changes speed) is a sample, so no chord straddles one.
    const nseg = curve.points.length - (curve.closed ? 0 : 1);
    const N = nseg * Math.ceil(2_000_000 / nseg);
    const cum = new Float64Array(N + 1);
    const a = new THREE.Vector3(), b = new THREE.Vector3();
    curve.getPoint(0, a);
    for (let k = 1; k <= N; ++k) {
        curve.getPoint(k / N, b);
        cum[k] = cum[k - 1] + a.distanceTo(b);
        a.copy(b);
    }
    const L = cum[N];
    let worst = 0;
    for (let j = 0; j <= 1000; ++j) {
        const u = j / 1000;
        const t = curve.getUtoTmapping(u);
        const x = t * N, i = Math.min(N - 1, Math.floor(x));
        const s = cum[i] + (cum[i + 1] - cum[i]) * (x - i);
        worst = Math.max(worst, Math.abs(s - u * L) / L);
    }
    return worst;
}
results['threejs_getPointAt/three'].rel_err = getPointAtError(curve);
results['threejs_getPointAt/three'].arcLengthDivisions = curve.arcLengthDivisions;

// The same calls through crspline's three.js adapter, if the package is
// installed here (run_bench.sh: js/build.sh, npm install --no-save).
try {
    const { init } = await import('crspline');
    const { CRSplineCurve3 } = await import('crspline/three');
    await init();
    const adapter = new CRSplineCurve3(pts.map(([x, y, z]) => new THREE.Vector3(x, y, z)), false, 'centripetal');
    results['threejs_getPoint/adapter'] = time(() => {
        for (let k = 0; k < n; ++k) {
            adapter.getPoint(k / (n - 1), target);
            out[3 * k] = target.x; out[3 * k + 1] = target.y; out[3 * k + 2] = target.z;
        }
        sink += out[3 * (n >> 1)];
    });
    results['threejs_getPointAt/adapter'] = time(() => {
        for (let k = 0; k < n; ++k) {
            adapter.getPointAt(k / (n - 1), target);
            out[3 * k] = target.x; out[3 * k + 1] = target.y; out[3 * k + 2] = target.z;
        }
        sink += out[3 * (n >> 1)];
    });
    results['threejs_getPointAt/adapter'].rel_err = getPointAtError(adapter);
    // The same curve as three.js' (no coincident points on the walk): the
    // largest distance between the two getPoint over the timed u.
    let gap = 0;
    const a = new THREE.Vector3(), b = new THREE.Vector3();
    for (let k = 0; k < n; k += 97) gap = Math.max(gap, curve.getPoint(k / (n - 1), a).distanceTo(adapter.getPoint(k / (n - 1), b)));
    results['threejs_getPoint/adapter'].max_distance_to_three = gap;
    adapter.dispose();
} catch (e) {
    results.adapter_error = String(e);
}

// crspline's WebAssembly module, if built.
const wasmDir = path.resolve(here, '../../web/dist');
if (fs.existsSync(path.join(wasmDir, 'crspline.mjs'))) {
    try {
        const { default: CrSpline } = await import(path.join(wasmDir, 'crspline.mjs'));
        const M = await CrSpline({ wasmBinary: fs.readFileSync(path.join(wasmDir, 'crspline.wasm')) });
        const s = new M.Spline(pts.flat(), 3);
        const t0 = s.tMin(), t1 = s.tMax();
        const t = new Float64Array(n);
        for (let k = 0; k < n; ++k) t[k] = Math.min(t1, t0 + (t1 - t0) * (k / (n - 1)));
        results['threejs_getPoint/wasm'] = time(() => { sink += s.evaluateMany(t)[0]; });
        results['threejs_getPointAt/wasm'] = time(() => { sink += s.sampleArcLength(n).points[0]; });
        s.delete();
    } catch (e) {
        results.wasm_error = String(e);
    }
} else {
    results.wasm_error = 'web/dist/crspline.mjs not built (web/build.sh)';
}

const threeVersion = JSON.parse(fs.readFileSync(path.join(here, 'node_modules/three/package.json'), 'utf8')).version;
fs.writeFileSync(outFile, JSON.stringify({ node: process.version, three: threeVersion, n, reps, sink, results }, null, 2));
for (const [k, v] of Object.entries(results))
    if (v.median_ns !== undefined) console.log(`${k.padEnd(28)} ${v.median_ns.toFixed(2).padStart(9)} ns/point`);
