// Static files: the page from --web and the avatar from --models, with the MIME types the browser
// needs, ETag/304, Cache-Control, gzip (precompressed sibling or compressed in memory), and no
// way out of the served directories (.., encoded .., symlinks, dot-files).
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import zlib from 'node:zlib';
import { after, before, test } from 'node:test';

import { makeTempDir, repoRoot, startServer } from './server_harness.mjs';

let server;
let dir;
const script = `// a module\n${'export const value = 42;\n'.repeat(100)}`;

before(async () => {
  dir = makeTempDir();
  const web = path.join(dir, 'web');
  const models = path.join(dir, 'models');
  fs.mkdirSync(path.join(web, 'gen'), { recursive: true });
  fs.mkdirSync(models);
  fs.writeFileSync(path.join(web, 'index.html'), `<!doctype html><title>t</title>${'<p>x</p>'.repeat(100)}`);
  fs.writeFileSync(path.join(web, 'app.js'), script);
  fs.writeFileSync(path.join(web, 'mod.mjs'), script);
  fs.writeFileSync(path.join(web, 'gen', 'core.wasm'), Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]));
  fs.writeFileSync(path.join(web, 'pre.js'), script);
  // A precompressed sibling with different content proves it is the one served.
  fs.writeFileSync(path.join(web, 'pre.js.gz'), zlib.gzipSync('// from the .gz file\n'));
  fs.writeFileSync(path.join(web, '.secret'), 'hidden');
  fs.writeFileSync(path.join(dir, 'outside.txt'), 'outside the web root');
  fs.symlinkSync(path.join(dir, 'outside.txt'), path.join(web, 'link-out.txt'));
  fs.writeFileSync(path.join(models, 'avatar.glb'), Buffer.from('glTF\x02\x00\x00\x00'));
  // An avatar pack (src/avatar/avatar_pack.h): floats that gzip about in half, like the .glb.
  const pack = Buffer.alloc(4096);
  pack.write('SWAVPACK');
  for (let i = 12; i + 4 <= pack.length; i += 4) pack.writeFloatLE(Math.round(Math.sin(i) * 100) / 100, i);
  fs.writeFileSync(path.join(web, 'gen', 'avatar.swavatar'), pack);
  // The server validates signs on the real avatar from the models directory.
  fs.copyFileSync(path.join(repoRoot, 'models', 'signweave-avatar.glb'), path.join(models, 'signweave-avatar.glb'));
  server = await startServer({ dir, web, models });
});
after(async () => { await server?.stop(); });

// fetch() normalises "..": send raw paths with node:http instead.
function rawGet(rawPath, headers = {}) {
  return new Promise((resolve, reject) => {
    const req = http.request({ host: '127.0.0.1', port: server.port, path: rawPath, headers }, (res) => {
      const chunks = [];
      res.on('data', (c) => chunks.push(c));
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body: Buffer.concat(chunks) }));
    });
    req.on('error', reject);
    req.end();
  });
}

test('MIME types the page depends on', async () => {
  const cases = [['/', 'text/html'], ['/app.js', 'text/javascript'], ['/mod.mjs', 'text/javascript'],
    ['/gen/core.wasm', 'application/wasm'], ['/models/avatar.glb', 'model/gltf-binary'],
    ['/gen/avatar.swavatar', 'application/vnd.signweave.avatar-pack']];
  for (const [url, type] of cases) {
    const response = await rawGet(url);
    assert.equal(response.status, 200, url);
    assert.ok(response.headers['content-type'].startsWith(type), `${url}: ${response.headers['content-type']}`);
  }
});

test('ETag and 304, Cache-Control by kind', async () => {
  const first = await rawGet('/app.js');
  assert.match(first.headers.etag, /^"[0-9a-f]+-[0-9a-f]+"$/);
  assert.match(first.headers['cache-control'], /max-age=/);
  const again = await rawGet('/app.js', { 'If-None-Match': first.headers.etag });
  assert.equal(again.status, 304);
  const html = await rawGet('/index.html');
  assert.equal(html.headers['cache-control'], 'no-cache');
});

test('gzip when accepted: compressed in memory, or the precompressed sibling', async () => {
  const plain = await rawGet('/app.js');
  assert.equal(plain.headers['content-encoding'], undefined);
  assert.equal(plain.body.toString(), script);
  const gz = await rawGet('/app.js', { 'Accept-Encoding': 'gzip, deflate' });
  assert.equal(gz.headers['content-encoding'], 'gzip');
  assert.equal(gz.headers.vary, 'Accept-Encoding');
  assert.notEqual(gz.headers.etag, plain.headers.etag, 'each encoding has its own strong ETag');
  assert.equal(zlib.gunzipSync(gz.body).toString(), script);
  assert.ok(gz.body.length < plain.body.length);
  const refused = await rawGet('/app.js', { 'Accept-Encoding': 'gzip;q=0' });
  assert.equal(refused.headers['content-encoding'], undefined);
  const pre = await rawGet('/pre.js', { 'Accept-Encoding': 'gzip' });
  assert.equal(zlib.gunzipSync(pre.body).toString(), '// from the .gz file\n');
});

test('static files are gzipped at start-up: no request waits for zlib, repeat bytes identical', async () => {
  const metric = async () => {
    const text = (await rawGet('/metrics')).body.toString();
    const line = text.split('\n').find((l) => l.startsWith('signweave_static_gzip_on_request_total '));
    assert.ok(line, 'the counter is exported');
    return Number(line.split(' ')[1]);
  };
  const before = await metric();
  // The real avatar and a page script, never asked for with gzip before this test.
  for (const url of ['/models/signweave-avatar.glb', '/mod.mjs', '/gen/avatar.swavatar']) {
    const first = await rawGet(url, { 'Accept-Encoding': 'gzip' });
    const second = await rawGet(url, { 'Accept-Encoding': 'gzip' });
    assert.equal(first.status, 200, url);
    assert.equal(first.headers['content-encoding'], 'gzip', url);
    assert.equal(first.headers.vary, 'Accept-Encoding', url);
    assert.ok(first.body.equals(second.body), `${url}: a second request returns identical bytes`);
    assert.equal(first.headers.etag, second.headers.etag, url);
    const identity = await rawGet(url, { 'Accept-Encoding': 'identity' });
    assert.equal(identity.headers['content-encoding'], undefined, `${url}: no gzip for a client without it`);
    assert.equal(identity.headers.vary, 'Accept-Encoding', url);
    assert.ok(zlib.gunzipSync(first.body).equals(identity.body), `${url}: gzip decodes to the file`);
  }
  assert.equal(await metric(), before, 'no request compressed a file itself');
  assert.equal(before, 0, 'every compressible file was compressed before the server listened');
});

test('a file changed after start-up is compressed again on request, not served stale', async () => {
  const file = path.join(dir, 'web', 'changed.js');
  const text = `// changed\n${'export const changed = 1;\n'.repeat(100)}`;
  fs.writeFileSync(file, text);
  const gz = await rawGet('/changed.js', { 'Accept-Encoding': 'gzip' });
  assert.equal(gz.headers['content-encoding'], 'gzip');
  assert.equal(zlib.gunzipSync(gz.body).toString(), text);
});

test('paths outside the web root are unreachable', async () => {
  for (const attempt of ['/../outside.txt', '/%2e%2e/outside.txt', '/gen/..%2f..%2foutside.txt',
    '/%2E%2E%2Foutside.txt', '/models/../outside.txt', '/..%5coutside.txt']) {
    const response = await rawGet(attempt);
    assert.ok(response.status === 400 || response.status === 404, `${attempt}: ${response.status}`);
    assert.ok(!response.body.toString().includes('outside the web root'), attempt);
    assert.ok(JSON.parse(response.body.toString()).error, attempt);
  }
  const link = await rawGet('/link-out.txt');
  assert.equal(link.status, 404, 'a symlink leading out of the root is not followed');
  const hidden = await rawGet('/.secret');
  assert.equal(hidden.status, 404);
  const nul = await rawGet('/app.js%00.txt');
  assert.equal(nul.status, 400);
});

test('a missing file is a JSON 404; a write method on a file is 405', async () => {
  const missing = await rawGet('/nope.js');
  assert.equal(missing.status, 404);
  assert.equal(JSON.parse(missing.body.toString()).detail.path, '/nope.js');
  const post = await fetch(`${server.base}/app.js`, { method: 'POST', body: 'x' });
  assert.equal(post.status, 405);
});
