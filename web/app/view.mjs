// The view: zoom (within limits), pan, fit to the points, y up or down
// (remembered by the browser), and screen <-> world. The view itself is
// state.mjs's `view`, changed through setView / setYUpFlag.
import { $, canvas } from './dom.mjs';
import { gridStep } from './draw.mjs';
import { state, view, ys, count, setView, setYUpFlag } from './state.mjs';

export const Y_UP_KEY = 'crspline.editor.yUp';
export const toWorld = (px, py) => [view.x0 + px / view.s, view.y0 + (py * ys()) / view.s];
export function snap(x, y) {
  if (!state.grid) return [x, y];
  const g = gridStep();
  return [Math.round(x / g) * g, Math.round(y / g) * g];
}

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
export function zoomAt(px, py, factor) {
  const [lo, hi] = scaleLimits();
  const s = Math.min(hi, Math.max(lo, view.s * factor));
  const wx = view.x0 + px / view.s, wy = view.y0 + (py * ys()) / view.s;
  setView(s, wx - px / s, wy - (py * ys()) / s);
}
export function panBy(dx, dy) {
  setView(view.s, view.x0 - dx / view.s, view.y0 - (dy * ys()) / view.s);
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
export function fit() {
  const n = count();
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (n === 0) { setView(1, 0, view.yUp ? h : 0); return; }
  const [x0, y0, x1, y1] = bounds();
  const s = fitScale();
  setView(s, (x0 + x1) / 2 - w / 2 / s, (y0 + y1) / 2 - (ys() * h) / 2 / s);
}
export function setYUp(on) {
  if (view.yUp === on) return;
  // Keep the world point at the canvas centre where it is.
  const h = canvas.clientHeight, cy = view.y0 + (ys() * h) / 2 / view.s;
  setYUpFlag(on);
  $('y-up').checked = on;
  // Remembered by the browser: the curve file has no place for it (every
  // field not in docs/spec.md is an error to the command line).
  try { localStorage.setItem(Y_UP_KEY, on ? '1' : '0'); } catch { /* storage off: for this page only */ }
  setView(view.s, view.x0, cy - (ys() * h) / 2 / view.s);
}
// The view at zoom 1 with the canvas' top-left corner at the world origin
// (y up: the bottom-left corner).
export function resetView() { setView(1, 0, view.yUp ? canvas.clientHeight : 0); }
