// Durability and shutdown: kill -9 in the middle of a write burst loses no acknowledged write and
// leaves an intact database; SIGTERM lets requests in flight finish, checkpoints the WAL and exits 0.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { test } from 'node:test';

import { fingerprint, request, sqliteIntegrity, sqliteQuery, startServer, validNotation } from './server_harness.mjs';

test('kill -9 during a write burst: every acknowledged write survives, integrity ok', async () => {
  const first = await startServer();
  const acknowledged = [];
  let stop = false;
  const writers = Array.from({ length: 6 }, async (_, w) => {
    for (let i = 0; !stop; ++i) {
      try {
        const response = await request(first, 'POST', '/api/signs', {
          headers: first.auth, body: { language: 'ase', gloss: `CRASH-${w}-${i}`, notation: validNotation(i), keywords: [`crash${w}x${i}`] },
        });
        if (response.status === 201) acknowledged.push(response.body);
        else assert.fail(`unexpected ${response.status}`);
      } catch (error) {
        if (!stop) throw error;  // after the kill, connection errors are expected
      }
    }
  });
  // Let the burst run, then kill without warning while requests are in flight.
  await new Promise((resolve) => setTimeout(resolve, 1500));
  stop = true;
  await first.kill9();
  await Promise.allSettled(writers);
  assert.ok(acknowledged.length > 10, `only ${acknowledged.length} writes before the kill`);
  assert.ok(fs.existsSync(`${first.db}-wal`), 'killed with a live WAL (the case that matters)');

  const integrity = sqliteIntegrity(first.db);
  if (integrity !== null) assert.equal(integrity, 'ok');

  const second = await startServer({ dir: first.dir, token: first.token });
  try {
    const health = await request(second, 'GET', '/healthz?deep=1');
    assert.equal(health.status, 200);
    assert.equal(health.body.integrity, 'ok');
    for (const sign of acknowledged) {
      const response = await request(second, 'GET', `/api/signs/${sign.id}`);
      assert.equal(response.status, 200, `acknowledged sign ${sign.id} lost`);
      assert.equal(response.body.gloss, sign.gloss);
      assert.equal(response.body.notation, sign.notation);
    }
    // The search index sees them too, and the server still writes.
    const last = acknowledged[acknowledged.length - 1];
    const found = await request(second, 'GET', `/api/signs?q=${last.keywords[0].word}&lang=ase`);
    assert.equal(found.body.hits[0].id, last.id);
    const after = await request(second, 'POST', '/api/signs', { headers: second.auth, body: { language: 'ase', gloss: 'AFTER-CRASH', notation: validNotation(2) } });
    assert.equal(after.status, 201);
  } finally {
    await second.stop();
  }
});

test('SIGTERM: requests in flight finish, the WAL is checkpointed, exit code 0', async () => {
  const server = await startServer();
  const before = await fingerprint(server);
  // Start a batch of writes and reads, and send SIGTERM while they are on the wire.
  const inFlight = Array.from({ length: 20 }, (_, i) => (i % 2
    ? request(server, 'POST', '/api/signs', { headers: server.auth, body: { language: 'ase', gloss: `TERM-${i}`, notation: validNotation(i) } })
    : request(server, 'GET', '/api/signs?q=he&lang=ase')).then((r) => r.status, (e) => e.code ?? 'error'));
  await new Promise((resolve) => setTimeout(resolve, 5));
  server.proc.kill('SIGTERM');
  const outcomes = await Promise.all(inFlight);
  const { code, signal } = await server.exited;
  assert.equal(signal, null);
  assert.equal(code, 0, server.stderr());
  assert.match(server.stderr(), /SIGTERM received/);
  assert.ok(!outcomes.includes(500));
  // Requests the server accepted were answered; WAL folded back into the main file.
  const walSize = fs.existsSync(`${server.db}-wal`) ? fs.statSync(`${server.db}-wal`).size : 0;
  assert.equal(walSize, 0, 'WAL checkpointed (truncated) on shutdown');
  const created = outcomes.filter((s) => s === 201).length;
  const rows = sqliteQuery(server.db, "SELECT COUNT(*) AS n FROM signs WHERE gloss LIKE 'TERM-%'");
  assert.equal(rows[0].n, created, 'every write answered 201 is in the file');
  assert.ok(before.length === 64);
});
