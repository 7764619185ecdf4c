// A module worker computing the whole-curve overlays off the main thread, so
// that dragging stays smooth while a 10^4-point curve is being certified.
import CrSpline from '../dist/crspline.mjs';
import { computeGlobal } from './overlays.mjs';

const ready = CrSpline({ locateFile: (p) => new URL('../dist/' + p, import.meta.url).href });

self.onmessage = async (e) => {
  const M = await ready;
  const out = computeGlobal(M, e.data);
  const transfer = [out.intersections?.buffer, out.ticks?.buffer, out.volumes?.boxes?.buffer, out.volumes?.balls?.buffer].filter(Boolean);
  self.postMessage(out, transfer);
};
