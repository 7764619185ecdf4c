// CRSplineTubeGeometry in Chromium (Debian's, through playwright-core; no
// downloads): browser/tube.html renders a closed trefoil-knot tube with
// three.js, banded around by a texture, next to the same tube without the
// seam fix, and measures the pixels of a close-up on the closing ring (row
// against row across it, and across rows elsewhere on the tube).
// CRSPLINE_TUBE_FIGURE=path keeps the page's screenshot (docs/sweep_knot_threejs.png
// is made that way; CRSPLINE_TUBE_LEFT=three (the default), three-closed or raw: which tube is on the left).
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

async function render(left) {
  const server = await serve();
  const base = `http://127.0.0.1:${server.address().port}/`;
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'crspline-tube-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 870, height: 480 },
    deviceScaleFactor: 1,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader'],
  });
  try {
    const page = context.pages()[0] ?? (await context.newPage());
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    await page.route('**/*', (r) => (r.request().url().startsWith(base) ? r.continue() : r.abort()));
    await page.goto(`${base}browser/tube.html?left=${left}`);
    await page.waitForFunction(() => window.result !== undefined, null, { timeout: 60000 })
      .catch((e) => { throw new Error(`${e.message}; page errors: ${errors.join(' | ')}`); });
    const result = await page.evaluate(() => window.result);
    assert.equal(result.error, undefined, result.error);
    assert.deepEqual(errors, []);
    const shot = process.env.CRSPLINE_TUBE_FIGURE && (process.env.CRSPLINE_TUBE_LEFT ?? 'three') === left
      ? path.resolve(process.env.CRSPLINE_TUBE_FIGURE) : path.join(profile, 'shot.png');
    await page.screenshot({ path: shot });
    assert.ok(fs.statSync(shot).size > 10000);
    return result;
  } finally {
    await context.close();
    server.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
}

test('Chromium: the closed knot tube has no seam at its closing ring; three.js\' TubeGeometry with the same arguments and the sweep without the twist spread have one', async () => {
  const raw = await render('raw');
  console.log(`pixels across the closing ring (mean channel difference, rows 6 px apart): crspline ${raw.right.seam.toFixed(2)} ` +
    `(elsewhere ${raw.right.elsewhere.toFixed(2)}); without the spread ${raw.left.seam.toFixed(2)} (elsewhere ${raw.left.elsewhere.toFixed(2)}); holonomy ${raw.holonomy}`);
  // Bands drawn with nearest filtering and no shading: rows 6 px apart on a
  // tube whose frame turns continuously differ only at the few band edges
  // that slant across them (a few of 255 on average), as rows elsewhere do.
  assert.ok(raw.right.seam <= raw.right.elsewhere + 3, JSON.stringify(raw.right));
  // The holonomy (|twist| > 0.05 rad) left at the closing ring shifts the
  // bands by that angle: whole band edges break across the ring.
  assert.ok(Math.abs(raw.holonomy) > 0.05, `holonomy ${raw.holonomy}`);
  assert.ok(raw.left.seam > raw.left.elsewhere + 10, JSON.stringify(raw.left));
  // three.js' TubeGeometry on the same closed path with the same arguments
  // (closed left to its default, false): its frame does not close.
  const three = await render('three');
  console.log(`three.js TubeGeometry(path, 200, 0.3, 32) across its closing ring: ${three.left.seam.toFixed(2)} (elsewhere ${three.left.elsewhere.toFixed(2)}); ` +
    `CRSplineTubeGeometry with the same arguments ${three.right.seam.toFixed(2)}`);
  assert.ok(three.left.seam > three.left.elsewhere + 10, JSON.stringify(three.left));
  assert.ok(three.right.seam <= three.right.elsewhere + 3, JSON.stringify(three.right));
  // With closed = true three.js spreads its own frame's twist: reported.
  const threeClosed = await render('three-closed');
  console.log(`three.js TubeGeometry(path, 200, 0.3, 32, true): ${threeClosed.left.seam.toFixed(2)} (elsewhere ${threeClosed.left.elsewhere.toFixed(2)})`);
  assert.ok(threeClosed.right.seam <= threeClosed.right.elsewhere + 3, JSON.stringify(threeClosed.right));
});
