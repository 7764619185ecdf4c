// The panel's controls: options (sliders, presets, closed, ends), the
// selected point's coordinate fields, overlays and their settings, the
// buttons (undo, redo, delete, insert, clear, demo, stress, fit, help) and
// the panel drawer itself.
import { $ } from './dom.mjs';
import { insertAfter } from './curve_points.mjs';
import { fit, setYUp } from './view.mjs';
import { toggleHelp } from './keyboard.mjs';
import { loadDemo, loadStress } from './samples.mjs';
import {
  state, count, edit, endEdit, undo, redo, deleteSelected, movePoints, setCoordinate, setPoints, setOption, slideOption,
  setOverlay, setVolumeKind, setCombScale, setTickSpacing, setSnapGrid, setMessage,
} from './state.mjs';

export function syncControls() {
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
export function syncPointFields() {
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
    if (e.target.value.trim() === '' || !Number.isFinite(v) || k < 0 || k >= count()) { setMessage(`${off ? 'y' : 'x'}: "${e.target.value}" is not a finite number`); return; }
    edit(() => {
      const from = Float64Array.of(state.pts[2 * k], state.pts[2 * k + 1]);
      movePoints([k], from, off ? 0 : v - from[0], off ? v - from[1] : 0);
      setCoordinate(k, off, v);  // exactly the typed double
    });
  });
}

// Sliders: one undo step per gesture (from the first input to the change
// that ends it), live updates in between.
for (const id of ['alpha', 'tension']) {
  const el = $(id);
  el.addEventListener('input', () => slideOption(id, Number(el.value)));
  el.addEventListener('change', endEdit);
  el.addEventListener('blur', endEdit);
}
for (const b of document.querySelectorAll('.presets button')) b.addEventListener('click', () => setOption('alpha', Number(b.dataset.alpha)));
$('closed').addEventListener('change', (e) => setOption('closed', e.target.checked));
for (const id of ['start', 'end']) $(id).addEventListener('change', (e) => { if (e.target.value !== 'tangent') setOption(id, e.target.value); });

for (const box of document.querySelectorAll('[data-overlay]')) {
  // The curve built again: the caches now enabled filled, the worker asked again.
  box.addEventListener('change', () => setOverlay(box.dataset.overlay, box.checked));
}
$('volume-kind').addEventListener('change', (e) => setVolumeKind(e.target.value));
$('comb-scale').addEventListener('input', (e) => setCombScale(Number(e.target.value)));
$('tick-spacing').addEventListener('change', (e) => {
  const v = Number(e.target.value);
  if (v > 0) setTickSpacing(v);
});
$('y-up').addEventListener('change', (e) => setYUp(e.target.checked));
$('grid').addEventListener('change', (e) => setSnapGrid(e.target.checked));

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

// The panel: beside the canvas on wide screens, a drawer over it on narrow
// ones (closed at first there).
const panelToggle = $('panel-toggle');
function setPanel(open) {
  document.body.classList.toggle('panel-closed', !open);
  panelToggle.setAttribute('aria-expanded', String(open));
}
panelToggle.addEventListener('click', () => setPanel(document.body.classList.contains('panel-closed')));
setPanel(!window.matchMedia('(max-width: 700px)').matches);
