// Sample data: the demo polygon and the stress test's spiral, placed in the
// visible area at zoom 1.
import { canvas } from './dom.mjs';
import { toWorld, resetView } from './view.mjs';
import { setPoints } from './state.mjs';

// The demo: a polygon with a sharp turn and a crossing, in the visible area.
export function loadDemo() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  const rel = [[0.08, 0.7], [0.2, 0.25], [0.36, 0.2], [0.42, 0.72], [0.3, 0.8], [0.55, 0.45], [0.62, 0.5], [0.66, 0.15], [0.8, 0.3], [0.93, 0.75]];
  resetView();
  setPoints(Float64Array.from(rel.flatMap(([u, v]) => toWorld(u * w, v * h))));
}

// n points on a spiral filling the view (seeded wobble): the stress test.
export function loadStress(n) {
  const w = canvas.clientWidth, h = canvas.clientHeight, R = 0.46 * Math.min(w, h);
  let seed = 12345;
  const rnd = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const a = new Float64Array(2 * n);
  resetView();
  for (let i = 0; i < n; ++i) {
    const t = i / n, ang = t * 2 * Math.PI * 40, r = R * (0.08 + 0.92 * t) * (1 + 0.01 * (rnd() - 0.5));
    const [x, y] = toWorld(w / 2 + r * Math.cos(ang), h / 2 + r * Math.sin(ang));
    a[2 * i] = x; a[2 * i + 1] = y;
  }
  setPoints(a);
}
