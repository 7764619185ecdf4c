// The fit benchmark's peers (issue 40), on the same lines as bench/fit_bench:
// simplify-js@1.2.4 (Ramer-Douglas-Peucker, high quality) and paper.js'
// Path.simplify (paper-jsdom@0.12.18, Schneider's fitting), each at the
// corpus line's tolerance. Prints their counts and their *measured*
// deviation both ways (neither proves it): the output's distance to the
// input polyline (paper.js: each cubic sampled at 64 points a curve; RDP:
// its segments sampled at 16 points) and the input points' distance to the
// output (to the sampled polyline). JSON on stdout.
//
//   (cd bench/js/fit && npm ci)   # once
//   node bench/js/fit_peers.mjs tests/reference/fit/dem_topobathy.txt ...
//   node bench/js/fit_peers.mjs --cubics < {"points": ..., "closed": ..., "tolerance": ...}
//        (paper.js' cubics of one line, for examples/python/plot_fit.py)
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(new URL('./fit/package.json', import.meta.url));
const simplify = require('simplify-js');
const paper = require('paper-jsdom');
paper.setup(new paper.Size(100, 100));

function readCorpus(path) {
  const words = readFileSync(path, 'utf8').split(/\s+/).filter((w) => w.length);
  const lines = [];
  for (let i = 0; i < words.length;) {
    if (words[i] !== 'line') throw new Error(`${path}: expected 'line' at word ${i}`);
    const name = words[i + 1], closed = words[i + 2] === '1', tolerance = Number(words[i + 3]), n = Number(words[i + 4]);
    i += 5;
    const pts = [];
    for (let k = 0; k < n; ++k, i += 2) pts.push([Number(words[i]), Number(words[i + 1])]);
    lines.push({ name, closed, tolerance, pts });
  }
  return lines;
}

// Distance from p to segment a-b.
function segDist(p, a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1], wx = p[0] - a[0], wy = p[1] - a[1];
  const l2 = dx * dx + dy * dy;
  const f = l2 > 0 ? Math.min(1, Math.max(0, (wx * dx + wy * dy) / l2)) : 0;
  return Math.hypot(wx - f * dx, wy - f * dy);
}

// A uniform grid over a polyline's segments: the distance from a point to
// the polyline, searching rings of cells outward until no nearer segment
// can exist.
class SegmentGrid {
  constructor(poly, cell) {
    this.poly = poly;
    this.cell = cell;
    this.map = new Map();
    for (let i = 0; i + 1 < poly.length; ++i) {
      const a = poly[i], b = poly[i + 1];
      const x0 = Math.floor(Math.min(a[0], b[0]) / cell), x1 = Math.floor(Math.max(a[0], b[0]) / cell);
      const y0 = Math.floor(Math.min(a[1], b[1]) / cell), y1 = Math.floor(Math.max(a[1], b[1]) / cell);
      for (let x = x0; x <= x1; ++x)
        for (let y = y0; y <= y1; ++y) {
          const k = `${x},${y}`;
          if (!this.map.has(k)) this.map.set(k, []);
          this.map.get(k).push(i);
        }
    }
  }
  distance(p) {
    const cx = Math.floor(p[0] / this.cell), cy = Math.floor(p[1] / this.cell);
    let best = Infinity;
    for (let r = 0; r < 1e6; ++r) {
      for (let x = cx - r; x <= cx + r; ++x)
        for (let y = cy - r; y <= cy + r; ++y) {
          if (Math.max(Math.abs(x - cx), Math.abs(y - cy)) !== r) continue;
          const segs = this.map.get(`${x},${y}`);
          if (segs) for (const i of segs) best = Math.min(best, segDist(p, this.poly[i], this.poly[i + 1]));
        }
      if (best <= r * this.cell) return best;
      if (r > 4 && best < Infinity && best <= (r + 1) * this.cell) return best;
    }
    return best;
  }
}

// Largest distance both ways between the input polyline and an output
// polyline (dense samples of the output).
function deviationBothWays(input, closed, samples, tolerance) {
  const inPoly = closed ? [...input, input[0]] : input;
  const gIn = new SegmentGrid(inPoly, tolerance * 4);
  const gOut = new SegmentGrid(samples, tolerance * 4);
  let c2i = 0, i2c = 0;
  for (const s of samples) c2i = Math.max(c2i, gIn.distance(s));
  for (const p of input) i2c = Math.max(i2c, gOut.distance(p));
  return Math.max(c2i, i2c);
}

function bezierAt(v, t) {
  const u = 1 - t;
  const a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
  return [a * v[0] + b * v[2] + c * v[4] + d * v[6], a * v[1] + b * v[3] + c * v[5] + d * v[7]];
}

function peers(line) {
  const { pts, closed, tolerance } = line;
  // simplify-js: RDP (high quality: no radial pre-pass). A ring is given
  // closed (first point repeated) and counted without the repeat.
  const ring = closed ? [...pts, pts[0]] : pts;
  const kept = simplify(ring.map(([x, y]) => ({ x, y })), tolerance, true).map((q) => [q.x, q.y]);
  const rdpCount = closed ? kept.length - 1 : kept.length;
  const rdpSamples = [];
  for (let i = 0; i + 1 < kept.length; ++i)
    for (let k = 0; k < 16; ++k) {
      const f = k / 16;
      rdpSamples.push([kept[i][0] + f * (kept[i + 1][0] - kept[i][0]), kept[i][1] + f * (kept[i + 1][1] - kept[i][1])]);
    }
  rdpSamples.push(kept[kept.length - 1]);
  const rdpDev = deviationBothWays(pts, closed, rdpSamples, tolerance);
  // paper.js: Path.simplify(tolerance).
  const path = new paper.Path({ segments: pts, closed, insert: false });
  path.simplify(tolerance);
  const curves = path.curves.map((c) => c.getValues());
  const paperSamples = [];
  for (const v of curves) for (let k = 0; k < 64; ++k) paperSamples.push(bezierAt(v, k / 64));
  if (curves.length) paperSamples.push(bezierAt(curves[curves.length - 1], 1));
  const paperDev = deviationBothWays(pts, closed, paperSamples, tolerance);
  return { rdpCount, rdpDev, paperSegments: path.segments.length, paperCurves: curves.length, paperDev };
}

if (process.argv[2] === '--cubics') {
  const { points, closed, tolerance } = JSON.parse(readFileSync(0, 'utf8'));
  const path = new paper.Path({ segments: points, closed, insert: false });
  path.simplify(tolerance);
  console.log(JSON.stringify({ segments: path.segments.length, cubics: path.curves.map((c) => c.getValues()) }));
  process.exit(0);
}

const report = {};
for (const file of process.argv.slice(2)) {
  const lines = readCorpus(file);
  const t0 = performance.now();
  let points = 0, rdp = 0, paperSegs = 0, paperCurves = 0, rdpWithin = 0, paperWithin = 0;
  const paperRatios = [];
  let rdpWorst = 0;
  for (const line of lines) {
    const r = peers(line);
    points += line.pts.length;
    rdp += r.rdpCount;
    paperSegs += r.paperSegments;
    paperCurves += r.paperCurves;
    rdpWithin += r.rdpDev <= line.tolerance * (1 + 1e-9);
    paperWithin += r.paperDev <= line.tolerance * (1 + 1e-9);
    paperRatios.push(r.paperDev / line.tolerance);
    rdpWorst = Math.max(rdpWorst, r.rdpDev / line.tolerance);
  }
  paperRatios.sort((a, b) => a - b);
  report[file.split('/').pop()] = {
    lines: lines.length, points,
    rdp_vertices: rdp, rdp_within_tolerance: rdpWithin, rdp_worst_over_tolerance: rdpWorst,
    paper_segments: paperSegs, paper_cubics: paperCurves, paper_stored_points: paperSegs * 3,
    paper_within_tolerance: paperWithin,
    paper_median_over_tolerance: paperRatios[Math.floor(paperRatios.length / 2)],
    paper_worst_over_tolerance: paperRatios[paperRatios.length - 1],
    seconds: (performance.now() - t0) / 1000,
  };
}
console.log(JSON.stringify(report, null, 1));
