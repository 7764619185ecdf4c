// The pencil (issue 40): P (or the Pencil button) turns it on and off. With
// it on, dragging on the canvas draws freehand; on release the stroke
// becomes the fitted curve (crspline's fit: the fewest control points whose
// curve stays within the tolerance of the stroke, both ways, proved), in
// one undo step. The tolerance is in screen pixels (the slider, default
// 2 px), turned into world units by the current zoom. "Fit selection"
// reduces the selected run of points (all of them when fewer than two are
// selected), e.g. an imported dense polyline, to the points the fit keeps.
//
// The controls are added to the panel from here, and the pencil's pointer
// handlers run in the capture phase on the canvas, ahead of pointer.mjs's,
// which they stop while the pencil is on: the other tools are untouched.
// The fit runs on the main thread: a stroke is a few hundred points, fitted
// in milliseconds (the worker is for the whole-curve overlays).
import { $, canvas } from './dom.mjs';
import { M } from './wasm.mjs';
import { toWorld } from './view.mjs';
import { showMessage } from './status.mjs';
import { state, view, count, edit, setDocument, setOptions, requestFrame } from './state.mjs';

export const pencil = { on: false, tolerancePx: 2, stroke: null, last: null };

// --- the controls -----------------------------------------------------------
const row = document.createElement('div');
row.className = 'row pencil';
row.innerHTML = '<button id="pencil" title="P: draw freehand; the stroke becomes a fitted curve" aria-pressed="false">Pencil</button>' +
  '<button id="fit-selection" title="Fit the selected points (all when none) within the tolerance">Fit selection</button>' +
  '<label class="slider">tolerance <input id="pencil-tolerance" type="range" min="0.25" max="10" step="0.25" value="2" ' +
  'aria-label="fit tolerance in screen pixels"> <output id="pencil-tolerance-value">2 px</output></label>';
$('fit').parentElement.after(row);
const button = $('pencil'), slider = $('pencil-tolerance');
button.addEventListener('click', () => setPencil(!pencil.on));
$('fit-selection').addEventListener('click', () => fitSelection());
slider.addEventListener('input', () => {
  pencil.tolerancePx = Number(slider.value);
  $('pencil-tolerance-value').textContent = `${pencil.tolerancePx} px`;
});
// A help row, beside the other keys.
const helpBody = $('help').querySelector('tbody') ?? $('help').querySelector('table');
if (helpBody) {
  const tr = document.createElement('tr');
  tr.innerHTML = '<td><kbd>P</kbd></td><td>pencil: draw freehand; on release the stroke becomes a fitted curve (tolerance slider, screen pixels)</td>';
  helpBody.append(tr);
}

export function setPencil(on) {
  pencil.on = on;
  button.setAttribute('aria-pressed', String(on));
  button.classList.toggle('active', on);
  canvas.classList.toggle('pencil', on);
}

const isTyping = (t) => t instanceof HTMLInputElement || t instanceof HTMLSelectElement || t instanceof HTMLTextAreaElement;
window.addEventListener('keydown', (e) => {
  if (isTyping(e.target) || e.ctrlKey || e.metaKey || e.altKey) return;
  if (e.key === 'p' || e.key === 'P') { e.preventDefault(); setPencil(!pencil.on); }
});

// --- the stroke, drawn on a layer over the canvas ---------------------------
const layer = document.createElement('canvas');
layer.id = 'pencil-layer';
layer.style.cssText = 'position:absolute; pointer-events:none; display:none;';
canvas.after(layer);

function local(e) {
  const r = canvas.getBoundingClientRect();
  return [e.clientX - r.left - canvas.clientLeft, e.clientY - r.top - canvas.clientTop];
}

function drawStroke() {
  const g = layer.getContext('2d'), s = pencil.stroke;
  g.clearRect(0, 0, layer.width, layer.height);
  if (!s || s.length < 4) return;
  g.strokeStyle = '#c05020';
  g.lineWidth = 1.5;
  g.beginPath();
  g.moveTo(s[0], s[1]);
  for (let i = 2; i < s.length; i += 2) g.lineTo(s[i], s[i + 1]);
  g.stroke();
}

canvas.addEventListener('pointerdown', (e) => {
  if (!pencil.on || e.button !== 0) return;
  e.stopImmediatePropagation();
  e.preventDefault();
  try { canvas.setPointerCapture(e.pointerId); } catch { /* synthetic events have no active pointer */ }
  // The layer covers the canvas' content box.
  layer.style.left = `${canvas.offsetLeft + canvas.clientLeft}px`;
  layer.style.top = `${canvas.offsetTop + canvas.clientTop}px`;
  layer.width = canvas.clientWidth;
  layer.height = canvas.clientHeight;
  layer.style.width = `${canvas.clientWidth}px`;
  layer.style.height = `${canvas.clientHeight}px`;
  layer.style.display = 'block';
  pencil.stroke = [...local(e)];
  pencil.pointer = e.pointerId;
  drawStroke();
}, { capture: true });

canvas.addEventListener('pointermove', (e) => {
  if (!pencil.on || !pencil.stroke || e.pointerId !== pencil.pointer) return;
  e.stopImmediatePropagation();
  // Coalesced events: every sample the pointer gave since the last frame.
  const events = typeof e.getCoalescedEvents === 'function' && e.getCoalescedEvents().length ? e.getCoalescedEvents() : [e];
  for (const c of events) pencil.stroke.push(...local(c));
  drawStroke();
}, { capture: true });

function endStroke(e) {
  if (!pencil.stroke || e.pointerId !== pencil.pointer) return;
  e.stopImmediatePropagation();
  const s = pencil.stroke;
  pencil.stroke = null;
  drawStroke();
  layer.style.display = 'none';
  if (e.type === 'pointerup') strokeToCurve(s);
}
canvas.addEventListener('pointerup', endStroke, { capture: true });
canvas.addEventListener('pointercancel', endStroke, { capture: true });

// --- the fit ----------------------------------------------------------------

// The fit's options from the document's: its alpha and tension, its ends
// where the fit takes them (natural, reflect).
function fitOptions(tolerance, closed) {
  const o = state.opts, ends = (x) => (x === 'reflect' ? 'reflect' : 'natural');
  return { tolerance, mode: 'subset', alpha: o.grid ? 0.5 : o.alpha, closed, tension: o.tension, start: ends(o.start), end: ends(o.end) };
}

function run(flat, options) {
  try {
    return M.fitPoints(flat, 2, options);
  } catch (e) {
    showMessage(`fit: ${e.message}`);
    return null;
  }
}

// The document's options for the fitted curve: the fit's own, and the
// per-vertex tension where it raised it.
function fittedOptions(r, kbTension) {
  const { grid: _g, kb: _k, ...o } = state.opts;
  const out = { ...o, alpha: r.alpha, tension: r.tension, closed: r.closed };
  if (!r.closed) {
    out.start = out.start === 'reflect' ? 'reflect' : 'natural';
    out.end = out.end === 'reflect' ? 'reflect' : 'natural';
  }
  if (kbTension) out.kb = { tension: Array.from(kbTension) };
  return out;
}

/// A stroke (flat screen x, y) -> the document's curve, one undo step.
export function strokeToCurve(screen) {
  if (state.dim !== 2) { showMessage('pencil: draws plane curves; this document has more coordinates'); return null; }
  const flat = new Float64Array(screen.length);
  for (let i = 0; i < screen.length; i += 2) [flat[i], flat[i + 1]] = toWorld(screen[i], screen[i + 1]);
  // A click without movement is no stroke.
  let distinct = 1;
  for (let i = 2; i < flat.length; i += 2) if (flat[i] !== flat[i - 2] || flat[i + 1] !== flat[i - 1]) ++distinct;
  if (distinct < 2) return null;
  const r = run(flat, fitOptions(pencil.tolerancePx / view.s, false));
  if (!r) return null;
  edit(() => {
    setDocument(r.points, 2);
    setOptions(fittedOptions(r, r.kbTension));
  });
  pencil.last = { input: flat, count: r.count, deviation: r.deviation, tolerance: pencil.tolerancePx / view.s };
  requestFrame();
  return pencil.last;
}

/// Fit selection: the selected run of points (first to last selected; all
/// points when fewer than two are selected) becomes the points the fit
/// keeps of it (subset mode: real vertices), one undo step. The whole curve
/// is fitted with the document's closedness; a run as an open line whose
/// ends stay.
export function fitSelection() {
  const n = count();
  if (state.dim !== 2) { showMessage('Fit selection: works on plane curves; this document has more coordinates'); return null; }
  if (n < 3) return null;
  const sel = [...state.sel].sort((a, b) => a - b);
  const whole = sel.length < 2 || (sel[0] === 0 && sel[sel.length - 1] === n - 1);
  const [i0, i1] = whole ? [0, n - 1] : [sel[0], sel[sel.length - 1]];
  if (i1 - i0 < 2) return null;
  const closed = whole && state.opts.closed;
  const run_ = state.pts.slice(2 * i0, 2 * i1 + 2);
  const r = run(run_, fitOptions(pencil.tolerancePx / view.s, closed));
  if (!r) return null;
  const keep = new Set();
  for (let i = 0; i < i0; ++i) keep.add(i);
  for (const k of r.indices) keep.add(i0 + k);
  for (let i = i1 + 1; i < n; ++i) keep.add(i);
  const order = [...keep].sort((a, b) => a - b);
  const pts = new Float64Array(2 * order.length);
  order.forEach((k, j) => { pts[2 * j] = state.pts[2 * k]; pts[2 * j + 1] = state.pts[2 * k + 1]; });
  // Per-vertex tension: the fit's inside the run, the document's (or 0) outside.
  let kb = null;
  const old = state.opts.kb?.tension;
  if (r.kbTension || old) {
    const inRun = new Map();
    Array.from(r.indices).forEach((k, j) => inRun.set(i0 + k, r.kbTension ? r.kbTension[j] : 0));
    kb = order.map((k) => (inRun.has(k) && (k !== i0 || i0 === 0) && (k !== i1 || i1 === n - 1) ? inRun.get(k) : (old?.[k] ?? 0)));
  }
  const before = n;
  edit(() => {
    setDocument(pts, 2);
    setOptions(fittedOptions({ alpha: r.alpha, tension: r.tension, closed: whole ? r.closed : state.opts.closed }, kb));
  });
  pencil.last = { from: before, count: order.length, deviation: r.deviation, tolerance: pencil.tolerancePx / view.s };
  requestFrame();
  return pencil.last;
}

// For tests and the console (window.editor is console_api.mjs's, imported first).
if (window.editor) {
  window.editor.pencil = {
    get on() { return pencil.on; },
    set(on) { setPencil(on); },
    get tolerancePx() { return pencil.tolerancePx; },
    /// The last stroke or Fit selection: {input (world, flat), count, deviation, tolerance} or {from, count, ...}.
    get last() { return pencil.last; },
    fitSelection,
  };
}
