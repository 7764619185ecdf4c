// The package in Chromium (Debian's, through playwright-core; no downloads):
// browser/index.html imports crspline, crspline/d3 and crspline/three from
// node_modules (the installed tarball) through an import map, as an
// application would, draws a d3 chart and a three.js tube, and reports what
// it drew. Set CRSPLINE_JS_SCREENSHOT=path to keep the screenshot
// (docs/js-browser.png is made that way).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const root = path.dirname(fileURLToPath(import.meta.url));
const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.wasm': 'application/wasm', '.json': 'application/json' };

// A static server for the scratch project on 127.0.0.1 (a free port).
function serve() {
  const server = http.createServer((req, res) => {
    const rel = decodeURIComponent(new URL(req.url, 'http://127.0.0.1').pathname);
    const file = path.resolve(root, '.' + rel);
    if (!file.startsWith(root + path.sep)) return res.writeHead(403).end();
    fs.readFile(file, (err, body) => {
      if (err) return res.writeHead(404).end('not found');
      res.writeHead(200, { 'content-type': types[path.extname(file)] ?? 'application/octet-stream' }).end(body);
    });
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

test('Chromium: a d3 chart with crsplineCurve and a three.js tube around a CRSplineCurve3', async () => {
  const server = await serve();
  const url = `http://127.0.0.1:${server.address().port}/browser/index.html`;
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'crspline-js-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1030, height: 400 },
    deviceScaleFactor: 1,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader'],
  });
  try {
    const page = context.pages()[0] ?? (await context.newPage());
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    page.on('requestfailed', (r) => errors.push(`${r.url()}: ${r.failure()?.errorText}`));
    // Nothing from outside the test server.
    await page.route('**/*', (r) => (r.request().url().startsWith(`http://127.0.0.1:${server.address().port}/`) ? r.continue() : r.abort()));
    await page.goto(url);
    await page.waitForFunction(() => window.result !== undefined, null, { timeout: 30000 })
      .catch((e) => { throw new Error(`${e.message}; page errors: ${errors.join(' | ')}`); });
    const result = await page.evaluate(() => window.result);
    assert.equal(result.error, undefined, result.error);
    assert.deepEqual(errors, []);
    // The chart: one M and a Bézier per gap between the 10 data points, the
    // stroke through every point, and the browser's own length of the path
    // equal to crspline's arc length (Chromium measures Béziers to ~1e-3
    // relative on its own).
    const { chart, tube } = result;
    assert.equal(chart.commands, 'M' + 'C'.repeat(9));
    assert.deepEqual(chart.onStroke, Array(10).fill(true));
    assert.ok(Math.abs(chart.lengths.browser - chart.lengths.crspline) <= 2e-3 * chart.lengths.crspline, JSON.stringify(chart.lengths));
    // The tube: 201 rings of 17 vertices; the curve's points project onto
    // blue tube pixels; a fair share of the canvas is drawn.
    assert.equal(tube.vertices, 201 * 17);
    for (const [r, g, b] of tube.samples) assert.ok(b > r + 40 && b > 80, `pixel ${[r, g, b]} is not the tube's blue`);
    assert.ok(tube.ink > 0.03 && tube.ink < 0.6, `ink ${tube.ink}`);
    const shot = process.env.CRSPLINE_JS_SCREENSHOT ?? path.join(profile, 'shot.png');
    await page.screenshot({ path: shot });
    assert.ok(fs.statSync(shot).size > 10000);
  } finally {
    await context.close();
    server.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
});
