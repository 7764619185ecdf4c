// The package's TypeScript declarations: `tsc --noEmit` (TypeScript pinned
// in package-lock.json) on consumer.ts, a typed program that uses the whole
// API the way docs/js.md does, with d3-shape's and three.js' own types. Its
// @ts-expect-error lines must fail to type-check, so declarations that
// degrade to `any` (or are missing: TS7016) fail this test.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

test('tsc --noEmit accepts the typed consumer and rejects its @ts-expect-error lines', () => {
  const here = path.dirname(fileURLToPath(import.meta.url));
  const tsc = createRequire(import.meta.url).resolve('typescript/bin/tsc');
  const r = spawnSync(process.execPath, [tsc, '-p', path.join(here, 'tsconfig.json')], { encoding: 'utf8', cwd: here });
  assert.equal(r.status, 0, r.stdout + r.stderr);
});
