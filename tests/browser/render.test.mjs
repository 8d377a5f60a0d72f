// The WebGL2 view draws the avatar: the real server serves the page, the WASM core skins the real
// avatar, and the centre of the canvas shows a figure (pixels unlike the background beside it).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { launchBrowser, openPage, screenshot, startServer } from './harness.mjs';

let server, browser;
before(async () => { server = await startServer(); browser = await launchBrowser(); });
after(async () => { await browser?.close(); await server?.stop(); });

// Share of pixels in the centre column band that differ from the background at the same height
// (the gradient is vertical, so the canvas's left edge at the same row is background).
async function figureCoverage(page) {
  return page.evaluate(() => {
    const sw = window.signweave;
    const gl = sw.renderer.gl;
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const all = sw.readRegion(0, 0, w, h);
    const px = (x, y) => (y * w + x) * 4;
    let differing = 0, total = 0;
    for (let y = Math.floor(h * 0.2); y < Math.floor(h * 0.9); y += 2) {
      const ref = px(2, y);
      for (let x = Math.floor(w * 0.45); x < Math.floor(w * 0.55); x += 2) {
        const p = px(x, y);
        const d = Math.abs(all.pixels[p] - all.pixels[ref]) + Math.abs(all.pixels[p + 1] - all.pixels[ref + 1]) + Math.abs(all.pixels[p + 2] - all.pixels[ref + 2]);
        if (d > 40) differing++;
        total++;
      }
    }
    return differing / total;
  });
}

test('WebGL2 draws the skinned avatar in the centre of the view', async () => {
  const { page, problems } = await openPage(browser, server.base, '#/');
  await page.waitForFunction(() => window.signweave.metrics.frames > 3);
  const info = await page.evaluate(() => ({
    flavour: window.signweave.state.flavour,
    vertices: window.signweave.core.info.vertex_count,
    joints: window.signweave.core.info.joints.length,
    webgl2: !!document.getElementById('view').getContext('webgl2'),
  }));
  assert.ok(info.webgl2, 'WebGL2 context');
  assert.ok(['simd', 'scalar'].includes(info.flavour), `core flavour ${info.flavour}`);
  assert.ok(info.vertices > 1000, `the avatar has ${info.vertices} vertices`);
  assert.ok(info.joints >= 55, `the avatar has ${info.joints} joints`);
  const coverage = await figureCoverage(page);
  await screenshot(page, 'render-rest.png');
  assert.ok(coverage > 0.25, `only ${(coverage * 100).toFixed(1)}% of the centre band shows the figure`);
  assert.deepEqual(problems, []);
});

test('camera presets and the skeleton overlay change the picture, and the view survives a resize', async () => {
  const { page } = await openPage(browser, server.base, '#/');
  await page.waitForFunction(() => window.signweave.metrics.frames > 3);
  const snapshot = () => page.evaluate(() => {
    const gl = window.signweave.renderer.gl;
    const r = window.signweave.readRegion(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
    let sum = 0;
    for (let i = 0; i < r.pixels.length; i += 97) sum = (sum * 31 + r.pixels[i]) >>> 0;
    return sum;
  });
  const front = await snapshot();
  await page.click('[data-preset="side"]');
  await page.waitForTimeout(900);
  await screenshot(page, 'render-side.png');
  assert.notEqual(await snapshot(), front, 'the side preset moves the camera');
  await page.click('[data-preset="hands"]');
  await page.waitForTimeout(900);
  await screenshot(page, 'render-hands.png');
  await page.click('#debug-toggle');
  await page.waitForTimeout(300);
  assert.equal(await page.getAttribute('#debug-toggle', 'aria-pressed'), 'true');
  await screenshot(page, 'render-skeleton.png');
  await page.setViewportSize({ width: 390, height: 800 });
  await page.waitForTimeout(500);
  const size = await page.evaluate(() => {
    const c = document.getElementById('view');
    return { w: c.width, h: c.height, cw: c.clientWidth, ch: c.clientHeight, dpr: devicePixelRatio };
  });
  assert.equal(size.w, Math.round(size.cw * Math.min(size.dpr, 2)), 'the canvas follows its CSS size');
  await screenshot(page, 'render-phone.png');
});
