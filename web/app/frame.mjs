// The frame loop: at most one frame per animation frame, each building the
// curve if it changed (curve.mjs), drawing (draw.mjs) and writing the
// status line (status.mjs), timed for the tests; and the editor's "idle"
// (no frame pending, no gesture, the curve built and analysed) that tests
// wait for. The bookkeeping is state.mjs's `frames`.
import { rebuild } from './curve.mjs';
import { draw } from './draw.mjs';
import { updateStatus } from './status.mjs';
import {
  session, built, analysis, frames, globalCurrent, record, setFrames, takeIdleWaiters,
} from './state.mjs';

export function requestFrame() {
  if (!frames.requested) {
    setFrames({ requested: true });
    requestAnimationFrame(frame);
  }
}

function frame(now) {
  setFrames({ requested: false });
  const t0 = performance.now();
  rebuild();
  const tm = performance.now();
  draw();
  const t1 = performance.now();
  record('work', t1 - t0);
  record('curve', tm - t0);
  if (frames.pendingEventAt) { record('latencies', t1 - frames.pendingEventAt); setFrames({ pendingEventAt: 0 }); }
  const drag = session.drag;
  if (drag && frames.lastAt) record('intervals', now - frames.lastAt);
  setFrames({ lastAt: drag ? now : 0 });
  updateStatus(t1 - t0);
  settle();
}

export function isIdle() {
  return !frames.requested && !session.drag && built.version === session.version && (!built.spline || globalCurrent()) && !analysis.busy;
}
/// Wakes whoever waits for the editor to be idle, if it is.
export function settle() {
  if (!isIdle()) return;
  for (const f of takeIdleWaiters()) f();
}
