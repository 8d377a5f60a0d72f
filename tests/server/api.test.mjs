// API behaviour over real HTTP against a real SQLite file: languages, search (prefix, keyword,
// typo, ranking, cursor pages), sign fetch with ETag, authoring with revisions and If-Match,
// history, phrase lookup, bulk import, health and metrics.
import assert from 'node:assert/strict';
import { after, before, describe, test } from 'node:test';

import { request, startServer, validNotation } from './server_harness.mjs';

let server;
before(async () => { server = await startServer(); });
after(async () => { await server?.stop(); });

async function search(query) {
  const response = await request(server, 'GET', `/api/signs?${new URLSearchParams(query)}`);
  assert.equal(response.status, 200, JSON.stringify(response.body));
  return response.body;
}

describe('startup', () => {
  test('a new database is filled from the data directory, languages first', async () => {
    const response = await request(server, 'GET', '/api/languages');
    assert.equal(response.status, 200);
    assert.deepEqual(response.body.languages.map((l) => l.code), ['ase', 'ukl']);
    assert.equal(response.body.languages[1].spoken, 'uk');
    const health = await request(server, 'GET', '/healthz');
    assert.equal(health.body.status, 'ok');
    assert.equal(health.body.signs, 20);
    assert.equal(health.body.notation_parser, true);
  });
});

describe('search', () => {
  test('exact keyword ranks before prefix matches', async () => {
    const body = await search({ q: 'help', lang: 'ase' });
    assert.equal(body.hits[0].gloss, 'HELP');
    assert.equal(body.hits[0].match.type, 'exact');
  });

  test('prefix on gloss and keywords, case-insensitive', async () => {
    const body = await search({ q: 'TH', lang: 'ase' });
    const glosses = body.hits.map((h) => h.gloss);
    assert.ok(glosses.includes('THINK') && glosses.includes('THANK-YOU'), glosses.join());
    for (const hit of body.hits) assert.equal(hit.match.type, 'prefix');
  });

  test('a later word of a multi-word keyword matches by word prefix', async () => {
    const body = await search({ q: 'york', lang: 'ase' });
    assert.equal(body.hits[0].gloss, 'NEW-YORK');
    assert.equal(body.hits[0].match.type, 'word_prefix');
  });

  test('typos within the edit bound are found, ranked after real matches', async () => {
    const body = await search({ q: 'helo', lang: 'ase' });
    const hello = body.hits.find((h) => h.gloss === 'HELLO');
    assert.ok(hello, JSON.stringify(body.hits));
    assert.equal(hello.match.type, 'fuzzy');
    assert.equal(hello.match.distance, 1);
    // A transposition is one edit (Damerau).
    const swapped = await search({ q: 'hlelo', lang: 'ase' });
    assert.ok(swapped.hits.some((h) => h.gloss === 'HELLO'));
    // Too far: nothing.
    const far = await search({ q: 'zzzzzz', lang: 'ase' });
    assert.equal(far.total, 0);
  });

  test('homonyms: one keyword, two signs, both listed with their senses', async () => {
    const body = await search({ q: 'bank', lang: 'ase' });
    assert.deepEqual(body.hits.slice(0, 2).map((h) => h.gloss), ['BANK', 'BANK#2']);
    const sign = await request(server, 'GET', `/api/signs/${body.hits[1].id}`);
    assert.equal(sign.body.keywords[0].sense, 'river side');
  });

  test('language filter and Cyrillic case folding', async () => {
    const body = await search({ q: 'ПРИВ', lang: 'ukl' });
    assert.equal(body.hits[0].gloss, 'ПРИВІТ');
    const none = await search({ q: 'привіт', lang: 'ase' });
    assert.equal(none.total, 0);
  });

  test('pages: cursors walk the whole ranking without repeats or gaps', async () => {
    const all = await search({ lang: 'ase', limit: '100' });
    const seen = [];
    let cursor = '';
    for (let page = 0; page < 20; ++page) {
      const body = await search({ lang: 'ase', limit: '3', ...(cursor ? { cursor } : {}) });
      seen.push(...body.hits.map((h) => h.id));
      if (!body.next_cursor) break;
      cursor = body.next_cursor;
    }
    assert.deepEqual(seen, all.hits.map((h) => h.id));
    assert.equal(new Set(seen).size, seen.length);
  });

  test('a cursor from another query is refused', async () => {
    const first = await search({ q: 'h', lang: 'ase', limit: '1' });
    assert.ok(first.next_cursor);
    const response = await request(server, 'GET', `/api/signs?q=t&lang=ase&cursor=${first.next_cursor}`);
    assert.equal(response.status, 400);
    assert.match(response.body.error, /cursor/);
  });
});

describe('signs', () => {
  test('GET a sign: fields, ETag is the revision, If-None-Match gives 304', async () => {
    const { hits } = await search({ q: 'hello', lang: 'ase' });
    const response = await request(server, 'GET', `/api/signs/${hits[0].id}`);
    assert.equal(response.status, 200);
    assert.equal(response.body.gloss, 'HELLO');
    assert.equal(response.body.format, 'formula');
    assert.deepEqual(response.body.keywords.map((k) => k.word), ['hello', 'hi']);
    assert.equal(response.body.keywords[0].sense, 'a greeting');
    assert.equal(response.headers.get('etag'), `"${response.body.revision}"`);
    // The core's parse of the notation is cached with the sign (the SignSpec as JSON).
    assert.equal(typeof response.body.compiled.spec, 'object');
    assert.ok(response.body.compiled.spec.dominant, JSON.stringify(response.body.compiled));
    const again = await request(server, 'GET', `/api/signs/${hits[0].id}`, { headers: { 'If-None-Match': response.headers.get('etag') } });
    assert.equal(again.status, 304);
  });

  test('letters know their letter', async () => {
    const { hits } = await search({ q: 'ASE-LETTER-B', lang: 'ase' });
    const response = await request(server, 'GET', `/api/signs/${hits[0].id}`);
    assert.equal(response.body.letter, 'B');
  });

  test('create, update with If-Match, delete: revisions and history', async () => {
    const created = await request(server, 'POST', '/api/signs', {
      headers: server.auth,
      body: { language: 'ase', gloss: 'WATER', notation: validNotation(1), keywords: ['water', { word: 'drink', sense: 'liquid' }], tags: ['food'] },
    });
    assert.equal(created.status, 201, JSON.stringify(created.body));
    assert.equal(created.body.revision, 1);
    assert.equal(created.headers.get('location'), `/api/signs/${created.body.id}`);
    const id = created.body.id;

    const found = await search({ q: 'water', lang: 'ase' });
    assert.equal(found.hits[0].id, id, 'a new sign is searchable at once');

    const updated = await request(server, 'PUT', `/api/signs/${id}`, {
      headers: { ...server.auth, 'If-Match': '"1"' },
      body: { gloss: 'WATER', notation: validNotation(2), keywords: ['water'] },
    });
    assert.equal(updated.status, 200, JSON.stringify(updated.body));
    assert.equal(updated.body.revision, 2);
    assert.equal(updated.body.notation, validNotation(2));
    assert.equal(updated.headers.get('etag'), '"2"');

    const stale = await request(server, 'PUT', `/api/signs/${id}`, {
      headers: { ...server.auth, 'If-Match': '"1"' },
      body: { gloss: 'WATER', notation: validNotation(3) },
    });
    assert.equal(stale.status, 409);
    assert.equal(stale.body.detail.current_revision, 2);

    const deleted = await request(server, 'DELETE', `/api/signs/${id}`, { headers: { ...server.auth, 'If-Match': '"2"' } });
    assert.equal(deleted.status, 200, JSON.stringify(deleted.body));
    assert.equal(deleted.body.revision, 3);
    assert.equal((await request(server, 'GET', `/api/signs/${id}`)).status, 410);
    assert.equal((await search({ q: 'water', lang: 'ase' })).hits.filter((h) => h.id === id).length, 0);

    const history = await request(server, 'GET', `/api/signs/${id}/history`);
    assert.equal(history.status, 200);
    assert.deepEqual(history.body.revisions.map((r) => [r.revision, r.op]), [[3, 'delete'], [2, 'update'], [1, 'create']]);
    assert.equal(history.body.revisions[2].notation, validNotation(1));
    assert.match(history.body.revisions[0].author, /admin/);
    assert.deepEqual(history.body.revisions[2].snapshot.keywords.map((k) => k.word), ['water', 'drink']);
  });

  test('a deleted gloss can be created again as a new sign', async () => {
    const first = await request(server, 'POST', '/api/signs', { headers: server.auth, body: { language: 'ase', gloss: 'AGAIN', notation: validNotation(0) } });
    assert.equal(first.status, 201);
    await request(server, 'DELETE', `/api/signs/${first.body.id}`, { headers: { ...server.auth, 'If-Match': '"1"' } });
    const second = await request(server, 'POST', '/api/signs', { headers: server.auth, body: { language: 'ase', gloss: 'AGAIN', notation: validNotation(0) } });
    assert.equal(second.status, 201);
    assert.notEqual(second.body.id, first.body.id);
  });

  test('a duplicate live gloss is a 409 naming the existing sign', async () => {
    const response = await request(server, 'POST', '/api/signs', { headers: server.auth, body: { language: 'ase', gloss: 'HELLO', notation: validNotation(0) } });
    assert.equal(response.status, 409);
    assert.ok(response.body.detail.existing_id > 0);
  });
});

describe('lookup', () => {
  async function lookup(text, lang = 'ase') {
    const response = await request(server, 'GET', `/api/lookup?${new URLSearchParams({ text, lang })}`);
    assert.equal(response.status, 200, JSON.stringify(response.body));
    return response.body.tokens;
  }

  test('words to signs, multi-word keywords greedily, pauses at punctuation', async () => {
    const tokens = await lookup('Hello, thank you! New York.');
    assert.deepEqual(tokens.map((t) => [t.type, t.text]), [
      ['sign', 'Hello'], ['pause', ','], ['sign', 'thank you'], ['pause', '!'], ['sign', 'New York'], ['pause', '.'],
    ]);
    assert.equal(tokens[4].gloss, 'NEW-YORK');
    assert.ok(tokens[3].duration_s > tokens[1].duration_s, 'a sentence end pauses longer than a comma');
    assert.equal(tokens[2].offset, 7);
  });

  test('a word without a sign is fingerspelled letter by letter, digraph digits longest first', async () => {
    const tokens = await lookup('Abz 10 oq');
    assert.equal(tokens[0].type, 'fingerspell');
    assert.deepEqual(tokens[0].letters.map((l) => l.letter), ['A', 'B', 'Z']);
    assert.ok(tokens[0].letters.every((l) => l.sign_id > 0));
    assert.deepEqual(tokens[1].letters.map((l) => l.letter), ['10']);
    // q has no sign in the fixture alphabet: it is listed, without a sign id.
    assert.deepEqual(tokens[2].letters.map((l) => [l.letter, l.sign_id]), [['O', tokens[2].letters[0].sign_id], ['q', null]]);
  });

  test('Cyrillic: case-aware, Ukrainian letters', async () => {
    const tokens = await lookup('Привіт, ЇВІТ', 'ukl');
    assert.equal(tokens[0].type, 'sign');
    assert.equal(tokens[0].gloss, 'ПРИВІТ');
    assert.deepEqual(tokens[2].letters.map((l) => l.letter), ['Ї', 'В', 'І', 'Т']);
  });

  test('homonym keywords give one sign and the alternatives', async () => {
    const tokens = await lookup('bank');
    assert.equal(tokens[0].type, 'sign');
    assert.equal(tokens[0].alternatives.length, 1);
  });

  test('lang is required and must exist', async () => {
    assert.equal((await request(server, 'GET', '/api/lookup?text=hi')).status, 400);
    assert.equal((await request(server, 'GET', '/api/lookup?text=hi&lang=xxx')).status, 422);
  });
});

describe('bulk import', () => {
  test('JSON lines: created, then unchanged on a second run, then updated', async () => {
    const lines = [
      { gloss: 'IMPORT-ONE', notation: validNotation(3), keywords: ['importone'] },
      { gloss: 'IMPORT-TWO', notation: validNotation(4) },
    ].map((l) => JSON.stringify(l)).join('\n');
    const first = await request(server, 'POST', '/api/import?lang=ase', { headers: { ...server.auth, 'Content-Type': 'application/x-ndjson' }, body: lines });
    assert.equal(first.status, 200, JSON.stringify(first.body));
    assert.deepEqual([first.body.created, first.body.updated, first.body.unchanged], [2, 0, 0]);
    const second = await request(server, 'POST', '/api/import?lang=ase', { headers: { ...server.auth, 'Content-Type': 'application/x-ndjson' }, body: lines });
    assert.deepEqual([second.body.created, second.body.updated, second.body.unchanged], [0, 0, 2]);
    const changed = lines.replace(validNotation(4), validNotation(5));
    const third = await request(server, 'POST', '/api/import?lang=ase', { headers: { ...server.auth, 'Content-Type': 'application/x-ndjson' }, body: changed });
    assert.deepEqual([third.body.created, third.body.updated, third.body.unchanged], [0, 1, 1]);
    const { hits } = await search({ q: 'importone', lang: 'ase' });
    assert.equal(hits[0].gloss, 'IMPORT-ONE');
  });
});

describe('operations', () => {
  test('/healthz?deep=1 runs the integrity check', async () => {
    const response = await request(server, 'GET', '/healthz?deep=1');
    assert.equal(response.status, 200);
    assert.equal(response.body.integrity, 'ok');
    assert.match(response.body.fingerprint, /^[0-9a-f]{64}$/);
  });

  test('/metrics: Prometheus text with route/status counters, latency histogram, db size', async () => {
    await request(server, 'GET', '/api/signs/999999');
    const response = await fetch(`${server.base}/metrics`);
    assert.equal(response.status, 200);
    assert.match(response.headers.get('content-type'), /^text\/plain; version=0\.0\.4/);
    const text = await response.text();
    assert.match(text, /signweave_http_requests_total\{route="\/api\/signs\/\{id\}",status="404"\} \d+/);
    assert.match(text, /signweave_http_request_duration_seconds_bucket\{route="\/api\/signs",le="\+Inf"\} \d+/);
    const size = /signweave_db_size_bytes (\d+)/.exec(text);
    assert.ok(size && Number(size[1]) > 4096);
  });
});
