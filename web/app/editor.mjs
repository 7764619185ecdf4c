// The crspline editor: a canvas, the WASM curve, and overlays.
//
// Frame budget. A frame makes one WASM call for the geometry (a new Spline
// from the points, then bezierAll(): every segment's Bézier points in one
// Float64Array) and draws the curve as one Path2D. Per-segment overlays
// (lengths for the status line, cusps, the curvature comb) are cached per
// segment: dragging point i recomputes only the segments i-2 .. i+1 it
// moves. Whole-curve overlays (certificate and self-intersections, bounding
// volumes, arc-length ticks) run in a worker, latest request wins; until an
// answer for the current curve arrives, the last one is drawn faded.
import CrSpline from '../dist/crspline.mjs';
import { parsePoints, pointsToJson, pointsToCsv, curveToSvg, splineOptions, defaultOptions, coordinateNames } from './io.mjs';
import { computeGlobal } from './overlays.mjs';

const M = await CrSpline({ locateFile: (p) => new URL('../dist/' + p, import.meta.url).href });

const $ = (id) => document.getElementById(id);
const canvas = $('canvas');
const ctx = canvas.getContext('2d');

// ---------------------------------------------------------------------------
// State
// ---------------------------------------------------------------------------
const state = {
  pts: new Float64Array(0),  // flat x, y in world units (the two drawn coordinates)
  // The document's dimension. A curve of dim > 2 coordinates is shown and
  // edited as its projection on coordinates pair[0] (across) and pair[1]
  // (up or down): `pts` holds those two of every point, `rest` the other
  // dim - 2 (in coordinate order), so that nothing is cut; the curve itself
  // (drawn, measured, certified) is the dim-D one. names: the coordinates'.
  dim: 2,
  pair: [0, 1],
  rest: new Float64Array(0),
  names: ['x', 'y'],
  opts: { ...defaultOptions },
  selected: -1,              // the primary selected point (-1: none)
  sel: new Set(),            // every selected point (marquee, Shift+click)
  overlays: { polygon: true, handles: false, cusps: true, intersections: true, volumes: false, comb: false, ticks: false },
  volumeKind: 'tightened',
  combScale: 0.5,
  tickSpacing: 25,
  grid: false,               // draw a grid and snap to it
};
// The view: world point (x0, y0) is at the canvas' top-left corner, s CSS
// pixels per world unit, y down (as SVG) or up (as `crspline plot`).
// Everything reaches the canvas as (world - origin) * s, computed in double:
// the canvas works in 32-bit floats, which far from the origin (1e8) would
// put the curve on a staircase of 8-unit steps.
const view = { s: 1, x0: 0, y0: 0, yUp: false };
const Y_UP_KEY = 'crspline.editor.yUp';
const ys = () => (view.yUp ? -1 : 1);
const SX = (x) => (x - view.x0) * view.s;
const SY = (y) => (y - view.y0) * view.s * ys();
let version = 0;                      // bumps on every change of the curve
let drag = null;                      // the pointer gesture under way (see "Pointer")
const undoStack = [], redoStack = [];
const UNDO_LIMIT = 200;

const count = () => state.pts.length / 2;

// The coordinates not drawn, in order (their values are in state.rest).
function hidden(dim = state.dim, pair = state.pair) {
  const h = [];
  for (let k = 0; k < dim; ++k) if (k !== pair[0] && k !== pair[1]) h.push(k);
  return h;
}
// The points with every coordinate, flat (dim per point).
function fullPoints() {
  const d = state.dim;
  if (d === 2 && state.pair[0] === 0) return state.pts;
  const n = count(), out = new Float64Array(n * d), h = hidden(), r = d - 2;
  for (let i = 0; i < n; ++i) {
    out[i * d + state.pair[0]] = state.pts[2 * i];
    out[i * d + state.pair[1]] = state.pts[2 * i + 1];
    for (let j = 0; j < r; ++j) out[i * d + h[j]] = state.rest[i * r + j];
  }
  return out;
}
// Full points -> { pts, rest } for a projection pair.
function splitPoints(full, d, pair) {
  const n = full.length / d, pts = new Float64Array(2 * n), h = hidden(d, pair), r = d - 2, rest = new Float64Array(n * r);
  for (let i = 0; i < n; ++i) {
    pts[2 * i] = full[i * d + pair[0]];
    pts[2 * i + 1] = full[i * d + pair[1]];
    for (let j = 0; j < r; ++j) rest[i * r + j] = full[i * d + h[j]];
  }
  return { pts, rest };
}
// The hidden coordinates of point k (a copy; empty for a plane curve).
const restOf = (k) => state.rest.slice(k * (state.dim - 2), (k + 1) * (state.dim - 2));
// Flat points of dimension d -> their pair coordinates, flat x, y.
function project(a, d = state.dim, pair = state.pair) {
  if (d === 2) return a;
  const n = a.length / d, out = new Float64Array(2 * n);
  for (let i = 0; i < n; ++i) { out[2 * i] = a[i * d + pair[0]]; out[2 * i + 1] = a[i * d + pair[1]]; }
  return out;
}

// ---------------------------------------------------------------------------
// The curve and its per-segment caches
// ---------------------------------------------------------------------------
let spline = null, splineError = null, bez = new Float64Array(0), builtVersion = -1;
const COMB_PER_SEGMENT = 12;
// Per-segment caches (arrays indexed by segment) and what must be redone.
const cache = { len: null, cusps: null, comb: null };
let dirty = { all: true, segments: new Set() };

function markAll() { dirty = { all: true, segments: new Set() }; }
// Segments whose shape depends on point k (its window P(i-1)..P(i+2)),
// widened by one for insertions and deletions; wraps on closed curves.
function markAround(k, lo = -2, hi = 1) {
  if (dirty.all) return;
  const n = count(), nseg = state.opts.closed ? n : n - 1;
  if (nseg <= 0) return markAll();
  for (let i = k + lo; i <= k + hi; ++i) {
    if (state.opts.closed) dirty.segments.add(((i % nseg) + nseg) % nseg);
    else if (i >= 0 && i < nseg) dirty.segments.add(i);
  }
}
// Keep the caches aligned with segment indices across an insertion
// (+1) or deletion (-1) of point k.
function shiftCaches(k, delta) {
  lenBlocks = null;
  for (const key of Object.keys(cache)) {
    const a = cache[key];
    if (!a) continue;
    if (delta > 0) a.splice(Math.max(0, k - 1), 0, null);
    else a.splice(Math.max(0, k - 1), 1);
  }
  // Indices in the pending set move too.
  const moved = new Set();
  for (const i of dirty.segments) moved.add(i >= k ? i + delta : i);
  dirty.segments = moved;
}

let importMessage = '';
function changed() {
  version++;
  importMessage = '';
  requestFrame();
}

// While the drag layer draws (see draw), only the segments the drag moves
// are read back from the new curve (bezier(i), a few numbers) instead of
// every segment (bezierAll, 64 bytes a segment); the others keep theirs,
// which differ from the new curve's by rounding at most (their knot
// intervals and points did not change). Once the drag ends, the whole.
let bezPartial = false;
function rebuild() {
  if (builtVersion === version) {
    if (bezPartial && spline && !layerWanted()) { bez = project(spline.bezierAll()); bezPartial = false; }
    return;
  }
  builtVersion = version;
  if (spline) { spline.delete(); spline = null; }
  splineError = null;
  const old = bez, partial = layerWanted() && !dirty.all;
  bez = new Float64Array(0);
  bezPartial = false;
  const n = count();
  if (n >= 2) {
    try {
      spline = new M.Spline(fullPoints(), state.dim, splineOptions(state.opts, state.dim));
      const nseg = spline.segmentCount();
      if (partial && old.length === 8 * nseg) {
        const d = state.dim, [a, b] = state.pair;
        for (const i of dirty.segments) {
          if (i >= nseg) continue;
          const q = spline.bezier(i);
          for (let j = 0; j < 4; ++j) { old[8 * i + 2 * j] = q[j * d + a]; old[8 * i + 2 * j + 1] = q[j * d + b]; }
        }
        bez = old;
        bezPartial = true;
      } else {
        bez = project(spline.bezierAll());
      }
    } catch (e) {
      splineError = e.message;
    }
  }
  updateCaches();
  requestGlobal();
}

function updateCaches() {
  const nseg = spline ? spline.segmentCount() : 0;
  // The comb needs a plane curve (signed curvature).
  const want = { len: true, cusps: state.overlays.cusps, comb: state.overlays.comb && state.dim === 2 };
  for (const key of Object.keys(cache)) {
    if (!want[key] || !spline) { cache[key] = null; continue; }
    const full = dirty.all || !cache[key] || cache[key].length !== nseg;
    if (full) {
      cache[key] = computeRange(key, 0, nseg);
      if (key === 'len') lenBlocks = null;
    } else {
      for (const i of dirty.segments) {
        if (i >= nseg) continue;
        cache[key][i] = computeRange(key, i, 1)[0];
        if (key === 'len' && lenBlocks) lenBlocks[Math.floor(i / LEN_BLOCK)] = NaN;
      }
    }
  }
  dirty = { all: false, segments: new Set() };
}

// Per-segment values for segments [first, first + n).
function computeRange(key, first, n) {
  if (key === 'len') return Array.from(spline.segmentLengths(first, n));
  if (key === 'comb') {
    const all = spline.curvatureComb(COMB_PER_SEGMENT, first, n);
    const stride = (COMB_PER_SEGMENT + 1) * 5;
    return Array.from({ length: n }, (_, j) => all.subarray(j * stride, (j + 1) * stride));
  }
  // cusps: (segment, u, t, point of dim coordinates) per cusp; kept as the
  // drawn pair.
  const flat = spline.cusps(first, n), stride = 3 + state.dim, [a, b] = state.pair;
  const out = Array.from({ length: n }, () => null);
  for (let k = 0; k < flat.length; k += stride) {
    const j = flat[k] - first, x = flat[k + 3 + a], y = flat[k + 3 + b];
    out[j] = out[j] ? Float64Array.from([...out[j], x, y]) : Float64Array.of(x, y);
  }
  return out;
}

// ---------------------------------------------------------------------------
// Whole-curve overlays: worker, latest request wins
// ---------------------------------------------------------------------------
// queued: the curve changed while the worker was busy; the request is made
// (the points copied) once it is free, not on every frame meanwhile.
let worker = null, workerBusy = false, queued = false, global = null;
try {
  worker = new Worker(new URL('./worker.mjs', import.meta.url), { type: 'module' });
  worker.onmessage = (e) => {
    workerBusy = false;
    global = e.data;
    if (queued) { queued = false; requestGlobal(); }
    requestFrame();
    settle();
  };
  worker.onerror = () => { worker = null; workerBusy = false; requestGlobal(); };
} catch {
  worker = null;
}

function send(req) {
  if (worker) {
    workerBusy = true;
    worker.postMessage(req, [req.points.buffer]);
  } else {
    global = computeGlobal(M, req);
  }
}

// While a point is dragged, a curve whose whole-curve overlays took longer
// than this (ms) waits for the release instead of keeping a core busy.
const DRAG_GLOBAL_BUDGET = 50;
let deferredGlobal = false;
function requestGlobal() {
  if (!spline) { global = null; settle(); return; }
  if (drag && drag.kind === 'move' && global && global.ms > DRAG_GLOBAL_BUDGET) { deferredGlobal = true; return; }
  deferredGlobal = false;
  if (workerBusy) { queued = true; return; }
  send({
    version,
    points: fullPoints().slice(),
    dimension: state.dim,
    pair: state.pair,
    options: splineOptions(state.opts, state.dim),
    // The paper's volumes are drawn for plane curves only (a projected
    // capsule is not the capsule of the projection).
    volumes: state.overlays.volumes && state.dim === 2 ? state.volumeKind : null,
    ticks: state.overlays.ticks ? Math.max(1e-9, state.tickSpacing) : null,
    maxTicks: 20000,
  });
}
const globalCurrent = () => global && global.version === version;

// ---------------------------------------------------------------------------
// Drawing (in CSS pixels relative to the view origin; see `view`)
// ---------------------------------------------------------------------------
const colors = {
  curve: '#1f5fbf', polygon: '#9aa3b5', handle: '#e08a1e', point: '#c0392b', selected: '#111',
  cusp: '#d81b60', crossing: '#8e24aa', volume: 'rgba(46, 160, 67, 0.13)', volumeEdge: 'rgba(46, 160, 67, 0.55)',
  comb: 'rgba(0, 150, 136, 0.55)', tick: '#37474f', grid: '#eceff4', axis: '#d5dae3',
};
let frameRequested = false;
const frameTimes = [];     // work per frame (ms): JS + WASM + canvas calls
const curveTimes = [];     // of which the curve and per-segment caches (WASM)
const frameIntervals = []; // time between frames while dragging (ms)
const latencies = [];      // pointer event to the end of the frame that shows it (ms)
let lastFrameAt = 0, pendingEventAt = 0;

function requestFrame() {
  if (!frameRequested) {
    frameRequested = true;
    requestAnimationFrame(frame);
  }
}

function resize() {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(1, Math.round(canvas.clientWidth * dpr)), h = Math.max(1, Math.round(canvas.clientHeight * dpr));
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  return dpr;
}

function frame(now) {
  frameRequested = false;
  const t0 = performance.now();
  rebuild();
  const tm = performance.now();
  draw();
  const t1 = performance.now();
  frameTimes.push(t1 - t0);
  curveTimes.push(tm - t0);
  if (pendingEventAt) { latencies.push(t1 - pendingEventAt); pendingEventAt = 0; }
  for (const a of [frameTimes, curveTimes, latencies]) if (a.length > 600) a.shift();
  if (drag && lastFrameAt) { frameIntervals.push(now - lastFrameAt); if (frameIntervals.length > 600) frameIntervals.shift(); }
  lastFrameAt = drag ? now : 0;
  updateStatus(t1 - t0);
  settle();
}

// Flat world x, y -> flat screen x, y (a reused buffer per use).
const buffers = {};
function toScreen(src, key) {
  let out = buffers[key];
  if (!out || out.length !== src.length) out = buffers[key] = new Float64Array(src.length);
  const x0 = view.x0, y0 = view.y0, s = view.s, t = view.s * ys();
  for (let i = 0; i < src.length; i += 2) { out[i] = (src[i] - x0) * s; out[i + 1] = (src[i + 1] - y0) * t; }
  return out;
}

// A "nice" grid step (1, 2 or 5 times a power of ten) about 40 px wide.
function gridStep() {
  const raw = 40 / view.s, p = 10 ** Math.floor(Math.log10(raw)), m = raw / p;
  return (m < 2 ? 2 : m < 5 ? 5 : 10) * p;
}

function drawGrid(ctx, w, h) {
  const step = gridStep();
  const path = new Path2D(), axes = new Path2D();
  const xa = view.x0, xb = view.x0 + w / view.s;
  const ya = Math.min(view.y0, view.y0 + (h / view.s) * ys()), yb = Math.max(view.y0, view.y0 + (h / view.s) * ys());
  for (let i = Math.ceil(xa / step); i * step <= xb; ++i) {
    const x = Math.round(SX(i * step)) + 0.5;
    (i === 0 ? axes : path).moveTo(x, 0); (i === 0 ? axes : path).lineTo(x, h);
  }
  for (let i = Math.ceil(ya / step); i * step <= yb; ++i) {
    const y = Math.round(SY(i * step)) + 0.5;
    (i === 0 ? axes : path).moveTo(0, y); (i === 0 ? axes : path).lineTo(w, y);
  }
  ctx.lineWidth = 1;
  ctx.strokeStyle = colors.grid;
  ctx.stroke(path);
  ctx.strokeStyle = colors.axis;
  ctx.stroke(axes);
}

// Paths clipped to the canvas (plus a margin) before they reach it: zoomed
// far in, a segment can be 10^6 px long, and Skia flattens (and dashes) all
// of it, which takes seconds. Cubics are split (de Casteljau) until each
// piece is either outside the view, dropped, or under 2048 px; lines are
// clipped (Liang-Barsky). Consecutive pieces continue one subpath.
function clipPen(path, inside = false) {
  const m = 16, X0 = -m, Y0 = -m, X1 = canvas.clientWidth + m, Y1 = canvas.clientHeight + m;
  let lx = NaN, ly = NaN;  // where the subpath ends now
  const pen = {
    line(ax, ay, bx, by) {
      if (!inside) {
        let t0 = 0, t1 = 1;
        const dx = bx - ax, dy = by - ay;
        // Liang-Barsky against the four sides, without allocating.
        for (let side = 0; side < 4; ++side) {
          const p = side === 0 ? -dx : side === 1 ? dx : side === 2 ? -dy : dy;
          const q = side === 0 ? ax - X0 : side === 1 ? X1 - ax : side === 2 ? ay - Y0 : Y1 - ay;
          if (p === 0) { if (q < 0) return; continue; }
          const r = q / p;
          if (p < 0) { if (r > t1) return; if (r > t0) t0 = r; } else { if (r < t0) return; if (r < t1) t1 = r; }
        }
        if (t0 > 0 || t1 < 1) {
          const sx = ax + t0 * dx, sy = ay + t0 * dy, ex = ax + t1 * dx, ey = ay + t1 * dy;
          path.moveTo(sx, sy); path.lineTo(ex, ey);
          lx = ex; ly = ey;
          return;
        }
      }
      if (ax !== lx || ay !== ly) path.moveTo(ax, ay);
      path.lineTo(bx, by);
      lx = bx; ly = by;
    },
    cubic(x0, y0, x1, y1, x2, y2, x3, y3, depth) {
      const xa = Math.min(x0, x1, x2, x3), xb = Math.max(x0, x1, x2, x3), ya = Math.min(y0, y1, y2, y3), yb = Math.max(y0, y1, y2, y3);
      if (!inside && (xb < X0 || xa > X1 || yb < Y0 || ya > Y1)) return;  // outside: the hull contains the curve
      if ((xb - xa < 2048 && yb - ya < 2048) || depth > 40) {
        if (x0 !== lx || y0 !== ly) path.moveTo(x0, y0);
        // A piece whose hull fits in a quarter pixel is drawn as its chord:
        // the same pixels, far fewer for Skia to flatten at 10^5 segments.
        if (xb - xa < 0.25 && yb - ya < 0.25) path.lineTo(x3, y3);
        else path.bezierCurveTo(x1, y1, x2, y2, x3, y3);
        lx = x3; ly = y3;
        return;
      }
      const ax = (x0 + x1) / 2, ay = (y0 + y1) / 2, bx = (x1 + x2) / 2, by = (y1 + y2) / 2, cx = (x2 + x3) / 2, cy = (y2 + y3) / 2;
      const dx = (ax + bx) / 2, dy = (ay + by) / 2, ex = (bx + cx) / 2, ey = (by + cy) / 2, fx = (dx + ex) / 2, fy = (dy + ey) / 2;
      pen.cubic(x0, y0, ax, ay, dx, dy, fx, fy, depth + 1);
      pen.cubic(fx, fy, ex, ey, cx, cy, x3, y3, depth + 1);
    },
  };
  return pen;
}

// Whether every coordinate of a flat screen array is within the canvas (the
// common case: then nothing needs clipping).
function allInside(a) {
  const X1 = canvas.clientWidth, Y1 = canvas.clientHeight;
  for (let i = 0; i < a.length; i += 2) if (!(a[i] >= 0 && a[i] <= X1 && a[i + 1] >= 0 && a[i + 1] <= Y1)) return false;
  return true;
}

// Which parts of the base picture (polygon edges, curve segments, control
// points) to draw: every one (null), every one but those in `skip`, or only
// those in `only`.
const every = { only: null, skip: null };
function* indices(n, part) {
  if (part.only) { for (const i of part.only) if (i >= 0 && i < n) yield i; return; }
  for (let i = 0; i < n; ++i) if (!part.skip || !part.skip.has(i)) yield i;
}

// The base picture: the control polygon, the curve (and its Bézier handles)
// and the control points, in that order (the comb between polygon and curve
// when on). Edge i joins points i and i + 1 (the last edge of a closed
// curve wraps).
function drawBase(c, P, B, parts, showComb) {
  const n = P.length / 2, nb = B.length / 8, o = state.overlays;
  if (o.polygon && n >= 2) {
    const ne = state.opts.closed ? n : n - 1;
    const path = new Path2D(), pen = clipPen(path, parts.edges === every && allInside(P));
    for (const i of indices(ne, parts.edges)) {
      const j = (i + 1) % n;
      pen.line(P[2 * i], P[2 * i + 1], P[2 * j], P[2 * j + 1]);
    }
    if (n <= 2000) c.setLineDash([4, 4]);  // dashing 10^4 edges costs more than the curve
    c.strokeStyle = colors.polygon;
    c.lineWidth = 1;
    c.stroke(path);
    c.setLineDash([]);
  }
  if (showComb) drawComb();
  // The curve: one path of cubic Béziers.
  if (nb > 0) {
    const path = new Path2D(), pen = clipPen(path, parts.segments === every && allInside(B));
    for (const i of indices(nb, parts.segments)) {
      const k = 8 * i;
      pen.cubic(B[k], B[k + 1], B[k + 2], B[k + 3], B[k + 4], B[k + 5], B[k + 6], B[k + 7], 0);
    }
    c.strokeStyle = colors.curve;
    // Past a few thousand segments a 1-pixel line (Skia's hairline path)
    // rasterizes several times faster than a thick stroke.
    c.lineWidth = nb > 2000 ? 1 : 2.5;
    c.stroke(path);
  }
  if (o.handles && nb > 0) {
    const lines = new Path2D(), dots = new Path2D(), r = 2.5, pen = clipPen(lines);
    for (const i of indices(nb, parts.segments)) {
      const k = 8 * i;
      pen.line(B[k], B[k + 1], B[k + 2], B[k + 3]);
      pen.line(B[k + 6], B[k + 7], B[k + 4], B[k + 5]);
      dots.rect(B[k + 2] - r, B[k + 3] - r, 2 * r, 2 * r);
      dots.rect(B[k + 4] - r, B[k + 5] - r, 2 * r, 2 * r);
    }
    c.strokeStyle = colors.handle;
    c.lineWidth = 1;
    c.stroke(lines);
    c.fillStyle = colors.handle;
    c.fill(dots);
  }
  // Control points.
  if (n > 0) {
    c.fillStyle = colors.point;
    if (n > 2000) {
      // Many points: fillRect each (one path of 10^4 squares fills slower),
      // those in view only; past 20 000 in view they are closer than the
      // pixels and the curve through them shows where they are.
      const W = canvas.clientWidth, H = canvas.clientHeight;
      const visible = parts.visible ?? visibleCount(P);
      if (visible <= 20000) {
        for (const i of indices(n, parts.points)) {
          const x = P[2 * i], y = P[2 * i + 1];
          if (x >= -2 && x <= W + 2 && y >= -2 && y <= H + 2) c.fillRect(x - 1, y - 1, 2, 2);
        }
      }
    } else {
      const r = 4, path = new Path2D();
      for (const i of indices(n, parts.points)) path.rect(P[2 * i] - r, P[2 * i + 1] - r, 2 * r, 2 * r);
      c.fill(path);
    }
  }
}

function visibleCount(P) {
  const W = canvas.clientWidth, H = canvas.clientHeight;
  let visible = 0;
  for (let i = 0; i < P.length; i += 2) { const x = P[i], y = P[i + 1]; if (x >= -2 && x <= W + 2 && y >= -2 && y <= H + 2) ++visible; }
  return visible;
}

// The drag layer. While points of a long curve are dragged, what the drag
// cannot change (the grid and the polygon, curve and points away from the
// dragged points: a segment depends on four points, so dragging point k
// moves segments k-2 .. k+1, edges k-1 and k) is drawn once into an
// offscreen canvas; each frame copies it and draws the few parts that move.
// Only without the comb and the bounding volumes (drawn between the base
// parts), and while the view stays as it was.
const LAYER_MIN_SEGMENTS = 200;
let layer = null;      // { canvas, key, parts (the moving ones) }
let useLayer = true;   // tests compare with and without
let layerFrames = 0;   // frames drawn from the layer (reported)
function movingParts(idx) {
  const n = count(), closed = state.opts.closed, nseg = closed ? n : n - 1;
  const segments = new Set(), edges = new Set();
  const wrap = (i, m) => (closed ? ((i % m) + m) % m : i);
  for (const k of idx) {
    for (let i = k - 2; i <= k + 1; ++i) { const j = wrap(i, nseg); if (j >= 0 && j < nseg) segments.add(j); }
    for (let i = k - 1; i <= k; ++i) { const j = wrap(i, nseg); if (j >= 0 && j < nseg) edges.add(j); }
  }
  return { segments, edges, points: new Set(idx) };
}
function layerKey(dpr) {
  const o = state.overlays;
  return [canvas.width, canvas.height, dpr, view.s, view.x0, view.y0, view.yUp, state.grid, o.polygon, o.handles,
    state.opts.closed, count(), bez.length, drag && drag.idx.join(',')].join('|');
}
function layerWanted() {
  const o = state.overlays;
  return useLayer && drag && drag.kind === 'move' && drag.idx.length <= 64 && !o.comb && !o.volumes &&
    bez.length / 8 > LAYER_MIN_SEGMENTS;
}

// Flat world coordinates -> screen, only for items `idx` (stride numbers
// each) of a buffer that toScreen filled for the same array length.
function toScreenAt(src, key, stride, idx) {
  const out = buffers[key];
  if (!out || out.length !== src.length) return toScreen(src, key);
  const x0 = view.x0, y0 = view.y0, s = view.s, t = view.s * ys();
  for (const i of idx) for (let j = i * stride; j < (i + 1) * stride; j += 2) { out[j] = (src[j] - x0) * s; out[j + 1] = (src[j + 1] - y0) * t; }
  return out;
}

function draw() {
  const dpr = resize();
  const n = count(), o = state.overlays;
  // With the drag layer drawn for this view, only the moving parts (and the
  // selection) need screen coordinates.
  const reuse = layerWanted() && layer && layer.key === layerKey(dpr);
  let P, B;
  if (reuse) {
    const m = layer.parts, ids = new Set([...m.points, ...state.sel]);
    for (const e of m.edges) { ids.add(e); ids.add((e + 1) % n); }
    P = toScreenAt(state.pts, 'pts', 2, ids);
    B = toScreenAt(bez, 'bez', 8, m.segments);
  } else {
    P = toScreen(state.pts, 'pts');
    B = toScreen(bez, 'bez');
  }
  const fresh = globalCurrent();
  const g = global && !global.error ? global : null;
  const clear = (c) => {
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.fillStyle = '#fff';
    c.fillRect(0, 0, canvas.width, canvas.height);
    c.setTransform(dpr, 0, 0, dpr, 0, 0);
    c.lineJoin = 'round';
    c.lineCap = 'round';
  };
  let moving = null;
  if (layerWanted()) {
    const key = layerKey(dpr);
    if (!layer || layer.key !== key) {
      // Drawn at the first frame of the drag (or after a zoom during it).
      const lc = layer && layer.canvas.width === canvas.width && layer.canvas.height === canvas.height
        ? layer.canvas : Object.assign(document.createElement('canvas'), { width: canvas.width, height: canvas.height });
      const parts = movingParts(drag.idx), c2 = lc.getContext('2d');
      clear(c2);
      if (state.grid) drawGrid(c2, canvas.clientWidth, canvas.clientHeight);
      drawBase(c2, P, B, { edges: { skip: parts.edges }, segments: { skip: parts.segments }, points: { skip: parts.points } }, false);
      layer = { canvas: lc, key, parts: { ...parts, visible: visibleCount(P) } };
    }
    moving = layer.parts;
  } else {
    layer = null;
  }
  if (moving) {
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(layer.canvas, 0, 0);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.lineJoin = 'round';
    ctx.lineCap = 'round';
    ++layerFrames;
  } else {
    clear(ctx);
    if (state.grid) drawGrid(ctx, canvas.clientWidth, canvas.clientHeight);
  }

  // Bounding volumes first (under everything).
  if (o.volumes && g && g.volumes) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    drawVolumes(g.volumes);
    ctx.globalAlpha = 1;
  }
  const only = (set) => ({ only: set });
  drawBase(ctx, P, B, moving ? { edges: only(moving.edges), segments: only(moving.segments), points: only(moving.points), visible: moving.visible }
    : { edges: every, segments: every, points: every }, o.comb && cache.comb);
  if (o.ticks && g && g.ticks) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    const t = g.ticks, m = t.length / 4, path = new Path2D(), L = 5, k = ys();
    for (let j = 0; j < m; ++j) {
      const x = SX(t[2 * j]), y = SY(t[2 * j + 1]), tx = t[2 * (m + j)], ty = t[2 * (m + j) + 1] * k;
      path.moveTo(x - ty * L, y + tx * L);
      path.lineTo(x + ty * L, y - tx * L);
    }
    ctx.strokeStyle = colors.tick;
    ctx.lineWidth = 1.2;
    ctx.stroke(path);
    ctx.globalAlpha = 1;
  }
  if (state.sel.size) {
    ctx.strokeStyle = colors.selected;
    ctx.lineWidth = 1.5;
    for (const s of state.sel) if (s < n) ctx.strokeRect(P[2 * s] - 7, P[2 * s + 1] - 7, 14, 14);
  }
  if (o.cusps && cache.cusps) {
    const path = new Path2D(), r = 6;
    for (const c of cache.cusps) {
      if (!c) continue;
      for (let k = 0; k < c.length; k += 2) { const x = SX(c[k]), y = SY(c[k + 1]); path.moveTo(x + r, y); path.arc(x, y, r, 0, 2 * Math.PI); }
    }
    ctx.strokeStyle = colors.cusp;
    ctx.lineWidth = 2.5;
    ctx.stroke(path);
  }
  if (o.intersections && g && g.intersections) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    const X = g.intersections, path = new Path2D(), r = 6;
    for (let k = 0; k < X.length; k += 2) {
      const x = SX(X[k]), y = SY(X[k + 1]);
      path.moveTo(x - r, y - r); path.lineTo(x + r, y + r);
      path.moveTo(x - r, y + r); path.lineTo(x + r, y - r);
    }
    ctx.strokeStyle = colors.crossing;
    ctx.lineWidth = 2.5;
    ctx.stroke(path);
    ctx.globalAlpha = 1;
  }
  if (drag && drag.kind === 'marquee') {
    const [ax, ay, bx, by] = drag.rect;
    ctx.setLineDash([3, 3]);
    ctx.strokeStyle = colors.selected;
    ctx.lineWidth = 1;
    ctx.strokeRect(Math.min(ax, bx) + 0.5, Math.min(ay, by) + 0.5, Math.abs(bx - ax), Math.abs(by - ay));
    ctx.setLineDash([]);
  }
}

function drawVolumes(v) {
  const boxes = new Path2D(), S = v.boxStride;
  for (let k = 0; k + S <= v.boxes.length; k += S) {
    const b = v.boxes;
    const ax = b[k + 1], ay = b[k + 2], bx = b[k + 3], by = b[k + 4], l0 = b[k + 5], l1 = b[k + 6], w = b[k + 7];
    const dx = bx - ax, dy = by - ay, L = Math.hypot(dx, dy);
    if (!(L > 0) || !Number.isFinite(w)) continue;
    const nx = -dy / L * w, ny = dx / L * w;
    const p0x = ax + l0 * dx, p0y = ay + l0 * dy, p1x = ax + l1 * dx, p1y = ay + l1 * dy;
    boxes.moveTo(SX(p0x + nx), SY(p0y + ny));
    boxes.lineTo(SX(p1x + nx), SY(p1y + ny));
    boxes.lineTo(SX(p1x - nx), SY(p1y - ny));
    boxes.lineTo(SX(p0x - nx), SY(p0y - ny));
    boxes.closePath();
  }
  for (let k = 0; k + v.ballStride <= v.balls.length; k += v.ballStride) {
    const x = SX(v.balls[k + 1]), y = SY(v.balls[k + 2]), r = v.balls[k + 3] * view.s;
    if (!Number.isFinite(r)) continue;
    boxes.moveTo(x + r, y);
    boxes.arc(x, y, r, 0, 2 * Math.PI);
  }
  ctx.fillStyle = colors.volume;
  ctx.fill(boxes, 'nonzero');
  ctx.strokeStyle = colors.volumeEdge;
  ctx.lineWidth = 1;
  ctx.stroke(boxes);
}

function drawComb() {
  // Teeth point away from the centre of curvature, with length proportional
  // to the curvature: the 90th percentile of |k| gets 30 px times twice the
  // comb slider; the rare huge values (near cusps) are clipped at twice that.
  const ks = [];
  for (const c of cache.comb) for (let j = 4; j < c.length; j += 5) if (Number.isFinite(c[j])) ks.push(Math.abs(c[j]));
  if (!ks.length) return;
  ks.sort((a, b) => a - b);
  const k90 = ks[Math.floor(0.9 * (ks.length - 1))] || ks[ks.length - 1];
  if (!(k90 > 0)) return;
  const scale = (60 * state.combScale) / k90, kmax = 2 * k90, sg = ys();
  const teeth = new Path2D(), hull = new Path2D();
  for (const c of cache.comb) {
    for (let j = 0; j < c.length; j += 5) {
      const k = Math.max(-kmax, Math.min(kmax, c[j + 4]));
      const x = SX(c[j]), y = SY(c[j + 1]);
      const tx = x - c[j + 2] * k * scale, ty = y - c[j + 3] * sg * k * scale;
      teeth.moveTo(x, y);
      teeth.lineTo(tx, ty);
      if (j === 0) hull.moveTo(tx, ty); else hull.lineTo(tx, ty);
    }
  }
  ctx.strokeStyle = colors.comb;
  ctx.lineWidth = 1;
  ctx.stroke(teeth);
  ctx.stroke(hull);
}

// ---------------------------------------------------------------------------
// Status line
// ---------------------------------------------------------------------------
const fmt = (x, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : String(x));
// Significant digits, whatever the scale: 7 (at least 6 asked for), no
// trailing exponent noise for ordinary magnitudes.
const sig = (x, d = 7) => (Number.isFinite(x) ? (x === 0 ? '0' : x.toPrecision(d).replace(/e\+?/, 'e')) : String(x));
// The total length: Kahan sums of blocks of 512 segment lengths, each
// redone only when a length in it changed (a drag at 10^5 points changes 4),
// then of the blocks.
const LEN_BLOCK = 512;
let lenBlocks = null;  // block sums; NaN: to redo
function kahan(a, from = 0, to = a.length) {
  let s = 0, c = 0;
  for (let i = from; i < to; ++i) { const y = a[i] - c, t = s + y; c = (t - s) - y; s = t; }
  return s;
}
function totalLength() {
  if (!cache.len) return NaN;
  const nb = Math.ceil(cache.len.length / LEN_BLOCK);
  if (!lenBlocks || lenBlocks.length !== nb) lenBlocks = new Float64Array(nb).fill(NaN);
  for (let b = 0; b < nb; ++b) if (Number.isNaN(lenBlocks[b])) lenBlocks[b] = kahan(cache.len, b * LEN_BLOCK, Math.min(cache.len.length, (b + 1) * LEN_BLOCK));
  return kahan(lenBlocks);
}
function cuspCount() {
  if (!cache.cusps) return null;
  let k = 0;
  for (const c of cache.cusps) if (c) k += c.length / 2;
  return k;
}
// Status texts are written only when they change.
const setText = (id, text) => { const el = $(id); if (el.textContent !== text) el.textContent = text; };
let frameTextAt = 0;
function updateStatus(ms) {
  const n = count();
  setText('status-points', `${n} point${n === 1 ? '' : 's'}` + (state.sel.size > 1 ? ` (${state.sel.size} selected)` : ''));
  const nseg = spline ? spline.segmentCount() : 0;
  setText('status-segments', `${nseg} segment${nseg === 1 ? '' : 's'}`);
  setText('status-length', spline ? `length ${sig(totalLength())}${state.dim > 2 ? ` (${state.dim}-D)` : ''}` : 'length —');
  const cc = cuspCount();
  setText('status-cusps', !spline ? 'cusps —' : cc === null ? 'cusps off' : `${cc} cusp${cc === 1 ? '' : 's'}`);
  let text, cls = '';
  if (!spline) {
    text = n < 2 ? 'click to add points' : '—';
  } else if (!globalCurrent()) {
    text = deferredGlobal ? 'certificate after release' : 'certifying…';
  } else if (global.error) {
    text = `error: ${global.error}`;
  } else if (global.cert.certified) {
    text = 'certified intersection-free';
    cls = 'ok';
  } else {
    const c = global.cert;
    const k = global.intersections.length / 2 + global.folds.length;
    const found = c.intersects === null ? '' : c.intersects ? `; ${k} self-intersection${k === 1 ? '' : 's'}${c.complete ? '' : ' (search incomplete)'}` : '; no self-intersection found';
    text = `not certified (${c.failed_rule.replace(/_/g, ' ')}: ${c.detail})${found}`;
    cls = c.intersects ? 'bad' : '';
  }
  const cert = $('status-cert');
  if (cert.textContent !== text) { cert.textContent = text; cert.title = text; }
  if (cert.className !== cls) cert.className = cls;
  // The frame time, four times a second (a text that changes every frame
  // costs a layout every frame).
  if (performance.now() - frameTextAt > 250) { frameTextAt = performance.now(); setText('status-frame', `frame ${fmt(ms, 1)} ms`); }
  showMessage(importMessage || splineError || '');
  syncPointFields();
  // For tests: the numbers as data attributes (written when they change).
  const d = document.body.dataset;
  const data = {
    points: n, segments: nseg, length: spline ? totalLength() : '', cusps: cc ?? '',
    certified: spline && globalCurrent() && !global.error ? String(global.cert.certified) : '',
    intersections: spline && globalCurrent() && !global.error ? String(global.intersections.length / 2) : '',
    version,
  };
  for (const [k, v] of Object.entries(data)) if (d[k] !== String(v)) d[k] = v;
}

// The message (import errors, the library's complaint about the curve):
// shown over the canvas, announced (role=alert), closable.
function showMessage(text) {
  const m = $('message');
  if (m.textContent !== text) m.textContent = text;
  $('toast').hidden = !text;
}

// ---------------------------------------------------------------------------
// Edits and undo. An edit (or a gesture: a drag, a slider pull) starts with
// beginEdit() and ends with endEdit(), which records one undo step only if
// the points or options actually changed. Selecting is not an edit.
// ---------------------------------------------------------------------------
function snapshot() {
  return { pts: state.pts.slice(), rest: state.rest.slice(), dim: state.dim, pair: [...state.pair], names: state.names,
    opts: { ...state.opts }, selected: state.selected, sel: [...state.sel] };
}
let pendingEdit = null;
function sameAsNow(s) {
  if (s.pts.length !== state.pts.length || s.rest.length !== state.rest.length || s.dim !== state.dim) return false;
  if (s.pair[0] !== state.pair[0] || s.pair[1] !== state.pair[1]) return false;
  for (let i = 0; i < s.pts.length; ++i) if (!Object.is(s.pts[i], state.pts[i])) return false;
  for (let i = 0; i < s.rest.length; ++i) if (!Object.is(s.rest[i], state.rest[i])) return false;
  for (const k of new Set([...Object.keys(s.opts), ...Object.keys(state.opts)])) if (s.opts[k] !== state.opts[k]) return false;
  return true;
}
function beginEdit() { if (!pendingEdit) pendingEdit = snapshot(); }
function endEdit() {
  if (!pendingEdit) return;
  const s = pendingEdit;
  pendingEdit = null;
  if (sameAsNow(s)) return;
  undoStack.push(s);
  if (undoStack.length > UNDO_LIMIT) undoStack.shift();
  redoStack.length = 0;
}
function edit(f) { beginEdit(); f(); endEdit(); }
function restore(s) {
  state.pts = s.pts;
  state.rest = s.rest;
  state.dim = s.dim;
  state.pair = s.pair;
  state.names = s.names;
  state.opts = s.opts;
  syncProjection();
  state.sel = new Set(s.sel.filter((i) => i < count()));
  state.selected = s.selected < count() ? s.selected : -1;
  syncControls();
  markAll();
  changed();
}
function undo() { endEdit(); if (undoStack.length) { redoStack.push(snapshot()); restore(undoStack.pop()); } }
function redo() { endEdit(); if (redoStack.length) { undoStack.push(snapshot()); restore(redoStack.pop()); } }

function select(list, primary = list.length ? list[list.length - 1] : -1) {
  state.sel = new Set(list);
  state.selected = primary;
  requestFrame();
}

// A plane curve (flat x, y).
function setPoints(flat) { setDocument(flat, 2); }
// A curve of any dimension (flat, dim per point), shown on `pair`.
function setDocument(full, dim, names = coordinateNames(dim), pair = [0, 1]) {
  const { pts, rest } = splitPoints(full, dim, pair);
  state.pts = pts;
  state.rest = rest;
  state.dim = dim;
  state.pair = pair;
  state.names = names;
  syncProjection();
  select([]);
  markAll();
  changed();
}

// Insert point (x, y) before point k; `rest`: its hidden coordinates (a
// point of a projected curve), by default those of its neighbour (the point
// before it, or the first): a point added in the view's plane lies in the
// plane parallel to it through that neighbour.
function insertPoint(k, x, y, rest = null) {
  const n = count(), a = new Float64Array(2 * (n + 1));
  a.set(state.pts.subarray(0, 2 * k));
  a[2 * k] = x; a[2 * k + 1] = y;
  a.set(state.pts.subarray(2 * k), 2 * k + 2);
  const r = state.dim - 2;
  if (r > 0) {
    const b = new Float64Array(r * (n + 1));
    b.set(state.rest.subarray(0, r * k));
    b.set(rest ?? (n ? restOf(Math.max(0, k - 1)) : new Float64Array(r)), r * k);
    b.set(state.rest.subarray(r * k), r * (k + 1));
    state.rest = b;
  }
  const before = state.opts.closed ? n : n - 1;
  if (state.opts.grid || state.opts.kb) perPointInsert(k);
  state.pts = a;
  select([k]);
  if (before >= 1 && k > 0) { shiftCaches(k, +1); markAround(k, -3, 2); } else markAll();
  changed();
}

function deletePoint(k) {
  const n = count();
  if (k < 0 || k >= n) return;
  const a = new Float64Array(2 * (n - 1));
  a.set(state.pts.subarray(0, 2 * k));
  a.set(state.pts.subarray(2 * k + 2), 2 * k);
  if (state.opts.grid || state.opts.kb) perPointKeep((i) => i !== k);
  state.pts = a;
  const r = state.dim - 2;
  if (r > 0) {
    const b = new Float64Array(r * (n - 1));
    b.set(state.rest.subarray(0, r * k));
    b.set(state.rest.subarray(r * (k + 1)), r * k);
    state.rest = b;
  }
  const next = Math.min(k, n - 2);
  select(next >= 0 ? [next] : []);
  if (n - 1 >= 3 && k > 0 && k < n - 1) { shiftCaches(k, -1); markAround(k, -3, 2); } else markAll();
  changed();
}

function deleteSelected() {
  const sel = [...state.sel].filter((i) => i < count());
  if (!sel.length) return;
  if (sel.length === 1) { edit(() => deletePoint(sel[0])); return; }
  edit(() => {
    const drop = new Set(sel), keep = [], keepRest = [], r = state.dim - 2;
    if (state.opts.grid || state.opts.kb) perPointKeep((i) => !drop.has(i));
    for (let i = 0; i < count(); ++i) {
      if (drop.has(i)) continue;
      keep.push(state.pts[2 * i], state.pts[2 * i + 1]);
      for (let j = 0; j < r; ++j) keepRest.push(state.rest[i * r + j]);
    }
    state.pts = Float64Array.from(keep);
    state.rest = Float64Array.from(keepRest);
    select([]);
    markAll();
    changed();
  });
}

// Move points `idx` to their positions in `from` plus (dx, dy).
function movePoints(idx, from, dx, dy) {
  for (let j = 0; j < idx.length; ++j) {
    const k = idx[j];
    state.pts[2 * k] = from[2 * j] + dx;
    state.pts[2 * k + 1] = from[2 * j + 1] + dy;
    if (idx.length <= 64) markAround(k);
  }
  if (idx.length > 64) markAll();
  changed();
}

function setOption(key, value) {
  if (state.opts[key] === value && !(key === 'alpha' && state.opts.grid)) return;
  edit(() => {
    state.opts = { ...state.opts, [key]: value };
    let dropped = false;
    if (key === 'alpha') dropped = dropGrid();
    // A closed grid has one knot more (the end of the period).
    if (key === 'closed' && state.opts.grid) state.opts.grid = value ? extendKnots(state.opts.grid, state.opts.grid.length) : state.opts.grid.slice(0, -1);
    syncControls();
    markAll();
    changed();
    if (dropped) noteGridDropped();
  });
}

// Knots and Kochanek-Bartels values from a file follow the points: a new
// point gets the knot halfway between its neighbours' (beyond an end, one
// interval further) and zero KB values; a deleted point takes its own away.
// Choosing alpha replaces the file's knots by alpha's (undo brings them
// back), and says so.
function extendKnots(g, k) {
  const a = g.slice();
  const t = k > 0 && k < g.length ? (g[k - 1] + g[k]) / 2 : k === 0 ? g[0] - (g[1] - g[0]) : g[k - 1] + (g[k - 1] - g[k - 2]);
  a.splice(k, 0, t);
  return a;
}
function perPointInsert(k) {
  const o = { ...state.opts };
  if (o.grid && o.grid.length >= 2) o.grid = extendKnots(o.grid, k);
  if (o.kb) o.kb = Object.fromEntries(Object.entries(o.kb).map(([key, v]) => { const a = v.slice(); a.splice(k, 0, 0); return [key, a]; }));
  state.opts = o;
}
// Before points are deleted: keep(i) for the points that stay.
function perPointKeep(keep) {
  const o = { ...state.opts }, n = count();
  if (o.grid) o.grid = o.grid.filter((_, i) => i >= n || keep(i));  // a closed grid's last knot stays
  if (o.kb) o.kb = Object.fromEntries(Object.entries(o.kb).map(([key, v]) => [key, v.filter((_, i) => keep(i))]));
  state.opts = o;
}
function dropGrid() {
  if (!state.opts.grid) return false;
  const { grid, ...rest } = state.opts;
  state.opts = rest;
  return true;
}
function noteGridDropped() {
  importMessage = `knots from α = ${state.opts.alpha} now, instead of the file's grid (Ctrl+Z brings it back)`;
  requestFrame();
}

// The point after `k` on the curve: the middle (in t) of segment k, or past
// the end of an open curve.
function insertAfter(k) {
  const n = count();
  if (n === 0) return;
  if (k < 0) k = n - 1;
  edit(() => {
    const nseg = spline ? spline.segmentCount() : 0;
    if (spline && k < nseg) {
      const g = spline.grid();
      const p = spline.evaluate((g[k] + g[k + 1]) / 2);
      const [xy, rest] = splitOne(p);
      insertPoint(k + 1, xy[0], xy[1], rest);
    } else {
      const x = state.pts[2 * k], y = state.pts[2 * k + 1];
      const dx = n > 1 ? x - state.pts[2 * k - 2] : 40 / view.s, dy = n > 1 ? y - state.pts[2 * k - 1] : 0;
      insertPoint(k + 1, x + dx / 2, y + dy / 2);
    }
  });
}

// ---------------------------------------------------------------------------
// View
// ---------------------------------------------------------------------------
// Zoom limits, relative to the scale that fits the points: 1e-3 to 1e6
// times it (and never so far in that one pixel is under ~16 ulps of the
// coordinates, where the curve itself stops being smooth).
function scaleLimits() {
  const f = fitScale();
  let m = Math.max(Math.abs(view.x0), Math.abs(view.y0));
  for (let i = 0; i < Math.min(state.pts.length, 4); ++i) m = Math.max(m, Math.abs(state.pts[i]));
  const ulpLimit = m > 0 ? 1 / (16 * m * Number.EPSILON) : Infinity;
  return [f * 1e-3, Math.min(f * 1e6, Math.max(ulpLimit, f))];
}
function zoomAt(px, py, factor) {
  const [lo, hi] = scaleLimits();
  const s = Math.min(hi, Math.max(lo, view.s * factor));
  const wx = view.x0 + px / view.s, wy = view.y0 + (py * ys()) / view.s;
  view.s = s;
  view.x0 = wx - px / s;
  view.y0 = wy - (py * ys()) / s;
  requestFrame();
}
function panBy(dx, dy) {
  view.x0 -= dx / view.s;
  view.y0 -= (dy * ys()) / view.s;
  requestFrame();
}
function bounds() {
  const n = count();
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < n; ++i) {
    x0 = Math.min(x0, state.pts[2 * i]); x1 = Math.max(x1, state.pts[2 * i]);
    y0 = Math.min(y0, state.pts[2 * i + 1]); y1 = Math.max(y1, state.pts[2 * i + 1]);
  }
  return [x0, y0, x1, y1];
}
function fitScale() {
  const n = count();
  if (n === 0) return 1;
  const [x0, y0, x1, y1] = bounds();
  const w = canvas.clientWidth, h = canvas.clientHeight;
  const ext = Math.max(x1 - x0, y1 - y0);
  if (!(ext > 0)) return 1;  // one point (or all equal): zoom 1, centred on it
  const tiny = ext * 1e-9;
  const s = Math.min(Math.max(w - 80, 40) / Math.max(x1 - x0, tiny), Math.max(h - 80, 40) / Math.max(y1 - y0, tiny));
  return Number.isFinite(s) && s > 0 ? s : 1;
}
function fit() {
  const n = count();
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (n === 0) { view.s = 1; view.x0 = 0; view.y0 = view.yUp ? h : 0; requestFrame(); return; }
  const [x0, y0, x1, y1] = bounds();
  view.s = fitScale();
  view.x0 = (x0 + x1) / 2 - w / 2 / view.s;
  view.y0 = (y0 + y1) / 2 - (ys() * h) / 2 / view.s;
  requestFrame();
}
function setYUp(on) {
  if (view.yUp === on) return;
  // Keep the world point at the canvas centre where it is.
  const h = canvas.clientHeight, cy = view.y0 + (ys() * h) / 2 / view.s;
  view.yUp = on;
  view.y0 = cy - (ys() * h) / 2 / view.s;
  $('y-up').checked = on;
  // Remembered by the browser: the curve file has no place for it (every
  // field not in docs/spec.md is an error to the command line).
  try { localStorage.setItem(Y_UP_KEY, on ? '1' : '0'); } catch { /* storage off: for this page only */ }
  requestFrame();
}

// ---------------------------------------------------------------------------
// Pointer: mouse, pen and touch through pointer events (touch-action: none
// on the canvas; the pointer is captured). Gestures (`drag`):
//   move     points `idx` follow the pointer (from their positions `from`)
//   pan      the view follows the pointer (right/middle button, Space+drag,
//            one finger on empty canvas once it moves)
//   tap      a finger on empty canvas, not yet moved: a point on release
//   pinch    two fingers: zoom about them and pan with them
//   marquee  Shift+drag on empty canvas: select the points inside
// ---------------------------------------------------------------------------
const pointers = new Map();  // pointerId -> [x, y] in canvas CSS px
// The canvas' position, read again at the start of every gesture (and after
// a resize): reading it on every move would force a layout each time, since
// the status line changes every frame.
let canvasRect = null;
function local(e, fresh = false) {
  if (fresh || !canvasRect) {
    const r = canvas.getBoundingClientRect();
    canvasRect = [r.left + canvas.clientLeft, r.top + canvas.clientTop];
  }
  return [e.clientX - canvasRect[0], e.clientY - canvasRect[1]];
}
const toWorld = (px, py) => [view.x0 + px / view.s, view.y0 + (py * ys()) / view.s];
function snap(x, y) {
  if (!state.grid) return [x, y];
  const g = gridStep();
  return [Math.round(x / g) * g, Math.round(y / g) * g];
}
// The point under screen position (px, py) within r CSS px: compared in
// screen space (the differences are small, exact enough far from 0).
function hit(px, py, r = 9) {
  const P = state.pts, n = count(), k = view.s * ys();
  let best = -1, bd = r * r;
  for (let i = 0; i < n; ++i) {
    const dx = (P[2 * i] - view.x0) * view.s - px, dy = (P[2 * i + 1] - view.y0) * k - py, d = dx * dx + dy * dy;
    if (d <= bd) { bd = d; best = i; }
  }
  return best;
}
// A point of the curve (dim coordinates) -> [[x, y], hidden coordinates].
function splitOne(p) {
  const h = hidden();
  return [[p[state.pair[0]], p[state.pair[1]]], Float64Array.from(h, (k) => p[k])];
}
// The nearest curve point to screen (px, py) if within r px: { segment,
// point: [x, y], rest }. A projected curve is searched in the view's plane
// (nearestProjected), then evaluated with every coordinate.
function nearCurve(px, py, r) {
  if (!spline) return null;
  if (state.dim === 2) {
    const near = spline.nearest(toWorld(px, py));
    return Math.sqrt(near.distanceSq) * view.s <= r ? { segment: near.segment, point: near.point, rest: null } : null;
  }
  const near = nearestProjected(bez, toWorld(px, py), r / view.s);
  if (!near) return null;
  const g = spline.grid(), t = g[near.segment] + near.u * (g[near.segment + 1] - g[near.segment]);
  const [xy, rest] = splitOne(spline.evaluate(Math.min(t, spline.tMax())));
  return { segment: near.segment, point: xy, rest };
}
// The nearest point within `within` (world units) of q on the plane
// Béziers `b` (8 numbers per segment): { segment, u } or null. Segments
// whose control hull is farther are skipped; the rest sampled, then the
// best sample refined by bisection on u.
function nearestProjected(b, q, within) {
  const at = (k, u) => {
    const v = 1 - u, c0 = v * v * v, c1 = 3 * v * v * u, c2 = 3 * v * u * u, c3 = u * u * u;
    return [c0 * b[k] + c1 * b[k + 2] + c2 * b[k + 4] + c3 * b[k + 6], c0 * b[k + 1] + c1 * b[k + 3] + c2 * b[k + 5] + c3 * b[k + 7]];
  };
  const d2 = (k, u) => { const p = at(k, u); return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2; };
  let best = null, bd = within * within;
  for (let i = 0; i < b.length / 8; ++i) {
    const k = 8 * i;
    const xa = Math.min(b[k], b[k + 2], b[k + 4], b[k + 6]), xb = Math.max(b[k], b[k + 2], b[k + 4], b[k + 6]);
    const ya = Math.min(b[k + 1], b[k + 3], b[k + 5], b[k + 7]), yb = Math.max(b[k + 1], b[k + 3], b[k + 5], b[k + 7]);
    const dx = Math.max(xa - q[0], 0, q[0] - xb), dy = Math.max(ya - q[1], 0, q[1] - yb);
    if (dx * dx + dy * dy > bd) continue;
    const m = 32;
    let u0 = 0, du = 1 / m, e0 = Infinity;
    for (let j = 0; j <= m; ++j) { const e = d2(k, j / m); if (e < e0) { e0 = e; u0 = j / m; } }
    for (let it = 0; it < 40; ++it) {
      du /= 2;
      const ea = d2(k, Math.max(0, u0 - du)), eb = d2(k, Math.min(1, u0 + du));
      if (ea < e0 && ea <= eb) { e0 = ea; u0 = Math.max(0, u0 - du); } else if (eb < e0) { e0 = eb; u0 = Math.min(1, u0 + du); }
    }
    if (e0 <= bd) { bd = e0; best = { segment: i, u: u0 }; }
  }
  return best;
}
let spaceDown = false;

function startMove(idx, px, py) {
  beginEdit();
  const from = new Float64Array(2 * idx.length);
  idx.forEach((k, j) => { from[2 * j] = state.pts[2 * k]; from[2 * j + 1] = state.pts[2 * k + 1]; });
  drag = { kind: 'move', idx, from, start: toWorld(px, py), lead: idx.indexOf(state.selected) };
}

canvas.addEventListener('contextmenu', (e) => e.preventDefault());
canvas.addEventListener('pointerdown', (e) => {
  canvas.focus({ preventScroll: true });
  try { canvas.setPointerCapture(e.pointerId); } catch { /* synthetic events have no active pointer */ }
  const [px, py] = local(e, true);
  pointers.set(e.pointerId, [px, py]);
  const touch = e.pointerType === 'touch';
  if (touch && pointers.size === 2) {
    // A second finger: whatever the first one began becomes a pinch; a
    // point it was dragging goes back where it was.
    if (drag && drag.kind === 'move') { movePoints(drag.idx, drag.from, 0, 0); endEdit(); }
    const [a, b] = [...pointers.values()];
    drag = { kind: 'pinch', last: [a, b] };
    return;
  }
  if (pointers.size > 1) return;
  if (e.button === 1 || e.button === 2 || (e.button === 0 && spaceDown)) { drag = { kind: 'pan', x: px, y: py }; return; }
  if (e.button !== 0) return;
  const k = hit(px, py, touch ? 22 : 9);
  if (k >= 0) {
    if (e.shiftKey) {
      // Shift+click toggles the point in the selection.
      const s = new Set(state.sel);
      if (s.has(k)) s.delete(k); else s.add(k);
      select([...s], s.has(k) ? k : [...s].pop() ?? -1);
      if (!s.has(k)) return;
    } else if (!state.sel.has(k)) select([k]);
    else state.selected = k;
    startMove([...state.sel], px, py);
    requestFrame();
    return;
  }
  if (e.shiftKey) {
    // Shift on the curve inserts there; elsewhere starts a marquee.
    const near = nearCurve(px, py, 12);
    if (near) {
      beginEdit();
      insertPoint(near.segment + 1, near.point[0], near.point[1], near.rest);
      startMove([near.segment + 1], px, py);
      return;
    }
    drag = { kind: 'marquee', rect: [px, py, px, py], base: [...state.sel] };
    return;
  }
  if (touch) { drag = { kind: 'tap', x: px, y: py }; return; }
  // On the curve: wait for a double-click (which inserts there).
  if (nearCurve(px, py, 5)) { select([]); return; }
  addPoint(px, py);
  startMove([state.selected], px, py);
});

// A new point under (px, py): at the start when the first point is the
// selected one (continuing the curve backwards), else at the end.
function addPoint(px, py) {
  beginEdit();
  const [x, y] = snap(...toWorld(px, py));
  const atStart = state.selected === 0 && count() > 1 && state.sel.size === 1;
  // A projected curve: the new point takes the hidden coordinates of the
  // end point it continues from.
  insertPoint(atStart ? 0 : count(), x, y, count() ? restOf(atStart ? 0 : count() - 1) : null);
}

canvas.addEventListener('pointermove', (e) => {
  const [px, py] = local(e);
  showPointer(px, py);
  if (!pointers.has(e.pointerId)) return;
  pointers.set(e.pointerId, [px, py]);
  if (!drag) return;
  pendingEventAt = pendingEventAt || e.timeStamp;
  if (drag.kind === 'pinch') {
    const [a, b] = [...pointers.values()];
    const [la, lb] = drag.last;
    const c0 = [(la[0] + lb[0]) / 2, (la[1] + lb[1]) / 2], c1 = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
    const d0 = Math.hypot(la[0] - lb[0], la[1] - lb[1]), d1 = Math.hypot(a[0] - b[0], a[1] - b[1]);
    panBy(c1[0] - c0[0], c1[1] - c0[1]);
    if (d0 > 0 && d1 > 0) zoomAt(c1[0], c1[1], d1 / d0);
    drag.last = [a, b];
    return;
  }
  if (drag.kind === 'tap') {
    if (Math.hypot(px - drag.x, py - drag.y) > 8) { panBy(px - drag.x, py - drag.y); drag = { kind: 'pan', x: px, y: py }; }
    return;
  }
  if (drag.kind === 'pan') {
    panBy(px - drag.x, py - drag.y);
    drag.x = px; drag.y = py;
    return;
  }
  if (drag.kind === 'marquee') {
    drag.rect[2] = px; drag.rect[3] = py;
    const [ax, ay, bx, by] = drag.rect;
    const P = toScreen(state.pts, 'hit'), inside = [];
    for (let i = 0; i < count(); ++i) {
      const x = P[2 * i], y = P[2 * i + 1];
      if (x >= Math.min(ax, bx) && x <= Math.max(ax, bx) && y >= Math.min(ay, by) && y <= Math.max(ay, by)) inside.push(i);
    }
    select([...new Set([...drag.base, ...inside])]);
    return;
  }
  if (drag.kind === 'move') {
    const [wx, wy] = toWorld(px, py);
    let dx = wx - drag.start[0], dy = wy - drag.start[1];
    if (state.grid && drag.lead >= 0) {
      // Snap the point under the pointer; the others keep their offsets.
      const [sx, sy] = snap(drag.from[2 * drag.lead] + dx, drag.from[2 * drag.lead + 1] + dy);
      dx = sx - drag.from[2 * drag.lead]; dy = sy - drag.from[2 * drag.lead + 1];
    }
    movePoints(drag.idx, drag.from, dx, dy);
  }
});
function endPointer(e) {
  if (!pointers.has(e.pointerId)) return;
  pointers.delete(e.pointerId);
  if (!drag) return;
  if (drag.kind === 'pinch') { if (pointers.size === 0) finishDrag(); return; }
  if (drag.kind === 'tap' && e.type === 'pointerup') {
    const [px, py] = local(e);
    const k = hit(px, py, 22);
    if (k >= 0) select([k]); else edit(() => addPoint(drag.x, drag.y));
  }
  if (drag.kind === 'marquee' && drag.rect[0] === drag.rect[2] && drag.rect[1] === drag.rect[3]) select([]);
  finishDrag();
}
function finishDrag() {
  drag = null;
  endEdit();
  lastFrameAt = 0;
  if (deferredGlobal) requestGlobal();
  requestFrame();
}
canvas.addEventListener('pointerup', endPointer);
canvas.addEventListener('pointercancel', endPointer);
canvas.addEventListener('pointerleave', () => { $('status-pointer').textContent = ''; });
canvas.addEventListener('dblclick', (e) => {
  const [px, py] = local(e);
  if (hit(px, py) >= 0) return;
  const near = nearCurve(px, py, 8);
  if (near) edit(() => insertPoint(near.segment + 1, near.point[0], near.point[1], near.rest));
});
// Wheel: scroll pans, Ctrl/⌘+scroll zooms (a touchpad pinch arrives as
// Ctrl+wheel too).
canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  const unit = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? canvas.clientHeight : 1;
  if (e.ctrlKey || e.metaKey) {
    const [px, py] = local(e);
    zoomAt(px, py, Math.exp(-e.deltaY * unit * 0.0025));
  } else if (e.shiftKey && !e.deltaX) {
    panBy(-e.deltaY * unit, 0);
  } else {
    panBy(-e.deltaX * unit, -e.deltaY * unit);
  }
}, { passive: false });

// The coordinate readout: enough digits to tell neighbouring pixels apart.
function showPointer(px, py) {
  const [x, y] = toWorld(px, py);
  const d = (v) => {
    const digits = Math.max(1, Math.min(17, Math.ceil(Math.log10(Math.max(Math.abs(v), 1e-300) * view.s)) + 1));
    return sig(v, Math.max(digits, 3));
  };
  $('status-pointer').textContent = `x ${d(x)}, y ${d(y)}`;
}

// ---------------------------------------------------------------------------
// Keyboard. Undo and redo work wherever the focus is (a slider, a checkbox,
// a dropdown), except in text fields, which keep their own. The other keys
// act on the canvas only when no form control has the focus.
// ---------------------------------------------------------------------------
const isTextField = (t) => (t instanceof HTMLInputElement && !['checkbox', 'range', 'radio', 'button', 'file'].includes(t.type)) || t instanceof HTMLTextAreaElement;
// Controls with keys of their own (arrows, Backspace, Space); a focused
// button has none but Space and Enter.
const isControl = (t) => t instanceof HTMLInputElement || t instanceof HTMLSelectElement || t instanceof HTMLTextAreaElement;
window.addEventListener('keydown', (e) => {
  if (isTextField(e.target)) return;
  const mod = e.ctrlKey || e.metaKey;
  if (mod && (e.key === 'z' || e.key === 'Z')) { e.preventDefault(); if (e.shiftKey) redo(); else undo(); return; }
  if (mod && (e.key === 'y' || e.key === 'Y')) { e.preventDefault(); redo(); return; }
  if (e.key === 'Escape') {
    if (!$('help').hidden) { toggleHelp(false); e.preventDefault(); return; }
    if (drag && drag.kind === 'marquee') { select(drag.base); drag = null; }
    if (!isControl(e.target)) { select([]); e.preventDefault(); }
    return;
  }
  if (isControl(e.target)) return;
  if (mod && (e.key === 'a' || e.key === 'A')) { e.preventDefault(); select(Array.from({ length: count() }, (_, i) => i)); return; }
  if (mod) return;
  if (e.key === 'Delete' || e.key === 'Backspace') { if (state.sel.size) { e.preventDefault(); deleteSelected(); } return; }
  if (e.key === 'i' || e.key === 'I') { e.preventDefault(); insertAfter(state.selected); return; }
  if (e.key === 'f' || e.key === 'F' || (e.key === '!' && e.shiftKey)) { e.preventDefault(); fit(); return; }
  if (e.key === '?') { e.preventDefault(); toggleHelp(); return; }
  if (e.key === 'g' || e.key === 'G') { e.preventDefault(); $('grid').click(); return; }
  if (e.key === ' ' && !(e.target instanceof HTMLButtonElement)) { e.preventDefault(); if (!spaceDown) { spaceDown = true; canvas.classList.add('grab'); } return; }
  const arrows = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
  if (arrows[e.key] && state.sel.size) {
    e.preventDefault();
    // One screen pixel (Shift: ten), or one grid step with the grid on.
    const step = (state.grid ? gridStep() : 1 / view.s) * (e.shiftKey ? 10 : 1);
    const [ax, ay] = arrows[e.key];
    const idx = [...state.sel];
    const from = Float64Array.from(idx.flatMap((k) => [state.pts[2 * k], state.pts[2 * k + 1]]));
    edit(() => movePoints(idx, from, ax * step, ay * ys() * step));
  }
});
window.addEventListener('keyup', (e) => { if (e.key === ' ') { spaceDown = false; canvas.classList.remove('grab'); } });
window.addEventListener('blur', () => { spaceDown = false; canvas.classList.remove('grab'); });

function toggleHelp(show = $('help').hidden) {
  $('help').hidden = !show;
  $('help-button').setAttribute('aria-expanded', String(show));
  if (show) $('help-close').focus(); else canvas.focus({ preventScroll: true });
}

// ---------------------------------------------------------------------------
// Projection: a curve of 3 or more coordinates is shown on two of them, and
// says so (the banner over the canvas, with the choice of the pair).
// ---------------------------------------------------------------------------
function projectionText() {
  const d = state.dim, N = state.names, [a, b] = state.pair, h = hidden().map((k) => N[k]);
  const list = (xs) => (xs.length <= 3 ? xs.join(', ') : `${xs.slice(0, 2).join(', ')}, … ${xs[xs.length - 1]}`);
  return [`${d}-D curve (${list(N)}) shown as its projection on ${N[a]}, ${N[b]}.`,
    `Edits move points in ${N[a]}, ${N[b]} and keep ${list(h)} (a new point takes ${h.length === 1 ? 'it' : 'them'} from its neighbour or the curve). ` +
    `Length, cusps and the certificate are of the ${d}-D curve; the comb and bounding volumes need a plane curve. ` +
    `JSON and CSV exports write all ${d} coordinates; SVG draws ${N[a]}, ${N[b]}.`];
}
function syncProjection() {
  const bar = $('projection'), on = state.dim > 2;
  bar.hidden = !on;
  if (!on) return;
  // The headline always; the details beside it (under a tap on phones).
  const [head, more] = projectionText();
  const b = document.createElement('strong'), m = document.createElement('span');
  b.textContent = head;
  m.textContent = ` ${more}`;
  m.className = 'more';
  $('projection-text').replaceChildren(b, m);
  $('projection-text').title = `${head} ${more}`;
  for (const [id, k] of [['pair-x', 0], ['pair-y', 1]]) {
    const el = $(id);
    const want = state.names.map((n, i) => `${i}:${n}`).join('|');
    if (el.dataset.options !== want) {
      el.replaceChildren(...state.names.map((n, i) => new Option(n, String(i))));
      el.dataset.options = want;
    }
    el.value = String(state.pair[k]);
  }
}
// Show coordinates (a, b): one undo step; the same coordinate on both axes
// swaps them.
function setPair(k, c) {
  const pair = [...state.pair];
  if (pair[1 - k] === c) pair[1 - k] = pair[k];
  pair[k] = c;
  if (pair[0] === state.pair[0] && pair[1] === state.pair[1]) return;
  edit(() => {
    const sel = [...state.sel], selected = state.selected;
    setDocument(fullPoints(), state.dim, state.names, pair);
    select(sel, selected);
  });
  fit();
}
$('projection-text').addEventListener('click', () => $('projection').classList.toggle('open'));
$('pair-x').addEventListener('change', (e) => setPair(0, Number(e.target.value)));
$('pair-y').addEventListener('change', (e) => setPair(1, Number(e.target.value)));

// ---------------------------------------------------------------------------
// Controls
// ---------------------------------------------------------------------------
function syncControls() {
  const o = state.opts;
  // Knots from a file's grid: alpha plays no part until it is chosen.
  $('alpha').value = o.alpha; $('alpha-value').value = o.grid ? 'grid' : o.alpha.toFixed(2);
  $('alpha').title = o.grid ? "knots from the file's grid; choosing alpha replaces them" : '';
  $('tension').value = o.tension; $('tension-value').value = o.tension.toFixed(2);
  $('closed').checked = o.closed;
  // An end tangent from a file (not zero) shows as its own choice.
  for (const id of ['start', 'end']) {
    const el = $(id), v = o[id];
    let opt = el.querySelector('option[value="tangent"]');
    if (Array.isArray(v)) {
      if (!opt) { opt = new Option('', 'tangent'); el.append(opt); }
      opt.textContent = `tangent [${v.join(', ')}]`;
      el.value = 'tangent';
    } else {
      if (opt) opt.remove();
      el.value = v;
    }
  }
  $('start').disabled = $('end').disabled = o.closed;
  for (const b of document.querySelectorAll('.presets button')) b.classList.toggle('active', !o.grid && Number(b.dataset.alpha) === o.alpha);
}

// The selected point's coordinates, editable (shortest round-trip text).
function syncPointFields() {
  const one = state.sel.size === 1 && state.selected >= 0 && state.selected < count();
  for (const [id, off] of [['point-x', 0], ['point-y', 1]]) {
    const el = $(id);
    el.disabled = !one;
    if (document.activeElement === el) continue;
    const v = one ? String(state.pts[2 * state.selected + off]) : '';
    if (el.value !== v) el.value = v;
  }
}
for (const [id, off] of [['point-x', 0], ['point-y', 1]]) {
  $(id).addEventListener('change', (e) => {
    const v = Number(e.target.value), k = state.selected;
    if (e.target.value.trim() === '' || !Number.isFinite(v) || k < 0 || k >= count()) { importMessage = `${off ? 'y' : 'x'}: "${e.target.value}" is not a finite number`; requestFrame(); return; }
    edit(() => {
      const from = Float64Array.of(state.pts[2 * k], state.pts[2 * k + 1]);
      movePoints([k], from, off ? 0 : v - from[0], off ? v - from[1] : 0);
      state.pts[2 * k + off] = v;  // exactly the typed double
    });
  });
}

// Sliders: one undo step per gesture (from the first input to the change
// that ends it), live updates in between.
for (const id of ['alpha', 'tension']) {
  const el = $(id);
  el.addEventListener('input', () => {
    beginEdit();
    state.opts = { ...state.opts, [id]: Number(el.value) };
    const dropped = id === 'alpha' && dropGrid();
    syncControls();
    markAll();
    changed();
    if (dropped) noteGridDropped();
  });
  el.addEventListener('change', endEdit);
  el.addEventListener('blur', endEdit);
}
for (const b of document.querySelectorAll('.presets button')) b.addEventListener('click', () => setOption('alpha', Number(b.dataset.alpha)));
$('closed').addEventListener('change', (e) => setOption('closed', e.target.checked));
for (const id of ['start', 'end']) $(id).addEventListener('change', (e) => { if (e.target.value !== 'tangent') setOption(id, e.target.value); });

for (const box of document.querySelectorAll('[data-overlay]')) {
  box.addEventListener('change', () => {
    state.overlays[box.dataset.overlay] = box.checked;
    builtVersion = -1;  // fill the caches now enabled, ask the worker again
    requestFrame();
  });
}
$('volume-kind').addEventListener('change', (e) => { state.volumeKind = e.target.value; if (state.overlays.volumes) { builtVersion = -1; requestFrame(); } });
$('comb-scale').addEventListener('input', (e) => { state.combScale = Number(e.target.value); requestFrame(); });
$('tick-spacing').addEventListener('change', (e) => {
  const v = Number(e.target.value);
  if (v > 0) { state.tickSpacing = v; if (state.overlays.ticks) { builtVersion = -1; requestFrame(); } }
});
$('y-up').addEventListener('change', (e) => setYUp(e.target.checked));
$('grid').addEventListener('change', (e) => { state.grid = e.target.checked; requestFrame(); });

$('undo').addEventListener('click', undo);
$('redo').addEventListener('click', redo);
$('delete').addEventListener('click', deleteSelected);
$('insert').addEventListener('click', () => insertAfter(state.selected));
$('clear').addEventListener('click', () => edit(() => setPoints(new Float64Array(0))));
$('demo').addEventListener('click', () => edit(() => loadDemo()));
$('stress').addEventListener('click', () => edit(() => loadStress(10000)));
for (const id of ['fit', 'fit-stage']) $(id).addEventListener('click', () => fit());
$('help-button').addEventListener('click', () => toggleHelp());
$('help-close').addEventListener('click', () => toggleHelp(false));
$('toast-close').addEventListener('click', () => { importMessage = ''; showMessage(''); });

// The panel: beside the canvas on wide screens, a drawer over it on narrow
// ones (closed at first there).
const panelToggle = $('panel-toggle');
function setPanel(open) {
  document.body.classList.toggle('panel-closed', !open);
  panelToggle.setAttribute('aria-expanded', String(open));
}
panelToggle.addEventListener('click', () => setPanel(document.body.classList.contains('panel-closed')));
setPanel(!window.matchMedia('(max-width: 700px)').matches);

function download(name, text, type) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement('a');
  a.href = url; a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
// JSON and CSV write every coordinate (a projected curve keeps its
// dimension); SVG draws the view's two.
$('export-json').addEventListener('click', () => download('crspline-points.json', pointsToJson(fullPoints(), state.opts, state.dim), 'application/json'));
$('export-csv').addEventListener('click', () => download('crspline-points.csv', pointsToCsv(fullPoints(), state.dim, state.names), 'text/csv'));
$('export-svg').addEventListener('click', () => {
  rebuild();
  download('crspline-curve.svg', curveToSvg(bez, state.pts, { closed: state.opts.closed }), 'image/svg+xml');
});

async function importFile(file) {
  try {
    const { points, dimension, names, options, notKept } = parsePoints(await file.text(), file.name);
    // What the editor holds, the library checks (the same words as the
    // command line: a grid of the wrong length, a KB value, ...). A module
    // that cannot build this dimension yet opens it anyway, and says so.
    if (points.length >= 2 * dimension) {
      try { new M.Spline(points, dimension, splineOptions(options, dimension)).delete(); } catch (e) { if (!/dimension must be/.test(e.message)) throw e; }
    }
    edit(() => {
      state.opts = options;
      syncControls();
      setDocument(points, dimension, names);
    });
    fit();
    // Nothing read is dropped without a word: the command line's requests
    // (t, derivatives, ...) are not part of the curve.
    if (notKept.length) {
      importMessage = `${file.name}: opened; ${notKept.map((k) => `"${k}"`).join(', ')} ${notKept.length === 1 ? 'is a request' : 'are requests'} ` +
        'to the command line, not part of the curve: not kept';
      requestFrame();
    }
  } catch (e) {
    importMessage = `import ${file.name}: ${e.message}`;
    requestFrame();
  }
}
$('import').addEventListener('change', (e) => { if (e.target.files[0]) importFile(e.target.files[0]); e.target.value = ''; });
canvas.addEventListener('dragover', (e) => e.preventDefault());
canvas.addEventListener('drop', (e) => { e.preventDefault(); if (e.dataTransfer.files[0]) importFile(e.dataTransfer.files[0]); });

// ---------------------------------------------------------------------------
// Sample data
// ---------------------------------------------------------------------------
// The view at zoom 1 with the canvas' top-left corner at the world origin
// (y up: the bottom-left corner).
function resetView() { view.s = 1; view.x0 = 0; view.y0 = view.yUp ? canvas.clientHeight : 0; }

// The demo: a polygon with a sharp turn and a crossing, in the visible area.
function loadDemo() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  const rel = [[0.08, 0.7], [0.2, 0.25], [0.36, 0.2], [0.42, 0.72], [0.3, 0.8], [0.55, 0.45], [0.62, 0.5], [0.66, 0.15], [0.8, 0.3], [0.93, 0.75]];
  resetView();
  setPoints(Float64Array.from(rel.flatMap(([u, v]) => toWorld(u * w, v * h))));
}

// n points on a spiral filling the view (seeded wobble): the stress test.
function loadStress(n) {
  const w = canvas.clientWidth, h = canvas.clientHeight, R = 0.46 * Math.min(w, h);
  let seed = 12345;
  const rnd = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const a = new Float64Array(2 * n);
  resetView();
  for (let i = 0; i < n; ++i) {
    const t = i / n, ang = t * 2 * Math.PI * 40, r = R * (0.08 + 0.92 * t) * (1 + 0.01 * (rnd() - 0.5));
    const [x, y] = toWorld(w / 2 + r * Math.cos(ang), h / 2 + r * Math.sin(ang));
    a[2 * i] = x; a[2 * i + 1] = y;
  }
  setPoints(a);
}

// ---------------------------------------------------------------------------
// For tests and the console: window.editor
// ---------------------------------------------------------------------------
let idleWaiters = [];
function isIdle() { return !frameRequested && !drag && builtVersion === version && (!spline || globalCurrent()) && !workerBusy; }
function settle() {
  if (!isIdle()) return;
  const w = idleWaiters;
  idleWaiters = [];
  for (const f of w) f();
}
const quantiles = (a) => {
  if (!a.length) return null;
  const s = [...a].sort((x, y) => x - y), q = (p) => s[Math.min(s.length - 1, Math.floor(p * s.length))];
  return { count: s.length, median: q(0.5), p95: q(0.95), max: s[s.length - 1], mean: s.reduce((x, y) => x + y, 0) / s.length };
};
window.editor = {
  module: M,
  get points() { return Array.from(state.pts); },
  get options() { return { ...state.opts }; },
  get selected() { return state.selected; },
  get selection() { return [...state.sel].sort((a, b) => a - b); },
  get view() { return { ...view }; },
  get undoDepth() { return undoStack.length; },
  setPoints(list) { edit(() => setPoints(Float64Array.from(list.flat()))); },
  setSelection(list) { select(list); },
  get dimension() { return state.dim; },
  get pair() { return [...state.pair]; },
  /// Every coordinate of every point, flat (dimension per point).
  get fullPoints() { return Array.from(fullPoints()); },
  /// What the JSON export writes.
  exportJson() { return pointsToJson(fullPoints(), state.opts, state.dim); },
  worldToScreen(x, y) { return [SX(x), SY(y)]; },
  screenToWorld(px, py) { return toWorld(px, py); },
  zoomBy(f, px = canvas.clientWidth / 2, py = canvas.clientHeight / 2) { zoomAt(px, py, f); },
  fitView() { fit(); },
  gridStep,
  evaluate(t) { rebuild(); return spline ? Array.from(spline.evaluate(t)) : null; },
  grid() { rebuild(); return spline ? Array.from(spline.grid()) : null; },
  bezier() { rebuild(); return Array.from(bez); },
  length() { rebuild(); return totalLength(); },
  cusps() { rebuild(); return cache.cusps ? cache.cusps.filter(Boolean).flatMap((c) => Array.from(c)) : null; },
  global() { return global; },
  /// True while the worker analyses (or has a request queued): its answer
  /// redraws the crossings, ticks and volumes when it comes.
  get analysing() { return workerBusy || queued; },
  idle() { return new Promise((resolve) => { idleWaiters.push(resolve); requestFrame(); }); },
  resetFrameStats() { frameTimes.length = 0; curveTimes.length = 0; frameIntervals.length = 0; latencies.length = 0; layerFrames = 0; },
  frameStats() { return { work: quantiles(frameTimes), curve: quantiles(curveTimes), interval: quantiles(frameIntervals), latency: quantiles(latencies), layerFrames }; },
  /// The drag layer on (default) or off, for comparisons; redraws.
  setDragLayer(on) { useLayer = on; layer = null; requestFrame(); },
  /// A frame now (in the middle of a gesture too), resolved when drawn.
  redraw() { return new Promise((resolve) => { requestFrame(); requestAnimationFrame(() => resolve()); }); },
  loadStress,
  loadDemo,
};

$('version').textContent = `v${M.version()}`;
try { if (localStorage.getItem(Y_UP_KEY) === '1') setYUp(true); } catch { /* storage off */ }
syncControls();
new ResizeObserver(() => { canvasRect = null; requestFrame(); }).observe(canvas);
window.addEventListener('scroll', () => { canvasRect = null; }, true);
changed();
