// The crspline editor: a canvas, the WASM curve, and overlays. This module
// starts it; each job is a module of its own:
//   state.mjs        the editor's state, all of it, and the named functions
//                    that change it (edits, undo, selection, view, session)
//   wasm.mjs         the WebAssembly module
//   curve.mjs        the curve of the points and its per-segment caches
//   analysis.mjs     the whole-curve overlays' worker protocol
//   frame.mjs        the frame loop and "idle"
//   draw.mjs         drawing (clip.mjs: clipping long paths to the canvas)
//   status.mjs       the status line and the message over the canvas
//   view.mjs         zoom, pan, fit, y up, screen <-> world
//   curve_points.mjs points under the pointer and on the curve
//   pointer.mjs      mouse, pen and touch gestures, wheel, double-click
//   keyboard.mjs     keys and the help panel
//   projection.mjs   curves of 3 or more coordinates shown on two
//   controls.mjs     the panel's controls
//   files.mjs        import and export
//   samples.mjs      the demo and the stress test
//   console_api.mjs  window.editor, for tests and the console
//   pencil.mjs       the pencil (freehand strokes become fitted curves) and Fit selection
//
// Frame budget. A frame makes one WASM call for the geometry (a new Spline
// from the points, then bezierAll(): every segment's Bézier points in one
// Float64Array) and draws the curve as one Path2D. Per-segment overlays
// (lengths for the status line, cusps, the curvature comb) are cached per
// segment: dragging point i recomputes only the segments i-2 .. i+1 it
// moves. Whole-curve overlays (certificate and self-intersections, bounding
// volumes, arc-length ticks) run in a worker, latest request wins; until an
// answer for the current curve arrives, the last one is drawn faded.
import { $, canvas } from './dom.mjs';
import { M } from './wasm.mjs';
import { connect, changed, setCanvasRect } from './state.mjs';
import { requestFrame, settle } from './frame.mjs';
import { syncControls } from './controls.mjs';
import { syncProjection } from './projection.mjs';
import { Y_UP_KEY, setYUp } from './view.mjs';
import './pointer.mjs';
import './keyboard.mjs';
import './files.mjs';
import './console_api.mjs';
import './pencil.mjs';

connect({ requestFrame, settle, syncControls, syncProjection });
$('version').textContent = `v${M.version()}`;
try { if (localStorage.getItem(Y_UP_KEY) === '1') setYUp(true); } catch { /* storage off */ }
syncControls();
new ResizeObserver(() => { setCanvasRect(null); requestFrame(); }).observe(canvas);
window.addEventListener('scroll', () => { setCanvasRect(null); }, true);
changed();
