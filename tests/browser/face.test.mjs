// The face controls: the page offers them for an avatar with face morph targets, and choosing an
// emotion re-synthesises the clip so the avatar's face actually changes (the core's face layer
// writes morph weights; the player maps them onto the avatar's morph targets).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { launchBrowser, nextFrames, openPage, screenshot, startServer } from './harness.mjs';

let server, browser;
before(async () => { server = await startServer(); browser = await launchBrowser(); });
after(async () => { await browser?.close(); await server?.stop(); });

// The drawn canvas at t = 0 of the current clip (paused), as RGBA bytes.
async function frameAtStart(page) {
  await page.evaluate(() => window.signweave.playback.seek(0));
  await nextFrames(page, 3);
  return page.evaluate(() => {
    const gl = window.signweave.renderer.gl;
    return Array.from(window.signweave.readRegion(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight).pixels);
  });
}

function differingPixels(a, b) {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 24) n++;
  }
  return n;
}

test('choosing an emotion changes the face, and only the face control does it', async () => {
  const { page, problems } = await openPage(browser, server.base, `#/phrase?text=${encodeURIComponent('hello')}&lang=ase`);
  await page.waitForFunction(() => window.signweave.state.playing, null, { timeout: 30_000 });
  assert.equal(await page.isVisible('#face-controls'), true, 'face controls are shown');
  const emotions = await page.$$eval('#emotion option', (options) => options.map((o) => o.value));
  for (const e of ['neutral', 'happy', 'sad', 'angry', 'surprised']) assert.ok(emotions.includes(e), `emotion ${e} offered`);

  await page.click('#play');  // pause: compare the same instant of the clip
  await page.selectOption('#emotion', 'neutral');
  const neutral = await frameAtStart(page);
  const neutralAgain = await frameAtStart(page);
  assert.equal(differingPixels(neutral, neutralAgain), 0, 'the same pose draws the same pixels');

  await page.locator('#intensity').fill('1');
  await page.selectOption('#emotion', 'surprised');
  const surprised = await frameAtStart(page);
  await screenshot(page, 'face-surprised.png');
  const changed = differingPixels(neutral, surprised);
  assert.ok(changed > 30, `a surprised face differs from the neutral one (${changed} pixels)`);

  await page.selectOption('#emotion', 'neutral');
  const back = await frameAtStart(page);
  assert.ok(differingPixels(neutral, back) < changed / 4, 'back to neutral restores the face');
  assert.deepEqual(problems, []);
});
