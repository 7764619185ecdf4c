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
import { parsePoints, pointsToJson, pointsToCsv, curveToSvg, splineOptions, defaultOptions } from './io.mjs';
import { computeGlobal } from './overlays.mjs';

const M = await CrSpline({ locateFile: (p) => new URL('../dist/' + p, import.meta.url).href });

const $ = (id) => document.getElementById(id);
const canvas = $('canvas');
const ctx = canvas.getContext('2d');

// ---------------------------------------------------------------------------
// State
// ---------------------------------------------------------------------------
const state = {
  pts: new Float64Array(0),  // flat x, y in world units
  opts: { ...defaultOptions },
  selected: -1,
  overlays: { polygon: true, handles: false, cusps: true, intersections: true, volumes: false, comb: false, ticks: false },
  volumeKind: 'tightened',
  combScale: 0.5,
  tickSpacing: 25,
};
const view = { s: 1, ox: 0, oy: 0 };  // screen = world * s + o (CSS pixels)
let version = 0;                      // bumps on every change of the curve
let drag = null;                      // { index } or { pan: true, x, y }
const undoStack = [], redoStack = [];
const UNDO_LIMIT = 200;

const count = () => state.pts.length / 2;

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

function rebuild() {
  if (builtVersion === version) return;
  builtVersion = version;
  if (spline) { spline.delete(); spline = null; }
  splineError = null;
  bez = new Float64Array(0);
  const n = count();
  if (n >= 2) {
    try {
      spline = new M.Spline(state.pts, 2, splineOptions(state.opts));
      bez = spline.bezierAll();
    } catch (e) {
      splineError = e.message;
    }
  }
  updateCaches();
  requestGlobal();
}

function updateCaches() {
  const nseg = spline ? spline.segmentCount() : 0;
  const want = { len: true, cusps: state.overlays.cusps, comb: state.overlays.comb };
  for (const key of Object.keys(cache)) {
    if (!want[key] || !spline) { cache[key] = null; continue; }
    const full = dirty.all || !cache[key] || cache[key].length !== nseg;
    if (full) {
      cache[key] = computeRange(key, 0, nseg);
    } else {
      for (const i of dirty.segments) if (i < nseg) cache[key][i] = computeRange(key, i, 1)[0];
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
  // cusps: (segment, u, t, x, y) per cusp
  const flat = spline.cusps(first, n);
  const out = Array.from({ length: n }, () => null);
  for (let k = 0; k < flat.length; k += 5) {
    const j = flat[k] - first;
    out[j] = out[j] ? Float64Array.from([...out[j], flat[k + 3], flat[k + 4]]) : Float64Array.of(flat[k + 3], flat[k + 4]);
  }
  return out;
}

// ---------------------------------------------------------------------------
// Whole-curve overlays: worker, latest request wins
// ---------------------------------------------------------------------------
let worker = null, workerBusy = false, queued = null, global = null;
try {
  worker = new Worker(new URL('./worker.mjs', import.meta.url), { type: 'module' });
  worker.onmessage = (e) => {
    workerBusy = false;
    global = e.data;
    if (queued) { const q = queued; queued = null; send(q); }
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
  if (drag && !drag.pan && global && global.ms > DRAG_GLOBAL_BUDGET) { deferredGlobal = true; return; }
  deferredGlobal = false;
  const req = {
    version,
    points: state.pts.slice(),
    options: splineOptions(state.opts),
    volumes: state.overlays.volumes ? state.volumeKind : null,
    ticks: state.overlays.ticks ? Math.max(1e-9, state.tickSpacing) : null,
    maxTicks: 20000,
  };
  if (workerBusy) queued = req;
  else send(req);
}
const globalCurrent = () => global && global.version === version;

// ---------------------------------------------------------------------------
// Drawing
// ---------------------------------------------------------------------------
const colors = {
  curve: '#1f5fbf', polygon: '#9aa3b5', handle: '#e08a1e', point: '#c0392b', selected: '#111',
  cusp: '#d81b60', crossing: '#8e24aa', volume: 'rgba(46, 160, 67, 0.13)', volumeEdge: 'rgba(46, 160, 67, 0.55)',
  comb: 'rgba(0, 150, 136, 0.55)', tick: '#37474f',
};
let frameRequested = false;
const frameTimes = [];     // work per frame (ms): JS + WASM + canvas calls
const curveTimes = [];     // of which the curve and per-segment caches (WASM)
const frameIntervals = []; // time between frames while dragging (ms)
let lastFrameAt = 0;

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
  if (frameTimes.length > 600) { frameTimes.shift(); curveTimes.shift(); }
  if (drag && lastFrameAt) { frameIntervals.push(now - lastFrameAt); if (frameIntervals.length > 600) frameIntervals.shift(); }
  lastFrameAt = drag ? now : 0;
  updateStatus(t1 - t0);
  settle();
}

function draw() {
  const dpr = resize();
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.setTransform(dpr * view.s, 0, 0, dpr * view.s, dpr * view.ox, dpr * view.oy);
  const px = 1 / view.s;  // one CSS pixel in world units
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  const n = count(), P = state.pts, o = state.overlays;
  const fresh = globalCurrent();
  const g = global && !global.error ? global : null;

  // Bounding volumes first (under everything).
  if (o.volumes && g && g.volumes) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    drawVolumes(g.volumes, px);
    ctx.globalAlpha = 1;
  }
  if (o.polygon && n >= 2) {
    const path = new Path2D();
    path.moveTo(P[0], P[1]);
    for (let i = 1; i < n; ++i) path.lineTo(P[2 * i], P[2 * i + 1]);
    if (state.opts.closed) path.closePath();
    if (n <= 2000) ctx.setLineDash([4 * px, 4 * px]);  // dashing 10^4 edges costs more than the curve
    ctx.strokeStyle = colors.polygon;
    ctx.lineWidth = px;
    ctx.stroke(path);
    ctx.setLineDash([]);
  }
  if (o.comb && cache.comb) drawComb(px);
  // The curve: one path of cubic Béziers.
  const nb = bez.length / 8;
  if (nb > 0) {
    const path = new Path2D();
    path.moveTo(bez[0], bez[1]);
    for (let i = 0; i < nb; ++i) {
      const k = 8 * i;
      path.bezierCurveTo(bez[k + 2], bez[k + 3], bez[k + 4], bez[k + 5], bez[k + 6], bez[k + 7]);
    }
    ctx.strokeStyle = colors.curve;
    // Past a few thousand segments a 1-pixel line (Skia's hairline path)
    // rasterizes several times faster than a thick stroke.
    ctx.lineWidth = (nb > 2000 ? 1 : 2.5) * px;
    ctx.stroke(path);
  }
  if (o.handles && nb > 0) {
    const lines = new Path2D(), dots = new Path2D();
    const r = 2.5 * px;
    for (let i = 0; i < nb; ++i) {
      const k = 8 * i;
      lines.moveTo(bez[k], bez[k + 1]); lines.lineTo(bez[k + 2], bez[k + 3]);
      lines.moveTo(bez[k + 6], bez[k + 7]); lines.lineTo(bez[k + 4], bez[k + 5]);
      dots.rect(bez[k + 2] - r, bez[k + 3] - r, 2 * r, 2 * r);
      dots.rect(bez[k + 4] - r, bez[k + 5] - r, 2 * r, 2 * r);
    }
    ctx.strokeStyle = colors.handle;
    ctx.lineWidth = px;
    ctx.stroke(lines);
    ctx.fillStyle = colors.handle;
    ctx.fill(dots);
  }
  if (o.ticks && g && g.ticks) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    const t = g.ticks, m = t.length / 4, path = new Path2D(), L = 5 * px;
    for (let k = 0; k < m; ++k) {
      const x = t[2 * k], y = t[2 * k + 1], tx = t[2 * (m + k)], ty = t[2 * (m + k) + 1];
      path.moveTo(x - ty * L, y + tx * L);
      path.lineTo(x + ty * L, y - tx * L);
    }
    ctx.strokeStyle = colors.tick;
    ctx.lineWidth = 1.2 * px;
    ctx.stroke(path);
    ctx.globalAlpha = 1;
  }
  // Control points.
  if (n > 0) {
    ctx.fillStyle = colors.point;
    if (n > 2000) {
      // Many points: fillRect each (one path of 10^4 squares fills slower).
      for (let i = 0; i < n; ++i) ctx.fillRect(P[2 * i] - px, P[2 * i + 1] - px, 2 * px, 2 * px);
    } else {
      const r = 4 * px, path = new Path2D();
      for (let i = 0; i < n; ++i) path.rect(P[2 * i] - r, P[2 * i + 1] - r, 2 * r, 2 * r);
      ctx.fill(path);
    }
    if (state.selected >= 0 && state.selected < n) {
      const s = state.selected;
      ctx.strokeStyle = colors.selected;
      ctx.lineWidth = 1.5 * px;
      ctx.strokeRect(P[2 * s] - 7 * px, P[2 * s + 1] - 7 * px, 14 * px, 14 * px);
    }
  }
  if (o.cusps && cache.cusps) {
    const path = new Path2D(), r = 6 * px;
    for (const c of cache.cusps) {
      if (!c) continue;
      for (let k = 0; k < c.length; k += 2) { path.moveTo(c[k] + r, c[k + 1]); path.arc(c[k], c[k + 1], r, 0, 2 * Math.PI); }
    }
    ctx.strokeStyle = colors.cusp;
    ctx.lineWidth = 2.5 * px;
    ctx.stroke(path);
  }
  if (o.intersections && g && g.intersections) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    const x = g.intersections, path = new Path2D(), r = 6 * px;
    for (let k = 0; k < x.length; k += 2) {
      path.moveTo(x[k] - r, x[k + 1] - r); path.lineTo(x[k] + r, x[k + 1] + r);
      path.moveTo(x[k] - r, x[k + 1] + r); path.lineTo(x[k] + r, x[k + 1] - r);
    }
    ctx.strokeStyle = colors.crossing;
    ctx.lineWidth = 2.5 * px;
    ctx.stroke(path);
    ctx.globalAlpha = 1;
  }
}

function drawVolumes(v, px) {
  const boxes = new Path2D(), S = v.boxStride;
  for (let k = 0; k + S <= v.boxes.length; k += S) {
    const b = v.boxes;
    const ax = b[k + 1], ay = b[k + 2], bx = b[k + 3], by = b[k + 4], l0 = b[k + 5], l1 = b[k + 6], w = b[k + 7];
    const dx = bx - ax, dy = by - ay, L = Math.hypot(dx, dy);
    if (!(L > 0) || !Number.isFinite(w)) continue;
    const nx = -dy / L * w, ny = dx / L * w;
    const p0x = ax + l0 * dx, p0y = ay + l0 * dy, p1x = ax + l1 * dx, p1y = ay + l1 * dy;
    boxes.moveTo(p0x + nx, p0y + ny);
    boxes.lineTo(p1x + nx, p1y + ny);
    boxes.lineTo(p1x - nx, p1y - ny);
    boxes.lineTo(p0x - nx, p0y - ny);
    boxes.closePath();
  }
  for (let k = 0; k + v.ballStride <= v.balls.length; k += v.ballStride) {
    const x = v.balls[k + 1], y = v.balls[k + 2], r = v.balls[k + 3];
    if (!Number.isFinite(r)) continue;
    boxes.moveTo(x + r, y);
    boxes.arc(x, y, r, 0, 2 * Math.PI);
  }
  ctx.fillStyle = colors.volume;
  ctx.fill(boxes, 'nonzero');
  ctx.strokeStyle = colors.volumeEdge;
  ctx.lineWidth = px;
  ctx.stroke(boxes);
}

function drawComb(px) {
  // Teeth point away from the centre of curvature, with length proportional
  // to the curvature: the 90th percentile of |k| gets 30 px times twice the
  // comb slider; the rare huge values (near cusps) are clipped at twice that.
  const ks = [];
  for (const c of cache.comb) for (let j = 4; j < c.length; j += 5) if (Number.isFinite(c[j])) ks.push(Math.abs(c[j]));
  if (!ks.length) return;
  ks.sort((a, b) => a - b);
  const k90 = ks[Math.floor(0.9 * (ks.length - 1))] || ks[ks.length - 1];
  if (!(k90 > 0)) return;
  const scale = (60 * state.combScale * px) / k90, kmax = 2 * k90;
  const teeth = new Path2D(), hull = new Path2D();
  for (const c of cache.comb) {
    for (let j = 0; j < c.length; j += 5) {
      const k = Math.max(-kmax, Math.min(kmax, c[j + 4]));
      const tx = c[j] - c[j + 2] * k * scale, ty = c[j + 1] - c[j + 3] * k * scale;
      teeth.moveTo(c[j], c[j + 1]);
      teeth.lineTo(tx, ty);
      if (j === 0) hull.moveTo(tx, ty); else hull.lineTo(tx, ty);
    }
  }
  ctx.strokeStyle = colors.comb;
  ctx.lineWidth = px;
  ctx.stroke(teeth);
  ctx.stroke(hull);
}

// ---------------------------------------------------------------------------
// Status line
// ---------------------------------------------------------------------------
const fmt = (x, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : String(x));
function totalLength() {
  if (!cache.len) return NaN;
  let s = 0, c = 0;  // Kahan sum
  for (const x of cache.len) { const y = x - c, t = s + y; c = (t - s) - y; s = t; }
  return s;
}
function cuspCount() {
  if (!cache.cusps) return null;
  let k = 0;
  for (const c of cache.cusps) if (c) k += c.length / 2;
  return k;
}
function updateStatus(ms) {
  const n = count();
  $('status-points').textContent = `${n} point${n === 1 ? '' : 's'}`;
  const nseg = spline ? spline.segmentCount() : 0;
  $('status-segments').textContent = `${nseg} segment${nseg === 1 ? '' : 's'}`;
  $('status-length').textContent = spline ? `length ${fmt(totalLength(), 3)}` : 'length —';
  const cc = cuspCount();
  $('status-cusps').textContent = cc === null ? 'cusps off' : `${cc} cusp${cc === 1 ? '' : 's'}`;
  const cert = $('status-cert');
  cert.className = '';
  if (!spline) {
    cert.textContent = n < 2 ? 'click to add points' : '—';
  } else if (!globalCurrent()) {
    cert.textContent = deferredGlobal ? 'certificate after release' : 'certifying…';
  } else if (global.error) {
    cert.textContent = `error: ${global.error}`;
  } else if (global.cert.certified) {
    cert.textContent = 'certified intersection-free';
    cert.className = 'ok';
  } else {
    const c = global.cert;
    const k = global.intersections.length / 2 + global.folds.length;
    const found = c.intersects === null ? '' : c.intersects ? `; ${k} self-intersection${k === 1 ? '' : 's'}${c.complete ? '' : ' (search incomplete)'}` : '; no self-intersection found';
    cert.textContent = `not certified (${c.failedRule.replace(/_/g, ' ')}: ${c.detail})${found}`;
    cert.className = c.intersects ? 'bad' : '';
  }
  $('status-frame').textContent = `frame ${fmt(ms, 1)} ms`;
  $('message').textContent = importMessage || splineError || '';
  const d = document.body.dataset;
  d.points = n;
  d.segments = nseg;
  d.length = spline ? totalLength() : '';
  d.cusps = cc ?? '';
  d.certified = spline && globalCurrent() && !global.error ? String(global.cert.certified) : '';
  d.intersections = spline && globalCurrent() && !global.error ? String(global.intersections.length / 2) : '';
  d.version = version;
}

// ---------------------------------------------------------------------------
// Edits (each one undoable)
// ---------------------------------------------------------------------------
function snapshot() { return { pts: state.pts.slice(), opts: { ...state.opts }, selected: state.selected }; }
function pushUndo() {
  undoStack.push(snapshot());
  if (undoStack.length > UNDO_LIMIT) undoStack.shift();
  redoStack.length = 0;
}
function restore(s) {
  state.pts = s.pts;
  state.opts = s.opts;
  state.selected = Math.min(s.selected, count() - 1);
  syncControls();
  markAll();
  changed();
}
function undo() { if (undoStack.length) { redoStack.push(snapshot()); restore(undoStack.pop()); } }
function redo() { if (redoStack.length) { undoStack.push(snapshot()); restore(redoStack.pop()); } }

function setPoints(flat) {
  state.pts = flat;
  state.selected = -1;
  markAll();
  changed();
}

function insertPoint(k, x, y) {
  const n = count(), a = new Float64Array(2 * (n + 1));
  a.set(state.pts.subarray(0, 2 * k));
  a[2 * k] = x; a[2 * k + 1] = y;
  a.set(state.pts.subarray(2 * k), 2 * k + 2);
  const before = state.opts.closed ? n : n - 1;
  state.pts = a;
  state.selected = k;
  if (before >= 1 && k > 0) { shiftCaches(k, +1); markAround(k, -3, 2); } else markAll();
  changed();
}

function deletePoint(k) {
  const n = count();
  if (k < 0 || k >= n) return;
  const a = new Float64Array(2 * (n - 1));
  a.set(state.pts.subarray(0, 2 * k));
  a.set(state.pts.subarray(2 * k + 2), 2 * k);
  state.pts = a;
  state.selected = Math.min(k, n - 2);
  if (n - 1 >= 3 && k > 0 && k < n - 1) { shiftCaches(k, -1); markAround(k, -3, 2); } else markAll();
  changed();
}

function movePoint(k, x, y) {
  state.pts[2 * k] = x;
  state.pts[2 * k + 1] = y;
  markAround(k);
  changed();
}

function setOption(key, value) {
  if (state.opts[key] === value) return;
  pushUndo();
  state.opts = { ...state.opts, [key]: value };
  syncControls();
  markAll();
  changed();
}

// The point after `k` on the curve: the middle (in t) of segment k, or past
// the end of an open curve.
function insertAfter(k) {
  const n = count();
  if (n === 0) return;
  if (k < 0) k = n - 1;
  pushUndo();
  const nseg = spline ? spline.segmentCount() : 0;
  if (spline && k < nseg) {
    const g = spline.grid();
    const p = spline.evaluate((g[k] + g[k + 1]) / 2);
    insertPoint(k + 1, p[0], p[1]);
  } else {
    const x = state.pts[2 * k], y = state.pts[2 * k + 1];
    const dx = n > 1 ? x - state.pts[2 * k - 2] : 40 / view.s, dy = n > 1 ? y - state.pts[2 * k - 1] : 0;
    insertPoint(k + 1, x + dx / 2, y + dy / 2);
  }
}

// ---------------------------------------------------------------------------
// Pointer and keyboard
// ---------------------------------------------------------------------------
function toWorld(e) {
  const r = canvas.getBoundingClientRect();
  const sx = e.clientX - r.left - canvas.clientLeft, sy = e.clientY - r.top - canvas.clientTop;
  return [(sx - view.ox) / view.s, (sy - view.oy) / view.s];
}
function hit(x, y) {
  const P = state.pts, n = count(), r = 9 / view.s;
  let best = -1, bd = r * r;
  for (let i = 0; i < n; ++i) {
    const dx = P[2 * i] - x, dy = P[2 * i + 1] - y, d = dx * dx + dy * dy;
    if (d <= bd) { bd = d; best = i; }
  }
  return best;
}

canvas.addEventListener('contextmenu', (e) => e.preventDefault());
canvas.addEventListener('pointerdown', (e) => {
  canvas.focus();
  try { canvas.setPointerCapture(e.pointerId); } catch { /* synthetic events have no active pointer */ }
  if (e.button === 1 || e.button === 2) { drag = { pan: true, x: e.clientX, y: e.clientY }; return; }
  if (e.button !== 0) return;
  const [x, y] = toWorld(e);
  const k = hit(x, y);
  if (k >= 0) {
    pushUndo();
    state.selected = k;
    drag = { index: k };
    requestFrame();
    return;
  }
  if (e.shiftKey && spline) {
    // Insert on the curve, at the nearest point, if it is near.
    const near = spline.nearest([x, y]);
    if (Math.sqrt(near.distanceSq) * view.s <= 12) {
      pushUndo();
      insertPoint(near.segment + 1, near.point[0], near.point[1]);
      drag = { index: near.segment + 1 };
      return;
    }
  }
  pushUndo();
  insertPoint(count(), x, y);
  drag = { index: count() - 1 };
});
canvas.addEventListener('pointermove', (e) => {
  if (!drag) return;
  if (drag.pan) {
    view.ox += e.clientX - drag.x; view.oy += e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    requestFrame();
    return;
  }
  const [x, y] = toWorld(e);
  movePoint(drag.index, x, y);
});
const endDrag = () => {
  if (!drag) return;
  drag = null;
  lastFrameAt = 0;
  if (deferredGlobal) requestGlobal();
  requestFrame();
};
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);
canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  const r = canvas.getBoundingClientRect();
  const sx = e.clientX - r.left - canvas.clientLeft, sy = e.clientY - r.top - canvas.clientTop;
  const f = Math.exp(-e.deltaY * 0.0015);
  view.ox = sx - (sx - view.ox) * f; view.oy = sy - (sy - view.oy) * f; view.s *= f;
  requestFrame();
}, { passive: false });

window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement && e.target.type !== 'checkbox' && e.target.type !== 'range') return;
  const mod = e.ctrlKey || e.metaKey;
  if (mod && (e.key === 'z' || e.key === 'Z')) { e.preventDefault(); if (e.shiftKey) redo(); else undo(); }
  else if (mod && (e.key === 'y' || e.key === 'Y')) { e.preventDefault(); redo(); }
  else if ((e.key === 'Delete' || e.key === 'Backspace') && state.selected >= 0) { e.preventDefault(); pushUndo(); deletePoint(state.selected); }
  else if ((e.key === 'i' || e.key === 'I') && !mod) { e.preventDefault(); insertAfter(state.selected); }
});

// ---------------------------------------------------------------------------
// Controls
// ---------------------------------------------------------------------------
function syncControls() {
  const o = state.opts;
  $('alpha').value = o.alpha; $('alpha-value').value = o.alpha.toFixed(2);
  $('tension').value = o.tension; $('tension-value').value = o.tension.toFixed(2);
  $('closed').checked = o.closed;
  $('start').value = o.start; $('end').value = o.end;
  $('start').disabled = $('end').disabled = o.closed;
  for (const b of document.querySelectorAll('.presets button')) b.classList.toggle('active', Number(b.dataset.alpha) === o.alpha);
}

// Sliders: one undo entry per gesture (on pointerdown / focus), live updates.
for (const id of ['alpha', 'tension']) {
  const el = $(id);
  el.addEventListener('pointerdown', () => pushUndo());
  el.addEventListener('keydown', () => pushUndo());
  el.addEventListener('input', () => {
    state.opts = { ...state.opts, [id]: Number(el.value) };
    syncControls();
    markAll();
    changed();
  });
}
for (const b of document.querySelectorAll('.presets button')) b.addEventListener('click', () => setOption('alpha', Number(b.dataset.alpha)));
$('closed').addEventListener('change', (e) => setOption('closed', e.target.checked));
$('start').addEventListener('change', (e) => setOption('start', e.target.value));
$('end').addEventListener('change', (e) => setOption('end', e.target.value));

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

$('undo').addEventListener('click', undo);
$('redo').addEventListener('click', redo);
$('delete').addEventListener('click', () => { if (state.selected >= 0) { pushUndo(); deletePoint(state.selected); } });
$('insert').addEventListener('click', () => insertAfter(state.selected));
$('clear').addEventListener('click', () => { pushUndo(); setPoints(new Float64Array(0)); });
$('demo').addEventListener('click', () => { pushUndo(); loadDemo(); });
$('stress').addEventListener('click', () => { pushUndo(); loadStress(10000); });
$('fit').addEventListener('click', () => { fit(); requestFrame(); });

function download(name, text, type) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement('a');
  a.href = url; a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
$('export-json').addEventListener('click', () => download('crspline-points.json', pointsToJson(state.pts, state.opts), 'application/json'));
$('export-csv').addEventListener('click', () => download('crspline-points.csv', pointsToCsv(state.pts), 'text/csv'));
$('export-svg').addEventListener('click', () => {
  rebuild();
  download('crspline-curve.svg', curveToSvg(bez, state.pts, { closed: state.opts.closed }), 'image/svg+xml');
});

async function importFile(file) {
  try {
    const { points, options } = parsePoints(await file.text(), file.name);
    pushUndo();
    state.opts = options;
    syncControls();
    setPoints(points);
    fit();
  } catch (e) {
    importMessage = `import ${file.name}: ${e.message}`;
    requestFrame();
  }
}
$('import').addEventListener('change', (e) => { if (e.target.files[0]) importFile(e.target.files[0]); e.target.value = ''; });
canvas.addEventListener('dragover', (e) => e.preventDefault());
canvas.addEventListener('drop', (e) => { e.preventDefault(); if (e.dataTransfer.files[0]) importFile(e.dataTransfer.files[0]); });

// ---------------------------------------------------------------------------
// View and sample data
// ---------------------------------------------------------------------------
function fit() {
  const n = count();
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (n === 0) { view.s = 1; view.ox = 0; view.oy = 0; return; }
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < n; ++i) {
    x0 = Math.min(x0, state.pts[2 * i]); x1 = Math.max(x1, state.pts[2 * i]);
    y0 = Math.min(y0, state.pts[2 * i + 1]); y1 = Math.max(y1, state.pts[2 * i + 1]);
  }
  const s = Math.min((w - 80) / Math.max(x1 - x0, 1e-9), (h - 80) / Math.max(y1 - y0, 1e-9));
  view.s = Number.isFinite(s) && s > 0 ? s : 1;
  view.ox = w / 2 - view.s * (x0 + x1) / 2;
  view.oy = h / 2 - view.s * (y0 + y1) / 2;
}

// The demo: a polygon with a sharp turn and a crossing, in the visible area.
function loadDemo() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  const rel = [[0.08, 0.7], [0.2, 0.25], [0.36, 0.2], [0.42, 0.72], [0.3, 0.8], [0.55, 0.45], [0.62, 0.5], [0.66, 0.15], [0.8, 0.3], [0.93, 0.75]];
  view.s = 1; view.ox = 0; view.oy = 0;
  setPoints(Float64Array.from(rel.flatMap(([u, v]) => [u * w, v * h])));
}

// n points on a spiral filling the view (seeded wobble): the stress test.
function loadStress(n) {
  const w = canvas.clientWidth, h = canvas.clientHeight, R = 0.46 * Math.min(w, h);
  let seed = 12345;
  const rnd = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const a = new Float64Array(2 * n);
  for (let i = 0; i < n; ++i) {
    const t = i / n, ang = t * 2 * Math.PI * 40, r = R * (0.08 + 0.92 * t) * (1 + 0.01 * (rnd() - 0.5));
    a[2 * i] = w / 2 + r * Math.cos(ang);
    a[2 * i + 1] = h / 2 + r * Math.sin(ang);
  }
  view.s = 1; view.ox = 0; view.oy = 0;
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
  get view() { return { ...view }; },
  setPoints(list) { pushUndo(); setPoints(Float64Array.from(list.flat())); },
  worldToScreen(x, y) { return [x * view.s + view.ox, y * view.s + view.oy]; },
  evaluate(t) { rebuild(); return spline ? Array.from(spline.evaluate(t)) : null; },
  grid() { rebuild(); return spline ? Array.from(spline.grid()) : null; },
  bezier() { rebuild(); return Array.from(bez); },
  length() { rebuild(); return totalLength(); },
  cusps() { rebuild(); return cache.cusps ? cache.cusps.filter(Boolean).flatMap((c) => Array.from(c)) : null; },
  global() { return global; },
  idle() { return new Promise((resolve) => { idleWaiters.push(resolve); requestFrame(); }); },
  resetFrameStats() { frameTimes.length = 0; curveTimes.length = 0; frameIntervals.length = 0; },
  frameStats() { return { work: quantiles(frameTimes), curve: quantiles(curveTimes), interval: quantiles(frameIntervals) }; },
  loadStress,
  loadDemo,
};

$('version').textContent = `v${M.version()}`;
syncControls();
new ResizeObserver(() => requestFrame()).observe(canvas);
changed();
