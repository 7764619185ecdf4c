// Frame times while dragging one point of a 10^3, 10^4 and 10^5-point
// curve (the stress spiral), driven from inside the page: one pointer move
// per animation frame. Printed and written to
// web/test-results/frame_times_sizes.json for docs/web.md; never asserted
// (speed lives in benchmarks). What is asserted: the point followed the
// pointer and a frame was drawn for the moves.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { open } from './harness.mjs';
import { webDir } from './support.mjs';

let h, page;
before(async () => { h = await open(); page = h.page; });
after(async () => { await h.close(); });

test('dragging one point at 10^3, 10^4, 10^5 points: frame times reported', async (t) => {
  const results = {};
  for (const n of [1000, 10000, 100000]) {
    const moves = n >= 100000 ? 40 : 120;
    const r = await page.evaluate(async ([n, moves]) => {
      const e = window.editor;
      e.loadStress(n);
      // Wait for the first frame of the new curve (not for the worker: the
      // certificate of 10^5 points takes long, and runs off this thread).
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      const k = Math.floor(0.9 * n), p0 = e.points.slice(2 * k, 2 * k + 2);
      const [x, y] = e.worldToScreen(p0[0], p0[1]);
      const c = document.getElementById('canvas'), rect = c.getBoundingClientRect();
      const ev = (type, dx) => c.dispatchEvent(new PointerEvent(type, {
        clientX: rect.left + x + dx, clientY: rect.top + y, button: 0, buttons: 1, pointerId: 9, isPrimary: true, pointerType: 'mouse', bubbles: true }));
      e.resetFrameStats();
      ev('pointerdown', 0);
      await new Promise((resolve) => {
        let j = 0;
        const step = () => { if (j++ < moves) { ev('pointermove', j / 4); requestAnimationFrame(step); } else resolve(); };
        requestAnimationFrame(step);
      });
      ev('pointerup', moves / 4);
      await new Promise((r) => requestAnimationFrame(r));
      const stats = e.frameStats();
      const p1 = e.points.slice(2 * k, 2 * k + 2);
      return { stats, moved: [p1[0] - p0[0], p1[1] - p0[1]], scale: e.view.s };
    }, [n, moves]);
    assert.ok(Math.abs(r.moved[0] - moves / 4 / r.scale) <= 0.05 / r.scale && r.moved[1] === 0, `${n}: moved ${r.moved}`);
    assert.ok(r.stats.work.count >= moves / 2, `${n}: ${r.stats.work.count} frames for ${moves} moves`);
    results[n] = r.stats;
    const f = (q) => (q ? `median ${q.median.toFixed(1)} ms, p95 ${q.p95.toFixed(1)} ms, max ${q.max.toFixed(1)} ms` : 'n/a');
    const line = `${n} points: frame work ${f(r.stats.work)}; curve + caches ${f(r.stats.curve)}; pointer to frame ${f(r.stats.latency)}; between frames ${f(r.stats.interval)} (${r.stats.work.count} frames)`;
    t.diagnostic(line);
    console.log(`# ${line}`);
  }
  fs.mkdirSync(path.join(webDir, 'test-results'), { recursive: true });
  fs.writeFileSync(path.join(webDir, 'test-results', 'frame_times_sizes.json'), JSON.stringify(results, null, 1));
  assert.deepEqual(h.errors, []);
});
