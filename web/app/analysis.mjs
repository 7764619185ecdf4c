// The whole-curve overlays (certificate and self-intersections, bounding
// volumes, arc-length ticks): the worker protocol. They run in a worker
// (worker.mjs), latest request wins; until an answer for the current curve
// arrives, the last one is drawn faded. Without a worker, on the main thread.
// The protocol's state (busy, queued, the last answer) is state.mjs's
// `analysis`.
import { M } from './wasm.mjs';
import { splineOptions } from './io.mjs';
import { computeGlobal } from './overlays.mjs';
import { state, session, built, analysis, fullPoints, setAnalysis, requestFrame, settle } from './state.mjs';

// queued: the curve changed while the worker was busy; the request is made
// (the points copied) once it is free, not on every frame meanwhile.
try {
  const worker = new Worker(new URL('./worker.mjs', import.meta.url), { type: 'module' });
  worker.onmessage = (e) => {
    setAnalysis({ busy: false, global: e.data });
    if (analysis.queued) { setAnalysis({ queued: false }); requestGlobal(); }
    requestFrame();
    settle();
  };
  worker.onerror = () => { setAnalysis({ worker: null, busy: false }); requestGlobal(); };
  setAnalysis({ worker });
} catch {
  setAnalysis({ worker: null });
}

function send(req) {
  if (analysis.worker) {
    setAnalysis({ busy: true });
    analysis.worker.postMessage(req, [req.points.buffer]);
  } else {
    setAnalysis({ global: computeGlobal(M, req) });
  }
}

// While a point is dragged, a curve whose whole-curve overlays took longer
// than this (ms) waits for the release instead of keeping a core busy.
const DRAG_GLOBAL_BUDGET = 50;
export function requestGlobal() {
  if (!built.spline) { setAnalysis({ global: null }); settle(); return; }
  const drag = session.drag, global = analysis.global;
  if (drag && drag.kind === 'move' && global && global.ms > DRAG_GLOBAL_BUDGET) { setAnalysis({ deferred: true }); return; }
  setAnalysis({ deferred: false });
  if (analysis.busy) { setAnalysis({ queued: true }); return; }
  send({
    version: session.version,
    points: fullPoints().slice(),
    dimension: state.dim,
    pair: state.pair,
    options: splineOptions(state.opts, state.dim),
    // The paper's volumes are drawn for plane curves only (a projected
    // capsule is not the capsule of the projection).
    volumes: state.overlays.volumes && state.dim === 2 ? state.volumeKind : null,
    ticks: state.overlays.ticks ? Math.max(1e-9, state.tickSpacing) : null,
    maxTicks: 20000,
  });
}
