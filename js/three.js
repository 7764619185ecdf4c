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
import { BufferGeometry, CatmullRomCurve3, CubicBezierCurve3, Curve, Float32BufferAttribute, LineCurve3, QuadraticBezierCurve3,
  Quaternion, Uint32BufferAttribute, Vector3 } from 'three';
import { catmullRom, poseCurve, quaternionSpline, rotationSpline, sweep } from './index.js';

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

// ---------------------------------------------------------------------------
// Rotations (issue 28). three.js' Quaternion is (x, y, z, w); crspline's
// core is [w, x, y, z]: the conversion happens here, in both directions, so
// users hand in and get back THREE.Quaternion (or [x, y, z, w] arrays, as
// Quaternion.toArray writes them). The parameter is three.js' u in [0, 1],
// mapped linearly onto the curve's own t (rates are per unit u).
// ---------------------------------------------------------------------------

// THREE.Quaternion or [x, y, z, w] -> crspline's flat [w, x, y, z].
function wxyzOf(quaternions, what) {
  if (!Array.isArray(quaternions)) throw Object.assign(new Error(`${what} must be an array of THREE.Quaternion or [x, y, z, w]`), { field: what, index: null, component: null, value: '' });
  const flat = new Float64Array(4 * quaternions.length);
  quaternions.forEach((q, i) => {
    const a = q && q.isQuaternion ? [q.x, q.y, q.z, q.w] : q;
    if (!a || a.length !== 4)
      throw Object.assign(new Error(`${what}[${i}] must be a THREE.Quaternion or [x, y, z, w]`), { field: what, index: i, component: null, value: JSON.stringify(q) });
    flat[4 * i] = a[3]; flat[4 * i + 1] = a[0]; flat[4 * i + 2] = a[1]; flat[4 * i + 3] = a[2];
  });
  return flat;
}

const toThree = (q, target) => target.set(q[1], q[2], q[3], q[0]);

/// A rotation curve through THREE.Quaternion keys: crspline's quaternion
/// Catmull-Rom family (options as quaternionSpline: kind, alpha, closed,
/// ...), or with options.times the C2 spline (rotationSpline's options).
export class CRSplineQuaternionCurve {
  constructor(quaternions = [], options = {}) {
    this.isCRSplineQuaternionCurve = true;
    this.type = 'CRSplineQuaternionCurve';
    const { times, ...rest } = options;
    const keys = wxyzOf(quaternions, 'quaternions');
    this.curve = times ? rotationSpline(times, keys, rest) : quaternionSpline(keys, rest);
    this._t0 = this.curve.tMin;
    this._span = this.curve.tMax - this._t0;
  }
  /// u in [0, 1] -> the curve's t.
  tAt(u) { return this._t0 + Math.min(Math.max(u, 0), 1) * this._span; }
  /// The rotation at u.
  getQuaternion(u, optionalTarget = new Quaternion()) {
    return toThree(this.curve.quaternion(this.tAt(u)), optionalTarget);
  }
  /// The angular velocity at u, rad per unit u, in frame 'world' or 'body'.
  getAngularVelocity(u, optionalTarget = new Vector3(), frame = 'world') {
    const w = this.curve.evaluate(this.tAt(u), 1, frame).omega;
    return optionalTarget.set(w[0], w[1], w[2]).multiplyScalar(this._span);
  }
  dispose() { this.curve.dispose(); }
}

/// A camera path: positions (THREE.Vector3) and orientations
/// (THREE.Quaternion) on one shared grid (crspline's pose curve: centripetal
/// positions, a C2 rotation spline). A three.js Curve of the positions, so
/// TubeGeometry and getPointAt work; getQuaternion gives the orientation and
/// applyTo(object, u) places an Object3D (a camera looks along its -z).
export class CRSplinePoseCurve extends Curve {
  constructor(positions = [], quaternions = [], options = {}) {
    super();
    this.isCRSplinePoseCurve = true;
    this.type = 'CRSplinePoseCurve';
    const flat = new Float64Array(3 * positions.length);
    positions.forEach((p, i) => {
      const a = p && p.isVector3 ? [p.x, p.y, p.z] : p;
      if (!a || a.length !== 3)
        throw Object.assign(new Error(`positions[${i}] must be a THREE.Vector3 or [x, y, z]`), { field: 'positions', index: i, component: null, value: JSON.stringify(p) });
      flat.set(a, 3 * i);
    });
    this.pose = poseCurve(flat, wxyzOf(quaternions, 'quaternions'), options);
    this._t0 = this.pose.tMin;
    this._span = this.pose.tMax - this._t0;
  }
  tAt(u) { return this._t0 + Math.min(Math.max(u, 0), 1) * this._span; }
  getPoint(u, optionalTarget = new Vector3()) {
    const p = this.pose.evaluate(this.tAt(u)).position;
    return optionalTarget.set(p[0], p[1], p[2]);
  }
  getQuaternion(u, optionalTarget = new Quaternion()) {
    return toThree(this.pose.evaluate(this.tAt(u)).orientation, optionalTarget);
  }
  /// Sets object.position and object.quaternion to the pose at u.
  applyTo(object, u) {
    const s = this.pose.evaluate(this.tAt(u));
    object.position.set(s.position[0], s.position[1], s.position[2]);
    toThree(s.orientation, object.quaternion);
    return object;
  }
  /// n values of u at constant speed of positionWeight |dx/dt| + angleWeight |omega|.
  constantSpeedU(n, positionWeight = 1, angleWeight = 0) {
    const t = this.pose.constantSpeedTimes(n, positionWeight, angleWeight);
    return Array.from(t, (x) => (x - this._t0) / this._span);
  }
  dispose() { this.pose.dispose(); }
}

// ---------------------------------------------------------------------------
// Tubes (issue 41): CRSplineTubeGeometry, a drop-in for THREE.TubeGeometry
// (path, tubularSegments, radius, radialSegments, closed) computed by
// crspline's sweep: the same attribute layout (tubularSegments + 1 rings of
// radialSegments + 1 vertices, rings at equal arc length as getPointAt
// places them, uv = (along, around) as three.js has them, the same quads
// split on the same diagonal), with a rotation-minimizing frame whose twist
// on a closed path is spread evenly (no seam: the last ring is the first,
// positions, normals and u), no frame flips, and options three.js lacks:
// a varying radius (scale keys at arc lengths), roll keys and an up vector.
// ---------------------------------------------------------------------------

const PATH_TYPES = { CRSplineCurve3, CatmullRomCurve3, CubicBezierCurve3, LineCurve3, QuadraticBezierCurve3 };
const TUBE_OPTIONS = ['scale', 'scaleS', 'roll', 'rollAt', 'rollS', 'up', 'spreadHolonomy'];

// The crspline curve to sweep: a CRSplineCurve3's own (when its closedness
// is the tube's), else the centripetal curve through the points three.js
// puts its rings on (getSpacedPoints; closed: the last one is the first).
// A tube is closed when `closed` says so or the path is closed: three.js
// then places its last ring on the first too, but with an open frame.
function sweepCurveOf(path, tubularSegments, closed) {
  if (path.isCRSplineCurve3 && Boolean(path.closed) === closed && path.points.length >= 2)
    return { curve: path._data().curve, owned: false };
  const pts = path.getSpacedPoints(Math.max(tubularSegments, 2));
  if (closed) pts.pop();
  const kept = pts.filter((p, i) => i === 0 || !p.equals(pts[i - 1]));
  const flat = new Float64Array(3 * kept.length);
  kept.forEach((p, i) => { flat[3 * i] = p.x; flat[3 * i + 1] = p.y; flat[3 * i + 2] = p.z; });
  return { curve: catmullRom(flat, { dimension: 3, closed }), owned: true };
}

export class CRSplineTubeGeometry extends BufferGeometry {
  constructor(path = new QuadraticBezierCurve3(new Vector3(-1, -1, 0), new Vector3(-1, 1, 0), new Vector3(1, 1, 0)),
    tubularSegments = 64, radius = 1, radialSegments = 8, closed = false, options = {}) {
    super();
    this.isCRSplineTubeGeometry = true;
    this.type = 'CRSplineTubeGeometry';
    this.parameters = { path, tubularSegments, radius, radialSegments, closed, options };
    for (const key of Object.keys(options))
      if (!TUBE_OPTIONS.includes(key))
        throw Object.assign(new Error(`unknown option '${key}' (options are ${TUBE_OPTIONS.join(', ')})`),
          { field: key, index: null, component: null, value: '' });
    const { curve, owned } = sweepCurveOf(path, tubularSegments, Boolean(closed) || path.closed === true);
    let mesh;
    try {
      mesh = sweep(curve, { radius, tubularSegments, radialSegments, clearance: false, ...options });
      // The frames three.js exposes: the tangent, and the normal as the
      // direction of each ring's first vertex (the profile's angle 0).
      this.tangents = [];
      this.normals = [];
      this.binormals = [];
      const m = mesh.ringSize, pos = mesh.positions;
      const X = curve.evaluateMany(mesh.t), D = curve.evaluateMany(mesh.t, 1);
      for (let k = 0; k < mesh.rings; ++k) {
        const T = new Vector3(D[3 * k], D[3 * k + 1], D[3 * k + 2]).normalize();
        const N = new Vector3(pos[3 * k * m] - X[3 * k], pos[3 * k * m + 1] - X[3 * k + 1], pos[3 * k * m + 2] - X[3 * k + 2]);
        N.sub(T.clone().multiplyScalar(N.dot(T))).normalize();
        this.tangents.push(T);
        this.normals.push(N);
        this.binormals.push(new Vector3().crossVectors(T, N));
      }
    } finally {
      if (owned) curve.dispose();
    }
    // uv: three.js has (along, around); the core (around, along).
    const uv = new Float32Array(mesh.uvs.length);
    for (let i = 0; i < uv.length; i += 2) {
      uv[i] = mesh.uvs[i + 1];
      uv[i + 1] = mesh.uvs[i];
    }
    this.setIndex(new Uint32BufferAttribute(mesh.indices, 1));
    this.setAttribute('position', new Float32BufferAttribute(mesh.positions, 3));
    this.setAttribute('normal', new Float32BufferAttribute(mesh.normals, 3));
    this.setAttribute('uv', new Float32BufferAttribute(uv, 2));
    /// The sweep's report (bound, holonomy, seamGap, selfIntersects, ...).
    this.report = mesh.report;
  }

  copy(source) {
    super.copy(source);
    this.parameters = Object.assign({}, source.parameters);
    this.report = source.report;
    return this;
  }

  toJSON() {
    const data = super.toJSON();
    data.path = this.parameters.path.toJSON();
    return data;
  }

  static fromJSON(data) {
    const Path = PATH_TYPES[data.path.type];
    if (!Path)
      throw Object.assign(new Error(`CRSplineTubeGeometry.fromJSON: path type '${data.path.type}' is not one of ${Object.keys(PATH_TYPES).join(', ')}`),
        { field: 'path', index: null, component: null, value: String(data.path.type) });
    return new CRSplineTubeGeometry(new Path().fromJSON(data.path), data.tubularSegments, data.radius,
      data.radialSegments, data.closed, data.options ?? {});
  }
}
