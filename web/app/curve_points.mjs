// Points under the pointer and on the curve: the control point under a
// screen position, the nearest point of the curve (in the view's plane for
// a projected curve), and a new point in the middle of a segment.
import { state, view, built, ys, count, splitOne, edit, insertPoint } from './state.mjs';
import { toWorld } from './view.mjs';

// The point under screen position (px, py) within r CSS px: compared in
// screen space (the differences are small, exact enough far from 0).
export function hit(px, py, r = 9) {
  const P = state.pts, n = count(), k = view.s * ys();
  let best = -1, bd = r * r;
  for (let i = 0; i < n; ++i) {
    const dx = (P[2 * i] - view.x0) * view.s - px, dy = (P[2 * i + 1] - view.y0) * k - py, d = dx * dx + dy * dy;
    if (d <= bd) { bd = d; best = i; }
  }
  return best;
}
// The nearest curve point to screen (px, py) if within r px: { segment,
// point: [x, y], rest }. A projected curve is searched in the view's plane
// (nearestProjected), then evaluated with every coordinate.
export function nearCurve(px, py, r) {
  const spline = built.spline;
  if (!spline) return null;
  if (state.dim === 2) {
    const near = spline.nearest(toWorld(px, py));
    return Math.sqrt(near.distanceSq) * view.s <= r ? { segment: near.segment, point: near.point, rest: null } : null;
  }
  const near = nearestProjected(built.bez, toWorld(px, py), r / view.s);
  if (!near) return null;
  const g = spline.grid(), t = g[near.segment] + near.u * (g[near.segment + 1] - g[near.segment]);
  const [xy, rest] = splitOne(spline.evaluate(Math.min(t, spline.tMax())));
  return { segment: near.segment, point: xy, rest };
}
// The nearest point within `within` (world units) of q on the plane
// Béziers `b` (8 numbers per segment): { segment, u } or null. Segments
// whose control hull is farther are skipped; the rest sampled, then the
// best sample refined by bisection on u.
function nearestProjected(b, q, within) {
  const at = (k, u) => {
    const v = 1 - u, c0 = v * v * v, c1 = 3 * v * v * u, c2 = 3 * v * u * u, c3 = u * u * u;
    return [c0 * b[k] + c1 * b[k + 2] + c2 * b[k + 4] + c3 * b[k + 6], c0 * b[k + 1] + c1 * b[k + 3] + c2 * b[k + 5] + c3 * b[k + 7]];
  };
  const d2 = (k, u) => { const p = at(k, u); return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2; };
  let best = null, bd = within * within;
  for (let i = 0; i < b.length / 8; ++i) {
    const k = 8 * i;
    const xa = Math.min(b[k], b[k + 2], b[k + 4], b[k + 6]), xb = Math.max(b[k], b[k + 2], b[k + 4], b[k + 6]);
    const ya = Math.min(b[k + 1], b[k + 3], b[k + 5], b[k + 7]), yb = Math.max(b[k + 1], b[k + 3], b[k + 5], b[k + 7]);
    const dx = Math.max(xa - q[0], 0, q[0] - xb), dy = Math.max(ya - q[1], 0, q[1] - yb);
    if (dx * dx + dy * dy > bd) continue;
    const m = 32;
    let u0 = 0, du = 1 / m, e0 = Infinity;
    for (let j = 0; j <= m; ++j) { const e = d2(k, j / m); if (e < e0) { e0 = e; u0 = j / m; } }
    for (let it = 0; it < 40; ++it) {
      du /= 2;
      const ea = d2(k, Math.max(0, u0 - du)), eb = d2(k, Math.min(1, u0 + du));
      if (ea < e0 && ea <= eb) { e0 = ea; u0 = Math.max(0, u0 - du); } else if (eb < e0) { e0 = eb; u0 = Math.min(1, u0 + du); }
    }
    if (e0 <= bd) { bd = e0; best = { segment: i, u: u0 }; }
  }
  return best;
}

// The point after `k` on the curve: the middle (in t) of segment k, or past
// the end of an open curve.
export function insertAfter(k) {
  const spline = built.spline;
  const n = count();
  if (n === 0) return;
  if (k < 0) k = n - 1;
  edit(() => {
    const nseg = spline ? spline.segmentCount() : 0;
    if (spline && k < nseg) {
      const g = spline.grid();
      const p = spline.evaluate((g[k] + g[k + 1]) / 2);
      const [xy, rest] = splitOne(p);
      insertPoint(k + 1, xy[0], xy[1], rest);
    } else {
      const x = state.pts[2 * k], y = state.pts[2 * k + 1];
      const dx = n > 1 ? x - state.pts[2 * k - 2] : 40 / view.s, dy = n > 1 ? y - state.pts[2 * k - 1] : 0;
      insertPoint(k + 1, x + dx / 2, y + dy / 2);
    }
  });
}
