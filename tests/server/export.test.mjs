// GET /api/signs/{id}?format=: a stored sign as a SiGML, HamNoSys or formula file to download,
// which `signweave check --spec` reads back as the same sign as the stored notation.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';

import { makeTempDir, repoRoot, request, startServer } from './server_harness.mjs';

const cli = process.env.SIGNWEAVE_CLI_BIN ?? path.join(repoRoot, 'build', 'native', 'signweave-cli');
let server;
before(async () => { server = await startServer(); });
after(async () => { await server?.stop(); });

function specOf(text, extension) {
  const file = path.join(makeTempDir(), `sign.${extension}`);
  fs.writeFileSync(file, text);
  const result = spawnSync(cli, ['check', file, '--spec'], { encoding: 'utf8' });
  const signs = result.stdout.trim().split('\n').map((l) => JSON.parse(l)).filter((o) => !o.summary);
  assert.equal(signs.length, 1, result.stdout);
  const { gloss, ...spec } = signs[0].spec;
  return { gloss, spec };
}

async function exportAndReadBack(query, formats) {
  const search = await request(server, 'GET', `/api/signs?${new URLSearchParams({ q: query, lang: 'ase' })}`);
  const sign = search.body.hits[0];
  const stored = specOf(sign.notation, 'txt');
  for (const format of formats) {
    const response = await request(server, 'GET', `/api/signs/${sign.id}?format=${format}`);
    assert.equal(response.status, 200, `${format}: ${JSON.stringify(response.body)}`);
    const xml = format.endsWith('sigml');
    assert.match(response.headers.get('content-type'), xml ? /^application\/xml/ : /^text\/plain/);
    assert.match(response.headers.get('content-disposition'),
      new RegExp(`^attachment; filename="sign-\\d+\\.(sigml|\\w+\\.txt)"; filename\\*=UTF-8''${sign.gloss}\\.`));
    const back = specOf(response.body, xml ? 'sigml' : 'txt');
    assert.equal(back.gloss, sign.gloss, format);
    assert.deepEqual(back.spec, stored.spec, `${sign.gloss} as ${format}`);
    const etag = response.headers.get('etag');
    const again = await request(server, 'GET', `/api/signs/${sign.id}?format=${format}`, { headers: { 'If-None-Match': etag } });
    assert.equal(again.status, 304);
  }
}

test('every export format downloads a file that reads back as the stored sign', async () => {
  await exportAndReadBack('help', ['sigml', 'hsigml', 'gsigml', 'hamnosys', 'formula']);
  await exportAndReadBack('hello', ['gsigml', 'formula']);
});

// HELLO is E(u), P(o): the HamNoSys printer writes the palm relative to the finger direction
// (hampalmu) and the reader takes it as absolute (palm up), so the palm turns. The palm
// orientation work (branch palm) owns both sides; this test says when they agree.
test('HamNoSys and H-SiGML exports keep a palm facing out with the fingers up', { todo: 'palm orientation relative vs absolute in the HamNoSys printer/reader' }, async () => {
  await exportAndReadBack('hello', ['sigml', 'hsigml', 'hamnosys']);
});

test('an unknown format is 400 naming the allowed ones; an unknown sign 404; JSON stays the default', async () => {
  const bad = await request(server, 'GET', '/api/signs/1?format=pdf');
  assert.equal(bad.status, 400);
  assert.deepEqual(bad.body.detail.allowed, ['sigml', 'hsigml', 'gsigml', 'hamnosys', 'formula']);
  assert.equal((await request(server, 'GET', '/api/signs/999999?format=sigml')).status, 404);
  const plain = await request(server, 'GET', '/api/signs/1');
  assert.equal(plain.status, 200);
  assert.equal(typeof plain.body.notation, 'string');
});

test('a Cyrillic gloss gives a percent-encoded UTF-8 file name', async () => {
  const search = await request(server, 'GET', `/api/signs?${new URLSearchParams({ q: 'привіт', lang: 'ukl' })}`);
  const response = await request(server, 'GET', `/api/signs/${search.body.hits[0].id}?format=sigml`);
  assert.equal(response.status, 200);
  assert.match(response.headers.get('content-disposition'), /filename\*=UTF-8''%D0%9F%D0%A0%D0%98%D0%92%D0%86%D0%A2\.sigml/);
});
