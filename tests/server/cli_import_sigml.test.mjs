// `signweave import DIR --lang CODE` over a SiGML collection (fixtures/sigml_collection, written
// for this test): one sign a file or many, H- and G-SiGML, glosses from the element or the file
// name, a report per file with every rejected sign's line and reason; a re-import is unchanged.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { test } from 'node:test';

import { fixturesData, makeTempDir, repoRoot, sqliteQuery } from './server_harness.mjs';

const cli = process.env.SIGNWEAVE_CLI_BIN ?? path.join(repoRoot, 'build', 'native', 'signweave-cli');
const collection = path.join(repoRoot, 'tests', 'server', 'fixtures', 'sigml_collection');

function runImport(args) {
  const result = spawnSync(cli, ['import', ...args], { encoding: 'utf8' });
  const lines = result.stdout.trim().split('\n').filter(Boolean).map((l) => JSON.parse(l));
  const files = Object.fromEntries(lines.filter((l) => l.file).map((l) => [path.basename(l.file), l]));
  return { status: result.status, files, summary: lines.at(-1)?.summary, stderr: result.stderr };
}

function freshDb() {
  const db = path.join(makeTempDir(), 'sigml.db');
  assert.equal(spawnSync(cli, ['import', path.join(fixturesData, 'languages.json'), '--db', db]).status, 0);
  return db;
}

test('a folder of .sigml files imports per file, glosses from the element or the file name', () => {
  const db = freshDb();
  const first = runImport([collection, '--db', db, '--lang', 'ase']);
  assert.equal(first.status, 1, 'one sign and one file are rejected');
  assert.deepEqual(Object.keys(first.files).sort(), ['HOUSE.sigml', 'gestural.sigml', 'greetings.sigml', 'notes.sigml']);
  assert.deepEqual([first.files['HOUSE.sigml'].signs, first.files['HOUSE.sigml'].created], [1, 1]);
  assert.deepEqual([first.files['gestural.sigml'].signs, first.files['gestural.sigml'].created], [1, 1]);
  const greetings = first.files['greetings.sigml'];
  assert.deepEqual([greetings.signs, greetings.created, greetings.rejected.length], [3, 2, 1]);
  assert.equal(greetings.rejected[0].gloss, 'BROKEN');
  assert.equal(greetings.rejected[0].line, 24);
  assert.match(greetings.rejected[0].reason, /hamnotasymbol/);
  assert.equal(first.files['notes.sigml'].signs, 0);
  assert.match(first.files['notes.sigml'].rejected[0].reason, /not a SiGML sign file/);
  assert.deepEqual(first.summary, { files: 4, signs: 5, created: 4, updated: 0, unchanged: 0, rejected: 2, outcome: 'imported' });

  const rows = sqliteQuery(db, "SELECT gloss, format, notation FROM signs WHERE language = 'ase' ORDER BY gloss");
  assert.deepEqual(rows.map((r) => [r.gloss, r.format]), [['GREET', 'hsigml'], ['HOUSE', 'hsigml'], ['STILLHAND', 'gsigml'], ['WAVE', 'hsigml']]);
  // Each sign is stored as written, in a document of its own.
  const wave = rows.find((r) => r.gloss === 'WAVE').notation;
  assert.match(wave, /^<sigml>\n  <hns_sign gloss="WAVE">[\s\S]*<hammover\/>[\s\S]*<\/hns_sign>\n<\/sigml>/);
  assert.doesNotMatch(wave, /GREET/);

  const again = runImport([collection, '--db', db, '--lang', 'ase']);
  assert.equal(again.summary.unchanged, 4);
  assert.equal(again.summary.created, 0);
});

test('--lang is required and must exist; --dry-run writes nothing', () => {
  const db = freshDb();
  assert.equal(runImport([collection, '--db', db]).status, 2);
  assert.equal(runImport([collection, '--db', db, '--lang', 'xxx']).status, 2);
  const dry = runImport([path.join(collection, 'HOUSE.sigml'), '--db', db, '--lang', 'ase', '--dry-run']);
  assert.equal(dry.status, 0, dry.stderr);
  assert.equal(dry.summary.signs, 1);
  assert.equal(sqliteQuery(db, "SELECT COUNT(*) AS n FROM signs WHERE gloss = 'HOUSE'")[0].n, 0);
});
