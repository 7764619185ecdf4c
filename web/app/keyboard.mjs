// Keyboard. Undo and redo work wherever the focus is (a slider, a checkbox,
// a dropdown), except in text fields, which keep their own. The other keys
// act on the canvas only when no form control has the focus. Also the help
// panel (?, Esc).
import { $, canvas } from './dom.mjs';
import { gridStep } from './draw.mjs';
import { insertAfter } from './curve_points.mjs';
import { fit } from './view.mjs';
import {
  state, view, session, ys, count, select, edit, undo, redo, deleteSelected, movePoints, setDrag, setSpaceDown,
} from './state.mjs';

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
    const drag = session.drag;
    if (drag && drag.kind === 'marquee') { select(drag.base); setDrag(null); }
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
  if (e.key === ' ' && !(e.target instanceof HTMLButtonElement)) { e.preventDefault(); if (!session.spaceDown) { setSpaceDown(true); canvas.classList.add('grab'); } return; }
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
window.addEventListener('keyup', (e) => { if (e.key === ' ') { setSpaceDown(false); canvas.classList.remove('grab'); } });
window.addEventListener('blur', () => { setSpaceDown(false); canvas.classList.remove('grab'); });

export function toggleHelp(show = $('help').hidden) {
  $('help').hidden = !show;
  $('help-button').setAttribute('aria-expanded', String(show));
  if (show) $('help-close').focus(); else canvas.focus({ preventScroll: true });
}

