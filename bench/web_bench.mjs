// web_bench.mjs — the page measured in headless Chromium on localhost against the real server:
//   web.first_signing_frame_ms   navigation start → first frame drawn while a sign plays (target < 1500)
//   web.transfer_bytes           bytes on the wire (compressed) to get there, avatar included (< 1.5 MB)
//   web.frame_work_ms_p50/_p95   main-thread time per frame for pose + skinning + upload (< 2 ms)
// Prints JSON lines {"name", "value", "unit"}. Cold cache per run (a fresh browser context); the
// median of RUNS runs is reported. SwiftShader renders on the CPU, so the GPU-side cost here is an
// upper bound of a real GPU's; the WASM work is what a user's CPU does.
import { launchBrowser, startServer } from '../tests/browser/harness.mjs';

const RUNS = 3;
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const percentile = (xs, p) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(xs.length * p))];
const emit = (name, value, unit, extra = {}) => console.log(JSON.stringify({ name, value: Number(value.toFixed(3)), unit, ...extra }));

let server, browser;
try {
  server = await startServer();
  browser = await launchBrowser();
  const list = await (await fetch(`${server.base}/api/signs?q=&limit=1`)).json();
  const first = (list.hits)[0];
  const firstFrames = [], transfers = [];
  let samples = [], flavour = '';
  for (let run = 0; run < RUNS; run++) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Network.enable');
    await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
    let bytes = 0;
    cdp.on('Network.loadingFinished', (e) => { bytes += e.encodedDataLength; });
    await page.goto(`${server.base}/#/sign/${first.id}`);
    await page.waitForFunction(() => window.signweave?.metrics.firstSigningFrame_ms !== null || window.signweave?.state.error, null, { timeout: 60_000 });
    const result = await page.evaluate(() => ({ first: window.signweave.metrics.firstSigningFrame_ms, error: window.signweave.state.error, flavour: window.signweave.state.flavour }));
    if (result.error) throw new Error(result.error);
    firstFrames.push(result.first);
    transfers.push(bytes);
    flavour = result.flavour;
    if (run === RUNS - 1) {
      await page.waitForTimeout(3000);   // ~180 frames of playback
      samples = await page.evaluate(() => window.signweave.metrics.frameWorkSamples);
    }
    await context.close();
  }
  emit('web.first_signing_frame_ms', median(firstFrames), 'ms', { target: 1500, runs: firstFrames.map((v) => Math.round(v)) });
  emit('web.transfer_bytes', median(transfers), 'bytes', { target: 1500000 });
  emit('web.frame_work_ms_p50', percentile(samples, 0.5), 'ms', { target: 2, flavour, frames: samples.length });
  emit('web.frame_work_ms_p95', percentile(samples, 0.95), 'ms', { target: 2, flavour, frames: samples.length });
} catch (err) {
  console.log(JSON.stringify({ name: 'web.error', value: 0, unit: '', error: String(err.message || err).slice(0, 500) }));
  process.exitCode = 1;
} finally {
  await browser?.close();
  await server?.stop();
}
