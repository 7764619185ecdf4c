// Import (the file dialog, or a file dropped on the canvas) and export
// (JSON, CSV, SVG downloads) of the curve file: io.mjs reads and writes
// it; the library checks what is read before the editor takes it.
import { $, canvas } from './dom.mjs';
import { M } from './wasm.mjs';
import { parsePoints, pointsToJson, pointsToCsv, curveToSvg, splineOptions } from './io.mjs';
import { rebuild } from './curve.mjs';
import { fit } from './view.mjs';
import { state, built, fullPoints, edit, setOptions, setDocument, setMessage } from './state.mjs';

function download(name, text, type) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement('a');
  a.href = url; a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
// JSON and CSV write every coordinate (a projected curve keeps its
// dimension); SVG draws the view's two.
$('export-json').addEventListener('click', () => download('crspline-points.json', pointsToJson(fullPoints(), state.opts, state.dim), 'application/json'));
$('export-csv').addEventListener('click', () => download('crspline-points.csv', pointsToCsv(fullPoints(), state.dim, state.names), 'text/csv'));
$('export-svg').addEventListener('click', () => {
  rebuild();
  download('crspline-curve.svg', curveToSvg(built.bez, state.pts, { closed: state.opts.closed }), 'image/svg+xml');
});

async function importFile(file) {
  try {
    const { points, dimension, names, options, notKept } = parsePoints(await file.text(), file.name);
    // What the editor holds, the library checks (the same words as the
    // command line: a grid of the wrong length, a KB value, ...). A module
    // that cannot build this dimension yet opens it anyway, and says so.
    if (points.length >= 2 * dimension) {
      try { new M.Spline(points, dimension, splineOptions(options, dimension)).delete(); } catch (e) { if (!/dimension must be/.test(e.message)) throw e; }
    }
    edit(() => {
      setOptions(options);
      setDocument(points, dimension, names);
    });
    fit();
    // Nothing read is dropped without a word: the command line's requests
    // (t, derivatives, ...) are not part of the curve.
    if (notKept.length) {
      setMessage(`${file.name}: opened; ${notKept.map((k) => `"${k}"`).join(', ')} ${notKept.length === 1 ? 'is a request' : 'are requests'} ` +
        'to the command line, not part of the curve: not kept');
    }
  } catch (e) {
    setMessage(`import ${file.name}: ${e.message}`);
  }
}
$('import').addEventListener('change', (e) => { if (e.target.files[0]) importFile(e.target.files[0]); e.target.value = ''; });
canvas.addEventListener('dragover', (e) => e.preventDefault());
canvas.addEventListener('drop', (e) => { e.preventDefault(); if (e.dataTransfer.files[0]) importFile(e.dataTransfer.files[0]); });
