// The defects of issue 17, each checked the way a user meets it: pixels on
// the canvas, what the keys and sliders do, where messages appear, and
// touch through Chromium's touch emulation (390x844 phone viewport).
import { test, before, after, describe } from 'node:test';
import assert from 'node:assert/strict';
import { open, idle, setPoints, canvasPixels, differingPixels, bluePixels, pixelAt, pagePoint, touchGesture, line } from './harness.mjs';

// A 6-point polygon (no cusp, no crossing), exact in doubles at any offset
// below 2^53 because every coordinate is an integer.
const polygon = [[0, 0], [120, 40], [200, -30], [310, 60], [260, 170], [90, 150]];
const shifted = (p, dx, dy = dx) => p.map(([x, y]) => [x + dx, y + dy]);
const viewScale = async (page) => page.evaluate(() => {
  const a = window.editor.worldToScreen(0, 0), b = window.editor.worldToScreen(1, 0);
  return b[0] - a[0];
});

describe('desktop 1280x800', () => {
  let h, page;
  before(async () => { h = await open(); page = h.page; });
  after(async () => { await h.close(); });

  test('defect 1: far from the origin, Fit draws the same pixels as at the origin', async () => {
    await setPoints(page, polygon);
    await page.click('#fit');
    await idle(page);
    const atOrigin = await canvasPixels(page);
    const curve = await bluePixels(page, atOrigin);
    assert.ok(curve > 1500, `the curve is drawn at the origin (${curve} blue pixels)`);
    for (const offset of [1e6, 1e8]) {
      await setPoints(page, shifted(polygon, offset));
      await page.click('#fit');
      await idle(page);
      const far = await canvasPixels(page);
      // The view subtracts its origin in double: what reaches the canvas is
      // the same to ~1e-7 px, so at most a few antialiased pixels may differ
      // by more than 24 of 255 (allow 0.05 % of the canvas).
      const diff = await differingPixels(page, atOrigin, far);
      assert.ok(diff.count <= 0.0005 * diff.total, `offset ${offset}: ${diff.count} pixels differ, curve pixels ${await bluePixels(page, far)} vs ${curve}`);
    }
    // Zoomed in 48x (about the vertex (120, 40), which the curve passes
    // through) on the polygon offset by 1e6: the same pixels as the polygon
    // at the origin under the same zoom.
    const zoom48 = async (dx) => {
      await page.click('#fit');
      const [sx, sy] = await page.evaluate(([x, y]) => window.editor.worldToScreen(x, y), [120 + dx, 40 + dx]);
      await page.evaluate(([x, y]) => window.editor.zoomBy(48, x, y), [sx, sy]);
      await idle(page);
      return canvasPixels(page);
    };
    await setPoints(page, polygon);
    const near = await zoom48(0);
    const nearBlue = await bluePixels(page, near);
    assert.ok(nearBlue > 300, `the curve is visible zoomed in (${nearBlue} blue pixels)`);
    await setPoints(page, shifted(polygon, 1e6));
    const far = await zoom48(1e6);
    const diff = await differingPixels(page, near, far);
    assert.ok(diff.count <= 0.0005 * diff.total, `1e6 offset zoomed 48x: ${diff.count} pixels differ`);
  });

  test('defect 3: Ctrl+Z with the alpha slider focused undoes the slider; selecting adds no undo step', async () => {
    await page.click('#clear');
    const box = await h.canvasBox();
    for (const [x, y] of [[200, 300], [400, 200], [600, 350]]) await page.mouse.click(box.x + x, box.y + y);
    await idle(page);
    const three = await page.evaluate(() => window.editor.points);
    assert.equal(three.length, 6);
    assert.equal(await page.evaluate(() => window.editor.options.alpha), 0.5);
    // Drag the slider's thumb to the left end.
    const s = await page.locator('#alpha').boundingBox();
    await page.mouse.move(s.x + s.width / 2, s.y + s.height / 2);
    await page.mouse.down();
    await page.mouse.move(s.x + s.width * 0.25, s.y + s.height / 2, { steps: 5 });
    await page.mouse.move(s.x - 20, s.y + s.height / 2, { steps: 5 });
    await page.mouse.up();
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.options.alpha), 0);
    assert.equal(await page.evaluate(() => document.activeElement.id), 'alpha');
    await page.keyboard.press('Control+z');
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.options.alpha), 0.5, 'Ctrl+Z undoes the slider while it has focus');
    await page.keyboard.press('Control+y');
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.options.alpha), 0, 'and Ctrl+Y redoes it');
    await page.keyboard.press('Control+z');
    await idle(page);
    // Selecting a point (a click without moving) is no edit: the next undo
    // removes the last point added.
    await page.mouse.click(box.x + 400, box.y + 200);
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.selected), 1);
    assert.deepEqual(await page.evaluate(() => window.editor.points), three, 'a click on a point only selects it');
    await page.keyboard.press('Control+z');
    await idle(page);
    assert.deepEqual(await page.evaluate(() => window.editor.points), three.slice(0, 4));
  });

  test('defect 2: a bad import shows its error over the canvas, as an alert', async () => {
    await page.setInputFiles('#import', { name: 'bad.csv', mimeType: 'text/csv', buffer: Buffer.from('1,2\n3,x\n') });
    const msg = page.locator('#message');
    await page.waitForFunction(() => /bad\.csv/.test(document.getElementById('message').textContent));
    const visible = async () => {
      const m = await msg.boundingBox(), c = await h.canvasBox();
      assert.ok(m && m.width > 0 && m.height > 0, 'the message has a box');
      // Inside the viewport and over the canvas.
      assert.ok(m.y >= 0 && m.y + m.height <= 800 && m.x >= 0 && m.x + m.width <= 1280, `message at ${JSON.stringify(m)}`);
      assert.ok(m.x < c.x + c.width && m.x + m.width > c.x && m.y < c.y + c.height && m.y + m.height > c.y, 'over the canvas');
      assert.equal(await msg.isVisible(), true);
    };
    await visible();
    assert.match(await msg.innerText(), /bad\.csv: CSV line 2/);
    assert.ok((await msg.getAttribute('role')) === 'alert' || (await msg.getAttribute('aria-live')) !== null);
    // Dropped on the canvas: the same.
    await page.click('#clear');
    await idle(page);
    await page.evaluate(() => {
      const dt = new DataTransfer();
      dt.items.add(new File(['{"points": [[0, 0], [1, "a"]]}'], 'dropped.json', { type: 'application/json' }));
      document.getElementById('canvas').dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
    });
    await page.waitForFunction(() => /dropped\.json/.test(document.getElementById('message').textContent));
    await visible();
  });

  test('defect 5: numbers show at least 6 significant digits at any scale', async () => {
    const tiny = polygon.map(([x, y]) => [x * 1e-6, y * 1e-6]);
    await setPoints(page, tiny);
    const text = await page.locator('#status-length').innerText();
    const shown = Number(text.replace(/^length\s*/, ''));
    const L = await page.evaluate((p) => {
      const s = new window.editor.module.Spline(p, 2, { alpha: 0.5 });
      const l = s.arcLength();
      s.delete();
      return l;
    }, tiny);
    // 6 significant digits: relative error at most 5e-6.
    assert.ok(Math.abs(shown - L) <= 5e-6 * L, `"${text}" vs ${L}`);
    const huge = polygon.map(([x, y]) => [x * 1e9 + 3e12, y * 1e9]);
    await setPoints(page, huge);
    const t2 = await page.locator('#status-length').innerText();
    const L2 = Number((await page.evaluate(() => ({ ...document.body.dataset }))).length);
    assert.ok(Math.abs(Number(t2.replace(/^length\s*/, '')) - L2) <= 5e-6 * L2, `"${t2}" vs ${L2}`);
  });

  test('defect 7: Backspace in a dropdown, Esc, zoom limits, status with < 2 points, accessible names', async () => {
    await setPoints(page, [[100, 100], [300, 200], [500, 150]]);
    await page.click('#fit');
    const [px, py] = await pagePoint(page, 300, 200);
    await page.mouse.click(px, py);
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.selected), 1);
    await page.locator('#start').focus();
    await page.keyboard.press('Backspace');
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.points.length), 6, 'Backspace in the dropdown deletes nothing');
    await page.locator('#canvas').focus();
    await page.keyboard.press('Escape');
    assert.equal(await page.evaluate(() => window.editor.selected), -1, 'Esc deselects');

    // Zoom limits: 40 big ctrl+wheel steps in, then 80 out.
    const s0 = await viewScale(page);
    const box = await h.canvasBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.keyboard.down('Control');
    for (let k = 0; k < 40; ++k) await page.mouse.wheel(0, -3000);
    await idle(page);
    const sIn = await viewScale(page);
    for (let k = 0; k < 80; ++k) await page.mouse.wheel(0, 3000);
    await page.keyboard.up('Control');
    await idle(page);
    const sOut = await viewScale(page);
    assert.ok(sIn > 100 * s0 && sIn <= 1e7 * s0, `zoomed in to ${sIn / s0} x`);
    assert.ok(sOut < s0 / 10 && sOut >= 1e-4 * s0, `zoomed out to ${sOut / s0} x`);

    // Fewer than 2 points: no curve, so no "cusps off" (the overlay is on).
    await setPoints(page, [[100, 100]]);
    assert.notEqual(await page.locator('#status-cusps').innerText(), 'cusps off');
    await page.locator('[data-overlay="cusps"]').uncheck();
    await setPoints(page, [[100, 100], [200, 100]]);
    assert.equal(await page.locator('#status-cusps').innerText(), 'cusps off');
    await page.locator('[data-overlay="cusps"]').check();

    // Every form control has an accessible name.
    assert.equal(await page.getByRole('spinbutton', { name: /tick spacing/i }).count(), 1);
    assert.equal(await page.getByRole('combobox', { name: /bounding volume/i }).count(), 1);
    const unnamed = await page.evaluate(() => [...document.querySelectorAll('input, select, button')]
      .filter((e) => e.type !== 'file' && !e.closest('[hidden]'))
      .filter((e) => !(e.getAttribute('aria-label') || e.title || e.labels?.[0]?.textContent.trim() || e.textContent.trim()))
      .map((e) => e.id || e.outerHTML));
    assert.deepEqual(unnamed, []);
  });

  test('defect 7: y up is a visible option; the same file then draws as crspline plot does', async () => {
    await setPoints(page, [[0, 0], [100, 0], [100, 100]]);
    const yUp = page.getByRole('checkbox', { name: /y up/i });
    assert.equal(await yUp.count(), 1);
    await yUp.check();
    await page.click('#fit');
    await idle(page);
    const [, yLow] = await page.evaluate(() => window.editor.worldToScreen(100, 0));
    const [, yHigh] = await page.evaluate(() => window.editor.worldToScreen(100, 100));
    assert.ok(yHigh < yLow - 50, 'larger y is higher on the screen');
    // And the pixels agree: the point (100, 100) is drawn (red) at the top.
    const [sx, sy] = await page.evaluate(() => window.editor.worldToScreen(100, 100));
    const px = await pixelAt(page, sx, sy);
    assert.ok(px[0] > 150 && px[1] < 90, `red point at ${sx}, ${sy}: ${px}`);
    // Clicking adds a point where the pointer is, in y-up coordinates.
    const box = await h.canvasBox();
    await page.mouse.click(box.x + sx - 150, box.y + sy - 40);
    await idle(page);
    const pts = await page.evaluate(() => window.editor.points);
    assert.ok(pts[pts.length - 1] > 100, `new point y ${pts[pts.length - 1]} above 100`);
    await yUp.uncheck();
    await idle(page);
  });

  test('no page errors', () => { assert.deepEqual(h.errors, []); });
});

describe('phone 390x844, touch', () => {
  let h, page;
  before(async () => { h = await open({ touch: true }); page = h.page; });
  after(async () => { await h.close(); });

  test('defect 4: the canvas gets the screen; the panel collapses and opens', async () => {
    const c = await h.canvasBox();
    assert.ok(c.width >= 380 && c.height >= 500, `canvas ${c.width}x${c.height}`);
    const toggle = page.getByRole('button', { name: /panel|controls|menu/i });
    assert.equal(await toggle.count(), 1);
    assert.equal(await page.locator('#panel').isVisible(), false);
    await toggle.tap();
    assert.equal(await page.locator('#panel').isVisible(), true);
    assert.equal(await toggle.getAttribute('aria-expanded'), 'true');
    await page.locator('#demo').tap();
    await toggle.tap();
    assert.equal(await page.locator('#panel').isVisible(), false);
    assert.equal((await h.canvasBox()).width, c.width);
  });

  test('defect 4: a touch drag moves the point by the finger distance; taps add points', async () => {
    await setPoints(page, [[100, 200], [200, 300], [300, 250]]);
    await page.evaluate(() => window.editor.fitView && window.editor.fitView());
    await idle(page);
    const s = await viewScale(page);
    const [x, y] = await pagePoint(page, 200, 300);
    await touchGesture(page, [line([x, y], [x + 30, y + 80], 12)]);
    await idle(page);
    const p = await page.evaluate(() => window.editor.points);
    // The finger moved (30, 80) CSS px: the point moves by that over the
    // scale (1 CSS px tolerance: touch positions are rounded to pixels).
    assert.ok(Math.abs(p[2] - (200 + 30 / s)) <= 1 / s && Math.abs(p[3] - (300 + 80 / s)) <= 1 / s, `moved to ${p[2]}, ${p[3]} (scale ${s})`);
    const box = await h.canvasBox();
    await page.touchscreen.tap(box.x + 40, box.y + 60);
    await idle(page);
    assert.equal((await page.evaluate(() => window.editor.points)).length, 8, 'a tap adds a point');
  });

  test('defect 4: pinch zooms about the fingers, two fingers pan', async () => {
    const box = await h.canvasBox();
    const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
    const before = await page.evaluate(() => window.editor.points.length);
    const s0 = await viewScale(page);
    const mid = await page.evaluate(([x, y]) => window.editor.screenToWorld(x, y), [box.width / 2, box.height / 2]);
    await touchGesture(page, [line([cx - 50, cy], [cx - 100, cy], 10), line([cx + 50, cy], [cx + 100, cy], 10)]);
    await idle(page);
    const s1 = await viewScale(page);
    assert.ok(Math.abs(s1 / s0 - 2) <= 0.05, `pinch: scale x${s1 / s0}`);
    // The world point between the fingers stays under them.
    const [mx, my] = await page.evaluate(([x, y]) => window.editor.worldToScreen(x, y), mid);
    assert.ok(Math.abs(mx - box.width / 2) <= 2 && Math.abs(my - box.height / 2) <= 2, `centre moved to ${mx}, ${my}`);
    // Two fingers moving together pan by their distance.
    await touchGesture(page, [line([cx - 40, cy], [cx, cy + 30], 10), line([cx + 40, cy], [cx + 80, cy + 30], 10)]);
    await idle(page);
    const [px, py] = await page.evaluate(([x, y]) => window.editor.worldToScreen(x, y), mid);
    assert.ok(Math.abs(px - mx - 40) <= 2 && Math.abs(py - my - 30) <= 2, `pan by ${px - mx}, ${py - my}`);
    assert.equal(await page.evaluate(() => window.editor.points.length), before, 'gestures add no point');
  });

  test('defect 7: the long certificate text does not wrap the status bar or resize the canvas', async () => {
    await setPoints(page, []);
    const c0 = await h.canvasBox();
    await page.evaluate(() => window.editor.loadDemo());
    await idle(page);
    assert.match(await page.locator('#status-cert').innerText(), /not certified/);
    const c1 = await h.canvasBox();
    assert.equal(c1.height, c0.height);
    const st = await page.locator('#status').boundingBox();
    assert.ok(st.height <= 30, `status bar ${st.height} px high`);
  });

  test('no page errors (touch)', () => { assert.deepEqual(h.errors, []); });
});

describe('tablet 1024x768, touch', () => {
  let h, page;
  before(async () => { h = await open({ width: 1024, height: 768, touch: true, phone: false }); page = h.page; });
  after(async () => { await h.close(); });

  test('defect 4: a touch drag is not taken by the browser: the point follows the finger', async () => {
    await setPoints(page, [[300, 300], [500, 400], [700, 350]]);
    const s = await viewScale(page);
    const [x, y] = await pagePoint(page, 500, 400);
    await touchGesture(page, [line([x, y], [x + 30, y + 80], 12)]);
    await idle(page);
    const p = await page.evaluate(() => window.editor.points);
    assert.ok(Math.abs(p[2] - (500 + 30 / s)) <= 1 / s && Math.abs(p[3] - (400 + 80 / s)) <= 1 / s, `moved to ${p[2]}, ${p[3]} (scale ${s})`);
    assert.equal(await page.locator('#canvas').evaluate((c) => getComputedStyle(c).touchAction), 'none');
  });
});

// The pencil (issue 40): a stroke drawn with the mouse (pointer events
// through playwright) becomes the fitted curve, in one undo step; Fit
// selection reduces a dense polyline. The fit is measured here, both
// ways, against the stroke the page recorded (world coordinates).
describe('pencil and Fit selection (issue 40)', () => {
  let h, page;
  before(async () => { h = await open(); page = h.page; });
  after(async () => { await h.close(); });

  // Both directions in the page: the curve (the editor's document, rebuilt
  // with its options) sampled 200 times a segment against the input
  // polyline, and every input point against the curve (nearest).
  const measure = (input) => page.evaluate((input) => {
    const e = window.editor, o = e.options;
    const opt = { alpha: o.alpha, tension: o.tension, closed: o.closed };
    if (!o.closed) { opt.start = o.start; opt.end = o.end; }
    if (o.kb) opt.kb = o.kb;
    const s = new e.module.Spline(Float64Array.from(e.points), 2, opt);
    const toPolyline = (x, y) => {
      let best = Infinity;
      for (let i = 0; i + 3 < input.length; i += 2) {
        const ax = input[i], ay = input[i + 1], bx = input[i + 2] - ax, by = input[i + 3] - ay;
        const ab = bx * bx + by * by, u = ab > 0 ? Math.min(1, Math.max(0, ((x - ax) * bx + (y - ay) * by) / ab)) : 0;
        best = Math.min(best, Math.hypot(ax + u * bx - x, ay + u * by - y));
      }
      return best;
    };
    let curveToInput = 0, inputToCurve = 0;
    const t0 = s.tMin(), t1 = s.tMax(), N = 200 * s.segmentCount();
    // k === N takes t1 itself: t0 + (t1 - t0) * N / N can round one ulp past it, which evaluate rejects (CI, stop 43).
    for (let k = 0; k <= N; ++k) {
      const p = s.evaluate(k === N ? t1 : t0 + ((t1 - t0) * k) / N);
      curveToInput = Math.max(curveToInput, toPolyline(p[0], p[1]));
    }
    for (let i = 0; i < input.length; i += 2) inputToCurve = Math.max(inputToCurve, Math.sqrt(s.nearest([input[i], input[i + 1]]).distanceSq));
    s.delete();
    return { curveToInput, inputToCurve };
  }, input);

  test('P, then a freehand stroke: far fewer points than the stroke, within 2 px both ways; one undo step back', async () => {
    const before = [[0, 0], [120, 40], [200, -30], [310, 60]];
    await setPoints(page, before);
    await page.click('#fit');
    await idle(page);
    const depth = await page.evaluate(() => window.editor.undoDepth);
    await page.locator('#canvas').focus();
    await page.keyboard.press('p');
    assert.equal(await page.evaluate(() => window.editor.pencil.on), true);
    assert.equal(await page.locator('#pencil').getAttribute('aria-pressed'), 'true');
    // A wavy stroke of 301 pointer samples with a seeded 0.4 px jitter.
    const seed = Number(process.env.CRSPLINE_SEED ?? Math.floor(Math.random() * 2 ** 31));
    let s = seed >>> 0 || 1;
    const rnd = () => { s ^= s << 13; s >>>= 0; s ^= s >>> 17; s ^= s << 5; s >>>= 0; return s / 2 ** 32 - 0.5; };
    const box = await h.canvasBox();
    const track = Array.from({ length: 301 }, (_, k) => [box.x + 150 + 2.5 * k + 0.8 * rnd(), box.y + 380 + 120 * Math.sin(k / 40) + 0.8 * rnd()]);
    await page.mouse.move(...track[0]);
    await page.mouse.down();
    for (const p of track.slice(1)) await page.mouse.move(...p);
    await page.mouse.up();
    await idle(page);
    const r = await page.evaluate(() => ({ last: window.editor.pencil.last, n: window.editor.points.length / 2, depth: window.editor.undoDepth,
      scale: window.editor.view.s }));
    const why = `seed ${seed}: ${JSON.stringify({ ...r, last: { ...r.last, input: undefined } })}`;
    const inputCount = r.last.input.length / 2;
    assert.ok(inputCount >= 250, `${why}: the page saw ${inputCount} pointer samples`);
    assert.equal(r.n, r.last.count, why);
    assert.ok(r.n >= 2 && r.n <= inputCount / 10, why);  // measured: about 8 to 12 of 301
    assert.equal(r.depth, depth + 1, why);
    // The tolerance: 2 screen pixels in world units at this zoom.
    assert.ok(Math.abs(r.last.tolerance - 2 / r.scale) < 1e-12, why);
    assert.ok(r.last.deviation <= r.last.tolerance, why);
    const m = await measure(r.last.input);
    console.log(`pencil: ${inputCount} pointer samples -> ${r.n} control points; tolerance ${r.last.tolerance}, proved ${r.last.deviation}, measured ${JSON.stringify(m)}`);
    // Sampling finds at most the proved bound (plus rounding, 1e-9 of the coordinates ~1e3).
    assert.ok(m.curveToInput <= r.last.tolerance + 1e-9 && m.inputToCurve <= r.last.tolerance + 1e-9, `${why}: measured ${JSON.stringify(m)}`);
    // The stroke is drawn on the curve's canvas: blue pixels along it.
    assert.ok(await bluePixels(page, await canvasPixels(page)) > 300, why);
    // One undo step back to the points before the stroke, redo again.
    await page.keyboard.press('Control+z');
    await idle(page);
    assert.deepEqual(await page.evaluate(() => window.editor.points), before.flat());
    assert.equal(await page.evaluate(() => window.editor.undoDepth), depth);
    await page.keyboard.press('Control+y');
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.points.length / 2), r.n);
    // A click with the pencil on adds nothing (no stroke), and P turns it off.
    await page.mouse.click(box.x + 600, box.y + 100);
    await idle(page);
    assert.equal(await page.evaluate(() => window.editor.undoDepth), depth + 1);
    await page.keyboard.press('p');
    assert.equal(await page.evaluate(() => window.editor.pencil.on), false);
    assert.deepEqual(h.errors, []);
  });

  test('Fit selection: a dense imported polyline (1000 points) -> a subset of its points within the tolerance, one undo step', async () => {
    const dense = Array.from({ length: 1000 }, (_, i) => [i * 0.8, 200 + 150 * Math.sin(i / 120) + 30 * Math.sin(i / 17)]);
    await setPoints(page, dense);
    await page.click('#fit');
    await idle(page);
    const depth = await page.evaluate(() => window.editor.undoDepth);
    await page.click('#fit-selection');
    await idle(page);
    const r = await page.evaluate(() => ({ pts: window.editor.points, last: window.editor.pencil.last, depth: window.editor.undoDepth }));
    const n = r.pts.length / 2;
    assert.equal(r.last.from, 1000);
    assert.ok(n >= 2 && n <= 100, `${n} points`);
    assert.equal(r.depth, depth + 1);
    // Real vertices: every kept point is one of the input points, in order.
    let j = 0;
    for (let k = 0; k < n; ++k) {
      while (j < 1000 && (dense[j][0] !== r.pts[2 * k] || dense[j][1] !== r.pts[2 * k + 1])) ++j;
      assert.ok(j < 1000, `point ${k} is not an input point in order`);
    }
    const m = await measure(dense.flat());
    console.log(`Fit selection: 1000 points -> ${n}; tolerance ${r.last.tolerance}, proved ${r.last.deviation}, measured ${JSON.stringify(m)}`);
    assert.ok(m.curveToInput <= r.last.tolerance + 1e-9 && m.inputToCurve <= r.last.tolerance + 1e-9, JSON.stringify({ m, last: r.last }));
    await page.keyboard.press('Control+z');
    await idle(page);
    assert.deepEqual(await page.evaluate(() => window.editor.points), dense.flat());
    assert.deepEqual(h.errors, []);
  });
});
