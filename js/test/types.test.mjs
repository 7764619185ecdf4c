// The package's TypeScript declarations: `tsc --noEmit` (TypeScript pinned
// in package-lock.json) on consumer.ts, a typed program that uses the whole
// API the way docs/js.md does, with d3-shape's and three.js' own types. Its
// @ts-expect-error lines must fail to type-check, so declarations that
// degrade to `any` (or are missing: TS7016) fail this test. consumer.ts is
// checked with skipLibCheck (checking all of @types/three takes half a
// minute); tsconfig.dts.json checks the package's own index.d.ts and d3.d.ts
// in full (three.d.ts is checked by its use in consumer.ts).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const tsc = createRequire(import.meta.url).resolve('typescript/bin/tsc');
const check = (config) => spawnSync(process.execPath, [tsc, '-p', path.join(here, config)], { encoding: 'utf8', cwd: here });

test('tsc --noEmit accepts the typed consumer and rejects its @ts-expect-error lines', () => {
  const r = check('tsconfig.json');
  assert.equal(r.status, 0, r.stdout + r.stderr);
});

test('tsc --noEmit: the package declarations are well-formed on their own', () => {
  const r = check('tsconfig.dts.json');
  assert.equal(r.status, 0, r.stdout + r.stderr);
});
