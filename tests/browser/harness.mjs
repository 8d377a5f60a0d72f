// harness.mjs — what every browser test shares: start the real signweave-server (built natively)
// on a free loopback port with a fresh temporary database created from data/, launch the Debian
// chromium through playwright-core with the flags TOOLCHAIN.md verified (SwiftShader WebGL2), open
// the page and wait until the signer is ready, save screenshots under tests/artifacts/.
// Not a test file itself (no .test.mjs): node --test only runs the *.test.mjs beside it.

import { spawn } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const ARTIFACTS = path.join(ROOT, 'tests', 'artifacts');
export const SERVER_BIN = path.join(ROOT, 'build', 'native', 'signweave-server');

export const CHROMIUM_ARGS = [
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox', '--disable-quic',
  '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync',
];

export function freePort() {
  return new Promise((resolve, reject) => {
    const srv = net.createServer();
    srv.unref();
    srv.on('error', reject);
    srv.listen(0, '127.0.0.1', () => {
      const { port } = srv.address();
      srv.close(() => resolve(port));
    });
  });
}

// What the browser tests need built; a missing piece is named so the failure says what to build.
export function missingPrerequisites() {
  const missing = [];
  if (!fs.existsSync(SERVER_BIN)) missing.push('build/native/signweave-server (./signweave build)');
  for (const f of ['signweave-simd.js', 'signweave-simd.wasm', 'signweave-scalar.js', 'signweave-scalar.wasm']) {
    if (!fs.existsSync(path.join(ROOT, 'web', 'gen', f))) missing.push(`web/gen/${f} (./signweave build)`);
  }
  if (!fs.existsSync(path.join(ROOT, 'models', 'signweave-avatar.glb'))) missing.push('models/signweave-avatar.glb');
  if (!fs.existsSync(path.join(ROOT, 'web', 'gen', 'signweave-avatar.swavatar'))) missing.push('web/gen/signweave-avatar.swavatar (./signweave build)');
  return missing;
}

// The admin token the test server accepts for writes (SIGNWEAVE_ADMIN_TOKEN, server/main.cpp).
export const TEST_TOKEN = 'browser-test-token-4f9c2a7e1b';

export async function startServer({ extraArgs = [] } = {}) {
  const missing = missingPrerequisites();
  if (missing.length) throw new Error(`browser tests need: ${missing.join(', ')}`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'signweave-browser-'));
  const db = path.join(dir, 'test.db');
  const port = await freePort();
  const args = ['--host', '127.0.0.1', '--port', String(port), '--db', db,
    '--web', path.join(ROOT, 'web'), '--data', path.join(ROOT, 'data'), ...extraArgs];
  const child = spawn(SERVER_BIN, args, {
    cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe'], env: { ...process.env, SIGNWEAVE_ADMIN_TOKEN: TEST_TOKEN },
  });
  let log = '';
  child.stdout.on('data', (d) => { log += d; });
  child.stderr.on('data', (d) => { log += d; });
  const base = `http://127.0.0.1:${port}`;
  const deadline = Date.now() + 30_000;
  for (;;) {
    if (child.exitCode !== null) throw new Error(`signweave-server exited (${child.exitCode}):\n${log}`);
    try {
      const r = await fetch(`${base}/healthz`);
      if (r.ok) break;
    } catch { /* not listening yet */ }
    if (Date.now() > deadline) { child.kill('SIGKILL'); throw new Error(`signweave-server did not become healthy:\n${log}`); }
    await new Promise((r) => setTimeout(r, 100));
  }
  return {
    base, db, dir, child,
    log: () => log,
    async stop() {
      if (child.exitCode === null) {
        child.kill('SIGTERM');
        await new Promise((resolve) => {
          const t = setTimeout(() => { child.kill('SIGKILL'); resolve(); }, 5000);
          child.once('exit', () => { clearTimeout(t); resolve(); });
        });
      }
      fs.rmSync(dir, { recursive: true, force: true });
    },
  };
}

export async function launchBrowser() {
  const { chromium } = await import('playwright-core');
  return chromium.launch({ executablePath: '/usr/bin/chromium', args: CHROMIUM_ARGS });
}

// Opens the page at `hash` and waits for window.signweave.state.ready (or a reported error).
export async function openPage(browser, base, hash = '', { width = 1200, height = 800 } = {}) {
  const context = await browser.newContext({ viewport: { width, height }, acceptDownloads: true });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  await page.goto(`${base}/${hash}`);
  await page.waitForFunction(() => window.signweave && (window.signweave.state.ready || window.signweave.state.error),
    null, { timeout: 60_000 });
  const error = await page.evaluate(() => window.signweave.state.error);
  if (error) throw new Error(`the page reported: ${error}\n${problems.join('\n')}`);
  return { page, context, problems };
}

export async function screenshot(page, name) {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  const file = path.join(ARTIFACTS, name);
  await page.screenshot({ path: file });
  return file;
}

// RGBA pixels of the canvas as drawn (the context keeps its drawing buffer for exactly this).
export async function canvasPixels(page) {
  return page.evaluate(() => {
    const canvas = document.getElementById('view');
    const gl = canvas.getContext('webgl2');
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const pixels = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return { width: w, height: h, data: Array.from(pixels) };
  });
}

// Wait until the play head is past `time_s` (playing clips only).
export async function waitForTime(page, time_s, timeout = 30_000) {
  await page.waitForFunction((t) => window.signweave.state.time_s >= t, time_s, { timeout });
}

// Wait until the page has drawn `count` more frames (after a seek, so the pixels show the new pose).
export async function nextFrames(page, count = 2) {
  const start = await page.evaluate(() => window.signweave.metrics.frames);
  await page.waitForFunction((n) => window.signweave.metrics.frames >= n, start + count, { timeout: 30_000 });
}
