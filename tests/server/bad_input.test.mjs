// The bad-input catalogue: every malformed or hostile request gets the right 4xx and a JSON
// message that names what was wrong — and the database is exactly as before (a SHA-256 over every
// table, /healthz?deep=1, compared before and after each case).
import assert from 'node:assert/strict';
import http from 'node:http';
import { after, before, test } from 'node:test';

import { fingerprint, request, startServer, validNotation } from './server_harness.mjs';

let server;
let helloId;
before(async () => {
  server = await startServer();
  const found = await request(server, 'GET', '/api/signs?q=hello&lang=ase');
  helloId = found.body.hits[0].id;
});
after(async () => { await server?.stop(); });

// Runs `send`, checks the status and the JSON error shape, and that nothing changed.
async function refused(name, send, status, messagePattern) {
  const before = await fingerprint(server);
  const response = await send();
  assert.equal(response.status, status, `${name}: ${JSON.stringify(response.body)}`);
  assert.equal(typeof response.body, 'object', `${name}: JSON body`);
  assert.equal(typeof response.body.error, 'string', `${name}: error message`);
  assert.equal(typeof response.body.detail, 'object', `${name}: detail object`);
  if (messagePattern) assert.match(response.body.error, messagePattern, name);
  assert.equal(await fingerprint(server), before, `${name}: the database changed`);
  return response.body;
}

const post = (body, headers = {}) => () => request(server, 'POST', '/api/signs', { headers: { ...server.auth, ...headers }, body });
const put = (body, headers = {}) => () => request(server, 'PUT', `/api/signs/${helloId}`, { headers: { ...server.auth, 'If-Match': '"1"', ...headers }, body });

test('malformed JSON names the position', async () => {
  const body = await refused('truncated', post('{"language": "ase", "gloss": '), 400, /malformed JSON/);
  assert.equal(body.detail.line, 1);
  assert.ok(body.detail.offset >= 28);
  await refused('trailing garbage', post('{"language":"ase"} x'), 400, /malformed JSON/);
  await refused('not an object', post('[1,2,3]'), 400, /must be a JSON object/);
  await refused('empty body', post(''), 400, /malformed JSON/);
  await refused('deep nesting', post(`${'['.repeat(100000)}${']'.repeat(100000)}`), 400, /nested deeper/);
});

test('wrong types name the field', async () => {
  const cases = [
    [{ language: 'ase', gloss: 42, notation: validNotation() }, 'gloss'],
    [{ language: 'ase', gloss: 'X', notation: ['R()'] }, 'notation'],
    [{ language: 'ase', gloss: 'X', notation: validNotation(), tags: 'food' }, 'tags'],
    [{ language: 'ase', gloss: 'X', notation: validNotation(), tags: ['ok', 7] }, 'tags[1]'],
    [{ language: 'ase', gloss: 'X', notation: validNotation(), keywords: [{ word: 1 }] }, 'keywords[0].word'],
    [{ language: 'ase', gloss: 'X', notation: validNotation(), starter: 'yes' }, 'starter'],
    [{ language: null, gloss: 'X', notation: validNotation() }, 'language'],
  ];
  for (const [body, field] of cases) {
    const refusal = await refused(`type of ${field}`, post(body), 400, new RegExp(`'${field.replace(/[[\]]/g, '\\$&')}'`));
    assert.equal(refusal.detail.field, field);
  }
});

test('unknown fields are refused by name', async () => {
  const refusal = await refused('unknown', post({ language: 'ase', gloss: 'X', notation: validNotation(), colour: 'red' }), 400, /unknown field 'colour'/);
  assert.equal(refusal.detail.field, 'colour');
  await refused('unknown nested', post({ language: 'ase', gloss: 'X', notation: validNotation(), keywords: [{ word: 'x', extra: 1 }] }), 400, /keywords\[0\]\.extra/);
  await refused('missing required', post({ language: 'ase', notation: validNotation() }), 400, /missing required field 'gloss'/);
  await refused('unknown query parameter', () => request(server, 'GET', '/api/signs?q=a&sort=desc'), 400, /unknown query parameter 'sort'/);
});

test('oversized bodies and fields', async () => {
  await refused('sign body over 256 KiB', post({ language: 'ase', gloss: 'X', notation: 'R'.repeat(300 * 1024) }), 413);
  await refused('notation over 64 KiB', post({ language: 'ase', gloss: 'X', notation: 'R'.repeat(70 * 1024) }), 400, /notation.*longer than/);
  await refused('gloss over its limit', post({ language: 'ase', gloss: 'G'.repeat(500), notation: validNotation() }), 400, /gloss/);
  // Over the server-wide 16 MiB body limit: httplib refuses before reading; still JSON.
  const huge = await refused('body over 16 MiB', post('x'.repeat(17 * 1024 * 1024)), 413);
  assert.ok(huge.detail.limit_bytes > 0);
  await refused('limit out of range', () => request(server, 'GET', '/api/signs?limit=1000'), 400, /limit/);
  await refused('limit not a number', () => request(server, 'GET', '/api/signs?limit=ten'), 400, /limit/);
});

test('invalid UTF-8 in the body and in query parameters', async () => {
  const bytes = Buffer.concat([Buffer.from('{"language":"ase","gloss":"'), Buffer.from([0xff, 0xfe]), Buffer.from('","notation":"R()"}')]);
  const refusal = await refused('body', post(new Uint8Array(bytes)), 400, /UTF-8/);
  assert.equal(refusal.detail.offset, 27);
  await refused('overlong encoding', post(new Uint8Array(Buffer.from([0x7b, 0x22, 0xc0, 0xaf, 0x22, 0x7d]))), 400, /UTF-8/);
  await refused('query', () => request(server, 'GET', '/api/signs?q=%ff%fe'), 400, /UTF-8/);
});

test('notation errors: 422 with the parser message, line, column, offset and symbol', async () => {
  const refusal = await refused('bad handshape', post({ language: 'ase', gloss: 'BADSIGN', notation: 'R(H(flax), E(u))' }), 422, /notation does not parse/);
  const [diagnostic] = refusal.detail.diagnostics;
  assert.equal(refusal.detail.field, 'notation');
  assert.equal(diagnostic.line, 1);
  assert.equal(diagnostic.column, 5);
  assert.equal(diagnostic.offset, 4);
  assert.ok(diagnostic.message.length > 10);
  assert.ok('symbol' in diagnostic);
  await refused('unbalanced', put({ gloss: 'HELLO', notation: 'R(H(flat), E(u' }), 422, /notation does not parse/);
  await refused('unknown format', post({ language: 'ase', gloss: 'X', notation: validNotation(), format: 'klingon' }), 400, /format/);
  await refused('unknown language', post({ language: 'zzz', gloss: 'X', notation: validNotation() }), 422, /unknown sign language 'zzz'/);
});

test('a sign whose hands are each written on the other is signed, not refused by the synthesis stage', async () => {
  // Each hand placed on the other, no body or space location: the synthesis stage refused it
  // (422, "each hand is placed on the other"), as it refused 120 clean signs of the real-sign
  // corpus. In HamNoSys such a pair meets in neutral space (sign_motion.cpp,
  // place_pair_in_neutral_space), so it is stored. No notation that parses is refused by the
  // synthesis stage on the project avatar any more (every location, every clean corpus sign):
  // its 422 answer (docs/API.md) is left for an avatar that lacks a place.
  const pair = 'R(H(flat), E(uo), P(l), Loc(hand, palm, touch)) L(H(flat), E(uo), P(r), Loc(hand, palm, touch))';
  const created = await post({ language: 'ase', gloss: 'HANDS-TOGETHER', notation: pair })();
  assert.equal(created.status, 201, JSON.stringify(created.body));
});

test('SQL injection strings are data, never SQL', async () => {
  const injections = ["'; DROP TABLE signs; --", "\" OR 1=1 --", "x' UNION SELECT hash FROM api_tokens --", "%' OR '%'='"];
  for (const text of injections) {
    const search = await request(server, 'GET', `/api/signs?${new URLSearchParams({ q: text, lang: 'ase' })}`);
    assert.equal(search.status, 200);
    assert.equal(search.body.total, 0, text);
    await refused(`injection as language: ${text}`, post({ language: text, gloss: 'X', notation: validNotation() }), 422);
    await refused(`injection as lookup language: ${text}`, () => request(server, 'GET', `/api/lookup?${new URLSearchParams({ text: 'hi', lang: text })}`), 422);
  }
  await refused('injection as id', () => request(server, 'GET', '/api/signs/1%20OR%201=1'), 400, /positive integer/);
  const languages = await request(server, 'GET', '/api/languages');
  assert.equal(languages.body.languages.length, 2);
});

test('path traversal on the API and the static root', async () => {
  const raw = (p) => new Promise((resolve, reject) => {
    http.get({ host: '127.0.0.1', port: server.port, path: p }, (res) => {
      let text = '';
      res.on('data', (c) => { text += c; });
      res.on('end', () => resolve({ status: res.statusCode, body: JSON.parse(text) }));
    }).on('error', reject);
  });
  for (const p of ['/../../etc/passwd', '/%2e%2e/%2e%2e/etc/passwd', '/models/%2e%2e/%2e%2e/etc/passwd', '/api/signs/..%2f..%2fetc']) {
    const before = await fingerprint(server);
    const response = await raw(p);
    assert.ok([400, 404].includes(response.status), `${p}: ${response.status}`);
    assert.equal(typeof response.body.error, 'string');
    assert.equal(await fingerprint(server), before);
  }
});

test('missing, malformed and wrong tokens', async () => {
  const body = { language: 'ase', gloss: 'TOKENLESS', notation: validNotation() };
  await refused('missing', () => request(server, 'POST', '/api/signs', { body }), 401, /Authorization/);
  await refused('not bearer', () => request(server, 'POST', '/api/signs', { body, headers: { Authorization: `Basic ${server.token}` } }), 401, /Bearer/);
  await refused('wrong', () => request(server, 'POST', '/api/signs', { body, headers: { Authorization: 'Bearer sw_0000000000000000000000000000000000000000000000000000000000000000' } }), 403);
  await refused('almost right', () => request(server, 'POST', '/api/signs', { body, headers: { Authorization: `Bearer ${server.token}x` } }), 403);
  await refused('delete without token', () => request(server, 'DELETE', `/api/signs/${helloId}`, { headers: { 'If-Match': '"1"' } }), 401);
  await refused('import without token', () => request(server, 'POST', '/api/import?lang=ase', { body: JSON.stringify(body) }), 401);
  const response = await request(server, 'POST', '/api/signs', { body });
  assert.match(response.headers.get('www-authenticate'), /^Bearer/);
});

test('stale, missing and malformed revisions', async () => {
  const current = await request(server, 'GET', `/api/signs/${helloId}`);
  const edit = { gloss: 'HELLO', notation: validNotation(5) };
  const stale = await refused('stale', put(edit, { 'If-Match': `"${current.body.revision + 1}"` }), 409, /revision/);
  assert.equal(stale.detail.current_revision, current.body.revision);
  await refused('missing If-Match', () => request(server, 'PUT', `/api/signs/${helloId}`, { headers: server.auth, body: edit }), 428, /If-Match/);
  await refused('malformed If-Match', put(edit, { 'If-Match': '"abc"' }), 400, /If-Match/);
  await refused('stale delete', () => request(server, 'DELETE', `/api/signs/${helloId}`, { headers: { ...server.auth, 'If-Match': '"99"' } }), 409);
  await refused('no such sign', () => request(server, 'PUT', '/api/signs/987654', { headers: { ...server.auth, 'If-Match': '"1"' }, body: edit }), 404);
});

test('bulk import is all or nothing, with per-line errors', async () => {
  const lines = [
    JSON.stringify({ gloss: 'BULK-OK', notation: validNotation(1) }),
    JSON.stringify({ gloss: 'BULK-BAD', notation: 'R(H(flax))' }),
    '{"gloss": "BULK-BROKEN", ',
    JSON.stringify({ gloss: 'BULK-FIELD', notation: validNotation(2), bogus: true }),
  ].join('\n');
  const refusal = await refused('mixed import', () => request(server, 'POST', '/api/import?lang=ase', { headers: { ...server.auth, 'Content-Type': 'application/x-ndjson' }, body: lines }), 422, /nothing was imported/);
  const byLine = Object.fromEntries(refusal.detail.rejected.map((r) => [r.line, r]));
  assert.deepEqual(Object.keys(byLine).map(Number).sort(), [2, 3, 4]);
  assert.equal(byLine[2].status, 422);
  assert.match(byLine[3].error, /malformed JSON/);
  assert.match(byLine[4].error, /unknown field 'bogus'/);
  const search = await request(server, 'GET', '/api/signs?q=BULK-OK&lang=ase');
  assert.equal(search.body.total, 0);
});

test('unknown routes and methods are JSON too', async () => {
  await refused('no route', () => request(server, 'GET', '/api/nothing'), 404);
  const wrong = await refused('wrong method', () => request(server, 'PATCH', `/api/signs/${helloId}`, { headers: server.auth, body: {} }), 405);
  assert.ok(wrong.detail.allow.includes('PUT'));
  await refused('wrong content type', post('gloss=X', { 'Content-Type': 'application/x-www-form-urlencoded' }), 415);
});
