// The page exposes its start-up timeline (web/js/startup_metrics.js) on window.signweave.metrics.startup
// for bench/web_bench.mjs: every step from navigation to the first signing frame is marked, in an
// order that makes sense, and the downloads the first frame needs start together rather than one
// after another. No timing thresholds here: speed targets live in the bench.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { launchBrowser, startServer } from './harness.mjs';

let server, browser;
before(async () => { server = await startServer(); browser = await launchBrowser(); });
after(async () => { await browser?.close(); await server?.stop(); });

const STEPS = ['app-start', 'wasm-fetch-start', 'wasm-script-loaded', 'wasm-instantiated', 'avatar-fetched',
  'avatar-parsed', 'mesh-uploaded', 'programs-linked', 'signer-ready', 'ready', 'sign-requested', 'sign-arrived', 'sign-fetched',
  'sign-synthesised', 'first-avatar-frame', 'first-signing-frame'];

// Steps a #/sign/ID link does not wait for before it signs.
const NOT_BEFORE_FIRST_FRAME = new Set(['ready']);

// Each pair: the first step happens no later than the second.
const BEFORE = [
  ['app-start', 'wasm-fetch-start'], ['wasm-fetch-start', 'wasm-instantiated'],
  ['wasm-script-loaded', 'wasm-instantiated'], ['avatar-fetched', 'avatar-parsed'],
  ['wasm-instantiated', 'avatar-parsed'], ['avatar-parsed', 'mesh-uploaded'], ['mesh-uploaded', 'programs-linked'],
  ['programs-linked', 'signer-ready'], ['signer-ready', 'ready'], ['sign-requested', 'sign-arrived'], ['sign-arrived', 'sign-fetched'],
  ['sign-fetched', 'sign-synthesised'], ['signer-ready', 'sign-synthesised'],
  ['sign-synthesised', 'first-signing-frame'], ['signer-ready', 'first-avatar-frame'],
  ['first-avatar-frame', 'first-signing-frame'],
  // Started together: the routed sign is asked for while the core is still loading, not after it.
  ['sign-requested', 'wasm-instantiated'], ['app-start', 'sign-requested'],
];

test('the start-up timeline is exposed, complete and ordered from navigation to the first signing frame', async () => {
  const context = await browser.newContext({ viewport: { width: 1000, height: 700 } });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  try {
    const list = await (await fetch(`${server.base}/api/signs?q=&limit=1`)).json();
    const id = list.hits[0].id;
    await page.goto(`${server.base}/#/sign/${encodeURIComponent(id)}`);
    await page.waitForFunction(() => window.signweave?.metrics.firstSigningFrame_ms !== null || window.signweave?.state.error,
      null, { timeout: 60_000 });
    const r = await page.evaluate(() => ({
      error: window.signweave.state.error,
      first: window.signweave.metrics.firstSigningFrame_ms,
      startup: window.signweave.metrics.startup,
      userTiming: performance.getEntriesByType('mark').map((m) => m.name),
    }));
    assert.equal(r.error, null);
    const { marks, measures, resources } = r.startup;
    for (const step of STEPS) {
      assert.ok(Number.isFinite(marks[step]) && marks[step] >= 0, `mark ${step}: ${marks[step]}`);
      // 'ready' (the language list loaded) is not on a #/sign link's path: the sign plays without
      // it (app.js), so it may come just after the first signing frame. Every other step is before.
      if (!NOT_BEFORE_FIRST_FRAME.has(step)) {
        assert.ok(marks[step] <= r.first + 0.1, `${step} (${marks[step]} ms) after the first signing frame (${r.first} ms)`);
      }
      assert.ok(r.userTiming.includes(`sw:${step}`), `sw:${step} is a User Timing mark too`);
    }
    assert.ok(Math.abs(marks['first-signing-frame'] - r.first) < 0.1, 'the mark is the metric the bench reads');
    for (const [a, b] of BEFORE) assert.ok(marks[a] <= marks[b], `${a} (${marks[a]} ms) should not come after ${b} (${marks[b]} ms)`);
    assert.ok(marks['html-received'] <= marks['app-start'], 'the page arrived before its script ran');
    for (const [name, ms] of Object.entries(measures)) assert.ok(Number.isFinite(ms) && ms >= 0, `span ${name}: ${ms}`);
    for (const span of ['wasm-download-and-compile', 'avatar-parse', 'sign-fetch', 'synthesis']) assert.ok(span in measures, `span ${span}`);

    // The waterfall: the core and the avatar were requested before either had finished arriving.
    // The avatar comes as the pack ./signweave build makes (src/avatar/avatar_pack.h), not as glTF.
    const wasm = resources.find((x) => /^gen\/signweave-(simd|scalar)\.wasm$/.test(x.name));
    const avatar = resources.find((x) => x.name === 'gen/signweave-avatar.swavatar');
    assert.ok(wasm && avatar, `resources: ${resources.map((x) => x.name).join(', ')}`);
    assert.ok(!resources.some((x) => x.name === 'models/signweave-avatar.glb'), 'the .glb is not downloaded beside the pack');
    assert.ok(avatar.start_ms <= wasm.end_ms && wasm.start_ms <= avatar.end_ms, `downloads overlap: wasm ${wasm.start_ms}–${wasm.end_ms}, avatar ${avatar.start_ms}–${avatar.end_ms}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('without the avatar pack (a server lacking the generated files) the page loads the .glb and signs', async () => {
  const context = await browser.newContext({ viewport: { width: 1000, height: 700 } });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.route('**/gen/signweave-avatar.swavatar', (route) => route.fulfill({ status: 404, body: 'not found' }));
  try {
    const list = await (await fetch(`${server.base}/api/signs?q=&limit=1`)).json();
    await page.goto(`${server.base}/#/sign/${encodeURIComponent(list.hits[0].id)}`);
    await page.waitForFunction(() => window.signweave?.metrics.firstSigningFrame_ms !== null || window.signweave?.state.error,
      null, { timeout: 60_000 });
    const r = await page.evaluate(() => ({
      error: window.signweave.state.error,
      vertices: window.signweave.core?.info?.vertex_count,
      anchors: window.signweave.core?.info?.anchors?.length,
      resources: window.signweave.metrics.startup.resources.map((x) => x.name),
    }));
    assert.equal(r.error, null);
    assert.ok(r.resources.includes('models/signweave-avatar.glb'), `resources: ${r.resources.join(', ')}`);
    assert.ok(r.vertices > 1000 && r.anchors > 50, `the glTF avatar loaded with its anchors computed: ${JSON.stringify(r)}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
