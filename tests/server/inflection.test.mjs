// Inflected words find the sign of their base form over real HTTP: GET /api/lookup plans "books"
// as BOOK with match {type: "stem", form: "book"}, in English (ase) and Ukrainian (ukl), over the
// table in fixtures/inflected_forms.json; search ranks another form after the exact match.
import { test, describe, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';

import { repoRoot, request, startServer } from './server_harness.mjs';

const table = JSON.parse(fs.readFileSync(path.join(repoRoot, 'tests', 'server', 'fixtures', 'inflected_forms.json'), 'utf8')).forms;
let server;

before(async () => {
  server = await startServer();
  const signs = new Map();
  for (const row of table) {
    const key = `${row.language}\u001f${row.gloss}`;
    if (!signs.has(key)) signs.set(key, { language: row.language, gloss: row.gloss, keywords: [] });
    if (!signs.get(key).keywords.includes(row.keyword)) signs.get(key).keywords.push(row.keyword);
  }
  const lines = [...signs.values()].map((sign) => JSON.stringify({
    ...sign, notation: 'R(H(flat), E(u), P(o), Loc(chin, centre, touch))', format: 'formula',
  }));
  const response = await request(server, 'POST', '/api/import', {
    body: lines.join('\n'), headers: { ...server.auth, 'Content-Type': 'application/x-ndjson' },
  });
  assert.equal(response.status, 200, JSON.stringify(response.body));
});
after(async () => { await server?.stop(); });

async function lookup(text, lang) {
  const response = await request(server, 'GET', `/api/lookup?${new URLSearchParams({ text, lang })}`);
  assert.equal(response.status, 200, JSON.stringify(response.body));
  return response.body.tokens;
}

describe('inflected forms', () => {
  test(`every form of the table (${table.length}) finds its base sign, and the plan says which form matched`, async () => {
    assert.ok(table.length >= 40);
    const missed = [];
    for (const row of table) {
      const tokens = await lookup(row.typed, row.language);
      const token = tokens[0];
      if (tokens.length !== 1 || token.type !== 'sign' || token.gloss !== row.gloss) {
        missed.push(`${row.typed} -> ${JSON.stringify(token)}`);
        continue;
      }
      // form is the spelling both share: the keyword, or a base form of both ("broth" for brothers).
      assert.equal(token.match.type, 'stem', row.typed);
      assert.equal(token.match.text, row.keyword, row.typed);
    }
    console.log(`inflected forms that found their base sign over HTTP: ${table.length - missed.length} of ${table.length}`);
    assert.deepEqual(missed, []);
  });

  test('the books, the mothers signed, книги: in a phrase, base signs before fingerspelling', async () => {
    const tokens = await lookup('Mothers signed books, cats!', 'ase');
    assert.deepEqual(tokens.map((t) => [t.type, t.text, t.gloss ?? null]), [
      ['sign', 'Mothers', 'MOTHER'], ['sign', 'signed', 'SIGN'], ['sign', 'books', 'BOOK'], ['pause', ',', null],
      ['sign', 'cats', 'CAT'], ['pause', '!', null],
    ]);
    assert.equal(tokens[0].match.form, 'mother');
    const ukrainian = await lookup('Книги', 'ukl');
    assert.equal(ukrainian[0].gloss, 'КНИГА');
    assert.deepEqual(ukrainian[0].match, { type: 'stem', form: 'книга', text: 'книга' });
  });

  test('a word typed as a keyword is an exact match; an unknown word is still fingerspelled', async () => {
    const tokens = await lookup('book zzq', 'ase');
    assert.deepEqual(tokens[0].match, { type: 'exact', form: 'book', text: 'book' });
    assert.equal(tokens[1].type, 'fingerspell');
  });

  test('search: another form of a keyword is a "stem" hit', async () => {
    const response = await request(server, 'GET', `/api/signs?${new URLSearchParams({ q: 'Mothers', lang: 'ase' })}`);
    assert.equal(response.status, 200);
    assert.equal(response.body.hits[0].gloss, 'MOTHER');
    assert.deepEqual(response.body.hits[0].match, { type: 'stem', field: 'keyword', text: 'mother' });
  });
});
