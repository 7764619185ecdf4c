// Drawing, in CSS pixels relative to the view origin (see state.mjs's
// `view`): the grid, the base picture (control polygon, curve, Bézier
// handles, control points), the drag layer that keeps long drags smooth,
// and the overlays (bounding volumes, comb, ticks, cusps, crossings, the
// selection and the marquee). Reads the state; changes only the drag
// layer's record (state.mjs's `frames`).
import { canvas, ctx } from './dom.mjs';
import { clipPen, allInside } from './clip.mjs';
import {
  state, view, session, built, cache, analysis, frames, ys, SX, SY, count, globalCurrent, layerWanted, screenBuffer, setFrames,
} from './state.mjs';

const colors = {
  curve: '#1f5fbf', polygon: '#9aa3b5', handle: '#e08a1e', point: '#c0392b', selected: '#111',
  cusp: '#d81b60', crossing: '#8e24aa', volume: 'rgba(46, 160, 67, 0.13)', volumeEdge: 'rgba(46, 160, 67, 0.55)',
  comb: 'rgba(0, 150, 136, 0.55)', tick: '#37474f', grid: '#eceff4', axis: '#d5dae3',
};

// The canvas' backing store follows its CSS size times the pixel ratio.
function resize() {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(1, Math.round(canvas.clientWidth * dpr)), h = Math.max(1, Math.round(canvas.clientHeight * dpr));
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  return dpr;
}

// Flat world x, y -> flat screen x, y (a reused buffer per use).
export function toScreen(src, key) {
  const { out } = screenBuffer(key, src.length);
  const x0 = view.x0, y0 = view.y0, s = view.s, t = view.s * ys();
  for (let i = 0; i < src.length; i += 2) { out[i] = (src[i] - x0) * s; out[i + 1] = (src[i + 1] - y0) * t; }
  return out;
}

// A "nice" grid step (1, 2 or 5 times a power of ten) about 40 px wide.
export function gridStep() {
  const raw = 40 / view.s, p = 10 ** Math.floor(Math.log10(raw)), m = raw / p;
  return (m < 2 ? 2 : m < 5 ? 5 : 10) * p;
}

function drawGrid(ctx, w, h) {
  const step = gridStep();
  const path = new Path2D(), axes = new Path2D();
  const xa = view.x0, xb = view.x0 + w / view.s;
  const ya = Math.min(view.y0, view.y0 + (h / view.s) * ys()), yb = Math.max(view.y0, view.y0 + (h / view.s) * ys());
  for (let i = Math.ceil(xa / step); i * step <= xb; ++i) {
    const x = Math.round(SX(i * step)) + 0.5;
    (i === 0 ? axes : path).moveTo(x, 0); (i === 0 ? axes : path).lineTo(x, h);
  }
  for (let i = Math.ceil(ya / step); i * step <= yb; ++i) {
    const y = Math.round(SY(i * step)) + 0.5;
    (i === 0 ? axes : path).moveTo(0, y); (i === 0 ? axes : path).lineTo(w, y);
  }
  ctx.lineWidth = 1;
  ctx.strokeStyle = colors.grid;
  ctx.stroke(path);
  ctx.strokeStyle = colors.axis;
  ctx.stroke(axes);
}

// Which parts of the base picture (polygon edges, curve segments, control
// points) to draw: every one (null), every one but those in `skip`, or only
// those in `only`.
const every = { only: null, skip: null };
function* indices(n, part) {
  if (part.only) { for (const i of part.only) if (i >= 0 && i < n) yield i; return; }
  for (let i = 0; i < n; ++i) if (!part.skip || !part.skip.has(i)) yield i;
}

// The base picture: the control polygon, the curve (and its Bézier handles)
// and the control points, in that order (the comb between polygon and curve
// when on). Edge i joins points i and i + 1 (the last edge of a closed
// curve wraps).
function drawBase(c, P, B, parts, showComb) {
  const n = P.length / 2, nb = B.length / 8, o = state.overlays;
  if (o.polygon && n >= 2) {
    const ne = state.opts.closed ? n : n - 1;
    const path = new Path2D(), pen = clipPen(path, parts.edges === every && allInside(P));
    for (const i of indices(ne, parts.edges)) {
      const j = (i + 1) % n;
      pen.line(P[2 * i], P[2 * i + 1], P[2 * j], P[2 * j + 1]);
    }
    if (n <= 2000) c.setLineDash([4, 4]);  // dashing 10^4 edges costs more than the curve
    c.strokeStyle = colors.polygon;
    c.lineWidth = 1;
    c.stroke(path);
    c.setLineDash([]);
  }
  if (showComb) drawComb();
  // The curve: one path of cubic Béziers.
  if (nb > 0) {
    const path = new Path2D(), pen = clipPen(path, parts.segments === every && allInside(B));
    for (const i of indices(nb, parts.segments)) {
      const k = 8 * i;
      pen.cubic(B[k], B[k + 1], B[k + 2], B[k + 3], B[k + 4], B[k + 5], B[k + 6], B[k + 7], 0);
    }
    c.strokeStyle = colors.curve;
    // Past a few thousand segments a 1-pixel line (Skia's hairline path)
    // rasterizes several times faster than a thick stroke.
    c.lineWidth = nb > 2000 ? 1 : 2.5;
    c.stroke(path);
  }
  if (o.handles && nb > 0) {
    const lines = new Path2D(), dots = new Path2D(), r = 2.5, pen = clipPen(lines);
    for (const i of indices(nb, parts.segments)) {
      const k = 8 * i;
      pen.line(B[k], B[k + 1], B[k + 2], B[k + 3]);
      pen.line(B[k + 6], B[k + 7], B[k + 4], B[k + 5]);
      dots.rect(B[k + 2] - r, B[k + 3] - r, 2 * r, 2 * r);
      dots.rect(B[k + 4] - r, B[k + 5] - r, 2 * r, 2 * r);
    }
    c.strokeStyle = colors.handle;
    c.lineWidth = 1;
    c.stroke(lines);
    c.fillStyle = colors.handle;
    c.fill(dots);
  }
  // Control points.
  if (n > 0) {
    c.fillStyle = colors.point;
    if (n > 2000) {
      // Many points: fillRect each (one path of 10^4 squares fills slower),
      // those in view only; past 20 000 in view they are closer than the
      // pixels and the curve through them shows where they are.
      const W = canvas.clientWidth, H = canvas.clientHeight;
      const visible = parts.visible ?? visibleCount(P);
      if (visible <= 20000) {
        for (const i of indices(n, parts.points)) {
          const x = P[2 * i], y = P[2 * i + 1];
          if (x >= -2 && x <= W + 2 && y >= -2 && y <= H + 2) c.fillRect(x - 1, y - 1, 2, 2);
        }
      }
    } else {
      const r = 4, path = new Path2D();
      for (const i of indices(n, parts.points)) path.rect(P[2 * i] - r, P[2 * i + 1] - r, 2 * r, 2 * r);
      c.fill(path);
    }
  }
}

function visibleCount(P) {
  const W = canvas.clientWidth, H = canvas.clientHeight;
  let visible = 0;
  for (let i = 0; i < P.length; i += 2) { const x = P[i], y = P[i + 1]; if (x >= -2 && x <= W + 2 && y >= -2 && y <= H + 2) ++visible; }
  return visible;
}

// The drag layer. While points of a long curve are dragged, what the drag
// cannot change (the grid and the polygon, curve and points away from the
// dragged points: a segment depends on four points, so dragging point k
// moves segments k-2 .. k+1, edges k-1 and k) is drawn once into an
// offscreen canvas; each frame copies it and draws the few parts that move.
// Only without the comb and the bounding volumes (drawn between the base
// parts), and while the view stays as it was.
function movingParts(idx) {
  const n = count(), closed = state.opts.closed, nseg = closed ? n : n - 1;
  const segments = new Set(), edges = new Set();
  const wrap = (i, m) => (closed ? ((i % m) + m) % m : i);
  for (const k of idx) {
    for (let i = k - 2; i <= k + 1; ++i) { const j = wrap(i, nseg); if (j >= 0 && j < nseg) segments.add(j); }
    for (let i = k - 1; i <= k; ++i) { const j = wrap(i, nseg); if (j >= 0 && j < nseg) edges.add(j); }
  }
  return { segments, edges, points: new Set(idx) };
}
function layerKey(dpr) {
  const o = state.overlays;
  return [canvas.width, canvas.height, dpr, view.s, view.x0, view.y0, view.yUp, state.grid, o.polygon, o.handles,
    state.opts.closed, count(), built.bez.length, session.drag && session.drag.idx.join(',')].join('|');
}
// Flat world coordinates -> screen, only for items `idx` (stride numbers
// each) of a buffer that toScreen filled for the same array length.
function toScreenAt(src, key, stride, idx) {
  const { out, fresh } = screenBuffer(key, src.length);
  if (fresh) return toScreen(src, key);
  const x0 = view.x0, y0 = view.y0, s = view.s, t = view.s * ys();
  for (const i of idx) for (let j = i * stride; j < (i + 1) * stride; j += 2) { out[j] = (src[j] - x0) * s; out[j + 1] = (src[j + 1] - y0) * t; }
  return out;
}

export function draw() {
  const dpr = resize();
  const n = count(), o = state.overlays;
  // With the drag layer drawn for this view, only the moving parts (and the
  // selection) need screen coordinates.
  const bez = built.bez, drag = session.drag, global = analysis.global;
  const reuse = layerWanted() && frames.layer && frames.layer.key === layerKey(dpr);
  let P, B;
  if (reuse) {
    const m = frames.layer.parts, ids = new Set([...m.points, ...state.sel]);
    for (const e of m.edges) { ids.add(e); ids.add((e + 1) % n); }
    P = toScreenAt(state.pts, 'pts', 2, ids);
    B = toScreenAt(bez, 'bez', 8, m.segments);
  } else {
    P = toScreen(state.pts, 'pts');
    B = toScreen(bez, 'bez');
  }
  const fresh = globalCurrent();
  const g = global && !global.error ? global : null;
  const clear = (c) => {
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.fillStyle = '#fff';
    c.fillRect(0, 0, canvas.width, canvas.height);
    c.setTransform(dpr, 0, 0, dpr, 0, 0);
    c.lineJoin = 'round';
    c.lineCap = 'round';
  };
  let moving = null;
  if (layerWanted()) {
    const key = layerKey(dpr);
    let layer = frames.layer;
    if (!layer || layer.key !== key) {
      // Drawn at the first frame of the drag (or after a zoom during it).
      const lc = layer && layer.canvas.width === canvas.width && layer.canvas.height === canvas.height
        ? layer.canvas : Object.assign(document.createElement('canvas'), { width: canvas.width, height: canvas.height });
      const parts = movingParts(drag.idx), c2 = lc.getContext('2d');
      clear(c2);
      if (state.grid) drawGrid(c2, canvas.clientWidth, canvas.clientHeight);
      drawBase(c2, P, B, { edges: { skip: parts.edges }, segments: { skip: parts.segments }, points: { skip: parts.points } }, false);
      layer = { canvas: lc, key, parts: { ...parts, visible: visibleCount(P) } };
      setFrames({ layer });
    }
    moving = layer.parts;
  } else {
    setFrames({ layer: null });
  }
  if (moving) {
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(frames.layer.canvas, 0, 0);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.lineJoin = 'round';
    ctx.lineCap = 'round';
    setFrames({ layerFrames: frames.layerFrames + 1 });
  } else {
    clear(ctx);
    if (state.grid) drawGrid(ctx, canvas.clientWidth, canvas.clientHeight);
  }

  // Bounding volumes first (under everything).
  if (o.volumes && g && g.volumes) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    drawVolumes(g.volumes);
    ctx.globalAlpha = 1;
  }
  const only = (set) => ({ only: set });
  drawBase(ctx, P, B, moving ? { edges: only(moving.edges), segments: only(moving.segments), points: only(moving.points), visible: moving.visible }
    : { edges: every, segments: every, points: every }, o.comb && cache.comb);
  if (o.ticks && g && g.ticks) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    const t = g.ticks, m = t.length / 4, path = new Path2D(), L = 5, k = ys();
    for (let j = 0; j < m; ++j) {
      const x = SX(t[2 * j]), y = SY(t[2 * j + 1]), tx = t[2 * (m + j)], ty = t[2 * (m + j) + 1] * k;
      path.moveTo(x - ty * L, y + tx * L);
      path.lineTo(x + ty * L, y - tx * L);
    }
    ctx.strokeStyle = colors.tick;
    ctx.lineWidth = 1.2;
    ctx.stroke(path);
    ctx.globalAlpha = 1;
  }
  if (state.sel.size) {
    ctx.strokeStyle = colors.selected;
    ctx.lineWidth = 1.5;
    for (const s of state.sel) if (s < n) ctx.strokeRect(P[2 * s] - 7, P[2 * s + 1] - 7, 14, 14);
  }
  if (o.cusps && cache.cusps) {
    const path = new Path2D(), r = 6;
    for (const c of cache.cusps) {
      if (!c) continue;
      for (let k = 0; k < c.length; k += 2) { const x = SX(c[k]), y = SY(c[k + 1]); path.moveTo(x + r, y); path.arc(x, y, r, 0, 2 * Math.PI); }
    }
    ctx.strokeStyle = colors.cusp;
    ctx.lineWidth = 2.5;
    ctx.stroke(path);
  }
  if (o.intersections && g && g.intersections) {
    ctx.globalAlpha = fresh ? 1 : 0.4;
    const X = g.intersections, path = new Path2D(), r = 6;
    for (let k = 0; k < X.length; k += 2) {
      const x = SX(X[k]), y = SY(X[k + 1]);
      path.moveTo(x - r, y - r); path.lineTo(x + r, y + r);
      path.moveTo(x - r, y + r); path.lineTo(x + r, y - r);
    }
    ctx.strokeStyle = colors.crossing;
    ctx.lineWidth = 2.5;
    ctx.stroke(path);
    ctx.globalAlpha = 1;
  }
  if (drag && drag.kind === 'marquee') {
    const [ax, ay, bx, by] = drag.rect;
    ctx.setLineDash([3, 3]);
    ctx.strokeStyle = colors.selected;
    ctx.lineWidth = 1;
    ctx.strokeRect(Math.min(ax, bx) + 0.5, Math.min(ay, by) + 0.5, Math.abs(bx - ax), Math.abs(by - ay));
    ctx.setLineDash([]);
  }
}

function drawVolumes(v) {
  const boxes = new Path2D(), S = v.boxStride;
  for (let k = 0; k + S <= v.boxes.length; k += S) {
    const b = v.boxes;
    const ax = b[k + 1], ay = b[k + 2], bx = b[k + 3], by = b[k + 4], l0 = b[k + 5], l1 = b[k + 6], w = b[k + 7];
    const dx = bx - ax, dy = by - ay, L = Math.hypot(dx, dy);
    if (!(L > 0) || !Number.isFinite(w)) continue;
    const nx = -dy / L * w, ny = dx / L * w;
    const p0x = ax + l0 * dx, p0y = ay + l0 * dy, p1x = ax + l1 * dx, p1y = ay + l1 * dy;
    boxes.moveTo(SX(p0x + nx), SY(p0y + ny));
    boxes.lineTo(SX(p1x + nx), SY(p1y + ny));
    boxes.lineTo(SX(p1x - nx), SY(p1y - ny));
    boxes.lineTo(SX(p0x - nx), SY(p0y - ny));
    boxes.closePath();
  }
  for (let k = 0; k + v.ballStride <= v.balls.length; k += v.ballStride) {
    const x = SX(v.balls[k + 1]), y = SY(v.balls[k + 2]), r = v.balls[k + 3] * view.s;
    if (!Number.isFinite(r)) continue;
    boxes.moveTo(x + r, y);
    boxes.arc(x, y, r, 0, 2 * Math.PI);
  }
  ctx.fillStyle = colors.volume;
  ctx.fill(boxes, 'nonzero');
  ctx.strokeStyle = colors.volumeEdge;
  ctx.lineWidth = 1;
  ctx.stroke(boxes);
}

function drawComb() {
  // Teeth point away from the centre of curvature, with length proportional
  // to the curvature: the 90th percentile of |k| gets 30 px times twice the
  // comb slider; the rare huge values (near cusps) are clipped at twice that.
  const ks = [];
  for (const c of cache.comb) for (let j = 4; j < c.length; j += 5) if (Number.isFinite(c[j])) ks.push(Math.abs(c[j]));
  if (!ks.length) return;
  ks.sort((a, b) => a - b);
  const k90 = ks[Math.floor(0.9 * (ks.length - 1))] || ks[ks.length - 1];
  if (!(k90 > 0)) return;
  const scale = (60 * state.combScale) / k90, kmax = 2 * k90, sg = ys();
  const teeth = new Path2D(), hull = new Path2D();
  for (const c of cache.comb) {
    for (let j = 0; j < c.length; j += 5) {
      const k = Math.max(-kmax, Math.min(kmax, c[j + 4]));
      const x = SX(c[j]), y = SY(c[j + 1]);
      const tx = x - c[j + 2] * k * scale, ty = y - c[j + 3] * sg * k * scale;
      teeth.moveTo(x, y);
      teeth.lineTo(tx, ty);
      if (j === 0) hull.moveTo(tx, ty); else hull.lineTo(tx, ty);
    }
  }
  ctx.strokeStyle = colors.comb;
  ctx.lineWidth = 1;
  ctx.stroke(teeth);
  ctx.stroke(hull);
}


