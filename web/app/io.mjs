// Import and export of the editor's points and curve. Pure functions (no
// DOM): the node tests use them too. Numbers are written with JavaScript's
// shortest round-trip form, so an export read back gives the same doubles.

/// Options the editor understands, with their defaults.
export const defaultOptions = Object.freeze({
  alpha: 0.5,
  tension: 0,
  closed: false,
  start: 'natural',
  end: 'natural',
});

const endKinds = ['natural', 'reflect', 'zero'];

/// The editor holds curves of 2 to 16 coordinates (the curve file's range
/// above 1-D); it draws two of them (see coordinateNames and the editor's
/// projection). The WASM module builds the curve; it may take fewer.
export const maxDimension = 16;

/// Options as the WASM Spline takes them ('zero' is a zero tangent, d3's
/// end, of `dimension` coordinates).
/// Options may also hold what a command-line file gives and the controls do
/// not: `grid` (the knots, instead of alpha's), `kb` ({tension, continuity,
/// bias}: one value per point, NaN for a null end value), `strict`, and an
/// end tangent other than zero (start / end an array dx/dt).
export function splineOptions(o, dimension = 2) {
  const end = (e) => (e === 'zero' ? { tangent: new Array(dimension).fill(0) } : Array.isArray(e) ? { tangent: e } : e);
  const opt = { tension: o.tension, closed: o.closed };
  if (o.grid) opt.grid = o.grid; else opt.alpha = o.alpha;
  if (o.kb) opt.kb = o.kb;
  if (o.strict) opt.strict = true;
  if (!o.closed) {
    opt.start = end(o.start);
    opt.end = end(o.end);
  }
  return opt;
}

/// Names of the coordinates of a `dimension`-D curve: x, y (, z (, w)) up
/// to 4, x1 .. xD beyond (the command line numbers columns from 1).
export function coordinateNames(dimension) {
  if (dimension <= 4) return ['x', 'y', 'z', 'w'].slice(0, dimension);
  return Array.from({ length: dimension }, (_, k) => `x${k + 1}`);
}

// "point 0 has 1 coordinate; the editor draws curves of 2 to 16 coordinates"
function checkDimension(d, what) {
  if (d >= 2 && d <= maxDimension) return;
  throw new Error(`${what} has ${d} coordinate${d === 1 ? '' : 's'}; the editor draws curves of 2 to ${maxDimension} coordinates`);
}

// Points of any one dimension from 2 to 16 (every point as many coordinates
// as the first): { flat, dimension }. Nothing is cut: a 3-D file stays 3-D.
function checkPoints(points, where) {
  if (!Array.isArray(points)) throw new Error(`${where}: "points" must be an array of [x, y, ...]`);
  let dim = 0, flat = null;
  points.forEach((p, i) => {
    const xy = Array.isArray(p) ? p : p && typeof p === 'object' ? [p.x, p.y] : null;
    if (!xy || xy.length < 2) {
      if (Array.isArray(xy) && xy.length === 1 && i === 0) checkDimension(1, `${where}: point 0`);
      throw new Error(`${where}: point ${i} is not [x, y]`);
    }
    if (i === 0) {
      dim = xy.length;
      checkDimension(dim, `${where}: point 0`);
      flat = new Float64Array(points.length * dim);
    } else if (xy.length !== dim) {
      throw new Error(`${where}: point ${i} has ${xy.length} coordinates, point 0 has ${dim}`);
    }
    for (let k = 0; k < dim; ++k) {
      const v = typeof xy[k] === 'number' ? xy[k] : NaN;
      // The editor holds and draws points before there is a curve (one
      // point while drawing one): they must be finite here already.
      if (!Number.isFinite(v)) throw new Error(`${where}: point ${i}, coordinate ${k} is not a finite number (${JSON.stringify(xy[k]) ?? xy[k]})`);
      flat[dim * i + k] = v;
    }
  });
  return { flat: flat ?? new Float64Array(0), dimension: dim || 2 };
}

// The shape of the options (a number where a number belongs, known names);
// what the values may be (alpha and tension in [0, 1], a grid's length and
// order, a tangent's length, where a KB null may stand) is the library's to
// judge, in its words: the editor builds the curve when it imports a file
// (files.mjs importFile), as the command line and Python do.
function checkOptions(o, where) {
  const out = { ...defaultOptions };
  if (o == null) return out;
  if (typeof o !== 'object') throw new Error(`${where}: "options" must be an object`);
  for (const key of ['alpha', 'tension']) {
    if (o[key] === undefined) continue;
    if (typeof o[key] !== 'number') throw new Error(`${where}: ${key} must be a number, got ${JSON.stringify(o[key])}`);
    out[key] = o[key];
  }
  if (o.closed !== undefined) out.closed = Boolean(o.closed);
  for (const key of ['start', 'end']) {
    if (o[key] === undefined) continue;
    const tangent = Array.isArray(o[key]) && o[key].length > 0 && o[key].every((v) => typeof v === 'number');
    if (!endKinds.includes(o[key]) && !tangent) {
      throw new Error(`${where}: ${key} must be one of ${endKinds.join(', ')} or a tangent [dx/dt, ...], got ${JSON.stringify(o[key])}`);
    }
    out[key] = tangent ? [...o[key]] : o[key];
  }
  // Numbers of a list (null: NaN where `nulls`); the core checks the rest
  // (count, order, finiteness, where NaN may be).
  const list = (a, path, nulls) => {
    if (!Array.isArray(a)) throw new Error(`${where}: ${path} must be an array of numbers, got ${JSON.stringify(a)}`);
    return a.map((v, i) => {
      if (v === null && nulls) return NaN;
      if (typeof v !== 'number') throw new Error(`${where}: ${path}[${i}] is not a number (${JSON.stringify(v)})`);
      return v;
    });
  };
  if (o.grid !== undefined && o.grid !== null) out.grid = list(o.grid, 'grid', false);
  if (o.kb !== undefined && o.kb !== null) {
    if (typeof o.kb !== 'object' || Array.isArray(o.kb)) throw new Error(`${where}: kb must be {"tension": [...], "continuity": [...], "bias": [...]}`);
    out.kb = {};
    for (const [k, v] of Object.entries(o.kb)) {
      if (!['tension', 'continuity', 'bias'].includes(k)) throw new Error(`${where}: kb: unknown field '${k}' (expected "tension", "continuity", "bias")`);
      out.kb[k] = list(v, `kb.${k}`, true);
    }
  }
  if (o.strict !== undefined) {
    if (typeof o.strict !== 'boolean') throw new Error(`${where}: strict must be true or false, got ${JSON.stringify(o.strict)}`);
    if (o.strict) out.strict = true;
  }
  return out;
}

// The curve file's ends (docs/spec.md, "The curve file") as editor options:
// the table's words, "closed": true | false, "start": E and "end": E with E
// "natural", "reflect" or a tangent [dx/dt, ...]; and the compact forms the
// command line still reads: "end": "closed", "end": {"start": E, "end": E},
// and a name in "end" with neither "start" nor "closed" beside it, for both
// ends. Two fields that say different things are an error naming them (the
// command line's rules, cli/json_input.cpp read_ends). A zero tangent of as
// many coordinates as the points is the editor's 'zero' (d3's end).
function endsFromFile(data, where, dimension) {
  const zero = `[${new Array(dimension).fill(0).join(', ')}]`;
  const one = (x, path) => {
    if (x === 'natural' || x === 'reflect') return x;
    if (Array.isArray(x) && x.length > 0 && x.every((v) => typeof v === 'number')) {
      return x.length === dimension && x.every((v) => v === 0) ? 'zero' : [...x];  // its length: the library's
    }
    throw new Error(`${where}: ${path}: expected "natural", "reflect" or a tangent like ${zero}, got ${JSON.stringify(x)}`);
  };
  const { closed, start, end } = data;
  if (closed !== undefined && typeof closed !== 'boolean') throw new Error(`${where}: closed: expected true or false, got ${JSON.stringify(closed)}`);
  if (end === 'closed') {  // the compact closed curve
    if (closed === false) throw new Error(`${where}: end: "end": "closed" contradicts "closed": false`);
    if (start !== undefined) throw new Error(`${where}: start: a closed curve ("end": "closed") has no start condition`);
    return { closed: true };
  }
  if (closed === true) {
    if (start !== undefined || end !== undefined) {
      const key = start !== undefined ? 'start' : 'end';
      throw new Error(`${where}: ${key}: a closed curve ("closed": true) has no ${key} condition`);
    }
    return { closed: true };
  }
  if (end && typeof end === 'object' && !Array.isArray(end)) {  // the compact {"start": E, "end": E}
    if (start !== undefined) throw new Error(`${where}: start: given twice: in "start" and in "end": {"start": ...}`);
    for (const key of Object.keys(end)) {
      if (key !== 'start' && key !== 'end') throw new Error(`${where}: end: unknown field '${key}' (expected "start" and "end")`);
    }
    return { closed: false, start: one(end.start ?? 'natural', 'end.start'), end: one(end.end ?? 'natural', 'end.end') };
  }
  if (end !== undefined && typeof end !== 'string' && !Array.isArray(end)) {
    throw new Error(`${where}: end: expected "natural", "reflect", a tangent like ${zero}, "closed" or {"start": ..., "end": ...}, got ${JSON.stringify(end)}`);
  }
  const o = { closed: false };
  if (start !== undefined) o.start = one(start, 'start');
  if (typeof end === 'string' && start === undefined && closed === undefined) o.start = o.end = one(end, 'end');  // the compact name for both ends
  else if (end !== undefined) o.end = one(end, 'end');
  return o;
}

// The fields of a curve file the editor reads: the command line's
// (docs/spec.md) that an editor curve can hold, plus the editor's older
// export form ("format", "dimension", "options"). The command line's
// requests (what to compute: t, s, derivatives, ...) are not part of the
// curve: they are read past and named in `notKept`, which the editor shows.
// Any other field is an error naming it, never dropped.
const fileFields = ['points', 'alpha', 'grid', 'tension', 'closed', 'start', 'end', 'kb', 'strict', 'format', 'dimension', 'options'];
export const requestFields = ['t', 's', 'u', 'arc_fraction', 'knots', 'derivatives', 'accuracy', 'count', 'spacing', 'tolerance', 'summary', 'search'];

function optionsFromFile(data, where, dimension) {
  for (const key of Object.keys(data)) {
    if (!fileFields.includes(key) && !requestFields.includes(key)) throw new Error(`${where}: field '${key}' is not supported by the editor`);
  }
  if (data.format !== undefined && data.format !== 'crspline-points') {
    throw new Error(`${where}: format must be "crspline-points", got ${JSON.stringify(data.format)}`);
  }
  if (data.dimension !== undefined && data.dimension !== dimension) {
    throw new Error(`${where}: dimension is ${JSON.stringify(data.dimension)}, but the points have ${dimension} coordinates`);
  }
  const top = ['alpha', 'grid', 'tension', 'closed', 'start', 'end', 'kb', 'strict'].filter((k) => data[k] !== undefined);
  if (top.length && data.options !== undefined) {
    throw new Error(`${where}: give "options" or the top-level ${top.map((k) => `"${k}"`).join(', ')}, not both`);
  }
  if (data.options !== undefined) return checkOptions(data.options, where);
  const o = {};
  for (const key of ['alpha', 'tension', 'grid', 'kb', 'strict']) if (data[key] !== undefined) o[key] = data[key];
  if (data.closed !== undefined || data.start !== undefined || data.end !== undefined) Object.assign(o, endsFromFile(data, where, dimension));
  return checkOptions(o, where);
}

/// Parse a curve file: JSON (the curve file of docs/spec.md: {points,
/// alpha, tension, closed, start, end, ...}, its compact "end" forms too;
/// the older {points, options}; or a bare
/// [[x, y, ...], ...]) or CSV (one point per line, 2 to 16 numbers; a header
/// line names the coordinates; # comments are skipped).
/// Returns { points: Float64Array (flat, `dimension` numbers per point),
/// dimension, names (the coordinates' names), options, notKept (request
/// fields read past) }. Throws Error with the line or index at fault.
export function parsePoints(text, name = '') {
  const trimmed = text.trim();
  const looksJson = /\.json$/i.test(name) || trimmed.startsWith('{') || trimmed.startsWith('[');
  if (looksJson) {
    let data;
    try {
      data = JSON.parse(trimmed);
    } catch (e) {
      throw new Error(`JSON: ${e.message}`);
    }
    const result = (pointsData, options = () => ({ ...defaultOptions }), notKept = []) => {
      const { flat, dimension } = checkPoints(pointsData, 'JSON');
      return { points: flat, dimension, names: coordinateNames(dimension), options: options(dimension), notKept };
    };
    if (Array.isArray(data)) return result(data);
    if (data && typeof data === 'object') {
      return result(data.points, (d) => optionsFromFile(data, 'JSON', d), requestFields.filter((k) => data[k] !== undefined));
    }
    throw new Error('JSON: expected {"points": [[x, y], ...]} or [[x, y], ...]');
  }
  const xs = [];
  let dim = 0, header = null;
  const lines = trimmed.split(/\r?\n/);
  lines.forEach((line, i) => {
    const l = line.trim();
    if (!l || l.startsWith('#')) return;
    const cells = l.split(/[,;\t ]+/);
    const numbers = cells.map((c) => (c === '' ? NaN : Number(c)));
    if (!numbers.every(Number.isFinite)) {
      // A header: the first line, with no cell that reads as a number,
      // NaN or an infinity ("NaN,1" is a bad point, not a header).
      const numberLike = (c) => c !== '' && (Number.isFinite(Number(c)) || /^[+-]?(nan|inf(inity)?)$/i.test(c));
      if (dim === 0 && header === null && /[a-z]/i.test(l) && !cells.some(numberLike)) {
        header = cells.map((c) => c.replace(/^"(.*)"$/, '$1'));
        return;
      }
      const k = dim || (header ? header.length : cells.length);
      throw new Error(`CSV line ${i + 1}: "${l}" is not ${k === 2 ? 'two' : k} finite numbers`);
    }
    if (dim === 0) {
      dim = cells.length;
      checkDimension(dim, `CSV line ${i + 1}: "${l}"`);
      if (header && header.length !== dim) throw new Error(`CSV line ${i + 1}: ${dim} numbers, but the header has ${header.length} names`);
    } else if (cells.length !== dim) {
      throw new Error(`CSV line ${i + 1}: expected ${dim} numbers like the first point, got ${cells.length}`);
    }
    xs.push(...numbers);
  });
  const dimension = dim || 2;
  return { points: Float64Array.from(xs), dimension, names: header ?? coordinateNames(dimension), options: { ...defaultOptions }, notKept: [] };
}

// Shortest round-trip text of a double, keeping the sign of -0.
const num = (x) => (Object.is(x, -0) ? '-0' : String(x));
const pairs = (flat) => Array.from({ length: flat.length / 2 }, (_, i) => [flat[2 * i], flat[2 * i + 1]]);
const rows = (flat, d) => Array.from({ length: flat.length / d }, (_, i) => Array.from(flat.subarray(d * i, d * i + d), num));

/// The curve file (docs/spec.md): the points (`dimension` numbers each) and
/// the command line's fields in the table's words ("closed": true, or
/// "closed": false with "start" and "end"), so that every crspline
/// subcommand and Python's crspline.load read an export unchanged.
export function pointsToJson(flat, options, dimension = 2) {
  const o = checkOptions(options, 'options');
  const body = rows(Float64Array.from(flat), dimension).map((p) => `    [${p.join(', ')}]`).join(',\n');
  const e = (x) => (x === 'zero' ? `[${new Array(dimension).fill(0).join(', ')}]` : Array.isArray(x) ? `[${x.map(num).join(', ')}]` : JSON.stringify(x));
  const list = (a) => `[${a.map((v) => (Number.isNaN(v) ? 'null' : num(v))).join(', ')}]`;
  const fields = [o.grid ? `  "grid": ${list(o.grid)}` : `  "alpha": ${num(o.alpha)}`, `  "tension": ${num(o.tension)}`];
  if (o.closed) fields.push('  "closed": true');
  else fields.push('  "closed": false', `  "start": ${e(o.start)}`, `  "end": ${e(o.end)}`);
  if (o.kb) fields.push(`  "kb": {${Object.entries(o.kb).map(([k, v]) => `"${k}": ${list(v)}`).join(', ')}}`);
  if (o.strict) fields.push('  "strict": true');
  return `{\n${fields.join(',\n')},\n  "points": [\n${body}\n  ]\n}\n`;
}

/// CSV with a header of the coordinates' names (x,y by default).
export function pointsToCsv(flat, dimension = 2, names = coordinateNames(dimension)) {
  return names.join(',') + '\n' + rows(Float64Array.from(flat), dimension).map((p) => p.join(',')).join('\n') + '\n';
}

/// SVG path data of the curve from bezierAll()'s flat B0..B3 per segment.
export function bezierPathData(bez) {
  const n = bez.length / 8;
  if (n === 0) return '';
  let d = `M${bez[0]} ${bez[1]}`;
  for (let i = 0; i < n; ++i) {
    const o = 8 * i;
    // A new subpath only if a segment does not start where the last ended.
    if (i > 0 && (bez[o] !== bez[o - 2] || bez[o + 1] !== bez[o - 1])) d += `M${bez[o]} ${bez[o + 1]}`;
    d += `C${bez[o + 2]} ${bez[o + 3]} ${bez[o + 4]} ${bez[o + 5]} ${bez[o + 6]} ${bez[o + 7]}`;
  }
  return d;
}

/// A standalone SVG of the curve (exact cubic Béziers, no sampling), with
/// the control points as small circles when showPoints.
export function curveToSvg(bez, flat, { showPoints = true, closed = false, stroke = '#1f5fbf' } = {}) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  const grow = (x, y) => { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); };
  for (let i = 0; i < bez.length; i += 2) grow(bez[i], bez[i + 1]);
  for (let i = 0; i < flat.length; i += 2) grow(flat[i], flat[i + 1]);
  if (!Number.isFinite(x0)) { x0 = y0 = 0; x1 = y1 = 1; }
  const pad = 0.05 * Math.max(x1 - x0, y1 - y0, 1e-9);
  const w = x1 - x0 + 2 * pad, h = y1 - y0 + 2 * pad;
  const r = 0.006 * Math.max(w, h);
  const d = bezierPathData(bez) + (closed && bez.length ? 'Z' : '');
  const dots = showPoints
    ? pairs(flat).map((p) => `  <circle cx="${p[0]}" cy="${p[1]}" r="${r}"/>`).join('\n')
    : '';
  return `<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" viewBox="${x0 - pad} ${y0 - pad} ${w} ${h}" width="${Math.round(Math.min(1200, w * (1200 / Math.max(w, h))))}" height="${Math.round(Math.min(1200, h * (1200 / Math.max(w, h))))}">
<title>Catmull-Rom curve (crspline)</title>
<path d="${d}" fill="none" stroke="${stroke}" stroke-width="${r / 2}" stroke-linejoin="round"/>
<g fill="#c0392b">
${dots}
</g>
</svg>
`;
}
