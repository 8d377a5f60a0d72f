// Dictionary: search the real server as you type, open a sign, and the avatar plays it in a loop
// with its notation and keywords shown; the sign's URL (#/sign/ID) opens it directly.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { launchBrowser, openPage, screenshot, startServer, waitForTime } from './harness.mjs';

let server, browser, sign;
before(async () => {
  server = await startServer();
  browser = await launchBrowser();
  const list = await (await fetch(`${server.base}/api/signs?q=&limit=50`)).json();
  const hits = list.hits;
  // A sign with a gloss of a few letters and keywords makes the search meaningful.
  sign = hits.find((s) => /^[A-Za-z]{3,}/.test(s.gloss) && (s.keywords || []).length) || hits[0];
  assert.ok(sign, 'the database created from data/ has signs');
});
after(async () => { await browser?.close(); await server?.stop(); });

test('search finds a sign by its gloss prefix, and opening it plays it in a loop', async () => {
  const { page, problems } = await openPage(browser, server.base, '#/');
  const prefix = sign.gloss.slice(0, 3).toLowerCase();
  await page.fill('#search', prefix);
  const link = page.locator(`#results a[data-sign-id="${sign.id}"]`);
  await link.waitFor({ timeout: 10_000 });
  await screenshot(page, 'dictionary-results.png');
  await link.click();
  await page.waitForFunction((id) => location.hash === `#/sign/${id}`, sign.id);
  await page.waitForFunction(() => window.signweave.state.playing && window.signweave.state.clipDuration_s > 0, null, { timeout: 20_000 });
  const shown = await page.evaluate(() => ({
    gloss: document.getElementById('sign-gloss').textContent,
    notation: document.getElementById('sign-notation').textContent,
    keywords: document.getElementById('sign-keywords').textContent,
    loop: window.signweave.playback.loop,
    duration: window.signweave.state.clipDuration_s,
  }));
  assert.equal(shown.gloss, sign.gloss);
  assert.equal(shown.notation, sign.notation);
  assert.ok(shown.loop, 'a sign page loops');
  // The sign is held in its segment: at some time the state names it.
  await page.waitForFunction((gloss) => window.signweave.state.currentSign === gloss, sign.gloss, { timeout: 20_000 });
  // Looping: the play head passes the end and comes back while still playing.
  await waitForTime(page, shown.duration * 0.8);
  await page.waitForFunction((d) => window.signweave.state.time_s < d * 0.5 && window.signweave.state.playing, shown.duration, { timeout: 30_000 });
  await screenshot(page, 'dictionary-sign.png');
  assert.deepEqual(problems, []);
});

test('a shared sign URL opens the sign directly', async () => {
  const { page } = await openPage(browser, server.base, `#/sign/${sign.id}`);
  await page.waitForFunction(() => window.signweave.state.playing, null, { timeout: 20_000 });
  assert.equal(await page.textContent('#sign-gloss'), sign.gloss);
  assert.equal(await page.getAttribute('[data-tab="dictionary"]', 'aria-current'), 'page');
});

test('an unknown sign id and an empty search say so', async () => {
  const { page } = await openPage(browser, server.base, '#/sign/999999999');
  await page.waitForFunction(() => /no sign/i.test(document.getElementById('search-status').textContent));
  await page.fill('#search', 'qqqqzzzzxxxx');
  await page.waitForFunction(() => /No sign found/.test(document.getElementById('search-status').textContent));
});
