// `signweave import` (build/native/signweave-cli import): the same validation as the server, a
// summary line, every rejected sign with file, line and reason; --strict writes nothing on error.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { fixturesData, makeTempDir, repoRoot, sqliteQuery, validNotation } from './server_harness.mjs';

const cli = process.env.SIGNWEAVE_CLI_BIN ?? path.join(repoRoot, 'build', 'native', 'signweave-cli');

function runImport(args) {
  const result = spawnSync(cli, ['import', ...args], { encoding: 'utf8' });
  const lines = result.stdout.trim().split('\n');
  return { status: result.status, lines, summary: JSON.parse(lines[lines.length - 1]), stderr: result.stderr };
}

test('a data directory imports languages first, then every sign file; re-import is unchanged', () => {
  const db = path.join(makeTempDir(), 'cli.db');
  const first = runImport([fixturesData, '--db', db]);
  assert.equal(first.status, 0, first.stderr + first.lines.join('\n'));
  assert.equal(first.summary.languages, 2);
  assert.equal(first.summary.created, 20);
  assert.equal(first.summary.rejected, 0);
  const second = runImport([fixturesData, '--db', db]);
  assert.equal(second.summary.unchanged, 20);
  assert.equal(sqliteQuery(db, 'SELECT COUNT(*) AS n FROM alphabet')[0].n, 11);
});

test('rejected signs are listed with file, line and reason; --strict writes nothing', () => {
  const dir = makeTempDir();
  const db = path.join(dir, 'cli.db');
  runImport([path.join(fixturesData, 'languages.json'), '--db', db]);
  const bad = path.join(dir, 'ase');
  fs.mkdirSync(bad);
  const file = path.join(bad, 'mixed.jsonl');
  fs.writeFileSync(file, [
    JSON.stringify({ gloss: 'GOOD-ONE', notation: validNotation(1) }),
    JSON.stringify({ gloss: 'BAD-ONE', notation: 'R(H(flax))' }),
    '{not json',
  ].join('\n'));
  const strict = runImport([file, '--db', db, '--strict']);
  assert.equal(strict.status, 1);
  assert.match(strict.lines[0], new RegExp(`^rejected ${file.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}:2: notation does not parse`));
  assert.match(strict.lines[1], /:3: malformed JSON/);
  assert.equal(strict.summary.created, 0);
  assert.equal(sqliteQuery(db, 'SELECT COUNT(*) AS n FROM signs')[0].n, 0);
  const lenient = runImport([file, '--db', db]);
  assert.equal(lenient.status, 1);
  assert.equal(lenient.summary.created, 1);
  assert.equal(lenient.summary.rejected, 2);
  assert.equal(sqliteQuery(db, 'SELECT gloss FROM signs')[0].gloss, 'GOOD-ONE');
});
