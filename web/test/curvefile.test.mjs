// One curve file (issue 14) in the editor: every command-line example input
// in the docs opens with the same curve (the same arc length to 12 digits
// as `crspline length`), curves of 3 or more coordinates open as a
// projection that says so and export back whole, and the y-up option is
// remembered. The command line is found at $CRSPLINE_CLI, else in
// build/release or build/rel (./run test builds it before the web suite);
// without it the comparisons with it are skipped, saying so.
import { test, before, after, describe } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { open, idle, pagePoint, canvasPixels, bluePixels } from './harness.mjs';
import { repoDir, loadModule } from './support.mjs';
import { requestFields, parsePoints, pointsToJson, splineOptions } from '../app/io.mjs';

const cli = [process.env.CRSPLINE_CLI, path.join(repoDir, 'build/release/cli/crspline'), path.join(repoDir, 'build/rel/cli/crspline')]
  .find((p) => p && fs.existsSync(p));
const noCli = cli ? false : 'the crspline command is not built (set CRSPLINE_CLI or build the crspline_cli target)';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'crspline-curvefile-'));

/// `crspline length` of a curve file's text (JSON or CSV): the total. The
/// command line's requests (t, derivatives, ...) belong to other
/// subcommands and are left out: they do not change the curve.
function cliLength(text, name) {
  let body = text;
  if (name.endsWith('.json')) {
    const data = JSON.parse(text);
    if (!Array.isArray(data)) for (const k of requestFields) delete data[k];
    body = JSON.stringify(data);
  }
  const file = path.join(tmp, name);
  fs.writeFileSync(file, body);
  return JSON.parse(execFileSync(cli, ['length', file], { encoding: 'utf8' })).total;
}

/// The command-line example inputs in README.md and docs/*.md: every JSON
/// object with a "points" field (in code blocks, inline code and `echo '...'`
/// lines; found by matching braces, so examples over several lines count),
/// and every ```csv block. Templates that are not JSON (`[...]`) are listed
/// apart.
export function docExamples() {
  const files = ['README.md', ...fs.readdirSync(path.join(repoDir, 'docs')).filter((f) => f.endsWith('.md')).map((f) => `docs/${f}`)];
  const found = [], templates = [];
  for (const f of files) {
    const text = fs.readFileSync(path.join(repoDir, f), 'utf8');
    const lineOf = (i) => text.slice(0, i).split('\n').length;
    for (let i = text.indexOf('{"points"'); i >= 0; i = text.indexOf('{"points"', i + 1)) {
      let depth = 0, j = i, inString = false;
      for (; j < text.length; ++j) {
        const c = text[j];
        if (inString) { if (c === '\\') ++j; else if (c === '"') inString = false; continue; }
        if (c === '"') inString = true;
        else if (c === '{') ++depth;
        else if (c === '}' && --depth === 0) break;
      }
      const snippet = text.slice(i, j + 1);
      const where = `${f}:${lineOf(i)}`;
      try {
        JSON.parse(snippet);
        found.push({ where, name: 'example.json', text: snippet });
      } catch {
        templates.push(where);
      }
    }
    for (const m of text.matchAll(/```csv\n([\s\S]*?)```/g)) found.push({ where: `${f}:${lineOf(m.index)}`, name: 'example.csv', text: m[1] });
  }
  return { found, templates };
}

async function importText(page, name, text) {
  const before = await page.evaluate(() => document.body.dataset.version);
  await page.setInputFiles('#import', { name, mimeType: name.endsWith('.csv') ? 'text/csv' : 'application/json', buffer: Buffer.from(text) });
  await page.waitForFunction((n) => document.body.dataset.version !== n, before);
  await idle(page);
}
const status = (page) => page.evaluate(() => ({
  message: document.getElementById('toast').hidden ? '' : document.getElementById('message').textContent,
  banner: document.getElementById('projection').hidden ? '' : document.getElementById('projection-text').textContent,
  length: document.getElementById('status-length').textContent,
}));

// A 3-D helix-like curve: no two points share a z, so a cut to 2-D or a
// projection built from the 2-D points (other knots) would show.
const helix = Array.from({ length: 9 }, (_, i) => [Math.round(100 * Math.cos(i)) / 4, Math.round(100 * Math.sin(i)) / 4, 7 * i - 20 + (i % 3)]);
const helixFile = JSON.stringify({ points: helix, alpha: 0.5, tension: 0.25, end: { start: 'reflect', end: [0, 0, 0] } });

describe('curve files in the editor', () => {
  let h, page;
  before(async () => { h = await open(); page = h.page; });
  after(async () => { await h.close(); fs.rmSync(tmp, { recursive: true, force: true }); });

  test('every command-line example input in the docs opens with the same curve as crspline length', { skip: noCli }, async (t) => {
    const { found, templates } = docExamples();
    t.diagnostic(`${found.length} examples: ${found.map((e) => e.where).join(', ')}; templates skipped: ${templates.join(', ') || 'none'}`);
    // The docs have (at least) these four today: cli.md's echo, spec.md's
    // curve file, README's two echoes; fewer means the extraction broke.
    assert.ok(found.length >= 4, `only ${found.length} examples found`);
    // The docs' examples are symmetric or use the defaults (alpha makes no
    // difference to them), so the same check runs on inputs where every
    // option the editor holds changes the curve.
    const uneven = [[0, 0], [1, 3], [5, 3.5], [5.5, 0], [9, -1]];
    // Each with the fields its export must hold: the table's words
    // ("closed", "start", "end"; issue 26), whichever spelling came in.
    const own = [
      [{ alpha: 0 }], [{ alpha: 1, tension: 0.3 }],
      [{ alpha: 0.25, end: 'reflect' }, { alpha: 0.25, closed: false, start: 'reflect', end: 'reflect' }],
      [{ end: 'closed' }, { closed: true }],
      [{ alpha: 0.75, end: { start: [0, 0], end: 'reflect' } }, { alpha: 0.75, closed: false, start: [0, 0], end: 'reflect' }],
      [{ grid: [0, 1, 2.5, 3, 4.5] }], [{ end: 'closed', grid: [0, 1, 2, 3.5, 4, 5.5] }, { closed: true, grid: [0, 1, 2, 3.5, 4, 5.5] }],
      [{ kb: { tension: [null, 0.2, -0.1, 0.3, null], continuity: [0, 0.1, 0, -0.2, 0], bias: [0, 0, 0.3, 0, 0] } }],
      [{ strict: true, tension: 0.2, end: { start: [2, -1], end: 'reflect' } }, { strict: true, tension: 0.2, closed: false, start: [2, -1], end: 'reflect' }],
      // The table's words themselves.
      [{ closed: true, alpha: 0.3 }], [{ closed: false, start: 'reflect', end: [1, -1] }],
      [{ closed: false, end: 'reflect' }, { closed: false, start: 'natural', end: 'reflect' }],
      [{ start: [0.5, 2], tension: 0.1 }, { closed: false, start: [0.5, 2], end: 'natural', tension: 0.1 }],
    ].map(([o, words], k) => ({ where: `own input ${k} ${JSON.stringify(o)}`, name: 'own.json', text: JSON.stringify({ points: uneven, ...o }),
      words: { points: uneven, ...(words ?? o) } }));
    own.push({ where: 'own CSV', name: 'own.csv', text: 'a,b\n' + uneven.map((p) => p.join(',')).join('\n') + '\n' });
    // An example the docs show being refused (an error message after it)
    // is refused by the editor too, with a message; counted.
    const refused = [];
    for (const e of [...found, ...own]) {
      let want;
      try {
        want = cliLength(e.text, e.name);
      } catch (err) {
        assert.ok(!e.where.startsWith('own'), `${e.where}: crspline length refused it: ${err.stderr ?? err.message}`);
        // A refused import changes nothing (no new version): wait for its message.
        await page.setInputFiles('#import', { name: e.name, mimeType: 'application/json', buffer: Buffer.from(e.text) });
        await page.waitForFunction(() => !document.getElementById('toast').hidden);
        const { message } = await status(page);
        assert.ok(message.startsWith(`import ${e.name}: `), `${e.where}: the command line refuses it (${String(err.stderr).trim()}), the editor says ${JSON.stringify(message)}`);
        refused.push(e.where);
        continue;
      }
      await importText(page, e.name, e.text);
      const got = await page.evaluate(() => window.editor.length());
      // "The same curve": the same points (exactly) and options give the
      // same per-segment lengths; 12 digits is the bar (both sum
      // per-segment arc_length at accuracy 1e-12).
      assert.ok(Math.abs(got - want) <= 1e-12 * Math.abs(want), `${e.where}: editor ${got}, crspline length ${want}`);
      if (e.name.endsWith('.json')) {
        const pts = JSON.parse(e.text).points ?? JSON.parse(e.text);
        assert.deepEqual(await page.evaluate(() => window.editor.fullPoints), pts.flat(), `${e.where}: points`);
      }
      // Exported back: the same fields (what the curve file holds).
      if (e.where.startsWith('own input')) {
        const back = JSON.parse(await page.evaluate(() => window.editor.exportJson()));
        for (const [k, v] of Object.entries(e.words)) assert.deepEqual(back[k], v, `${e.where}: exported ${k}`);
        assert.ok(!back.closed || (back.start === undefined && back.end === undefined), `${e.where}: a closed export has no ends`);
      }
      // Nothing is dropped without a word: a request field is named.
      const keys = e.name.endsWith('.json') ? Object.keys(JSON.parse(e.text)).filter((k) => requestFields.includes(k)) : [];
      const { message } = await status(page);
      for (const k of keys) assert.match(message, new RegExp(`"${k}"`), `${e.where}: the message names "${k}"`);
      if (!keys.length) assert.equal(message, '', `${e.where}: no message`);
    }
    t.diagnostic(`refused by the command line and the editor alike: ${refused.join(', ') || 'none'}`);
    assert.ok(refused.length < found.length / 2, `${refused.length} of ${found.length} examples refused: the extraction broke`);
    assert.deepEqual(h.errors, []);
  });

  test('a 3-D curve opens as a projection that says so, with the 3-D length', { skip: noCli }, async () => {
    await importText(page, 'helix.json', helixFile);
    const s = await status(page);
    assert.match(s.banner, /^3-D curve \(x, y, z\) shown as its projection on x, y\./);
    assert.match(s.banner, /JSON and CSV exports write all 3 coordinates/);
    assert.equal(s.message, '');
    assert.match(s.length, /\(3-D\)$/);
    assert.deepEqual(await page.evaluate(() => [window.editor.dimension, window.editor.pair]), [3, [0, 1]]);
    // The length is the 3-D curve's (the plane curve through the projected
    // points would be shorter, and have other knots).
    const want = cliLength(helixFile, 'helix.json');
    const got = await page.evaluate(() => window.editor.length());
    assert.ok(Math.abs(got - want) <= 1e-12 * want, `editor ${got}, crspline length ${want}`);
    const flat = cliLength(JSON.stringify({ points: helix.map(([x, y]) => [x, y]), alpha: 0.5, tension: 0.25 }), 'flat.json');
    assert.ok(Math.abs(flat - want) > 1e-3 * want, `the projection's own length ${flat} differs from the 3-D length ${want}`);
    // What is drawn is the projection of the 3-D curve: its Bézier points
    // are the x, y of the 3-D curve's (the curve's own evaluation).
    const ok = await page.evaluate(() => {
      const e = window.editor, g = e.grid(), b = e.bezier();
      const p = e.evaluate(g[3]);  // start of segment 3 = B0 of segment 3
      return [b[24], b[25], p[0], p[1], p.length];
    });
    assert.deepEqual(ok.slice(0, 2), ok.slice(2, 4));
    assert.equal(ok[4], 3);
    // The curve is drawn.
    assert.ok((await bluePixels(page, await canvasPixels(page))) > 500);
    // Exported unedited: the same 3-D file (the same doubles, options).
    const back = JSON.parse(await page.evaluate(() => window.editor.exportJson()));
    assert.deepEqual(back.points, helix);
    // In the table's words (issue 26; the file said "end": {"start": ..., "end": ...}).
    assert.deepEqual([back.alpha, back.tension, back.closed, back.start, back.end], [0.5, 0.25, false, 'reflect', [0, 0, 0]]);
    assert.equal(cliLength(JSON.stringify(back), 'back.json'), want);
    // CSV too: a header and 3 numbers per line.
    const csvPoints = JSON.parse(await page.evaluate(() => JSON.stringify(window.editor.fullPoints)));
    assert.deepEqual(csvPoints, helix.flat());
  });

  test('another pair of coordinates; edits keep the hidden ones; export says and writes 3-D', async () => {
    await importText(page, 'helix.json', helixFile);
    await page.selectOption('#pair-y', '2');
    await idle(page);
    let s = await status(page);
    assert.match(s.banner, /^3-D curve \(x, y, z\) shown as its projection on x, z\. Edits move points in x, z and keep y/);
    assert.deepEqual(await page.evaluate(() => window.editor.pair), [0, 2]);
    assert.deepEqual(await page.evaluate(() => window.editor.points), helix.flatMap(([x, , z]) => [x, z]));
    // Move point 4 in the view (x, z): its y stays.
    const [px, py] = await pagePoint(page, helix[4][0], helix[4][2]);
    await page.mouse.move(px, py);
    await page.mouse.down();
    await page.mouse.move(px + 30, py - 20, { steps: 4 });
    await page.mouse.up();
    await idle(page);
    const moved = JSON.parse(await page.evaluate(() => window.editor.exportJson())).points;
    assert.equal(moved.length, helix.length);
    assert.notEqual(moved[4][0], helix[4][0]);
    assert.notEqual(moved[4][2], helix[4][2]);
    assert.equal(moved[4][1], helix[4][1], 'y of the moved point is kept');
    for (const i of [0, 1, 2, 3, 5, 6, 7, 8]) assert.deepEqual(moved[i], helix[i]);
    // Double-click on the curve inserts a point of the 3-D curve: all three
    // coordinates from the curve at that parameter.
    const ins = await page.evaluate(() => {
      const e = window.editor, g = e.grid(), t = (g[1] + g[2]) / 2;
      return { p: e.evaluate(t), s: e.worldToScreen(...(() => { const q = e.evaluate(t); return [q[0], q[2]]; })()) };
    });
    const box = await h.canvasBox();
    await page.mouse.dblclick(box.x + ins.s[0], box.y + ins.s[1]);
    await idle(page);
    const after = JSON.parse(await page.evaluate(() => window.editor.exportJson())).points;
    assert.equal(after.length, helix.length + 1);
    // Within a pixel of the clicked curve point in x, z; y from the curve
    // there (the projection's nearest point is within 1 px: about 0.1 units
    // at this zoom, so y within the curve's change over that).
    const scale = await page.evaluate(() => window.editor.view.s);
    for (const k of [0, 1, 2]) assert.ok(Math.abs(after[2][k] - ins.p[k]) <= 3 / scale, `coordinate ${k}: ${after[2][k]} vs ${ins.p[k]}`);
    // A click on empty canvas adds a point at the end with the last point's y.
    await page.mouse.click(box.x + 40, box.y + box.height - 40);
    await idle(page);
    const added = JSON.parse(await page.evaluate(() => window.editor.exportJson())).points;
    assert.equal(added.length, helix.length + 2);
    assert.equal(added.at(-1)[1], helix.at(-1)[1]);
    // Undo three times: the file as imported; undo once more: the pair x, y.
    for (let k = 0; k < 3; ++k) await page.keyboard.press('Control+z');
    await idle(page);
    assert.deepEqual(JSON.parse(await page.evaluate(() => window.editor.exportJson())).points, helix);
    await page.keyboard.press('Control+z');
    await idle(page);
    assert.deepEqual(await page.evaluate(() => window.editor.pair), [0, 1]);
    s = await status(page);
    assert.match(s.banner, /projection on x, y\./);
    assert.deepEqual(h.errors, []);
  });

  test('knots and Kochanek-Bartels values from a file follow the points; alpha replaces the knots, undo brings them back', { skip: noCli }, async () => {
    const file = { points: [[0, 0], [100, 60], [220, 40], [300, 160], [420, 120]], grid: [0, 1, 2.5, 3, 4.5],
      kb: { tension: [null, 0.2, -0.1, 0.3, null], bias: [0, 0, 0.3, 0, 0] } };
    await importText(page, 'kb.json', JSON.stringify(file));
    assert.equal(await page.evaluate(() => document.getElementById('alpha-value').value), 'grid');
    // Double-click on segment 1: a point with the knot halfway (1.75) and
    // zero KB values.
    const s = await page.evaluate(() => { const e = window.editor, g = e.grid(); return e.worldToScreen(...e.evaluate((g[1] + g[2]) / 2)); });
    const box = await h.canvasBox();
    await page.mouse.dblclick(box.x + s[0], box.y + s[1]);
    await idle(page);
    let back = JSON.parse(await page.evaluate(() => window.editor.exportJson()));
    assert.equal(back.points.length, 6);
    assert.deepEqual(back.grid, [0, 1, 1.75, 2.5, 3, 4.5]);
    assert.deepEqual(back.kb, { tension: [null, 0.2, 0, -0.1, 0.3, null], bias: [0, 0, 0, 0.3, 0, 0] });
    // The export is the curve the editor shows, to the command line too.
    const want = cliLength(JSON.stringify(back), 'kb_back.json');
    assert.ok(Math.abs((await page.evaluate(() => window.editor.length())) - want) <= 1e-12 * want);
    // Deleting point 3 takes its knot and values away.
    await page.evaluate(() => window.editor.setSelection([3]));
    await page.keyboard.press('Delete');
    await idle(page);
    back = JSON.parse(await page.evaluate(() => window.editor.exportJson()));
    assert.deepEqual(back.grid, [0, 1, 1.75, 3, 4.5]);
    assert.deepEqual(back.kb, { tension: [null, 0.2, 0, 0.3, null], bias: [0, 0, 0, 0, 0] });
    // The chordal preset: knots from alpha = 1, said so; undo: the grid.
    await page.click('#chordal');
    await idle(page);
    back = JSON.parse(await page.evaluate(() => window.editor.exportJson()));
    assert.equal(back.grid, undefined);
    assert.equal(back.alpha, 1);
    assert.match((await status(page)).message, /knots from α = 1 now, instead of the file's grid/);
    await page.keyboard.press('Control+z');
    await idle(page);
    back = JSON.parse(await page.evaluate(() => window.editor.exportJson()));
    assert.deepEqual(back.grid, [0, 1, 1.75, 3, 4.5]);
    // A grid of the wrong length is refused at import with the library's
    // words, and the curve stays as it was.
    await page.setInputFiles('#import', { name: 'bad.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify({ ...file, grid: [0, 1, 2] })) });
    await page.waitForFunction(() => !document.getElementById('toast').hidden);
    const after = await status(page);
    assert.match(after.message, /^import bad\.json: .*grid/);
    assert.equal(JSON.parse(await page.evaluate(() => window.editor.exportJson())).points.length, 5);
    assert.deepEqual(h.errors, []);
  });

  test('a 7-D curve opens as a projection; exported back whole', { skip: noCli }, async () => {
    const seven = JSON.parse(fs.readFileSync(path.join(repoDir, 'tests', 'reference', 'seven_d.json'), 'utf8'));
    const pts = seven.input.points;
    assert.ok(Array.isArray(pts) && pts[0].length === 7, 'tests/reference/seven_d.json has 7-D points');
    const file = JSON.stringify({ points: pts });
    await importText(page, 'seven.json', file);
    const s = await status(page);
    assert.match(s.banner, /^7-D curve \(x1, x2, … x7\) shown as its projection on x1, x2\./);
    assert.deepEqual(JSON.parse(await page.evaluate(() => window.editor.exportJson())).points, pts);
    // The WASM module takes 1 to 4 coordinates for now: then the module's
    // own message shows (nothing silent); once it takes 7, the length is
    // the command line's.
    const takes7 = await page.evaluate(() => {
      try { new window.editor.module.Spline([0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1], 7).delete(); return true; } catch { return false; }
    });
    if (takes7) {
      const want = cliLength(file, 'seven.json');
      const got = await page.evaluate(() => window.editor.length());
      assert.ok(Math.abs(got - want) <= 1e-12 * want, `editor ${got}, crspline length ${want}`);
    } else {
      assert.match(s.message, /dimension/);
    }
  });

  test('y up is remembered by the browser', async () => {
    await page.evaluate(() => window.editor.setPoints([[0, 0], [100, 100]]));
    await idle(page);
    assert.equal(await page.isChecked('#y-up'), false);
    await page.check('#y-up');
    await page.reload();
    await page.waitForFunction(() => window.editor !== undefined);
    assert.equal(await page.isChecked('#y-up'), true);
    assert.equal(await page.evaluate(() => window.editor.view.yUp), true);
    await page.uncheck('#y-up');
    await page.reload();
    await page.waitForFunction(() => window.editor !== undefined);
    assert.equal(await page.isChecked('#y-up'), false);
  });
});

// One spelling (issue 26): the curve file's ends are the table's words of
// docs/spec.md ("closed": true | false, "start": E, "end": E); the compact
// forms of older files ("end": "closed", "end": {"start": E, "end": E}, a
// name in "end" alone for both ends) still read the same; the export writes
// the table's words. Node only: the reader and writer, and the WASM module
// for "the same curve".
describe("the curve file's ends in the table's words (issue 26)", () => {
  const pts = [[0, 0], [1, 3], [5, 3.5], [5.5, 0], [9, -1]];
  const read = (fields) => parsePoints(JSON.stringify({ points: pts, ...fields }), 'a.json');

  test('every end the table allows reads in its words and in its compact form, with the same options', () => {
    // [table's words, compact form, the editor's options]
    const cases = [
      [{ closed: true }, { end: 'closed' }, { closed: true, start: 'natural', end: 'natural' }],
      [{ closed: false }, {}, { closed: false, start: 'natural', end: 'natural' }],
      [{ start: 'reflect', end: 'reflect' }, { end: 'reflect' }, { closed: false, start: 'reflect', end: 'reflect' }],
      [{ closed: false, start: 'natural', end: 'natural' }, { end: 'natural' }, { closed: false, start: 'natural', end: 'natural' }],
      [{ start: 'reflect' }, { end: { start: 'reflect' } }, { closed: false, start: 'reflect', end: 'natural' }],
      [{ closed: false, end: 'reflect' }, { end: { end: 'reflect' } }, { closed: false, start: 'natural', end: 'reflect' }],
      [{ start: [1, -1], end: 'reflect' }, { end: { start: [1, -1], end: 'reflect' } }, { closed: false, start: [1, -1], end: 'reflect' }],
      [{ start: [0, 0], end: [2, 0.5] }, { end: { start: [0, 0], end: [2, 0.5] } }, { closed: false, start: 'zero', end: [2, 0.5] }],
      [{ end: [2, 0.5] }, { end: { end: [2, 0.5] } }, { closed: false, start: 'natural', end: [2, 0.5] }],
    ];
    let checked = 0;
    for (const [words, compact, want] of cases) {
      const a = read(words).options, b = read(compact).options;
      for (const [k, v] of Object.entries(want)) assert.deepEqual(a[k], v, `${JSON.stringify(words)}: ${k}`);
      assert.deepEqual(a, b, `${JSON.stringify(words)} and ${JSON.stringify(compact)}`);
      // Exported: the table's words, and read back the same.
      const back = JSON.parse(pointsToJson(read(words).points, a));
      assert.equal(back.closed, want.closed, JSON.stringify(words));
      if (want.closed) assert.deepEqual([back.start, back.end], [undefined, undefined], JSON.stringify(words));
      else assert.deepEqual([back.start, back.end], [want.start === 'zero' ? [0, 0] : want.start, want.end], JSON.stringify(words));
      assert.deepEqual(read({ closed: back.closed, start: back.start, end: back.end }).options, a);
      ++checked;
    }
    assert.equal(checked, cases.length);
  });

  test("the table's words and the compact form make the same curve (arc length, Bézier points) in the WASM module", async () => {
    const M = await loadModule();
    const forms = [
      [{ closed: true, alpha: 0 }, { end: 'closed', alpha: 0 }],
      [{ closed: false, start: 'reflect', end: [1, -2] }, { end: { start: 'reflect', end: [1, -2] } }],
      [{ start: 'reflect', end: 'reflect', tension: 0.3 }, { end: 'reflect', tension: 0.3 }],
      [{ closed: false, end: 'reflect' }, { end: { end: 'reflect' } }],
    ];
    const curve = (fields) => {
      const r = read(fields);
      const c = new M.Spline(r.points, r.dimension, splineOptions(r.options, r.dimension));
      try { return { length: c.arcLength(), bez: Array.from(c.bezierAll()) }; } finally { c.delete(); }
    };
    const lengths = new Set();
    for (const [words, compact] of forms) {
      const a = curve(words), b = curve(compact);
      // The same options build the same curve: identical numbers.
      assert.deepEqual(a, b, `${JSON.stringify(words)} vs ${JSON.stringify(compact)}`);
      lengths.add(a.length);
    }
    // The four forms are four different curves (so the ends were read, not dropped).
    assert.equal(lengths.size, forms.length);
  });

  test('fields that say different things are an error naming them; a closed export has no ends', () => {
    const bad = [
      [{ closed: true, start: 'reflect' }, 'JSON: start: a closed curve ("closed": true) has no start condition'],
      [{ closed: true, end: [1, 0] }, 'JSON: end: a closed curve ("closed": true) has no end condition'],
      [{ closed: false, end: 'closed' }, 'JSON: end: "end": "closed" contradicts "closed": false'],
      [{ start: 'natural', end: 'closed' }, 'JSON: start: a closed curve ("end": "closed") has no start condition'],
      [{ start: 'reflect', end: { end: 'natural' } }, 'JSON: start: given twice: in "start" and in "end": {"start": ...}'],
      [{ closed: 'yes' }, 'JSON: closed: expected true or false, got "yes"'],
      [{ closed: 1 }, 'JSON: closed: expected true or false, got 1'],
      [{ start: 'closed' }, 'JSON: start: expected "natural", "reflect" or a tangent like [0, 0], got "closed"'],
      [{ start: 'zero' }, 'JSON: start: expected "natural", "reflect" or a tangent like [0, 0], got "zero"'],
      [{ end: 3 }, 'JSON: end: expected "natural", "reflect", a tangent like [0, 0], "closed" or {"start": ..., "end": ...}, got 3'],
      [{ closed: true, options: {} }, 'JSON: give "options" or the top-level "closed", not both'],
    ];
    for (const [fields, message] of bad) assert.throws(() => read(fields), (e) => e.message === message, `${JSON.stringify(fields)}: expected ${message}`);
    assert.equal(bad.length, 11);
    const text = pointsToJson(Float64Array.from(pts.flat()), { alpha: 0.5, tension: 0, closed: true, start: 'reflect', end: [1, 1] });
    assert.deepEqual(Object.keys(JSON.parse(text)), ['alpha', 'tension', 'closed', 'points']);
    const open = pointsToJson(Float64Array.from(pts.flat()), { alpha: 0.5, tension: 0, closed: false, start: 'reflect', end: 'zero' });
    assert.deepEqual(Object.keys(JSON.parse(open)), ['alpha', 'tension', 'closed', 'start', 'end', 'points']);
    assert.deepEqual(JSON.parse(open).end, [0, 0]);
  });

  test("the spec table's closed, start and end rows are the words the editor reads and writes", () => {
    // docs/spec.md's table names the fields; a row the editor did not know
    // would be refused on import as "field '...' is not supported".
    const spec = fs.readFileSync(path.join(repoDir, 'docs', 'spec.md'), 'utf8');
    const rows = [...spec.matchAll(/^\| `([a-z_.]+)`(?:, `([a-z_.]+)`)? \|/gm)].flatMap((m) => [m[1], m[2]]).filter(Boolean);
    for (const word of ['closed', 'start', 'end']) assert.ok(rows.includes(word), `docs/spec.md's table has no row '${word}' (rows: ${rows.join(', ')})`);
    const text = pointsToJson(Float64Array.from(pts.flat()), { alpha: 0.5, tension: 0, closed: false, start: 'reflect', end: 'natural' });
    for (const key of Object.keys(JSON.parse(text))) assert.ok(rows.includes(key), `the export writes '${key}', which docs/spec.md's table does not name`);
  });
});
