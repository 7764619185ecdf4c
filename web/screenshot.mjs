// Writes docs/web_screenshot.png (the picture at the top of docs/web.md):
// the demo curve with its overlays at 1280x800 in headless Chromium. A
// script, run by hand when the page changes (`node web/screenshot.mjs`);
// no test writes into the source tree.
import path from 'node:path';
import { open, idle } from './test/harness.mjs';
import { repoDir } from './test/support.mjs';

const h = await open();
const { page } = h;
try {
  await page.click('#demo');
  for (const box of await page.locator('[data-overlay]').all()) {
    const name = await box.getAttribute('data-overlay');
    await box.setChecked(['polygon', 'handles', 'cusps', 'intersections', 'comb', 'ticks'].includes(name));
  }
  await idle(page);
  // The pointer over the curve: the coordinate readout shows.
  const c = await page.locator('#canvas').boundingBox();
  await page.mouse.move(c.x + c.width * 0.5, c.y + c.height * 0.45);
  await idle(page);
  if (h.errors.length) throw new Error(h.errors.join('\n'));
  const out = path.join(repoDir, 'docs', 'web_screenshot.png');
  await page.screenshot({ path: out });
  console.log(`wrote ${out}`);
} finally {
  await h.close();
}
