// The avatar on screen with a fist and with a spread hand (issue 3): the editor previews each
// handshape, the camera goes to the hands, and the picture is checked where the hand is drawn —
// skin-coloured pixels at the projected hand, fingertips far from the wrist when spread and
// curled back when in a fist — and the ASL letter S seen from the front, the thumb across the
// front of the fingers (issue 4: it used to stick straight out). Screenshots: avatar-fist.png,
// avatar-spread.png, avatar-asl-s.png.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { launchBrowser, nextFrames, openPage, screenshot, startServer } from './harness.mjs';

let server, browser;
before(async () => { server = await startServer(); browser = await launchBrowser(); });
after(async () => { await browser?.close(); await server?.stop(); });

const FIST = 'R(H(fist, thumbacross), E(uo), P(l), Loc(neutral, right))';
const SPREAD = 'R(H(finger2345, thumbout), E(u), P(o), Loc(neutral, right))';
// ASL S (data/ase/alphabet.jsonl), palm towards the viewer.
const ASL_S = 'R(H(fist, thumbacross), E(u), P(o), Loc(neutral, right))';

async function showHand(page, notation, picture) {
  await page.fill('#editor-text', notation);
  // The preview has run for THIS text (the highlight layer is redrawn from it, plus a zero-width
  // space): an 'ok' left from the previous text must not let the test measure the previous pose.
  await page.waitForFunction((t) => document.getElementById('editor-highlight').textContent.replace('\u200b', '') === t, notation, { timeout: 10_000 });
  await page.waitForSelector('#editor-diagnostics li.ok', { timeout: 10_000 });
  await page.waitForFunction(() => window.signweave.state.playing && window.signweave.state.clipDuration_s > 0);
  if (await page.evaluate(() => window.signweave.state.playing)) await page.click('#play');
  // The middle of the clip is the hold of the key pose.
  await page.evaluate(() => window.signweave.playback.seek(window.signweave.state.clipDuration_s / 2));
  await page.click('[data-preset="hands"]');
  await nextFrames(page, 4);
  await screenshot(page, picture);
  return page.evaluate(() => {
    const sw = window.signweave;
    const at = (name) => sw.projectJoint(name);
    const wrist = at('rightHand'), knuckle = at('rightMiddleProximal');
    const tips = ['rightIndexTip', 'rightMiddleTip', 'rightLittleTip'].map(at);
    const dist = (a, b) => Math.hypot(a.x - b.x, a.y - b.y);
    const palm = dist(wrist, knuckle);
    // Skin-coloured pixels in a box around the hand (reddish, lit): the hand is really drawn.
    const r = 2.5 * palm;
    const box = sw.readRegion(wrist.x - r, wrist.y - r, 2 * r, 2 * r);
    let skin = 0;
    for (let i = 0; i < box.pixels.length; i += 4) {
      const [R, G, B] = [box.pixels[i], box.pixels[i + 1], box.pixels[i + 2]];
      if (R > 110 && R > G + 15 && G > B) skin++;
    }
    const across = ['rightThumbTip', 'rightIndexIntermediate', 'rightMiddleIntermediate', 'rightRingIntermediate'].map(at);
    return {
      across,
      palm_px: palm,
      reach: dist(wrist, tips[1]) / palm,     // middle fingertip from the wrist, in palm lengths
      span: dist(tips[0], tips[2]) / palm,    // index tip to little tip
      skin,
    };
  });
}

test('the avatar makes a fist and a spread hand that read on screen', async () => {
  const { page, problems } = await openPage(browser, server.base, '#/editor');
  await page.selectOption('#editor-format', 'formula');
  const fist = await showHand(page, FIST, 'avatar-fist.png');
  const spread = await showHand(page, SPREAD, 'avatar-spread.png');
  assert.ok(fist.palm_px > 8, `the hands preset shows the hand large enough (${fist.palm_px.toFixed(1)} px palm)`);
  assert.ok(fist.skin > 150, `the fist is drawn (${fist.skin} skin pixels)`);
  assert.ok(spread.skin > fist.skin, `the spread hand covers more of the picture (${spread.skin} vs ${fist.skin})`);
  // A straight middle finger reaches about two palm lengths from the wrist; a fist curls it back.
  assert.ok(spread.reach > 1.6, `spread: fingertip at ${spread.reach.toFixed(2)} palm lengths`);
  assert.ok(fist.reach < 1.3, `fist: fingertip at ${fist.reach.toFixed(2)} palm lengths`);
  assert.ok(spread.span > fist.span * 1.3, `spread fingers fan out (${spread.span.toFixed(2)} vs ${fist.span.toFixed(2)})`);
  assert.deepEqual(problems, []);
});

test('the ASL S hand shows the thumb across the front of the fingers', async () => {
  const { page, problems } = await openPage(browser, server.base, '#/editor');
  await page.selectOption('#editor-format', 'formula');
  const s = await showHand(page, ASL_S, 'avatar-asl-s.png');
  const [thumb, index, middle, ring] = s.across;
  const dist = (a, b) => Math.hypot(a.x - b.x, a.y - b.y);
  // Seen from the front the thumb tip lies over the fingers: across the hand between the index
  // and ring middle joints, and near the index/middle middle joints (not off to the side).
  const lo = Math.min(index.x, ring.x), hi = Math.max(index.x, ring.x);
  assert.ok(thumb.x > lo && thumb.x < hi, `thumb tip x ${thumb.x.toFixed(1)} between index ${index.x.toFixed(1)} and ring ${ring.x.toFixed(1)}`);
  const mid = { x: (index.x + middle.x) / 2, y: (index.y + middle.y) / 2 };
  assert.ok(dist(thumb, mid) < 0.8 * s.palm_px, `thumb tip ${dist(thumb, mid).toFixed(1)} px from the middle joints (palm ${s.palm_px.toFixed(1)} px)`);
  assert.deepEqual(problems, []);
});
