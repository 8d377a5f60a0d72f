// Export: the current clip downloads as BVH and glTF binary written by the core, and both parse
// back — the BVH's hierarchy has the avatar's joints and its motion the clip's frames; the .glb is
// a valid glTF 2.0 container with an animation. A WebM of the canvas is recorded.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { after, before, test } from 'node:test';

import { launchBrowser, openPage, startServer } from './harness.mjs';

let server, browser, page;
before(async () => {
  server = await startServer();
  browser = await launchBrowser();
  ({ page } = await openPage(browser, server.base, '#/editor'));
  await page.fill('#editor-text', 'R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))');
  await page.waitForFunction(() => window.signweave.state.playing && window.signweave.state.clipDuration_s > 0, null, { timeout: 20_000 });
});
after(async () => { await browser?.close(); await server?.stop(); });

async function downloadVia(buttonId) {
  await page.click('.export summary');
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 60_000 }), page.click(`#${buttonId}`)]);
  const file = await download.path();
  return { name: download.suggestedFilename(), bytes: fs.readFileSync(file) };
}

// A small independent BVH reader: joints with their channel counts, then the motion table.
function parseBvh(text) {
  const words = text.split(/\s+/).filter(Boolean);
  let i = 0;
  const joints = [];
  assert.equal(words[i++], 'HIERARCHY');
  while (words[i] !== 'MOTION') {
    const w = words[i++];
    if (w === 'ROOT' || w === 'JOINT') joints.push({ name: words[i++], channels: 0 });
    else if (w === 'CHANNELS') {
      const n = Number(words[i++]);
      joints[joints.length - 1].channels = n;
      i += n;
    } else if (w === 'OFFSET') {
      for (let k = 0; k < 3; k++) assert.ok(Number.isFinite(Number(words[i++])), 'OFFSET numbers');
    }
    assert.ok(i < words.length, 'MOTION section present');
  }
  i++;
  assert.equal(words[i++], 'Frames:');
  const frames = Number(words[i++]);
  assert.equal(`${words[i++]} ${words[i++]}`, 'Frame Time:');
  const frameTime = Number(words[i++]);
  const values = words.slice(i).map(Number);
  return { joints, frames, frameTime, values };
}

test('BVH export parses back with the avatar skeleton and the clip timing', async () => {
  const { name, bytes } = await downloadVia('export-bvh');
  assert.match(name, /\.bvh$/);
  const bvh = parseBvh(bytes.toString('utf8'));
  const clip = await page.evaluate(() => ({
    duration: window.signweave.state.clipDuration_s,
    joints: window.signweave.core.info.joints.map((j) => j.name),
  }));
  const channels = bvh.joints.reduce((n, j) => n + j.channels, 0);
  assert.ok(bvh.joints.length >= 20, `${bvh.joints.length} joints in the hierarchy`);
  for (const j of bvh.joints) assert.ok(clip.joints.includes(j.name), `BVH joint ${j.name} is an avatar joint`);
  assert.equal(bvh.values.length, bvh.frames * channels, 'every frame has a value per channel');
  assert.ok(bvh.values.every(Number.isFinite), 'all values are numbers');
  assert.ok(Math.abs((bvh.frames - 1) * bvh.frameTime - clip.duration) < 2 * bvh.frameTime,
    `frames ${bvh.frames} × ${bvh.frameTime} s cover the clip's ${clip.duration} s`);
  // The motion moves: some channel varies over the frames.
  let varies = false;
  for (let c = 0; c < channels && !varies; c++) {
    const first = bvh.values[c];
    for (let f = 1; f < bvh.frames; f++) if (Math.abs(bvh.values[f * channels + c] - first) > 1) { varies = true; break; }
  }
  assert.ok(varies, 'the exported motion is not frozen');
});

test('glTF export is a valid .glb with an animation', async () => {
  const { name, bytes } = await downloadVia('export-glb');
  assert.match(name, /\.glb$/);
  assert.equal(bytes.toString('ascii', 0, 4), 'glTF');
  assert.equal(bytes.readUInt32LE(4), 2, 'glTF version 2');
  assert.equal(bytes.readUInt32LE(8), bytes.length, 'header length matches');
  const jsonLength = bytes.readUInt32LE(12);
  assert.equal(bytes.toString('ascii', 16, 20), 'JSON');
  const gltf = JSON.parse(bytes.toString('utf8', 20, 20 + jsonLength));
  assert.equal(gltf.asset.version, '2.0');
  assert.ok(gltf.animations?.length >= 1, 'an animation');
  const anim = gltf.animations[0];
  assert.ok(anim.channels.length > 10 && anim.samplers.length > 10, 'channels for the joints');
  for (const s of anim.samplers) {
    const input = gltf.accessors[s.input];
    assert.ok(input.count >= 2 && input.max[0] > 0, 'keyframe times');
  }
});

test('WebM recording of the canvas', async (t) => {
  const supported = await page.evaluate(() => typeof MediaRecorder !== 'undefined' && MediaRecorder.isTypeSupported('video/webm'));
  if (!supported) { t.skip('this chromium has no WebM MediaRecorder (the page hides the button)'); return; }
  const { name, bytes } = await downloadVia('export-webm');
  assert.match(name, /\.webm$/);
  assert.deepEqual([...bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'EBML header');
  assert.ok(bytes.length > 2000, `${bytes.length} bytes of video`);
});
