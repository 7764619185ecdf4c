// For tests and the console: window.editor, the editor's state and actions
// as the browser tests drive them (docs/web.md).
import { canvas } from './dom.mjs';
import { M } from './wasm.mjs';
import { pointsToJson } from './io.mjs';
import { rebuild, totalLength } from './curve.mjs';
import { gridStep } from './draw.mjs';
import { requestFrame } from './frame.mjs';
import { toWorld, zoomAt, fit } from './view.mjs';
import { loadDemo, loadStress } from './samples.mjs';
import {
  state, view, built, cache, analysis, frames, SX, SY, fullPoints, undoDepth, edit, select, setPoints, setFrames,
  resetFrameStats, waitForIdle,
} from './state.mjs';

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
  get undoDepth() { return undoDepth(); },
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
  evaluate(t) { rebuild(); return built.spline ? Array.from(built.spline.evaluate(t)) : null; },
  grid() { rebuild(); return built.spline ? Array.from(built.spline.grid()) : null; },
  bezier() { rebuild(); return Array.from(built.bez); },
  length() { rebuild(); return totalLength(); },
  cusps() { rebuild(); return cache.cusps ? cache.cusps.filter(Boolean).flatMap((c) => Array.from(c)) : null; },
  global() { return analysis.global; },
  /// True while the worker analyses (or has a request queued): its answer
  /// redraws the crossings, ticks and volumes when it comes.
  get analysing() { return analysis.busy || analysis.queued; },
  idle() { return new Promise((resolve) => { waitForIdle(resolve); requestFrame(); }); },
  resetFrameStats() { resetFrameStats(); },
  frameStats() {
    return { work: quantiles(frames.work), curve: quantiles(frames.curve), interval: quantiles(frames.intervals),
      latency: quantiles(frames.latencies), layerFrames: frames.layerFrames };
  },
  /// The drag layer on (default) or off, for comparisons; redraws.
  setDragLayer(on) { setFrames({ useLayer: on, layer: null }); requestFrame(); },
  /// A frame now (in the middle of a gesture too), resolved when drawn.
  redraw() { return new Promise((resolve) => { requestFrame(); requestAnimationFrame(() => resolve()); }); },
  loadStress,
  loadDemo,
};
