// crspline as a d3-shape curve factory:
//
//   import * as d3 from 'd3-shape';
//   import { init } from 'crspline';
//   import { crsplineCurve } from 'crspline/d3';
//   await init();
//   d3.line().curve(crsplineCurve.alpha(0.5))(data);
//
// Each line d3 hands to the curve becomes one crspline curve, and its exact
// cubic Bézier segments (crspline's Bézier form) go to d3's path context with
// bezierCurveTo. Works with d3.line(), d3.area(), d3.lineRadial() and a
// canvas context. No import of d3: the factory follows d3's curve protocol
// (lineStart, point, lineEnd, areaStart, areaEnd).
//
// Three factories mirror d3's:
//   crsplineCurve        open curve through every point
//   crsplineCurveClosed  closed loop (starts at the first point, ends with Z)
//   crsplineCurveOpen    d3's "open" variant: the first and last points only
//                        steer, the path runs from the second to the
//                        next-to-last
// and each has .alpha(a) (0 uniform, 0.5 centripetal (default, as in d3),
// 1 chordal) and .ends(e) for the two ends of an open curve:
//   'natural' (crspline's default: zero second derivative),
//   'd3'      (d3's curveCatmullRom: zero-length end handles),
//   'reflect' (three.js: phantom points 2 P0 - P1).
import { catmullRom } from './index.js';

const ENDS = new Set(['natural', 'd3', 'reflect']);

class CRSplineD3 {
  constructor(context, kind, alpha, ends) {
    this._context = context;
    this._kind = kind;
    this._alpha = alpha;
    this._ends = ends;
  }

  areaStart() { this._line = 0; }
  areaEnd() { this._line = NaN; }
  lineStart() { this._x = []; this._y = []; }
  point(x, y) {
    this._x.push(+x);
    this._y.push(+y);
  }

  lineEnd() {
    const ctx = this._context, x = this._x, y = this._y;
    const n = x.length;
    // d3's own bookkeeping: in an area the second line joins the first
    // (lineTo) and closes it; a lone point of a line closes on itself.
    const join = (i) => (this._line ? ctx.lineTo(x[i], y[i]) : ctx.moveTo(x[i], y[i]));
    if (this._kind === 'closed') {
      if (n > 0) ctx.moveTo(x[0], y[0]);
      if (n === 2) ctx.lineTo(x[1], y[1]);
      if (n >= 3) this._segments(0, n);
      if (n > 0) ctx.closePath();
      return;
    }
    if (this._kind === 'interior') {
      if (n >= 3) join(1);
      if (n >= 4) this._segments(1, n - 3);
      if (this._line || (this._line !== 0 && n === 3)) ctx.closePath();
      this._line = 1 - this._line;
      return;
    }
    if (n > 0) join(0);
    if (n === 2) ctx.lineTo(x[1], y[1]);
    if (n >= 3) this._segments(0, n - 1);
    if (this._line || (this._line !== 0 && n === 1)) ctx.closePath();
    this._line = 1 - this._line;
  }

  // Segments first .. first + count - 1 of the curve through the buffered
  // points, as bezierCurveTo from the current point.
  _segments(first, count) {
    const x = this._x, y = this._y, n = x.length;
    const points = new Float64Array(2 * n);
    for (let i = 0; i < n; ++i) {
      points[2 * i] = x[i];
      points[2 * i + 1] = y[i];
    }
    const options = { dimension: 2, alpha: this._alpha, closed: this._kind === 'closed' };
    if (!options.closed) {
      const end = this._ends === 'd3' ? { tangent: [0, 0] } : this._ends;
      options.start = end;
      options.end = end;
    }
    const curve = catmullRom(points, options);
    try {
      const b = curve.bezier();
      for (let i = first; i < first + count; ++i) {
        const o = 8 * i;
        this._context.bezierCurveTo(b[o + 2], b[o + 3], b[o + 4], b[o + 5], b[o + 6], b[o + 7]);
      }
    } finally {
      curve.dispose();
    }
  }
}

function factory(kind, alpha, ends) {
  const curve = (context) => new CRSplineD3(context, kind, alpha, ends);
  curve.alpha = (a) => {
    const v = +a;
    if (!(v >= 0 && v <= 1)) throw Object.assign(new Error(`alpha must be in [0, 1], got ${a}`), { field: 'alpha', index: null, component: null, value: String(a) });
    return factory(kind, v, ends);
  };
  curve.ends = (e) => {
    if (!ENDS.has(e)) throw Object.assign(new Error(`ends must be 'natural', 'd3' or 'reflect', got '${e}'`), { field: 'ends', index: null, component: null, value: String(e) });
    return factory(kind, alpha, e);
  };
  return curve;
}

export const crsplineCurve = factory('open', 0.5, 'natural');
export const crsplineCurveClosed = factory('closed', 0.5, 'natural');
export const crsplineCurveOpen = factory('interior', 0.5, 'natural');
