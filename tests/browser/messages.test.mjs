// What the page says when something is missing: no WebGL2 (a clear message, no crash), an
// unreachable API (a banner; the signer still loads and the editor still previews), and no
// WebAssembly SIMD (the scalar build is used silently, everything works). Plus keyboard access.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { launchBrowser, screenshot, startServer } from './harness.mjs';

let server, browser;
before(async () => { server = await startServer(); browser = await launchBrowser(); });
after(async () => { await browser?.close(); await server?.stop(); });

async function open(hash, { init, route } = {}) {
  const context = await browser.newContext({ viewport: { width: 1000, height: 700 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  if (init) await page.addInitScript(init);
  if (route) await page.route(route, (r) => r.abort('connectionrefused'));
  await page.goto(`${server.base}/${hash}`);
  await page.waitForFunction(() => window.signweave && (window.signweave.state.ready || window.signweave.state.error), null, { timeout: 60_000 });
  return { page, errors };
}

test('without WebGL2 the page says so instead of failing silently', async () => {
  const { page, errors } = await open('#/', {
    init: () => {
      const original = HTMLCanvasElement.prototype.getContext;
      HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
        return type === 'webgl2' ? null : original.call(this, type, ...rest);
      };
    },
  });
  const banner = await page.textContent('#banner');
  assert.match(banner, /WebGL2 is missing/);
  assert.equal(await page.isVisible('#banner'), true);
  assert.deepEqual(errors, []);
  await screenshot(page, 'message-no-webgl2.png');
});

test('an unreachable API is announced, and the signer and editor still work', async () => {
  const { page, errors } = await open('#/editor', { route: '**/api/**' });
  assert.equal(await page.evaluate(() => window.signweave.state.ready), true);
  assert.match(await page.textContent('#banner'), /cannot be reached/);
  await page.fill('#editor-text', 'R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))');
  await page.waitForSelector('#editor-diagnostics li.ok', { timeout: 20_000 });
  await page.goto(`${server.base}/#/`);
  await page.fill('#search', 'hello');
  await page.waitForFunction(() => /cannot be reached/.test(document.getElementById('search-status').textContent), null, { timeout: 20_000 });
  assert.deepEqual(errors, []);
  await screenshot(page, 'message-unreachable.png');
});

test('without WebAssembly SIMD the scalar core loads silently', async () => {
  const { page, errors } = await open('#/editor', {
    init: () => {
      const validate = WebAssembly.validate;
      // The SIMD probe is the only module the page validates; report it unsupported.
      WebAssembly.validate = (bytes) => (bytes.byteLength < 64 ? false : validate(bytes));
    },
  });
  assert.equal(await page.evaluate(() => window.signweave.state.flavour), 'scalar');
  assert.equal(await page.isVisible('#banner'), false, 'no message for a silent fallback');
  await page.fill('#editor-text', 'R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))');
  await page.waitForFunction(() => window.signweave.state.playing && window.signweave.state.clipDuration_s > 0, null, { timeout: 20_000 });
  assert.deepEqual(errors, []);
});

test('keyboard: tabs, search results and playback are reachable without a mouse', async () => {
  const { page } = await open('#/');
  await page.focus('#search');
  await page.keyboard.type('hel');
  await page.waitForSelector('#results a', { timeout: 20_000 });
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.evaluate(() => document.activeElement.closest('#results') !== null), true);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => location.hash.startsWith('#/sign/'));
  await page.waitForFunction(() => window.signweave.state.playing, null, { timeout: 20_000 });
  await page.focus('#view');
  await page.keyboard.press(' ');
  assert.equal(await page.evaluate(() => window.signweave.state.playing), false, 'space pauses');
  await page.keyboard.press('3');   // side preset from the canvas
  // Every control has an accessible name.
  const unnamed = await page.evaluate(() => [...document.querySelectorAll('button, input, select, textarea, canvas')]
    .filter((el) => !el.hidden && el.type !== 'hidden' && !(el.getAttribute('aria-label') || el.labels?.length || el.textContent.trim() || el.title))
    .map((el) => el.id || el.outerHTML.slice(0, 60)));
  assert.deepEqual(unnamed, []);
});
