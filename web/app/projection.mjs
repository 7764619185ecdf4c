// Projection: a curve of 3 or more coordinates is shown on two of them, and
// says so (the banner over the canvas, with the choice of the pair).
import { $ } from './dom.mjs';
import { fit } from './view.mjs';
import { state, hidden, fullPoints, edit, select, setDocument } from './state.mjs';

function projectionText() {
  const d = state.dim, N = state.names, [a, b] = state.pair, h = hidden().map((k) => N[k]);
  const list = (xs) => (xs.length <= 3 ? xs.join(', ') : `${xs.slice(0, 2).join(', ')}, … ${xs[xs.length - 1]}`);
  return [`${d}-D curve (${list(N)}) shown as its projection on ${N[a]}, ${N[b]}.`,
    `Edits move points in ${N[a]}, ${N[b]} and keep ${list(h)} (a new point takes ${h.length === 1 ? 'it' : 'them'} from its neighbour or the curve). ` +
    `Length, cusps and the certificate are of the ${d}-D curve; the comb and bounding volumes need a plane curve. ` +
    `JSON and CSV exports write all ${d} coordinates; SVG draws ${N[a]}, ${N[b]}.`];
}
export function syncProjection() {
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
