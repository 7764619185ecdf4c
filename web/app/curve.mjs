// The curve of the current points, built by the WASM module at most once a
// version, and its per-segment caches (lengths for the status line, cusps,
// the curvature comb): dragging point i recomputes only the segments
// i-2 .. i+1 it moves. The results live in state.mjs (built, cache).
import { M } from './wasm.mjs';
import { splineOptions } from './io.mjs';
import {
  state, session, built, cache, dirty, lenBlocks, count, fullPoints, project, layerWanted,
  setBuilt, setSegmentBezier, setCache, setCacheEntry, setLenBlocks, setLenBlock, clearDirty,
} from './state.mjs';
import { requestGlobal } from './analysis.mjs';

const COMB_PER_SEGMENT = 12;

// While the drag layer draws (see draw.mjs), only the segments the drag
// moves are read back from the new curve (bezier(i), a few numbers) instead
// of every segment (bezierAll, 64 bytes a segment); the others keep theirs,
// which differ from the new curve's by rounding at most (their knot
// intervals and points did not change). Once the drag ends, the whole.
export function rebuild() {
  if (built.version === session.version) {
    if (built.partial && built.spline && !layerWanted()) setBuilt({ bez: project(built.spline.bezierAll()), partial: false });
    return;
  }
  if (built.spline) built.spline.delete();
  const old = built.bez, partial = layerWanted() && !dirty.all;
  setBuilt({ version: session.version, spline: null, splineError: null, bez: new Float64Array(0), partial: false });
  const n = count();
  if (n >= 2) {
    try {
      const spline = new M.Spline(fullPoints(), state.dim, splineOptions(state.opts, state.dim));
      setBuilt({ spline });
      const nseg = spline.segmentCount();
      if (partial && old.length === 8 * nseg) {
        setBuilt({ bez: old, partial: true });
        for (const i of dirty.segments) if (i < nseg) setSegmentBezier(i, spline.bezier(i));
      } else {
        setBuilt({ bez: project(spline.bezierAll()) });
      }
    } catch (e) {
      setBuilt({ splineError: e.message, bez: new Float64Array(0), partial: false });
    }
  }
  updateCaches();
  requestGlobal();
}

function updateCaches() {
  const spline = built.spline, nseg = spline ? spline.segmentCount() : 0;
  // The comb needs a plane curve (signed curvature).
  const want = { len: true, cusps: state.overlays.cusps, comb: state.overlays.comb && state.dim === 2 };
  for (const key of Object.keys(cache)) {
    if (!want[key] || !spline) { setCache(key, null); continue; }
    const full = dirty.all || !cache[key] || cache[key].length !== nseg;
    if (full) {
      setCache(key, computeRange(key, 0, nseg));
      if (key === 'len') setLenBlocks(null);
    } else {
      for (const i of dirty.segments) {
        if (i >= nseg) continue;
        setCacheEntry(key, i, computeRange(key, i, 1)[0]);
        if (key === 'len' && lenBlocks) setLenBlock(Math.floor(i / LEN_BLOCK), NaN);
      }
    }
  }
  clearDirty();
}

// Per-segment values for segments [first, first + n).
function computeRange(key, first, n) {
  const spline = built.spline;
  if (key === 'len') return Array.from(spline.segmentLengths(first, n));
  if (key === 'comb') {
    const all = spline.curvatureComb(COMB_PER_SEGMENT, first, n);
    const stride = (COMB_PER_SEGMENT + 1) * 5;
    return Array.from({ length: n }, (_, j) => all.subarray(j * stride, (j + 1) * stride));
  }
  // cusps: (segment, u, t, point of dim coordinates) per cusp; kept as the
  // drawn pair.
  const flat = spline.cusps(first, n), stride = 3 + state.dim, [a, b] = state.pair;
  const out = Array.from({ length: n }, () => null);
  for (let k = 0; k < flat.length; k += stride) {
    const j = flat[k] - first, x = flat[k + 3 + a], y = flat[k + 3 + b];
    out[j] = out[j] ? Float64Array.from([...out[j], x, y]) : Float64Array.of(x, y);
  }
  return out;
}

// The total length: Kahan sums of blocks of 512 segment lengths, each
// redone only when a length in it changed (a drag at 10^5 points changes 4),
// then of the blocks.
const LEN_BLOCK = 512;
function kahan(a, from = 0, to = a.length) {
  let s = 0, c = 0;
  for (let i = from; i < to; ++i) { const y = a[i] - c, t = s + y; c = (t - s) - y; s = t; }
  return s;
}
export function totalLength() {
  if (!cache.len) return NaN;
  const nb = Math.ceil(cache.len.length / LEN_BLOCK);
  if (!lenBlocks || lenBlocks.length !== nb) setLenBlocks(new Float64Array(nb).fill(NaN));
  for (let b = 0; b < nb; ++b) if (Number.isNaN(lenBlocks[b])) setLenBlock(b, kahan(cache.len, b * LEN_BLOCK, Math.min(cache.len.length, (b + 1) * LEN_BLOCK)));
  return kahan(lenBlocks);
}
export function cuspCount() {
  if (!cache.cusps) return null;
  let k = 0;
  for (const c of cache.cusps) if (c) k += c.length / 2;
  return k;
}
