// Notation export on a dictionary sign: "Export as" SiGML / HamNoSys / formula downloads the file
// the server prints (GET /api/signs/{id}?format=) under the gloss's name, and the download reads
// back with `signweave check` (the formula one as the very sign the dictionary shows).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';

import { launchBrowser, openPage, startServer } from './harness.mjs';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const cli = process.env.SIGNWEAVE_CLI_BIN ?? path.join(repoRoot, 'build', 'native', 'signweave-cli');
let server, browser, sign;
before(async () => {
  server = await startServer();
  browser = await launchBrowser();
  const found = await (await fetch(`${server.base}/api/signs?q=help&lang=ase`)).json();
  sign = found.hits[0];
  assert.equal(sign.gloss, 'HELP');
});
after(async () => { await browser?.close(); await server?.stop(); });

function checkSpecs(bytes, extension) {
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'signweave-export-')), `sign.${extension}`);
  fs.writeFileSync(file, bytes);
  const result = spawnSync(cli, ['check', file, '--spec'], { encoding: 'utf8' });
  return result.stdout.trim().split('\n').map((l) => JSON.parse(l)).filter((o) => !o.summary);
}

test('each export format downloads the server\'s file under the gloss, and it reads back', async () => {
  const { page, problems } = await openPage(browser, server.base, `#/sign/${sign.id}`);
  await page.waitForSelector('#sign-page:not([hidden])');
  const stored = checkSpecs(sign.notation, 'txt')[0].spec;
  for (const [format, name, extension] of [['sigml', 'HELP.sigml', 'sigml'], ['hamnosys', 'HELP.hamnosys.txt', 'txt'], ['formula', 'HELP.formula.txt', 'txt']]) {
    await page.selectOption('#sign-export-format', format);
    const [download] = await Promise.all([page.waitForEvent('download', { timeout: 20_000 }), page.click('#sign-export')]);
    assert.equal(download.suggestedFilename(), name);
    const bytes = fs.readFileSync(await download.path());
    const served = await (await fetch(`${server.base}/api/signs/${sign.id}?format=${format}`)).text();
    assert.equal(bytes.toString('utf8'), served, format);
    const back = checkSpecs(bytes, extension);
    assert.equal(back.length, 1, format);
    assert.equal(back[0].parsed, true, `${format}: ${JSON.stringify(back[0].diagnostics)}`);
    assert.equal(back[0].spec.gloss, 'HELP');
    if (format === 'formula') assert.deepEqual({ ...back[0].spec, gloss: '' }, { ...stored, gloss: '' });
  }
  assert.match(await page.textContent('#sign-export-status'), /Downloaded HELP\.formula\.txt/);
  assert.deepEqual(problems.filter((p) => !/favicon/.test(p)), []);
});
