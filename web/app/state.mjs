// The editor's state, all of it, in one place: the document (points,
// options, selection, overlay settings), the view, the undo history, the
// built curve and its per-segment caches, the whole-curve overlays' worker
// protocol, the gesture under way and the frame loop's bookkeeping. The
// other modules read it through the exported objects and change it only
// through the named functions below (none of them keeps state of its own).
//
// What a change must set off elsewhere (a frame, the controls, the
// projection banner) reaches the modules that do it through `connect`,
// called once by editor.mjs: this module imports none of them.
import { defaultOptions, coordinateNames } from './io.mjs';

const hooks = { requestFrame() {}, settle() {}, syncControls() {}, syncProjection() {} };
/// editor.mjs: the functions a change of state calls (requestFrame,
/// settle, syncControls, syncProjection).
export function connect(h) { Object.assign(hooks, h); }

// ---------------------------------------------------------------------------
// The document
// ---------------------------------------------------------------------------
export const state = {
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
export const view = { s: 1, x0: 0, y0: 0, yUp: false };
export const ys = () => (view.yUp ? -1 : 1);
export const SX = (x) => (x - view.x0) * view.s;
export const SY = (y) => (y - view.y0) * view.s * ys();

/// The session: what is not the document but changes as the editor runs.
///   version        bumps on every change of the curve
///   drag           the pointer gesture under way (see pointer.mjs)
///   message        the message over the canvas (an import's, a field's)
///   pointers       pointerId -> [x, y] in canvas CSS px
///   canvasRect     the canvas' page position, read at a gesture's start
///   spaceDown      Space held: a drag pans
export const session = { version: 0, drag: null, message: '', pointers: new Map(), canvasRect: null, spaceDown: false };

export const count = () => state.pts.length / 2;

// The coordinates not drawn, in order (their values are in state.rest).
export function hidden(dim = state.dim, pair = state.pair) {
  const h = [];
  for (let k = 0; k < dim; ++k) if (k !== pair[0] && k !== pair[1]) h.push(k);
  return h;
}
// The points with every coordinate, flat (dim per point).
export function fullPoints() {
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
export const restOf = (k) => state.rest.slice(k * (state.dim - 2), (k + 1) * (state.dim - 2));
// Flat points of dimension d -> their pair coordinates, flat x, y.
export function project(a, d = state.dim, pair = state.pair) {
  if (d === 2) return a;
  const n = a.length / d, out = new Float64Array(2 * n);
  for (let i = 0; i < n; ++i) { out[2 * i] = a[i * d + pair[0]]; out[2 * i + 1] = a[i * d + pair[1]]; }
  return out;
}
// A point of the curve (dim coordinates) -> [[x, y], hidden coordinates].
export function splitOne(p) {
  const h = hidden();
  return [[p[state.pair[0]], p[state.pair[1]]], Float64Array.from(h, (k) => p[k])];
}

// ---------------------------------------------------------------------------
// The built curve and its per-segment caches (curve.mjs fills them)
// ---------------------------------------------------------------------------
/// spline: the WASM Spline of the current points (null: fewer than two, or
/// the library refused them: splineError); bez: its Bézier points in the
/// drawn pair, 8 numbers a segment (partial: only the dragged segments are
/// fresh); builtVersion: the version they were built for.
export const built = { spline: null, splineError: null, bez: new Float64Array(0), partial: false, version: -1 };
// Per-segment caches (arrays indexed by segment), the segments to redo, and
// the total length's block sums (NaN: to redo; see curve.mjs).
export const cache = { len: null, cusps: null, comb: null };
export let dirty = { all: true, segments: new Set() };
export let lenBlocks = null;

export function setBuilt(fields) { Object.assign(built, fields); }
/// Segment i's Bézier points in built.bez, from q (its four points of
/// dim coordinates): the drawn pair's.
export function setSegmentBezier(i, q) {
  const d = state.dim, [a, b] = state.pair, bez = built.bez;
  for (let j = 0; j < 4; ++j) { bez[8 * i + 2 * j] = q[j * d + a]; bez[8 * i + 2 * j + 1] = q[j * d + b]; }
}
/// The curve is built again at the next frame (an overlay turned on needs
/// its cache filled and the worker asked again).
export function invalidateCurve() { built.version = -1; }
export function setCache(key, values) { cache[key] = values; }
export function setCacheEntry(key, i, value) { cache[key][i] = value; }
export function setLenBlocks(blocks) { lenBlocks = blocks; }
export function setLenBlock(b, sum) { lenBlocks[b] = sum; }
export function clearDirty() { dirty = { all: false, segments: new Set() }; }

export function markAll() { dirty = { all: true, segments: new Set() }; }
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

/// The curve changed: a new version, the message cleared, a frame asked for.
export function changed() {
  session.version++;
  session.message = '';
  hooks.requestFrame();
}
export function setMessage(text) { session.message = text; hooks.requestFrame(); }
export function clearMessage() { session.message = ''; }

// ---------------------------------------------------------------------------
// Whole-curve overlays: the worker protocol's state (worker.mjs's client,
// analysis.mjs, drives it). queued: the curve changed while the worker was
// busy; deferred: held back until a drag's release.
// ---------------------------------------------------------------------------
export const analysis = { worker: null, busy: false, queued: false, global: null, deferred: false };
export function setAnalysis(fields) { Object.assign(analysis, fields); }
export function requestFrame() { hooks.requestFrame(); }
export function settle() { hooks.settle(); }
export const globalCurrent = () => analysis.global && analysis.global.version === session.version;

// ---------------------------------------------------------------------------
// Frames: the request flag, the drag layer, reused screen buffers, the
// timings reported to the tests, and who waits for the editor to be idle.
// ---------------------------------------------------------------------------
export const frames = {
  requested: false,
  work: [],          // work per frame (ms): JS + WASM + canvas calls
  curve: [],         // of which the curve and per-segment caches (WASM)
  intervals: [],     // time between frames while dragging (ms)
  latencies: [],     // pointer event to the end of the frame that shows it (ms)
  lastAt: 0, pendingEventAt: 0, textAt: 0,
  layer: null,       // the drag layer: { canvas, key, parts (the moving ones) }
  useLayer: true,    // tests compare with and without
  layerFrames: 0,    // frames drawn from the layer (reported)
  idleWaiters: [],
};
export function setFrames(fields) { Object.assign(frames, fields); }
/// Keeps the last 600 of a timing series.
export function record(series, ms) {
  const a = frames[series];
  a.push(ms);
  if (a.length > 600) a.shift();
}
export function resetFrameStats() {
  for (const k of ['work', 'curve', 'intervals', 'latencies']) frames[k].length = 0;
  frames.layerFrames = 0;
}
export function waitForIdle(resolve) { frames.idleWaiters.push(resolve); }
/// The waiters so far, now released (the caller calls them).
export function takeIdleWaiters() {
  const w = frames.idleWaiters;
  frames.idleWaiters = [];
  return w;
}
const buffers = {};
/// A reused Float64Array of `length` numbers for `key` (screen coordinates);
/// `fresh`: whether it was made now (its old contents are gone).
export function screenBuffer(key, length) {
  const out = buffers[key];
  if (out && out.length === length) return { out, fresh: false };
  return { out: (buffers[key] = new Float64Array(length)), fresh: true };
}

// ---------------------------------------------------------------------------
// Gestures and the view
// ---------------------------------------------------------------------------
export function setDrag(d) { session.drag = d; }
export function updateDrag(fields) { Object.assign(session.drag, fields); }
export function setPointer(id, xy) { session.pointers.set(id, xy); }
export function dropPointer(id) { session.pointers.delete(id); }
export function setCanvasRect(r) { session.canvasRect = r; }
export function setSpaceDown(on) { session.spaceDown = on; }
export function setView(s, x0, y0) { view.s = s; view.x0 = x0; view.y0 = y0; hooks.requestFrame(); }
export function setYUpFlag(on) { view.yUp = on; }
// Overlays and their settings: a frame; the curve built again (caches
// filled, the worker asked) where the overlay drawn needs it.
export function setOverlay(name, on) { state.overlays[name] = on; invalidateCurve(); hooks.requestFrame(); }
export function setVolumeKind(kind) { state.volumeKind = kind; if (state.overlays.volumes) { invalidateCurve(); hooks.requestFrame(); } }
export function setCombScale(scale) { state.combScale = scale; hooks.requestFrame(); }
export function setTickSpacing(spacing) { state.tickSpacing = spacing; if (state.overlays.ticks) { invalidateCurve(); hooks.requestFrame(); } }
export function setSnapGrid(on) { state.grid = on; hooks.requestFrame(); }

// The drag layer (draw.mjs) is drawn while a few points of a long curve
// move, without the comb and the bounding volumes (drawn between the base
// parts); curve.mjs then reads back only the moving segments.
const LAYER_MIN_SEGMENTS = 200;
export function layerWanted() {
  const o = state.overlays, drag = session.drag;
  return frames.useLayer && drag && drag.kind === 'move' && drag.idx.length <= 64 && !o.comb && !o.volumes &&
    built.bez.length / 8 > LAYER_MIN_SEGMENTS;
}

// ---------------------------------------------------------------------------
// Edits and undo. An edit (or a gesture: a drag, a slider pull) starts with
// beginEdit() and ends with endEdit(), which records one undo step only if
// the points or options actually changed. Selecting is not an edit.
// ---------------------------------------------------------------------------
const undoStack = [], redoStack = [];
const UNDO_LIMIT = 200;
let pendingEdit = null;
export const undoDepth = () => undoStack.length;
function snapshot() {
  return { pts: state.pts.slice(), rest: state.rest.slice(), dim: state.dim, pair: [...state.pair], names: state.names,
    opts: { ...state.opts }, selected: state.selected, sel: [...state.sel] };
}
function sameAsNow(s) {
  if (s.pts.length !== state.pts.length || s.rest.length !== state.rest.length || s.dim !== state.dim) return false;
  if (s.pair[0] !== state.pair[0] || s.pair[1] !== state.pair[1]) return false;
  for (let i = 0; i < s.pts.length; ++i) if (!Object.is(s.pts[i], state.pts[i])) return false;
  for (let i = 0; i < s.rest.length; ++i) if (!Object.is(s.rest[i], state.rest[i])) return false;
  for (const k of new Set([...Object.keys(s.opts), ...Object.keys(state.opts)])) if (s.opts[k] !== state.opts[k]) return false;
  return true;
}
export function beginEdit() { if (!pendingEdit) pendingEdit = snapshot(); }
export function endEdit() {
  if (!pendingEdit) return;
  const s = pendingEdit;
  pendingEdit = null;
  if (sameAsNow(s)) return;
  undoStack.push(s);
  if (undoStack.length > UNDO_LIMIT) undoStack.shift();
  redoStack.length = 0;
}
export function edit(f) { beginEdit(); f(); endEdit(); }
function restore(s) {
  state.pts = s.pts;
  state.rest = s.rest;
  state.dim = s.dim;
  state.pair = s.pair;
  state.names = s.names;
  state.opts = s.opts;
  hooks.syncProjection();
  state.sel = new Set(s.sel.filter((i) => i < count()));
  state.selected = s.selected < count() ? s.selected : -1;
  hooks.syncControls();
  markAll();
  changed();
}
export function undo() { endEdit(); if (undoStack.length) { redoStack.push(snapshot()); restore(undoStack.pop()); } }
export function redo() { endEdit(); if (redoStack.length) { undoStack.push(snapshot()); restore(redoStack.pop()); } }

export function select(list, primary = list.length ? list[list.length - 1] : -1) {
  state.sel = new Set(list);
  state.selected = primary;
  hooks.requestFrame();
}
/// Another point of the selection becomes the primary one.
export function setPrimary(k) { state.selected = k; }

// A plane curve (flat x, y).
export function setPoints(flat) { setDocument(flat, 2); }
// A curve of any dimension (flat, dim per point), shown on `pair`.
export function setDocument(full, dim, names = coordinateNames(dim), pair = [0, 1]) {
  const { pts, rest } = splitPoints(full, dim, pair);
  state.pts = pts;
  state.rest = rest;
  state.dim = dim;
  state.pair = pair;
  state.names = names;
  hooks.syncProjection();
  select([]);
  markAll();
  changed();
}
/// A file's options replace the editor's (an import).
export function setOptions(options) { state.opts = options; hooks.syncControls(); }

// Insert point (x, y) before point k; `rest`: its hidden coordinates (a
// point of a projected curve), by default those of its neighbour (the point
// before it, or the first): a point added in the view's plane lies in the
// plane parallel to it through that neighbour.
export function insertPoint(k, x, y, rest = null) {
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

export function deleteSelected() {
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
export function movePoints(idx, from, dx, dy) {
  for (let j = 0; j < idx.length; ++j) {
    const k = idx[j];
    state.pts[2 * k] = from[2 * j] + dx;
    state.pts[2 * k + 1] = from[2 * j + 1] + dy;
    if (idx.length <= 64) markAround(k);
  }
  if (idx.length > 64) markAll();
  changed();
}
/// Coordinate `off` (0: x, 1: y) of point k is exactly v (a typed value).
export function setCoordinate(k, off, v) { state.pts[2 * k + off] = v; }

export function setOption(key, value) {
  if (state.opts[key] === value && !(key === 'alpha' && state.opts.grid)) return;
  edit(() => {
    state.opts = { ...state.opts, [key]: value };
    let dropped = false;
    if (key === 'alpha') dropped = dropGrid();
    // A closed grid has one knot more (the end of the period).
    if (key === 'closed' && state.opts.grid) state.opts.grid = value ? extendKnots(state.opts.grid, state.opts.grid.length) : state.opts.grid.slice(0, -1);
    hooks.syncControls();
    markAll();
    changed();
    if (dropped) noteGridDropped();
  });
}
/// A slider's live value (the gesture's edit begun, not ended: the slider
/// ends it on release).
export function slideOption(key, value) {
  beginEdit();
  state.opts = { ...state.opts, [key]: value };
  const dropped = key === 'alpha' && dropGrid();
  hooks.syncControls();
  markAll();
  changed();
  if (dropped) noteGridDropped();
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
  session.message = `knots from α = ${state.opts.alpha} now, instead of the file's grid (Ctrl+Z brings it back)`;
  hooks.requestFrame();
}
