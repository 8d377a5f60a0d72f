// Typed phrase → signing against the real server: the page shows the server's lookup plan (a
// known word as its sign, an unknown word fingerspelled, a pause at the comma), the caption follows
// the words as they are signed, and the hands really move (pixels in the hand region change).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { launchBrowser, nextFrames, openPage, screenshot, startServer } from './harness.mjs';

let server, browser, keyword, language;
before(async () => {
  server = await startServer();
  browser = await launchBrowser();
  const list = await (await fetch(`${server.base}/api/signs?q=&limit=100`)).json();
  const hits = list.hits;
  // A one-word keyword of a sign whose language has an alphabet (so an unknown word can be spelled).
  for (const s of hits) {
    const word = (s.keywords || []).map((k) => (typeof k === 'string' ? k : k.word)).find((k) => /^[a-z]{3,}$/i.test(k));
    if (!word) continue;
    const plan = await (await fetch(`${server.base}/api/lookup?text=${encodeURIComponent(`${word} zqx`)}&lang=${s.language}`)).json();
    const kinds = (plan.tokens || []).map((t) => String(t.type));
    if (kinds.some((k) => /finger/i.test(k))) { keyword = word; language = s.language; break; }
  }
  assert.ok(keyword, 'a sign with a keyword, in a language with an alphabet');
});
after(async () => { await browser?.close(); await server?.stop(); });

const handRegion = (page) => page.evaluate(() => {
  const sw = window.signweave;
  const l = sw.projectJoint('leftHand'), r = sw.projectJoint('rightHand');
  return { l, r };
});

async function regionAt(page, time_s, box) {
  await page.evaluate((t) => { window.signweave.playback.pause(); window.signweave.playback.seek(t); }, time_s);
  await nextFrames(page);   // the core poses, the renderer draws
  return page.evaluate((b) => window.signweave.readRegion(b.x, b.y, b.width, b.height).pixels, box);
}

test('a phrase is planned, fingerspells the unknown word, captions the words and moves the hands', async () => {
  const text = `${keyword}, zqx`;
  const expected = await (await fetch(`${server.base}/api/lookup?text=${encodeURIComponent(text)}&lang=${language}`)).json();
  const { page, problems } = await openPage(browser, server.base, `#/phrase?text=${encodeURIComponent(text)}&lang=${language}`);
  await page.waitForFunction(() => window.signweave.state.playing && window.signweave.state.clipDuration_s > 0, null, { timeout: 30_000 });

  // The plan on the page is the server's plan, token for token.
  const planned = await page.$$eval('#plan li', (items) => items.map((li) => li.textContent));
  assert.equal(planned.length, expected.tokens.length);
  const kinds = expected.tokens.map((t) => String(t.type).toLowerCase());
  assert.ok(kinds.some((k) => k.startsWith('finger')), `the unknown word is fingerspelled: ${kinds}`);
  assert.ok(kinds.includes('pause'), `the comma is a pause: ${kinds}`);
  assert.match(planned[0], new RegExp(keyword, 'i'));
  assert.match(planned.find((p) => /fingerspelled/.test(p)), /Z-Q-X/i);

  // The caption follows the phrase: in each word's segments the state and the caption name it.
  // (Seeking, not waiting: headless SwiftShader may draw only a few frames a second.)
  const segments = await page.evaluate(() => window.signweave.playback.segments);
  const words = [];
  await page.evaluate(() => window.signweave.playback.pause());
  for (const seg of segments.filter((sg) => sg.word_index >= 0 && sg.kind !== 'pause')) {
    await page.evaluate((t) => window.signweave.playback.seek(t), (seg.start_s + seg.end_s) / 2);
    const word = await page.evaluate(() => window.signweave.state.currentWord);
    await page.waitForFunction((w) => document.querySelector('#caption .word.current')?.textContent === w, word);
    words.push(word.toLowerCase());
  }
  assert.ok(words.includes(keyword.toLowerCase()) && words.includes('zqx'), `caption words: ${words}`);
  assert.deepEqual(segments.filter((sg) => sg.kind === 'letter').map((sg) => sg.label.toUpperCase()), ['Z', 'Q', 'X']);
  await screenshot(page, 'phrase-playing.png');

  // The hands move: a region around both hands differs between two moments of the sign.
  const duration = await page.evaluate(() => window.signweave.state.clipDuration_s);
  const firstSign = segments.find((s) => s.kind !== 'transition' && s.kind !== 'pause') || { start_s: duration * 0.3, end_s: duration * 0.5 };
  await page.evaluate(() => { window.signweave.playback.pause(); window.signweave.playback.seek(0); });
  await nextFrames(page);
  const rest = await handRegion(page);
  const mid = (firstSign.start_s + firstSign.end_s) / 2;
  await page.evaluate((t) => window.signweave.playback.seek(t), mid);
  await nextFrames(page);
  const signing = await handRegion(page);
  const xs = [rest.l.x, rest.r.x, signing.l.x, signing.r.x], ys = [rest.l.y, rest.r.y, signing.l.y, signing.r.y];
  const pad = 40;
  const box = { x: Math.min(...xs) - pad, y: Math.min(...ys) - pad, width: Math.max(...xs) - Math.min(...xs) + 2 * pad, height: Math.max(...ys) - Math.min(...ys) + 2 * pad };
  const a = await regionAt(page, 0, box);
  await screenshot(page, 'phrase-rest.png');
  const b = await regionAt(page, mid, box);
  await screenshot(page, 'phrase-signing.png');
  let changed = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 30) changed++;
  }
  const share = changed / (a.length / 4);
  assert.ok(share > 0.02, `only ${(share * 100).toFixed(2)}% of the hand region changed between rest and signing`);
  assert.deepEqual(problems, []);
});

test('speed, loop and the timeline control playback', async () => {
  const { page } = await openPage(browser, server.base, `#/phrase?text=${encodeURIComponent(keyword)}&lang=${language}`);
  await page.waitForFunction(() => window.signweave.state.playing, null, { timeout: 30_000 });
  await page.selectOption('#speed', '0.25');
  assert.equal(await page.evaluate(() => window.signweave.playback.speed), 0.25);
  await page.click('#play');
  assert.equal(await page.evaluate(() => window.signweave.state.playing), false);
  await page.locator('#timeline').fill('0.5');
  const t = await page.evaluate(() => window.signweave.state.time_s / window.signweave.state.clipDuration_s);
  assert.ok(Math.abs(t - 0.5) < 0.01, `scrubbed to ${t}`);
  await page.uncheck('#loop');
  await page.selectOption('#speed', '2');
  await page.click('#play');
  await page.waitForFunction(() => !window.signweave.state.playing, null, { timeout: 30_000 });
  const end = await page.evaluate(() => window.signweave.state.time_s - window.signweave.state.clipDuration_s);
  assert.ok(Math.abs(end) < 1e-6, 'without loop, playback stops at the end');
});
