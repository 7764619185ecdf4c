// crspline as a three.js curve: CRSplineCurve3, a drop-in for
// THREE.CatmullRomCurve3 (same constructor arguments: points, closed,
// curveType 'centripetal' | 'chordal' | 'catmullrom', tension).
//
//   import { init } from 'crspline';
//   import { CRSplineCurve3 } from 'crspline/three';
//   await init();
//   const curve = new CRSplineCurve3(points, false, 'centripetal');
//   const tube = new THREE.TubeGeometry(curve, 200, 0.1, 8, false);
//
// The curve is three.js' own (the same parameter t in [0, 1], each segment
// an equal share of it, the same reflected end points), computed exactly:
//  - getPoint / getTangent evaluate crspline's Bézier form of each segment
//    (exact derivative, no finite differences);
//  - getPointAt / getTangentAt / getLength / getUtoTmapping use crspline's
//    arc length (relative error 1e-12, not a 200-chord table);
//  - getLengths(divisions) keeps three.js' Curve contract: the cumulative
//    chord lengths of the `divisions`-division polyline of getPoint, cached
//    in cacheArcLengths until needsUpdate (code built on three.js reads it as
//    that polyline, so it is not replaced by exact arc lengths);
//  - coincident points are handled by the core's rules, not replaced by a
//    1e-4 constant knot interval.
// The curve is rebuilt when `points` is a new array or changes length; after
// moving points in place, call updateArcLengths() (as three.js asks for
// getPointAt). dispose() frees the WASM memory now.
import { Curve, Vector3 } from 'three';
import { catmullRom } from './index.js';

const ALPHA = { centripetal: 0.5, chordal: 1, catmullrom: 0 };

export class CRSplineCurve3 extends Curve {
  constructor(points = [], closed = false, curveType = 'centripetal', tension = 0.5) {
    super();
    this.isCRSplineCurve3 = true;
    // As CatmullRomCurve3 sets it: code that branches on the flag (loaders,
    // serializers, users' own) takes the adapter for the curve it replaces.
    Object.defineProperty(this, 'isCatmullRomCurve3', { value: true, enumerable: true });
    this.type = 'CRSplineCurve3';
    this.points = points;
    this.closed = closed;
    this.curveType = curveType;
    this.tension = tension;
    this._c = null;  // {curve, bez, grid, nseg, length, n}
  }

  // The crspline curve for the current points, built on first use.
  _data() {
    const pts = this.points;
    if (this._c && !this.needsUpdate && this._c.points === pts && this._c.n === pts.length) return this._c;
    this._free();
    this.needsUpdate = false;
    const alpha = ALPHA[this.curveType];
    if (alpha === undefined)
      throw Object.assign(new Error(`curveType must be 'centripetal', 'chordal' or 'catmullrom', got '${this.curveType}'`),
        { field: 'curveType', index: null, component: null, value: String(this.curveType) });
    const options = { alpha, closed: Boolean(this.closed) };  // three.js takes any truthy value
    if (!this.closed) options.start = options.end = 'reflect';  // three.js' phantom points 2 P0 - P1
    if (this.curveType === 'catmullrom') {
      // three.js: tangent tension * (P[i+1] - P[i-1]) on the uniform grid;
      // crspline scales the standard (P[i+1] - P[i-1]) / 2 by 1 - tension.
      if (!(this.tension >= 0 && this.tension <= 0.5))
        throw Object.assign(new Error(`tension must be in [0, 0.5] for curveType 'catmullrom' (crspline's tension is 1 - 2 tension), got ${this.tension}`),
          { field: 'tension', index: null, component: null, value: String(this.tension) });
      options.tension = 1 - 2 * this.tension;
    }
    const flat = new Float64Array(3 * pts.length);
    pts.forEach((p, i) => { flat[3 * i] = p.x; flat[3 * i + 1] = p.y; flat[3 * i + 2] = p.z; });
    const curve = catmullRom(flat, { ...options, dimension: 3 });
    this._c = { curve, bez: curve.bezier(), grid: curve.grid, nseg: curve.segmentCount, length: curve.arcLength(),
      points: pts, n: pts.length };
    return this._c;
  }

  _free() {
    if (this._c) this._c.curve.dispose();
    this._c = null;
  }

  /// Frees the WASM memory now (the curve is rebuilt if used again).
  dispose() { this._free(); }

  // three.js' t in [0, 1] -> segment and local u (an equal share each).
  _locate(t, c) {
    let x = t * c.nseg;
    if (this.closed) x -= Math.floor(x / c.nseg) * c.nseg;
    else x = Math.min(Math.max(x, 0), c.nseg);
    const i = Math.min(Math.floor(x), c.nseg - 1);
    return [i, x - i];
  }

  getPoint(t, optionalTarget = new Vector3()) {
    const c = this._data();
    const [i, u] = this._locate(t, c);
    const b = c.bez, o = 12 * i, v = 1 - u;
    const w0 = v * v * v, w1 = 3 * v * v * u, w2 = 3 * v * u * u, w3 = u * u * u;
    return optionalTarget.set(
      w0 * b[o] + w1 * b[o + 3] + w2 * b[o + 6] + w3 * b[o + 9],
      w0 * b[o + 1] + w1 * b[o + 4] + w2 * b[o + 7] + w3 * b[o + 10],
      w0 * b[o + 2] + w1 * b[o + 5] + w2 * b[o + 8] + w3 * b[o + 11]);
  }

  /// The unit tangent, from the exact derivative (at a zero-speed point,
  /// the direction of the first non-zero higher derivative: the limit).
  getTangent(t, optionalTarget = new Vector3()) {
    const c = this._data();
    const [i, u] = this._locate(t, c);
    const b = c.bez, o = 12 * i, v = 1 - u;
    const d = [0, 0, 0];
    for (let k = 0; k < 3; ++k) {
      const d0 = b[o + 3 + k] - b[o + k], d1 = b[o + 6 + k] - b[o + 3 + k], d2 = b[o + 9 + k] - b[o + 6 + k];
      d[k] = v * v * d0 + 2 * v * u * d1 + u * u * d2;
      if (!Number.isFinite(d[k])) d[k] = 0;
    }
    if (d[0] === 0 && d[1] === 0 && d[2] === 0) {
      for (let k = 0; k < 3; ++k) {
        const d0 = b[o + 3 + k] - b[o + k], d1 = b[o + 6 + k] - b[o + 3 + k], d2 = b[o + 9 + k] - b[o + 6 + k];
        d[k] = v * (d1 - d0) + u * (d2 - d1);
      }
      if (d[0] === 0 && d[1] === 0 && d[2] === 0)
        for (let k = 0; k < 3; ++k) d[k] = b[o + 9 + k] - 3 * b[o + 6 + k] + 3 * b[o + 3 + k] - b[o + k];
    }
    return optionalTarget.set(d[0], d[1], d[2]).normalize();
  }

  getLength() { return this._data().length; }

  /// three.js' Curve.getLengths: the cumulative chord lengths of the
  /// polyline through getPoint(k / divisions), k = 0..divisions (so its last
  /// entry falls short of getLength() by the polyline's error). Cached in
  /// cacheArcLengths as three.js does: the same array comes back until
  /// `divisions` changes, needsUpdate is set or the curve is rebuilt.
  getLengths(divisions = this.arcLengthDivisions) {
    const stale = this.needsUpdate;
    const c = this._data();  // rebuilds on needsUpdate (and clears it), or on a new points array
    const cache = this.cacheArcLengths;
    if (cache && cache.length === divisions + 1 && !stale && this._lengthsOf === c) return cache;
    const out = [0];
    const last = this.getPoint(0), current = new Vector3();
    let sum = 0;
    for (let p = 1; p <= divisions; ++p) {
      this.getPoint(p / divisions, current);
      sum += current.distanceTo(last);
      out.push(sum);
      last.copy(current);
    }
    this.cacheArcLengths = out;
    this._lengthsOf = c;
    return out;
  }

  updateArcLengths() {
    this.needsUpdate = true;
    this.getLengths();
  }

  /// The t at which the arc length from the start is u * getLength() (or
  /// `distance`), through crspline's arc length. As in three.js, a distance
  /// of 0 or null means "use u".
  getUtoTmapping(u, distance = null) {
    const c = this._data();
    const s = distance ? distance : u * c.length;
    const T = c.curve.tAtArcLength(Math.min(Math.max(s, 0), c.length));
    const g = c.grid;
    // The segment of T: binary search in the knots.
    let lo = 0, hi = c.nseg - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (g[mid] <= T) lo = mid; else hi = mid - 1;
    }
    return Math.min(1, (lo + (T - g[lo]) / (g[lo + 1] - g[lo])) / c.nseg);
  }

  copy(source) {
    super.copy(source);
    this.points = source.points.map((p) => p.clone());
    this.closed = source.closed;
    this.curveType = source.curveType;
    this.tension = source.tension;
    this.needsUpdate = true;
    return this;
  }

  toJSON() {
    const data = super.toJSON();
    data.points = this.points.map((p) => p.toArray());
    data.closed = this.closed;
    data.curveType = this.curveType;
    data.tension = this.tension;
    return data;
  }

  fromJSON(json) {
    super.fromJSON(json);
    this.points = json.points.map((p) => new Vector3().fromArray(p));
    this.closed = json.closed;
    this.curveType = json.curveType;
    this.tension = json.tension;
    this.needsUpdate = true;
    return this;
  }
}
