// crspline for JavaScript: cubic Catmull-Rom curves, the C++ library compiled
// to WebAssembly (dist/crspline.mjs + dist/crspline.wasm, built by
// web/build.sh) behind an API that reads like JavaScript.
//
//   import { init, catmullRom } from 'crspline';
//   await init();                      // loads the .wasm once
//   const curve = catmullRom([[0, 0], [1, 2], [3, 1]], { alpha: 0.5 });
//   curve.evaluate(0.7);               // Float64Array [x, y]
//   curve.dispose();                   // or let the garbage collector do it
//
// Every number is computed by the C++ core; this file only converts
// arguments, checks what the core cannot see (the shape of the JavaScript
// input, option names) and owns the WASM object's lifetime.
import CrSpline from './dist/crspline.mjs';

let wasm = null;      // the instantiated module
let loading = null;   // its promise while it loads

/// Loads the WebAssembly module (once; later calls return the same promise).
/// In node the .wasm next to this file is read from disk; in a browser or a
/// bundler it is fetched from the URL next to this module. Pass
/// { wasmBinary } (bytes) or { wasmURL } to load it from elsewhere.
export function init(options = {}) {
  if (wasm) return Promise.resolve(api);
  if (!loading) {
    loading = load(options).then((m) => {
      wasm = m;
      return api;
    }, (e) => {
      loading = null;
      throw e;
    });
  }
  return loading;
}

async function load({ wasmBinary, wasmURL } = {}) {
  const url = new URL(wasmURL ?? './dist/crspline.wasm', import.meta.url);
  const args = {};
  if (wasmBinary) {
    args.wasmBinary = wasmBinary;
  } else if (url.protocol === 'file:' && typeof process !== 'undefined' && process.versions?.node) {
    // node's fetch cannot read file: URLs; read the bytes instead. (The
    // specifier is a variable, hidden from bundlers: browsers never get here.)
    const fsModule = 'node:fs/promises';
    const { readFile } = await import(/* webpackIgnore: true */ /* @vite-ignore */ fsModule);
    args.wasmBinary = await readFile(url);
  } else {
    args.locateFile = (name) => (name.endsWith('.wasm') ? url.href : name);
  }
  return CrSpline(args);
}

/// true once init() has resolved.
export function isReady() {
  return wasm !== null;
}

function module() {
  if (!wasm) throw new Error('crspline: call `await init()` before creating curves');
  return wasm;
}

/// The C++ library's version.
export function version() {
  return module().version();
}

/// The size of the WebAssembly memory in bytes (it grows, never shrinks):
/// what curves that were neither disposed nor collected hold shows here.
export function wasmMemoryBytes() {
  return module().HEAPU8.length;
}

// An Error shaped like the core's spec_error: message, then field, index,
// component, value (null where there is none).
function inputError(message, field, index = null, component = null, value = '') {
  const e = new Error(message);
  Object.assign(e, { field, index, component, value });
  return e;
}

const OPTIONS = new Set(['alpha', 'grid', 'closed', 'tension', 'start', 'end', 'strict', 'kb', 'tangents',
  'tangentsIn', 'dimension']);

// points: [[x, y, ...], ...], [{x, y, z?}, ...] or a flat typed array /
// array of numbers with options.dimension. Returns [flat Float64Array, dimension].
function flatten(points, dimension) {
  if (points === null || points === undefined || typeof points.length !== 'number' || typeof points === 'string')
    throw inputError('points must be an array of points', 'points');
  const n = points.length;
  if (dimension !== undefined) {
    if (!Number.isInteger(dimension) || dimension < 1)
      throw inputError(`dimension must be a positive integer, got ${dimension}`, 'dimension', null, null, String(dimension));
    if (n > 0 && typeof points[0] !== 'number')
      throw inputError('options.dimension is for flat coordinates; points[0] is not a number', 'points', 0);
    return [Float64Array.from(points), dimension];
  }
  if (n === 0) throw inputError('a curve needs at least 2 points, got 0', 'points', null, null, '0');
  const first = points[0];
  if (typeof first === 'number')
    throw inputError('flat coordinates need options.dimension (or give points as [[x, y], ...])', 'points');
  if (first && typeof first === 'object' && typeof first.length !== 'number' && 'x' in first) {
    // {x, y, z?} objects (three.js Vector3, d3 data): 2-D unless z is there.
    const dim = 'z' in first && first.z !== undefined ? 3 : 2;
    const flat = new Float64Array(n * dim);
    for (let i = 0; i < n; ++i) {
      const p = points[i];
      if (!p || typeof p !== 'object')
        throw inputError(`point ${i} is not an object with x, y${dim === 3 ? ', z' : ''}`, 'points', i);
      flat[i * dim] = p.x;
      flat[i * dim + 1] = p.y;
      if (dim === 3) flat[i * dim + 2] = p.z;
    }
    return [flat, dim];
  }
  if (!first || typeof first.length !== 'number')
    throw inputError('point 0 is not an array of coordinates', 'points', 0);
  const dim = first.length;
  const flat = new Float64Array(n * dim);
  for (let i = 0; i < n; ++i) {
    const p = points[i];
    if (!p || typeof p.length !== 'number')
      throw inputError(`point ${i} is not an array of coordinates`, 'points', i);
    if (p.length !== dim)
      throw inputError(`point ${i} has ${p.length} coordinates, point 0 has ${dim}`, 'points', i, null, String(p.length));
    for (let k = 0; k < dim; ++k) flat[i * dim + k] = p[k];
  }
  return [flat, dim];
}

// The WASM Spline of a CatmullRom (set in the class's static block).
let rawSpline;

// The WASM object is freed when its curve is collected, unless dispose()
// freed it first.
const registry = typeof FinalizationRegistry === 'function'
  ? new FinalizationRegistry((spline) => { if (!spline.isDeleted()) spline.delete(); })
  : null;

/// A Catmull-Rom curve through points. options: alpha (0 uniform, 0.5
/// centripetal, the default, 1 chordal) or grid (the knots), closed,
/// tension, start/end ('natural' | 'reflect' | {tangent: [...]}), strict,
/// kb ({tension, continuity, bias} per point), tangents/tangentsIn (given
/// dx/dt: a Hermite curve), dimension (with flat coordinates).
export function catmullRom(points, options = {}) {
  const M = module();
  if (options === null || typeof options !== 'object') throw inputError('options must be an object', 'options');
  for (const key of Object.keys(options))
    if (!OPTIONS.has(key) && options[key] !== undefined)
      throw inputError(`unknown option '${key}' (options are ${[...OPTIONS].join(', ')})`, key);
  // The options' ends are the specification table's words (closed, start,
  // end); a truthy non-boolean closed or a curve file's compact
  // {"start": E, "end": E} in start / end would otherwise be misread.
  if (options.closed !== undefined && typeof options.closed !== 'boolean')
    throw inputError(`closed must be true or false, got ${JSON.stringify(options.closed) ?? String(options.closed)}`, 'closed', null, null, String(options.closed));
  for (const key of ['start', 'end']) {
    const e = options[key];
    if (e !== null && typeof e === 'object' && !('tangent' in e) && typeof e.length !== 'number')
      throw inputError(`${key} condition must be 'natural', 'reflect' or a tangent ([dx/dt, ...] or {tangent: [...]}), got ${JSON.stringify(e)}` +
        ' (a curve file\'s "end": {"start": ..., "end": ...} is the options start and end)', key, null, null, JSON.stringify(e));
  }
  const [flat, dim] = flatten(points, options.dimension);
  const { dimension: _, ...rest } = options;
  return new CatmullRom(new M.Spline(flat, dim, rest));
}

/// A curve, as catmullRom() makes it. t is the curve's own parameter
/// (the knots: curve.tMin .. curve.tMax), s is arc length.
export class CatmullRom {
  #s;
  #dim;

  /// @internal: use catmullRom().
  constructor(spline) {
    this.#s = spline;
    this.#dim = spline.dimension();
    registry?.register(this, spline, this);
  }

  #spline() {
    if (!this.#s) throw new Error('crspline: this curve was disposed');
    return this.#s;
  }

  /// Frees the WASM memory now; the curve cannot be used afterwards.
  dispose() {
    if (!this.#s) return;
    registry?.unregister(this);
    this.#s.delete();
    this.#s = null;
  }

  get disposed() { return this.#s === null; }
  get dimension() { return this.#dim; }
  get pointCount() { return this.#spline().pointCount(); }
  get segmentCount() { return this.#spline().segmentCount(); }
  get closed() { return this.#spline().closed(); }
  get tMin() { return this.#spline().tMin(); }
  get tMax() { return this.#spline().tMax(); }
  /// The knots (pointCount values, one more when closed).
  get grid() { return this.#spline().grid(); }
  /// The points, flat: point i is [i * dimension, (i + 1) * dimension).
  get points() { return this.#spline().points(); }

  /// Position (order 0) or derivative d^order x / dt^order (1..3) at t.
  evaluate(t, order = 0) { return this.#spline().evaluate(t, order); }
  /// Many parameters at once: point k is [k * dimension, (k + 1) * dimension)
  /// of the result (written into `out` when given).
  evaluateMany(t, order = 0, out) {
    const r = this.#spline().evaluateMany(t, order);
    if (!out) return r;
    if (out.length < r.length)
      throw inputError(`out has ${out.length} numbers, ${r.length} needed`, 'out', null, null, String(out.length));
    out.set(r);
    return out;
  }
  /// The segment holding t.
  locate(t) { return this.#spline().locate(t); }
  /// Curvature at t (null where the speed is zero).
  curvature(t) { return this.#spline().curvature(t); }

  /// The Bézier control points B0..B3: of segment i, or of every segment
  /// in turn (4 * dimension numbers per segment).
  bezier(i) { return i === undefined ? this.#spline().bezierAll() : this.#spline().bezier(i); }

  /// Total arc length (the cached table), or to the given accuracy.
  arcLength(accuracy) {
    return accuracy === undefined ? this.#spline().arcLength() : this.#spline().arcLength(accuracy);
  }
  arcLengthBetween(t0, t1) { return this.#spline().arcLengthBetween(t0, t1); }
  /// Arc length from the start to t, and its inverse.
  sAt(t) { return this.#spline().sAt(t); }
  tAtArcLength(s) { return this.#spline().tAtArcLength(s); }
  /// Arc length at every knot.
  knotLengths() { return this.#spline().knotLengths(); }
  /// n points evenly spaced in arc length: {t, s, points}.
  sampleArcLength(n, accuracy = 0) { return this.#spline().sampleArcLength(n, accuracy); }
  /// n points evenly spaced in t.
  sampleT(n) { return this.#spline().sampleT(n); }
  /// A polyline within `tolerance` of the curve: {points, t}.
  tessellate(tolerance = 0) { return this.#spline().tessellate(tolerance); }
  boundingBox() { return this.#spline().boundingBox(); }
  /// The point of the curve nearest to p: {t, distance, distanceSq, segment, point}.
  nearest(p) {
    const r = this.#spline().nearest(p);
    r.distance = Math.sqrt(r.distanceSq);
    return r;
  }

  /// The paper's analysis, per segment, as the core reports it.
  analyze() { return this.#spline().analyze(); }
  /// The intersection-free certificate, as the core reports it.
  certify(options) { return options === undefined ? this.#spline().certify() : this.#spline().certify(options); }
  intersections(tolerance = 0) { return this.#spline().intersections(tolerance); }
  cusps() { return this.#spline().cusps(); }
  /// Does the curve cross itself? A proved verdict (plane curves): the
  /// report's decision object {verdict: 'simple' | 'crosses' | 'touches',
  /// fast_path, floor, crossings, touches, pairs}. options: {fastPath,
  /// budget, pairBudget, recordPairs}.
  decide(options) { return options === undefined ? this.#spline().decide() : this.#spline().decide(options); }
  /// The least distance between non-adjacent segments (any dimension):
  /// {distance, lowerBound, curves, segments, u, points, exhausted}.
  clearance(accuracy = 0) { return this.#spline().clearance(accuracy); }
  static {
    rawSpline = (c) => {
      if (!(c instanceof CatmullRom)) throw inputError('expected a curve made by catmullRom()', 'curve');
      return c.#spline();
    };
  }
}
if (typeof Symbol.dispose === 'symbol') CatmullRom.prototype[Symbol.dispose] = CatmullRom.prototype.dispose;

// ---------------------------------------------------------------------------
// The decision between curves (issue 27) and clearance.
// ---------------------------------------------------------------------------

/// The verdict of one curve: curve.decide(options).
export function decide(curve, options) { return rawSpline(curve) && curve.decide(options); }

/// Do two plane curves cross each other? (Each one's own crossings are
/// decide()'s.) Crossings name curve 0 (a) and 1 (b).
export function decidePair(a, b, options = {}) {
  return module().Spline.decidePair(rawSpline(a), rawSpline(b), options);
}

/// Do any two curves of a set cross? options.self: each curve's own
/// crossings too. Crossings name the curves by their index in the array.
export function decideSet(curves, options = {}) {
  if (!Array.isArray(curves)) throw inputError('decideSet takes an array of curves', 'curves');
  return module().Spline.decideSet(curves.map((c, i) => {
    try {
      return rawSpline(c);
    } catch (e) {
      throw inputError(`curve ${i} of the set: ${e.message}`, 'curves', i);
    }
  }), options);
}

/// clearance(curve, accuracy?): between non-adjacent segments of one curve;
/// clearance(a, b, accuracy?): between two curves of one dimension.
export function clearance(a, b, accuracy) {
  if (b instanceof CatmullRom) return module().Spline.clearancePair(rawSpline(a), rawSpline(b), accuracy ?? 0);
  return rawSpline(a) && a.clearance(b ?? 0);
}

// ---------------------------------------------------------------------------
// Fit (issue 40), sweeps and strokes (issue 41): the core's fit.hpp,
// sweep.hpp and stroke.hpp (web/src/bind_fit.cpp, bind_sweep.cpp).
// ---------------------------------------------------------------------------

/// The fewest control points whose curve stays within options.tolerance of
/// the points, both ways (proved): {curve, deviation, curveToInput,
/// inputToCurve, indices (subset mode; null in free mode), count, tensioned,
/// roundingFloor}. options: tolerance (required), mode ('subset' | 'free'),
/// alpha (0.5), closed, tension, start / end ('natural' | 'reflect'),
/// dimension (with flat coordinates).
export function fit(points, options = {}) {
  const M = module();
  if (options === null || typeof options !== 'object') throw inputError('options must be an object', 'options');
  const { dimension, ...rest } = options;
  const [flat, dim] = flatten(points, dimension);
  const r = M.fitPoints(flat, dim, rest);
  // The core's curve, built again from the same points and options.
  const kb = r.kbTension ? { tension: r.kbTension } : undefined;
  const ends = r.closed ? {} : { start: rest.start ?? 'natural', end: rest.end ?? 'natural' };
  r.curve = catmullRom(r.points, { dimension: dim, alpha: r.alpha, closed: r.closed, tension: r.tension, kb, ...ends });
  for (const k of ['points', 'dimension', 'kbTension', 'alpha', 'closed', 'tension']) delete r[k];
  return r;
}

const curveData = (curve) => {
  const c = rawSpline(curve) && curve;
  return [c.points, c.grid, c.bezier(), c.closed, c.dimension];
};
const SWEEP_OPTIONS = new Set(['radius', 'profile', 'roll', 'rollAt', 'rollS', 'scale', 'scaleS', 'up', 'tolerance',
  'tubularSegments', 'radialSegments', 'spreadHolonomy', 'clearance']);

/// A profile carried along a 3-D curve by a rotation-minimizing frame (a
/// closed curve's twist spread: no seam): {positions, normals, uvs
/// (Float32Array: 3, 3, 2 per vertex, vertex ring * ringSize + j), indices
/// (Uint32Array, 3 per triangle), rings, ringSize, t, s, report}. options:
/// radius (a circle) or profile ([[x, y], ...] polyline, or {points, closed,
/// curve: true, alpha} a Catmull-Rom profile), roll (radians per knot, or at
/// rollS arc lengths with rollAt 'arcLength'), scale at scaleS, up [x, y, z],
/// tolerance (0: the default) or tubularSegments / radialSegments,
/// spreadHolonomy (false: the seam, for comparison), clearance (report).
export function sweep(curve, options = {}) {
  const M = module();
  if (options === null || typeof options !== 'object') throw inputError('options must be an object', 'options');
  for (const key of Object.keys(options))
    if (!SWEEP_OPTIONS.has(key) && options[key] !== undefined)
      throw inputError(`unknown option '${key}' (options are ${[...SWEEP_OPTIONS].join(', ')})`, key);
  const { profile, up, ...o } = options;
  if (up !== undefined && up !== null) o.up = 'x' in up ? [up.x, up.y, up.z] : up;
  if (profile !== undefined && profile !== null) {
    const p = typeof profile.length === 'number' ? { points: profile } : profile;
    if (!p.points || typeof p.points.length !== 'number')
      throw inputError('profile must be [[x, y], ...] or {points, closed, curve, alpha}', 'profile');
    o.profileKind = p.curve ? 'curve' : 'polyline';
    o.profilePoints = typeof p.points[0] === 'number' ? p.points : flatten(p.points)[0];
    o.profileClosed = p.closed ?? !!p.curve;
    if (p.alpha !== undefined) o.profileAlpha = p.alpha;
  }
  return M.sweepCurve(...curveData(curve), o);
}

const STROKE_OPTIONS = new Set(['join', 'cap', 'miterLimit', 'tolerance']);

/// The outline of a 2-D curve stroked at `width`, as simple polygons (the
/// union where the stroke overlaps itself): {polygons: [[exterior, ...holes]]
/// with each ring a flat Float64Array [x0, y0, x1, y1, ...], tolerance,
/// tessellationVertices}. options: join ('round' | 'miter' | 'bevel'), cap
/// ('butt' | 'round' | 'square'), miterLimit (4), tolerance (0: the default).
export function stroke(curve, width, options = {}) {
  const M = module();
  if (options === null || typeof options !== 'object') throw inputError('options must be an object', 'options');
  for (const key of Object.keys(options))
    if (!STROKE_OPTIONS.has(key) && options[key] !== undefined)
      throw inputError(`unknown option '${key}' (options are ${[...STROKE_OPTIONS].join(', ')})`, key);
  if (typeof width !== 'number') throw inputError(`width: must be a number, got ${typeof width}`, 'width');
  return M.strokeCurve(...curveData(curve), width, options);
}

// ---------------------------------------------------------------------------
// Rotations (issue 28): quaternions are [w, x, y, z] here, the core's order
// (crspline/three converts to and from three.js' [x, y, z, w]).
// ---------------------------------------------------------------------------

// [[w, x, y, z], ...] or flat numbers, as a flat Float64Array.
function flatQuaternions(q, what) {
  if (q === null || q === undefined || typeof q.length !== 'number' || typeof q === 'string')
    throw inputError(`${what} must be an array of quaternions [w, x, y, z]`, what);
  if (q.length > 0 && typeof q[0] !== 'number') {
    const flat = new Float64Array(q.length * 4);
    for (let i = 0; i < q.length; ++i) {
      const r = q[i];
      if (!r || typeof r.length !== 'number' || r.length !== 4)
        throw inputError(`${what}[${i}] must be [w, x, y, z], got ${JSON.stringify(r)}`, what, i);
      flat.set(r, i * 4);
    }
    return flat;
  }
  return Float64Array.from(q);
}

function flatVectors(p, what) {
  if (p === null || p === undefined || typeof p.length !== 'number')
    throw inputError(`${what} must be an array of [x, y, z]`, what);
  if (p.length > 0 && typeof p[0] !== 'number') {
    const flat = new Float64Array(p.length * 3);
    for (let i = 0; i < p.length; ++i) {
      const r = p[i];
      const v = r && typeof r.length === 'number' ? r : r && 'x' in r ? [r.x, r.y, r.z] : null;
      if (!v || v.length !== 3) throw inputError(`${what}[${i}] must be [x, y, z] or {x, y, z}`, what, i);
      flat.set(v, i * 3);
    }
    return flat;
  }
  return Float64Array.from(p);
}

const rotationRegistry = typeof FinalizationRegistry === 'function'
  ? new FinalizationRegistry((o) => { if (!o.isDeleted()) o.delete(); })
  : null;

// Owns a WASM object: dispose() frees it now, else the collector does.
class Owned {
  #o;
  constructor(o) {
    this.#o = o;
    rotationRegistry?.register(this, o, this);
  }
  _o() {
    if (!this.#o) throw new Error('crspline: this curve was disposed');
    return this.#o;
  }
  dispose() {
    if (!this.#o) return;
    rotationRegistry?.unregister(this);
    this.#o.delete();
    this.#o = null;
  }
  get disposed() { return this.#o === null; }
}

/// A rotation curve through unit quaternions: quaternionSpline() (the
/// Catmull-Rom family) or rotationSpline() (C2).
export class RotationCurve extends Owned {
  get kind() { return this._o().kind(); }
  get closed() { return this._o().closed(); }
  get segmentCount() { return this._o().segmentCount(); }
  get grid() { return this._o().grid(); }
  get tMin() { return this._o().tMin(); }
  get tMax() { return this._o().tMax(); }
  /// The keys after the sign rule, flat [w, x, y, z] (closed: one more).
  get keys() { return this._o().keys(); }
  /// C2 only: the Newton residual and iteration count (null otherwise).
  get residual() { return this._o().residual(); }
  get iterations() { return this._o().iterations(); }
  /// {q: [w, x, y, z], omega, alpha} at t: rates to `order` (0..2) in
  /// `frame` ('world' or 'body'), rad per unit t (null beyond order).
  evaluate(t, order = 0, frame = 'world') { return this._o().evaluate(t, order, frame); }
  /// The rotation at t, [w, x, y, z].
  quaternion(t) { return this._o().evaluate(t).q; }
  /// Many t: {q: 4 numbers per t, omega, alpha: 3 per t or null}.
  evaluateMany(t, order = 0, frame = 'world') { return this._o().evaluateMany(t, order, frame); }
  /// The total angle turned through (radians), to relative accuracy.
  angleLength(accuracy = 0) { return this._o().angleLength(accuracy); }
  /// n values of t at constant angular speed.
  constantAngularSpeedTimes(n, accuracy = 0) { return this._o().constantAngularSpeedTimes(n, accuracy); }
}

/// The quaternion Catmull-Rom family. keys: [[w, x, y, z], ...] or flat.
/// options: kind ('catmull_rom' | 'kochanek_bartels' | 'piecewise_slerp' |
/// 'barry_goldman' | 'squad'), alpha (on the rotation angle) or grid,
/// closed, start / end ('natural' | 'natural_splines' | {omega, frame}),
/// kb ({tension, continuity, bias}), keepSigns, strict, unitTolerance.
export function quaternionSpline(keys, options = {}) {
  const M = module();
  return new RotationCurve(M.RotationCurve.quaternionSpline(flatQuaternions(keys, 'keys'), options));
}

/// The C2 rotation spline (SciPy's RotationSpline, converged) through keys
/// at times. options: closed, start / end ('scipy' | 'natural' | {omega,
/// frame}), keepSigns, unitTolerance.
export function rotationSpline(times, keys, options = {}) {
  const M = module();
  return new RotationCurve(M.RotationCurve.c2Spline(Float64Array.from(times), flatQuaternions(keys, 'keys'), options));
}

/// A pose curve: a centripetal (or alpha / grid) position curve and a C2
/// rotation curve (options.c2Rotation = false: quaternion Catmull-Rom) on
/// one shared grid.
export class PoseCurve extends Owned {
  get grid() { return this._o().grid(); }
  get tMin() { return this._o().tMin(); }
  get tMax() { return this._o().tMax(); }
  /// {position, orientation [w, x, y, z], velocity, omega} at t.
  evaluate(t, frame = 'world') { return this._o().evaluate(t, frame); }
  /// Many t: {positions: 3 per t, orientations: 4 per t}.
  evaluateMany(t) { return this._o().evaluateMany(t); }
  /// n values of t at constant speed of positionWeight |dx/dt| +
  /// angleWeight |omega| (1, 0: along the path; 0, 1: of the angle).
  constantSpeedTimes(n, positionWeight = 1, angleWeight = 0, accuracy = 0) {
    return this._o().constantSpeedTimes(n, positionWeight, angleWeight, accuracy);
  }
}

/// positions: [[x, y, z], ...] (or {x, y, z}); rotations: [[w, x, y, z], ...].
/// options: alpha, grid, closed, c2Rotation.
export function poseCurve(positions, rotations, options = {}) {
  const M = module();
  return new PoseCurve(new M.PoseCurve(flatVectors(positions, 'positions'), flatQuaternions(rotations, 'rotations'), options));
}

/// [w, x, y, z] <-> [x, y, z, w] (three.js, SciPy, glTF order).
export function toXYZW(q, out = new Float64Array(4)) {
  out[0] = q[1]; out[1] = q[2]; out[2] = q[3]; out[3] = q[0];
  return out;
}
export function fromXYZW(q, out = new Float64Array(4)) {
  out[0] = q[3]; out[1] = q[0]; out[2] = q[1]; out[3] = q[2];
  return out;
}

const api = { init, isReady, version, wasmMemoryBytes, catmullRom, CatmullRom, decide, decidePair, decideSet, clearance,
  fit, sweep, stroke,
  quaternionSpline, rotationSpline, poseCurve, RotationCurve, PoseCurve, toXYZW, fromXYZW };
export default api;
