// What designers expect from a curve editor (issue 17): scroll pans,
// Ctrl+scroll zooms, Space+drag pans, F fits, arrow keys nudge, numeric
// X/Y entry, a coordinate readout, a grid with snapping, marquee and
// Shift-click multi-selection, adding at either end, double-click to
// insert, and the `?` shortcuts overlay.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { open, idle, setPoints, pagePoint } from './harness.mjs';

let h, page;
before(async () => { h = await open(); page = h.page; });
after(async () => { await h.close(); });
const pts = () => page.evaluate(() => window.editor.points);
const screenOf = (x, y) => page.evaluate(([x, y]) => window.editor.worldToScreen(x, y), [x, y]);
const scale = async () => (await screenOf(1, 0))[0] - (await screenOf(0, 0))[0];
const base = [[100, 100], [300, 250], [500, 150], [700, 300]];

test('scroll pans, Ctrl+scroll zooms about the pointer, Space+drag pans, F fits', async () => {
  await setPoints(page, base);
  await page.keyboard.press('f');
  const box = await h.canvasBox();
  await page.mouse.move(box.x + 400, box.y + 300);
  const a0 = await screenOf(300, 250), s0 = await scale();
  await page.mouse.wheel(0, 100);
  await idle(page);
  const a1 = await screenOf(300, 250);
  assert.ok(Math.abs(a1[1] - (a0[1] - 100)) < 1e-6 && Math.abs(a1[0] - a0[0]) < 1e-6, `scroll pans: ${a0} -> ${a1}`);
  assert.equal(await scale(), s0);
  const w = await page.evaluate(() => window.editor.screenToWorld(400, 300));
  await page.keyboard.down('Control');
  await page.mouse.wheel(0, -200);
  await page.keyboard.up('Control');
  await idle(page);
  assert.ok((await scale()) > 1.5 * s0, 'Ctrl+scroll zooms in');
  const [wx, wy] = await screenOf(...w);
  assert.ok(Math.abs(wx - 400) < 1e-6 && Math.abs(wy - 300) < 1e-6, 'about the pointer');
  // Space+drag pans (and adds no point).
  const n = (await pts()).length;
  const b0 = await screenOf(300, 250);
  await page.locator('#canvas').focus();
  await page.keyboard.down(' ');
  await page.mouse.move(box.x + 600, box.y + 500);
  await page.mouse.down();
  await page.mouse.move(box.x + 650, box.y + 470, { steps: 4 });
  await page.mouse.up();
  await page.keyboard.up(' ');
  await idle(page);
  const b1 = await screenOf(300, 250);
  assert.ok(Math.abs(b1[0] - b0[0] - 50) < 1e-6 && Math.abs(b1[1] - b0[1] + 30) < 1e-6, `space+drag: ${b0} -> ${b1}`);
  assert.equal((await pts()).length, n);
  await page.keyboard.press('f');
  assert.ok(Math.abs((await scale()) - s0) < 1e-9 * s0, 'F fits again');
});

test('arrow keys nudge the selection (Shift: 10x); X/Y fields set the exact coordinates; undo', async () => {
  await setPoints(page, base);
  await page.keyboard.press('f');
  const s = await scale();
  const [x, y] = await pagePoint(page, 300, 250);
  await page.mouse.click(x, y);
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Shift+ArrowUp');
  await idle(page);
  let p = await pts();
  assert.ok(Math.abs(p[2] - (300 + 1 / s)) < 1e-9 && Math.abs(p[3] - (250 - 10 / s)) < 1e-9, `nudged to ${p[2]}, ${p[3]}`);
  assert.equal(await page.locator('#point-x').inputValue(), String(p[2]));
  await page.locator('#point-x').fill('123.456789012345');
  await page.locator('#point-x').press('Enter');
  await page.locator('#point-y').fill('-1e-7');
  await page.locator('#point-y').press('Enter');
  await idle(page);
  p = await pts();
  assert.deepEqual(p.slice(2, 4), [123.456789012345, -1e-7]);
  await page.locator('#point-y').fill('abc');
  await page.locator('#point-y').press('Enter');
  await page.waitForFunction(() => /not a finite number/.test(document.getElementById('message').textContent));
  assert.deepEqual((await pts()).slice(2, 4), [123.456789012345, -1e-7], 'a bad entry changes nothing');
  await page.locator('#canvas').focus();
  for (let k = 0; k < 4; ++k) await page.keyboard.press('Control+z');
  await idle(page);
  assert.deepEqual((await pts()).slice(2, 4), [300, 250], 'four undo steps: y, x, two nudges');
});

test('the pointer coordinate readout; the grid snaps dragged points', async () => {
  await setPoints(page, base);
  await page.keyboard.press('f');
  const [x, y] = await pagePoint(page, 500, 150);
  await page.mouse.move(x, y);
  const text = await page.locator('#status-pointer').innerText();
  const [, rx, ry] = text.match(/x (\S+), y (\S+)/).map(Number);
  const s0 = await scale();
  assert.ok(Math.abs(rx - 500) <= 1 / s0 && Math.abs(ry - 150) <= 1 / s0, text);
  await page.locator('#grid').check();
  const g = await page.evaluate(() => window.editor.gridStep());
  const s = await scale();
  await page.mouse.move(x, y);  // back from the checkbox
  await page.mouse.down();
  await page.mouse.move(x + 2.3 * g * s, y + 1.4 * g * s, { steps: 3 });
  await page.mouse.up();
  await idle(page);
  const p = await pts();
  for (const v of p.slice(4, 6)) assert.ok(Math.abs(v / g - Math.round(v / g)) < 1e-9, `${v} on the grid of ${g}`);
  // 2.3 and 1.4 steps from a point on the grid: snapped to 2 and 1 steps.
  assert.deepEqual(p.slice(4, 6).map((v, i) => Math.round((v - [500, 150][i]) / g)), [2, 1]);
  await page.locator('#grid').uncheck();
});

test('marquee and Shift+click select several points; they move and delete together', async () => {
  await setPoints(page, [...base, [900, 120]]);
  await page.keyboard.press('f');
  const box = await h.canvasBox();
  const [ax, ay] = await pagePoint(page, 250, 80), [bx, by] = await pagePoint(page, 750, 320);
  await page.keyboard.down('Shift');
  await page.mouse.move(ax, ay);
  await page.mouse.down();
  await page.mouse.move(bx, by, { steps: 5 });
  await page.mouse.up();
  await page.keyboard.up('Shift');
  assert.deepEqual(await page.evaluate(() => window.editor.selection), [1, 2, 3]);
  // Shift+click takes point 2 out and point 0 in.
  await page.keyboard.down('Shift');
  await page.mouse.click(...(await pagePoint(page, 500, 150)));
  await page.mouse.click(...(await pagePoint(page, 100, 100)));
  await page.keyboard.up('Shift');
  assert.deepEqual(await page.evaluate(() => window.editor.selection), [0, 1, 3]);
  // Dragging one moves all three by the same amount.
  const s = await scale();
  const [px, py] = await pagePoint(page, 300, 250);
  await page.mouse.move(px, py);
  await page.mouse.down();
  await page.mouse.move(px + 20, py + 10, { steps: 3 });
  await page.mouse.up();
  await idle(page);
  const p = await pts();
  for (const [k, [x, y]] of [[0, base[0]], [1, base[1]], [3, base[3]]]) {
    // Pointer positions reach the page rounded (to 1/64 px or so).
    assert.ok(Math.abs(p[2 * k] - x - 20 / s) < 0.05 / s && Math.abs(p[2 * k + 1] - y - 10 / s) < 0.05 / s, `point ${k}: ${p[2 * k]}, ${p[2 * k + 1]}`);
  }
  assert.deepEqual(p.slice(4, 6), [500, 150]);
  await page.keyboard.press('Delete');
  await idle(page);
  assert.deepEqual(await pts(), [500, 150, 900, 120]);
  await page.keyboard.press('Control+z');
  await idle(page);
  assert.deepEqual(await pts(), p, 'one undo brings all three back');
  await page.keyboard.press('Escape');
  assert.deepEqual(await page.evaluate(() => window.editor.selection), []);
  void box;
});

test('points are added at the end, or at the start when the first point is selected; double-click on the curve inserts', async () => {
  await setPoints(page, base);
  await page.keyboard.press('f');
  const [ex, ey] = await pagePoint(page, 640, 110);
  await page.mouse.click(ex, ey);
  await idle(page);
  let p = await pts();
  assert.equal(p.length, 10);
  assert.ok(Math.abs(p[8] - 640) < 0.5 && Math.abs(p[9] - 110) < 0.5, 'at the end');
  await page.mouse.click(...(await pagePoint(page, 100, 100)));  // select the first point
  const [sx, sy] = await pagePoint(page, 110, 290);
  await page.mouse.click(sx, sy);
  await idle(page);
  p = await pts();
  assert.equal(p.length, 12);
  assert.ok(Math.abs(p[0] - 110) < 0.5 && Math.abs(p[1] - 290) < 0.5, 'at the start');
  assert.equal(await page.evaluate(() => window.editor.selected), 0);
  // Double-click on the middle of segment 2: one point inserted there.
  const grid = await page.evaluate(() => window.editor.grid());
  const [mx, my] = await page.evaluate((t) => window.editor.evaluate(t), (grid[2] + grid[3]) / 2);
  await page.mouse.dblclick(...(await pagePoint(page, mx, my)));
  await idle(page);
  const q = await pts();
  assert.equal(q.length, 14);
  assert.ok(Math.hypot(q[6] - mx, q[7] - my) <= 1 / (await scale()), `inserted at ${q[6]}, ${q[7]}`);
});

test('? shows the shortcuts; Esc closes them', async () => {
  await page.locator('#canvas').focus();
  assert.equal(await page.locator('#help').isVisible(), false);
  await page.keyboard.press('?');
  assert.equal(await page.locator('#help').isVisible(), true);
  assert.match(await page.locator('#help').innerText(), /nudge/);
  await page.keyboard.press('Escape');
  assert.equal(await page.locator('#help').isVisible(), false);
  assert.deepEqual(h.errors, []);
});
