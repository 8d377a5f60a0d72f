// web/js/core_loader.js in a real browser (Debian chromium through playwright-core): the <script>
// path, SIMD detection, download progress, and the silent fallback when the SIMD build cannot be
// fetched. Serves web/ itself from a tiny static server, so it needs no signweave-server.
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';

import { chromium } from 'playwright-core';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const WEB = path.join(ROOT, 'web');
const CHROMIUM = '/usr/bin/chromium';
const TYPES = { '.js': 'text/javascript', '.wasm': 'application/wasm', '.html': 'text/html' };

let server;
let browser;
let base;
const blocked = new Set(); // paths the server answers with 404, to simulate a missing SIMD build

before(async () => {
  for (const f of ['signweave-simd.js', 'signweave-simd.wasm', 'signweave-scalar.js', 'signweave-scalar.wasm']) {
    assert.ok(existsSync(path.join(WEB, 'gen', f)), `web/gen/${f} is missing: run ./signweave build`);
  }
  server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    const file = path.join(WEB, path.normalize(url.pathname));
    if (url.pathname === '/') {
      res.writeHead(200, { 'content-type': 'text/html' }).end('<!doctype html><title>loader</title>');
    } else if (!file.startsWith(WEB) || blocked.has(url.pathname) || !existsSync(file)) {
      res.writeHead(404).end();
    } else {
      const body = readFileSync(file);
      res.writeHead(200, { 'content-type': TYPES[path.extname(file)] ?? 'application/octet-stream', 'content-length': body.length });
      res.end(body);
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  base = `http://127.0.0.1:${server.address().port}`;
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync'],
  });
});

after(async () => {
  await browser?.close();
  await new Promise((resolve) => (server ? server.close(resolve) : resolve()));
});

async function loadInPage() {
  const page = await browser.newPage();
  try {
    await page.goto(base + '/');
    return await page.evaluate(async () => {
      const { loadCore, simdSupported } = await import('/js/core_loader.js');
      const progress = [];
      const { module, flavour } = await loadCore({ onProgress: (f) => progress.push(f) });
      return {
        flavour,
        simdSupported: simdSupported(),
        moduleSimd: module.simd(),
        quat: module.quatFromEuler(0, 0, Math.PI / 2, 'XYZ'),
        progress,
      };
    });
  } finally {
    await page.close();
  }
}

test('chromium gets the SIMD build through a script tag, with download progress', async () => {
  const r = await loadInPage();
  assert.equal(r.simdSupported, true);
  assert.equal(r.flavour, 'simd');
  assert.equal(r.moduleSimd, true);
  assert.ok(Math.abs(r.quat[0] - Math.SQRT1_2) < 1e-6 && Math.abs(r.quat[3] - Math.SQRT1_2) < 1e-6, String(r.quat));
  assert.ok(r.progress.length >= 2, 'progress reported while downloading');
  assert.equal(r.progress.at(-1), 1);
  for (let i = 1; i < r.progress.length; ++i) assert.ok(r.progress[i] >= r.progress[i - 1], 'progress never goes back');
});

test('a missing SIMD build falls back to scalar silently', async () => {
  blocked.add('/gen/signweave-simd.wasm');
  try {
    const r = await loadInPage();
    assert.equal(r.flavour, 'scalar');
    assert.equal(r.moduleSimd, false);
  } finally {
    blocked.clear();
  }
});
