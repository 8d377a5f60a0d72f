// Concurrency: parallel writers and readers against one server. Optimistic concurrency must make
// every edit either win (and bump the revision by one) or get a 409 — never a lost update — and
// nothing may answer 500.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { request, sqliteQuery, startServer, validNotation } from './server_harness.mjs';

let server;
before(async () => { server = await startServer(); });
after(async () => { await server?.stop(); });

test('racing edits of one sign: each revision has exactly one winner, no update lost', async () => {
  const created = await request(server, 'POST', '/api/signs', { headers: server.auth, body: { language: 'ase', gloss: 'RACE', notation: validNotation(0), tags: [] } });
  assert.equal(created.status, 201);
  const id = created.body.id;
  const writers = 6;  // 6 x 5 = 30 tags, under the 32-tag limit
  const editsPerWriter = 5;
  const wins = [];
  const statuses = [];
  // Each writer reads, then writes its own tag on top of what it read, retrying on 409: the final
  // sign must carry every writer's every tag (a lost update would drop one).
  await Promise.all(Array.from({ length: writers }, async (_, w) => {
    for (let e = 0; e < editsPerWriter; ++e) {
      for (;;) {
        const current = await request(server, 'GET', `/api/signs/${id}`);
        statuses.push(current.status);
        const tags = [...current.body.tags, `w${w}e${e}`];
        const put = await request(server, 'PUT', `/api/signs/${id}`, {
          headers: { ...server.auth, 'If-Match': `"${current.body.revision}"` },
          body: { gloss: 'RACE', notation: validNotation(w + e), tags },
        });
        statuses.push(put.status);
        if (put.status === 200) { wins.push(put.body.revision); break; }
        assert.equal(put.status, 409, JSON.stringify(put.body));
      }
    }
  }));
  assert.ok(!statuses.includes(500), 'no 500');
  assert.equal(wins.length, writers * editsPerWriter);
  assert.deepEqual([...wins].sort((a, b) => a - b), Array.from({ length: wins.length }, (_, i) => i + 2), 'each revision won once');
  const final = await request(server, 'GET', `/api/signs/${id}`);
  assert.equal(final.body.revision, 1 + writers * editsPerWriter);
  assert.equal(final.body.tags.length, writers * editsPerWriter, 'every edit survives');
  const history = await request(server, 'GET', `/api/signs/${id}/history`);
  assert.equal(history.body.revisions.length, 1 + writers * editsPerWriter);
  const rows = sqliteQuery(server.db, `SELECT COUNT(*) AS n FROM revisions WHERE sign_id = ${id}`);
  assert.equal(rows[0].n, 1 + writers * editsPerWriter);
});

test('parallel creators and readers: all creates land, readers never fail', async () => {
  const creators = Array.from({ length: 40 }, (_, i) => request(server, 'POST', '/api/signs', {
    headers: server.auth, body: { language: 'ase', gloss: `PARALLEL-${i}`, notation: validNotation(i), keywords: [`parallel${i}`] },
  }));
  const readers = Array.from({ length: 80 }, (_, i) => (i % 2
    ? request(server, 'GET', '/api/signs?q=parallel&lang=ase&limit=100')
    : request(server, 'GET', '/api/lookup?lang=ase&text=hello%20parallel3')));
  const results = await Promise.all([...creators, ...readers]);
  for (const result of results) assert.ok(result.status === 200 || result.status === 201, `${result.status} ${JSON.stringify(result.body)}`);
  const search = await request(server, 'GET', '/api/signs?q=parallel&lang=ase&limit=100');
  assert.equal(search.body.total, 40);
  // The same gloss created twice at once: exactly one wins.
  const twins = await Promise.all([0, 1, 2].map(() => request(server, 'POST', '/api/signs', {
    headers: server.auth, body: { language: 'ase', gloss: 'TWIN', notation: validNotation(1) },
  })));
  assert.deepEqual(twins.map((t) => t.status).sort(), [201, 409, 409]);
});
