// Issue 41: three.js' TubeGeometry at the counts of crspline_sweep_bench
// (tubularSegments 4999, radialSegments 199: 10^6 vertices) along
// CatmullRomCurve3 (centripetal, closed) through the same 48 knot points
// (written by `crspline_sweep_bench --dump-points=FILE`).
//
//   node bench/js/tube_bench.mjs POINTS.json [repetitions]
//
// Prints JSON: the fastest of the repetitions (after one warm-up), in
// seconds, and how far three.js' closing ring is from its first ring
// (positions and normals, largest coordinate difference).
import fs from 'node:fs';
import process from 'node:process';
import * as THREE from 'three';

const [pointsFile, repsArg] = process.argv.slice(2);
if (!pointsFile) {
    console.error('usage: node tube_bench.mjs POINTS.json [repetitions]');
    process.exit(2);
}
const reps = Number(repsArg ?? 7);
const pts = JSON.parse(fs.readFileSync(pointsFile, 'utf8')).map((p) => new THREE.Vector3(...p));
const curve = new THREE.CatmullRomCurve3(pts, true, 'centripetal');
const tubular = 4999, radial = 199, radius = 0.2;

let geometry = new THREE.TubeGeometry(curve, tubular, radius, radial, true);  // warm-up
let best = Infinity;
for (let r = 0; r < reps; ++r) {
    const t0 = process.hrtime.bigint();
    geometry = new THREE.TubeGeometry(curve, tubular, radius, radial, true);
    best = Math.min(best, Number(process.hrtime.bigint() - t0) / 1e9);
}
const pos = geometry.attributes.position.array;
const ring = radial + 1, last = tubular * ring;
const nor = geometry.attributes.normal.array;
let seam = 0, normal_seam = 0;
for (let j = 0; j < ring; ++j)
    for (let i = 0; i < 3; ++i) {
        seam = Math.max(seam, Math.abs(pos[3 * (last + j) + i] - pos[3 * j + i]));
        normal_seam = Math.max(normal_seam, Math.abs(nor[3 * (last + j) + i] - nor[3 * j + i]));
    }
console.log(JSON.stringify({
    three: THREE.REVISION, vertices: pos.length / 3, tube_geometry_s: best, closing_ring_gap: seam, closing_ring_normal_gap: normal_seam, repetitions: reps,
}));
