// Pointer input on the canvas: mouse, pen and touch through pointer events
// (touch-action: none on the canvas; the pointer is captured). Gestures
// (state.mjs's session.drag):
//   move     points `idx` follow the pointer (from their positions `from`)
//   pan      the view follows the pointer (right/middle button, Space+drag,
//            one finger on empty canvas once it moves)
//   tap      a finger on empty canvas, not yet moved: a point on release
//   pinch    two fingers: zoom about them and pan with them
//   marquee  Shift+drag on empty canvas: select the points inside
// Also the wheel (pan, Ctrl+wheel zoom), double-click (insert on the
// curve) and the coordinate readout.
import { $, canvas } from './dom.mjs';
import { toScreen } from './draw.mjs';
import { requestGlobal } from './analysis.mjs';
import { sig } from './status.mjs';
import { hit, nearCurve } from './curve_points.mjs';
import { toWorld, snap, zoomAt, panBy } from './view.mjs';
import {
  state, view, session, analysis, frames, count, restOf, select, setPrimary, beginEdit, endEdit, edit, insertPoint, movePoints,
  setDrag, updateDrag, setPointer, dropPointer, setCanvasRect, setFrames, requestFrame,
} from './state.mjs';

// The canvas' position, read again at the start of every gesture (and after
// a resize): reading it on every move would force a layout each time, since
// the status line changes every frame.
function local(e, fresh = false) {
  if (fresh || !session.canvasRect) {
    const r = canvas.getBoundingClientRect();
    setCanvasRect([r.left + canvas.clientLeft, r.top + canvas.clientTop]);
  }
  const [x0, y0] = session.canvasRect;
  return [e.clientX - x0, e.clientY - y0];
}

function startMove(idx, px, py) {
  beginEdit();
  const from = new Float64Array(2 * idx.length);
  idx.forEach((k, j) => { from[2 * j] = state.pts[2 * k]; from[2 * j + 1] = state.pts[2 * k + 1]; });
  setDrag({ kind: 'move', idx, from, start: toWorld(px, py), lead: idx.indexOf(state.selected) });
}

canvas.addEventListener('contextmenu', (e) => e.preventDefault());
canvas.addEventListener('pointerdown', (e) => {
  canvas.focus({ preventScroll: true });
  try { canvas.setPointerCapture(e.pointerId); } catch { /* synthetic events have no active pointer */ }
  const [px, py] = local(e, true);
  setPointer(e.pointerId, [px, py]);
  const touch = e.pointerType === 'touch', pointers = session.pointers, drag = session.drag;
  if (touch && pointers.size === 2) {
    // A second finger: whatever the first one began becomes a pinch; a
    // point it was dragging goes back where it was.
    if (drag && drag.kind === 'move') { movePoints(drag.idx, drag.from, 0, 0); endEdit(); }
    const [a, b] = [...pointers.values()];
    setDrag({ kind: 'pinch', last: [a, b] });
    return;
  }
  if (pointers.size > 1) return;
  if (e.button === 1 || e.button === 2 || (e.button === 0 && session.spaceDown)) { setDrag({ kind: 'pan', x: px, y: py }); return; }
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
    else setPrimary(k);
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
    setDrag({ kind: 'marquee', rect: [px, py, px, py], base: [...state.sel] });
    return;
  }
  if (touch) { setDrag({ kind: 'tap', x: px, y: py }); return; }
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
  const pointers = session.pointers, drag = session.drag;
  if (!pointers.has(e.pointerId)) return;
  setPointer(e.pointerId, [px, py]);
  if (!drag) return;
  setFrames({ pendingEventAt: frames.pendingEventAt || e.timeStamp });
  if (drag.kind === 'pinch') {
    const [a, b] = [...pointers.values()];
    const [la, lb] = drag.last;
    const c0 = [(la[0] + lb[0]) / 2, (la[1] + lb[1]) / 2], c1 = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
    const d0 = Math.hypot(la[0] - lb[0], la[1] - lb[1]), d1 = Math.hypot(a[0] - b[0], a[1] - b[1]);
    panBy(c1[0] - c0[0], c1[1] - c0[1]);
    if (d0 > 0 && d1 > 0) zoomAt(c1[0], c1[1], d1 / d0);
    updateDrag({ last: [a, b] });
    return;
  }
  if (drag.kind === 'tap') {
    if (Math.hypot(px - drag.x, py - drag.y) > 8) { panBy(px - drag.x, py - drag.y); setDrag({ kind: 'pan', x: px, y: py }); }
    return;
  }
  if (drag.kind === 'pan') {
    panBy(px - drag.x, py - drag.y);
    updateDrag({ x: px, y: py });
    return;
  }
  if (drag.kind === 'marquee') {
    updateDrag({ rect: [drag.rect[0], drag.rect[1], px, py] });
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
  const pointers = session.pointers, drag = session.drag;
  if (!pointers.has(e.pointerId)) return;
  dropPointer(e.pointerId);
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
export function finishDrag() {
  setDrag(null);
  endEdit();
  setFrames({ lastAt: 0 });
  if (analysis.deferred) requestGlobal();
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

