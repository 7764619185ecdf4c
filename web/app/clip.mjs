// Paths clipped to the canvas before they reach it (see clipPen), and the
// test that lets the common case skip clipping.
import { canvas } from './dom.mjs';

// Paths clipped to the canvas (plus a margin) before they reach it: zoomed
// far in, a segment can be 10^6 px long, and Skia flattens (and dashes) all
// of it, which takes seconds. Cubics are split (de Casteljau) until each
// piece is either outside the view, dropped, or under 2048 px; lines are
// clipped (Liang-Barsky). Consecutive pieces continue one subpath.
export function clipPen(path, inside = false) {
  const m = 16, X0 = -m, Y0 = -m, X1 = canvas.clientWidth + m, Y1 = canvas.clientHeight + m;
  let lx = NaN, ly = NaN;  // where the subpath ends now
  const pen = {
    line(ax, ay, bx, by) {
      if (!inside) {
        let t0 = 0, t1 = 1;
        const dx = bx - ax, dy = by - ay;
        // Liang-Barsky against the four sides, without allocating.
        for (let side = 0; side < 4; ++side) {
          const p = side === 0 ? -dx : side === 1 ? dx : side === 2 ? -dy : dy;
          const q = side === 0 ? ax - X0 : side === 1 ? X1 - ax : side === 2 ? ay - Y0 : Y1 - ay;
          if (p === 0) { if (q < 0) return; continue; }
          const r = q / p;
          if (p < 0) { if (r > t1) return; if (r > t0) t0 = r; } else { if (r < t0) return; if (r < t1) t1 = r; }
        }
        if (t0 > 0 || t1 < 1) {
          const sx = ax + t0 * dx, sy = ay + t0 * dy, ex = ax + t1 * dx, ey = ay + t1 * dy;
          path.moveTo(sx, sy); path.lineTo(ex, ey);
          lx = ex; ly = ey;
          return;
        }
      }
      if (ax !== lx || ay !== ly) path.moveTo(ax, ay);
      path.lineTo(bx, by);
      lx = bx; ly = by;
    },
    cubic(x0, y0, x1, y1, x2, y2, x3, y3, depth) {
      const xa = Math.min(x0, x1, x2, x3), xb = Math.max(x0, x1, x2, x3), ya = Math.min(y0, y1, y2, y3), yb = Math.max(y0, y1, y2, y3);
      if (!inside && (xb < X0 || xa > X1 || yb < Y0 || ya > Y1)) return;  // outside: the hull contains the curve
      if ((xb - xa < 2048 && yb - ya < 2048) || depth > 40) {
        if (x0 !== lx || y0 !== ly) path.moveTo(x0, y0);
        // A piece whose hull fits in a quarter pixel is drawn as its chord:
        // the same pixels, far fewer for Skia to flatten at 10^5 segments.
        if (xb - xa < 0.25 && yb - ya < 0.25) path.lineTo(x3, y3);
        else path.bezierCurveTo(x1, y1, x2, y2, x3, y3);
        lx = x3; ly = y3;
        return;
      }
      const ax = (x0 + x1) / 2, ay = (y0 + y1) / 2, bx = (x1 + x2) / 2, by = (y1 + y2) / 2, cx = (x2 + x3) / 2, cy = (y2 + y3) / 2;
      const dx = (ax + bx) / 2, dy = (ay + by) / 2, ex = (bx + cx) / 2, ey = (by + cy) / 2, fx = (dx + ex) / 2, fy = (dy + ey) / 2;
      pen.cubic(x0, y0, ax, ay, dx, dy, fx, fy, depth + 1);
      pen.cubic(fx, fy, ex, ey, cx, cy, x3, y3, depth + 1);
    },
  };
  return pen;
}

// Whether every coordinate of a flat screen array is within the canvas (the
// common case: then nothing needs clipping).
export function allInside(a) {
  const X1 = canvas.clientWidth, Y1 = canvas.clientHeight;
  for (let i = 0; i < a.length; i += 2) if (!(a[i] >= 0 && a[i] <= X1 && a[i + 1] >= 0 && a[i + 1] <= Y1)) return false;
  return true;
}
