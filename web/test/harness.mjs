// Shared by the editor's browser tests (editor.test.mjs, designer.test.mjs,
// perf.test.mjs): Debian's Chromium through playwright-core against the
// static server on a free 127.0.0.1 port; requests to anywhere else are
// aborted. open() gives a page with the editor loaded, in a desktop or a
// touch (phone) viewport, and helpers that read the canvas pixels.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { ensureBuilt, webDir } from './support.mjs';
import { serve } from '../serve.mjs';

const chromiumPath = process.env.CHROMIUM ?? '/usr/bin/chromium';
const args = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync'];

/// { page, close, errors, canvasBox } with the editor ready. touch: touch
/// emulation (Chromium's hasTouch), in a 390x844 phone viewport (isMobile)
/// unless phone is false.
export async function open({ width = 1280, height = 800, touch = false, phone = touch } = {}) {
  ensureBuilt();
  const { server, url } = await serve(webDir, 0);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'crspline-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: chromiumPath,
    headless: true,
    viewport: phone ? { width: 390, height: 844 } : { width, height },
    deviceScaleFactor: 1,
    hasTouch: touch,
    isMobile: phone,
    acceptDownloads: true,
    args,
  });
  const page = context.pages()[0] ?? (await context.newPage());
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.route('**/*', (route) => (route.request().url().startsWith(url) || route.request().url().startsWith('data:')
    ? route.continue() : route.abort()));
  await page.goto(url);
  await page.waitForFunction(() => window.editor !== undefined);
  const close = async () => {
    await context.close();
    await new Promise((resolve) => server.close(resolve));
    fs.rmSync(profile, { recursive: true, force: true });
  };
  return { page, close, errors, canvasBox: () => page.locator('#canvas').boundingBox() };
}

export const idle = (page) => page.evaluate(() => window.editor.idle());

/// Replace the curve (through the page's test hook) and wait for it.
export async function setPoints(page, list) {
  await page.evaluate((l) => window.editor.setPoints(l), list);
  await idle(page);
}

/// Keep a copy of the canvas pixels in the page (the pixels stay there: a
/// 1000x800 canvas is 3.2 MB, too slow to bring over as JSON). Returns its
/// name for differingPixels and bluePixels.
let shots = 0;
export async function canvasPixels(page) {
  const name = `shot${++shots}`;
  await page.evaluate((name) => {
    const c = document.getElementById('canvas');
    (window.__shots ??= {})[name] = { w: c.width, h: c.height, data: c.getContext('2d').getImageData(0, 0, c.width, c.height).data };
  }, name);
  return name;
}

/// Pixels whose largest channel difference exceeds `tol` between two
/// copies; { count, total }.
export async function differingPixels(page, a, b, tol = 24) {
  return page.evaluate(([a, b, tol]) => {
    const A = window.__shots[a], B = window.__shots[b];
    if (A.w !== B.w || A.h !== B.h) return { count: Infinity, total: A.w * A.h };
    let k = 0;
    for (let i = 0; i < A.data.length; i += 4) {
      const d = Math.max(Math.abs(A.data[i] - B.data[i]), Math.abs(A.data[i + 1] - B.data[i + 1]), Math.abs(A.data[i + 2] - B.data[i + 2]));
      if (d > tol) ++k;
    }
    return { count: k, total: A.w * A.h };
  }, [a, b, tol]);
}

/// Pixels of the curve's blue (#1f5fbf, antialiased edges excluded).
export async function bluePixels(page, a) {
  return page.evaluate((a) => {
    const d = window.__shots[a].data;
    let k = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 2] > 150 && d[i] < 120 && d[i + 2] - d[i] > 80) ++k;
    return k;
  }, a);
}

/// The canvas pixel [r, g, b, a] at canvas CSS position (x, y).
export async function pixelAt(page, x, y) {
  return page.evaluate(([x, y]) => {
    const c = document.getElementById('canvas'), dpr = c.width / c.clientWidth;
    return Array.from(c.getContext('2d').getImageData(Math.round(x * dpr), Math.round(y * dpr), 1, 1).data);
  }, [x, y]);
}

/// Screen position (page coordinates) of world point (x, y).
export async function pagePoint(page, x, y) {
  const box = await page.locator('#canvas').boundingBox();
  const [sx, sy] = await page.evaluate(([x, y]) => window.editor.worldToScreen(x, y), [x, y]);
  return [box.x + sx, box.y + sy];
}

/// A touch gesture through the DevTools protocol (Chromium's touch
/// emulation): `tracks` is one array of page positions per finger, all the
/// same length; the fingers go down at the first, move through the rest,
/// and lift.
export async function touchGesture(page, tracks, { stepDelay = 0 } = {}) {
  const cdp = await page.context().newCDPSession(page);
  const at = (k) => tracks.map((t, id) => ({ x: t[k][0], y: t[k][1], id, radiusX: 4, radiusY: 4, force: 1 }));
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
  for (let k = 1; k < tracks[0].length; ++k) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k) });
    if (stepDelay) await new Promise((r) => setTimeout(r, stepDelay));
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
}

/// Straight line from a to b in n steps (n + 1 positions).
export const line = (a, b, n = 10) => Array.from({ length: n + 1 }, (_, k) => [a[0] + ((b[0] - a[0]) * k) / n, a[1] + ((b[1] - a[1]) * k) / n]);
