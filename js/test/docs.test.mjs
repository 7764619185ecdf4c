// The JavaScript examples of docs/js.md and docs/web.md are tested text
// (issue 42, point 3), as tests/frontends/test_docs_examples.py tests the
// shell, Python and JSON blocks of every page. The conventions, as a page
// author writes them:
//
// * a ```js block followed directly (blank lines aside) by a ```text block: the block runs as an
//   ES module in node and what it prints (console.log, stdout) must be the
//   text block; `...` in the text matches any text (doctest's ELLIPSIS: how a
//   page says that digits legitimately vary; no tolerance of its own);
// * a ```js block alone: it must run without an error;
// * `<!-- not run: REASON -->` on the line before a block: skipped, counted.
//
// Each block is its own module in a folder of this scratch project, so
// `import ... from 'crspline'` (and 'crspline/three', 'crspline/d3',
// 'three', 'd3-shape') resolves to the installed tarball and the pinned
// test dependencies, as in a user's project; './dist/crspline.mjs' (the
// raw module of docs/web.md) is the repository's web/dist. The number of
// blocks run and skipped per page is asserted (PAGES), and a changed digit
// in a shown output is checked to fail.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { repo } from './support.mjs';

const PAGES = {
  'docs/js.md': { run: 9, skipped: 0 },
  'docs/web.md': { run: 1, skipped: 0 },
};

const FENCE = /^(\s*)(```+)\s*([\w+-]*)\s*$/;
const MARKER = /^<!--\s*(not run):\s*(.*?)\s*-->$/;

/// The fenced blocks of a page: {line, lang, text, marker}.
function readBlocks(text) {
  const lines = text.split('\n');
  const blocks = [];
  for (let i = 0; i < lines.length; ++i) {
    const open = FENCE.exec(lines[i]);
    if (!open) continue;
    let j = i + 1;
    const closes = (line) => {
      const f = FENCE.exec(line);
      return f !== null && f[2] === open[2] && f[3] === '';
    };
    while (j < lines.length && !closes(lines[j])) ++j;
    let above = i - 1;
    while (above >= 0 && lines[above].trim() === '') --above;
    const marker = above >= 0 ? MARKER.exec(lines[above].trim()) : null;
    // Directly after the previous block: only blank lines between.
    const prev = blocks.at(-1);
    const follows = !!prev && lines.slice(prev.end, i).every((l) => l.trim() === '');
    blocks.push({ line: i + 1, end: j + 1, lang: open[3], text: lines.slice(i + 1, j).join('\n') + '\n', marker, follows });
    i = j;
  }
  return blocks;
}

/// doctest's ELLIPSIS: `...` matches any text (newlines included).
export function matches(shown, got) {
  const parts = shown.split('...').map((p) => p.replace(/[.*+?^${}()|[\]\\]/g, '\\$&'));
  return new RegExp(`^${parts.join('[\\s\\S]*')}$`).test(got);
}

const folder = fs.mkdtempSync(path.join(process.cwd(), 'docs-blocks-'));
fs.symlinkSync(path.join(repo, 'web', 'dist'), path.join(folder, 'dist'));
process.on('exit', () => fs.rmSync(folder, { recursive: true, force: true }));

function runBlock(name, block) {
  const file = path.join(folder, `${path.basename(name, '.md')}_${block.line}.mjs`);
  fs.writeFileSync(file, block.text);
  try {
    return execFileSync(process.execPath, [file], { cwd: folder, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  } catch (e) {
    assert.fail(`${name}:${block.line}: the block failed (exit ${e.status}):\n${e.stderr}`);
  }
}

for (const [name, want] of Object.entries(PAGES)) {
  test(`${name}: every js block runs and prints what the page shows`, () => {
    const blocks = readBlocks(fs.readFileSync(path.join(repo, name), 'utf8'));
    let run = 0, skipped = 0;
    for (let k = 0; k < blocks.length; ++k) {
      const b = blocks[k];
      if (b.lang !== 'js') continue;
      if (b.marker) {
        assert.ok(b.marker[2], `${name}:${b.line}: a \`not run\` marker must say why`);
        ++skipped;
        continue;
      }
      const got = runBlock(name, b);
      const next = blocks[k + 1];
      if (next && next.lang === 'text' && next.follows) {
        assert.ok(matches(next.text, got), `${name}:${b.line}: the block printed\n${got}\nwhere the page shows (line ${next.line})\n${next.text}`);
      } else {
        assert.equal(got, '', `${name}:${b.line}: the block printed output the page does not show (add a \`\`\`text block after it):\n${got}`);
      }
      ++run;
    }
    assert.deepEqual({ run, skipped }, want, `${name}: blocks run and skipped changed (a block added, removed or no longer recognised: update PAGES when that is meant)`);
  });
}

test('a changed digit in a shown output fails the comparison; `...` elides', () => {
  assert.ok(matches('length 9.797976965280847\n', 'length 9.797976965280847\n'));
  assert.ok(!matches('length 9.797976965280848\n', 'length 9.797976965280847\n'));
  assert.ok(matches('length 9.79797...\n', 'length 9.797976965280847\n'));
  assert.ok(!matches('length 9.79797...\n', 'length 9.897976965280847\n'));
  assert.ok(!matches('a\n', 'a\nb\n'));
});
