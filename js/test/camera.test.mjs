// The three.js camera example (js/examples/camera_path.html, issue 28) in
// Chromium (Debian's, through playwright-core): the page flies a camera
// along a CRSplinePoseCurve. Stopped at several u, the camera must stand
// where crspline's pose curve says and look where its orientation says
// (its -z axis rotated by the pose's [w, x, y, z], computed here, apart
// from three.js), must have moved along the path, and at the keys must
// look at the red box in the middle of the scene.
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

// v rotated by the unit quaternion q = [w, x, y, z]: v + 2 w (u x v) + 2 u x (u x v).
function rotate([w, x, y, z], v) {
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]), v[2] + w * t[2] + (x * t[1] - y * t[0])];
}
const dist = (a, b) => Math.hypot(...a.map((x, i) => x - b[i]));

test('Chromium: the camera flies along the pose curve and looks where the pose says', async () => {
  const server = await serve();
  const url = `http://127.0.0.1:${server.address().port}/examples/camera_path.html`;
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'crspline-js-camera-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 700, height: 480 },
    deviceScaleFactor: 1,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader'],
  });
  try {
    const page = context.pages()[0] ?? (await context.newPage());
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    await page.route('**/*', (r) => (r.request().url().startsWith(`http://127.0.0.1:${server.address().port}/`) ? r.continue() : r.abort()));
    await page.goto(url);
    await page.waitForFunction(() => window.flight?.ready === true, null, { timeout: 30000 })
      .catch((e) => { throw new Error(`${e.message}; page errors: ${errors.join(' | ')}`); });
    // The flight runs: the camera is somewhere on the path after a few frames.
    const keyU = await page.evaluate(() => window.flight.keyU);
    const keys = await page.evaluate(() => window.flight.positions);
    assert.equal(keyU.length, 6);
    let checked = 0;
    const seen = [];
    for (const u of [0, 0.1, 0.25, 0.4, 0.5, 0.77, 1, ...keyU]) {
      const cam = await page.evaluate((x) => window.flight.setU(x), u);
      const pose = await page.evaluate((x) => window.flight.pose(x), u);
      // Where: three.js' camera.position is the pose's position (copied
      // doubles; Vector3 holds numbers).
      assert.ok(dist(cam.position, pose.position) <= 1e-12, `u=${u}: camera at ${cam.position}, pose at ${pose.position}`);
      // Where it looks: a camera looks along its -z; rotated by crspline's
      // [w, x, y, z] here, by three.js' [x, y, z, w] in the page.
      const want = rotate(pose.orientation, [0, 0, -1]);
      assert.ok(dist(cam.direction, want) <= 1e-12, `u=${u}: looks along ${cam.direction}, pose says ${want}`);
      const [w, x, y, z] = pose.orientation;
      assert.deepEqual(cam.quaternion, [x, y, z, w]);
      seen.push(cam.position);
      checked++;
    }
    assert.equal(checked, 13);
    // It moved along the curve: the positions differ, and u = 0 and 1 are the end keys.
    assert.ok(dist(seen[0], seen[4]) > 5, `${seen[0]} vs ${seen[4]}`);
    assert.ok(dist(seen[0], keys[0]) <= 1e-12 && dist(seen[6], keys[5]) <= 1e-12 * 10);
    // At every key the camera looks at the red box (the keys' lookAt): the
    // middle pixel is red. Rolled keys too (roll keeps the view axis).
    for (const u of keyU) {
      const { center } = await page.evaluate((x) => window.flight.setU(x), u);
      assert.ok(center[0] > 150 && center[1] < 80 && center[2] < 80, `u=${u}: the middle pixel ${center} is not the red box`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
    server.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
});
