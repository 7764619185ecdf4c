// The status line under the canvas (points, segments, length, cusps, the
// verdict, the certificate, the frame time), the message over the canvas, and the
// numbers the tests read as data attributes of <body>.
import { $ } from './dom.mjs';
import { totalLength, cuspCount } from './curve.mjs';
import { syncPointFields } from './controls.mjs';
import { state, session, built, analysis, frames, count, globalCurrent, setFrames, clearMessage } from './state.mjs';

export const fmt = (x, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : String(x));
// Significant digits, whatever the scale: 7 (at least 6 asked for), no
// trailing exponent noise for ordinary magnitudes.
export const sig = (x, d = 7) => (Number.isFinite(x) ? (x === 0 ? '0' : x.toPrecision(d).replace(/e\+?/, 'e')) : String(x));

// Status texts are written only when they change.
const setText = (id, text) => { const el = $(id); if (el.textContent !== text) el.textContent = text; };
export function updateStatus(ms) {
  const n = count(), spline = built.spline, global = analysis.global;
  setText('status-points', `${n} point${n === 1 ? '' : 's'}` + (state.sel.size > 1 ? ` (${state.sel.size} selected)` : ''));
  const nseg = spline ? spline.segmentCount() : 0;
  setText('status-segments', `${nseg} segment${nseg === 1 ? '' : 's'}`);
  setText('status-length', spline ? `length ${sig(totalLength())}${state.dim > 2 ? ` (${state.dim}-D)` : ''}` : 'length —');
  const cc = cuspCount();
  setText('status-cusps', !spline ? 'cusps —' : cc === null ? 'cusps off' : `${cc} cusp${cc === 1 ? '' : 's'}`);
  let text, cls = '';
  if (!spline) {
    text = n < 2 ? 'click to add points' : '—';
  } else if (!globalCurrent()) {
    text = analysis.deferred ? 'certificate after release' : 'certifying…';
  } else if (global.error) {
    text = `error: ${global.error}`;
  } else if (global.cert.certified) {
    text = 'certified intersection-free';
    cls = 'ok';
  } else {
    const c = global.cert;
    const k = global.intersections.length / 2 + global.folds.length;
    const found = c.intersects === null ? '' : c.intersects ? `; ${k} self-intersection${k === 1 ? '' : 's'}${c.complete ? '' : ' (search incomplete)'}` : '; no self-intersection found';
    text = `not certified (${c.failed_rule.replace(/_/g, ' ')}: ${c.detail})${found}`;
    cls = c.intersects ? 'bad' : '';
  }
  // The verdict (every alpha): proved simple, proved crossings, or contacts
  // closer than the floor that neither proof resolves.
  let vtext = '', vcls = '';
  if (spline && globalCurrent() && !global.error && global.decision) {
    const v = global.decision;
    vcls = v.verdict === 'simple' ? 'ok' : v.verdict === 'crosses' ? 'bad' : 'warn';
    vtext = v.verdict === 'simple' ? `simple${v.fast_path ? ' (paper\'s rule)' : ' (proved)'}`
      : v.verdict === 'crosses' ? `crosses (${v.crossings} proved crossing${v.crossings === 1 ? '' : 's'})`
        : `touches (${v.touches} contact${v.touches === 1 ? '' : 's'} within ${sig(v.closest, 2)})`;
  } else if (spline && globalCurrent() && !global.error) {
    vtext = 'verdict: plane curves only';
  } else if (spline && !globalCurrent()) {
    vtext = analysis.deferred ? '' : 'deciding…';
  }
  const verdict = $('status-verdict');
  if (verdict.textContent !== vtext) { verdict.textContent = vtext; verdict.title = vtext; }
  if (verdict.className !== vcls) verdict.className = vcls;
  const cert = $('status-cert');
  if (cert.textContent !== text) { cert.textContent = text; cert.title = text; }
  if (cert.className !== cls) cert.className = cls;
  // The frame time, four times a second (a text that changes every frame
  // costs a layout every frame).
  if (performance.now() - frames.textAt > 250) { setFrames({ textAt: performance.now() }); setText('status-frame', `frame ${fmt(ms, 1)} ms`); }
  showMessage(session.message || built.splineError || '');
  syncPointFields();
  // For tests: the numbers as data attributes (written when they change).
  const d = document.body.dataset;
  const data = {
    points: n, segments: nseg, length: spline ? totalLength() : '', cusps: cc ?? '',
    certified: spline && globalCurrent() && !global.error ? String(global.cert.certified) : '',
    intersections: spline && globalCurrent() && !global.error ? String(global.intersections.length / 2) : '',
    verdict: spline && globalCurrent() && !global.error && global.decision ? global.decision.verdict : '',
    version: session.version,
  };
  for (const [k, v] of Object.entries(data)) if (d[k] !== String(v)) d[k] = v;
}

// The message (import errors, the library's complaint about the curve):
// shown over the canvas, announced (role=alert), closable.
export function showMessage(text) {
  const m = $('message');
  if (m.textContent !== text) m.textContent = text;
  $('toast').hidden = !text;
}
$('toast-close').addEventListener('click', () => { clearMessage(); showMessage(''); });
