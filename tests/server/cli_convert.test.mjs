// `signweave convert IN --to FORMAT` (build/native/signweave-cli convert): signs of any notation
// written in another; what comes out is read back by `signweave check --spec` as the same sign.
// The signs are written for this test.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { makeTempDir, repoRoot } from './server_harness.mjs';

const cli = process.env.SIGNWEAVE_CLI_BIN ?? path.join(repoRoot, 'build', 'native', 'signweave-cli');
const signs = [
  'GREET = R(H(flat, thumbacross), E(uo), P(l), Loc(forehead, right, touch), M(straight, o, small))',
  'STILL = R(H(fist), E(u), P(l), Loc(chest, centre))',
].join('\n');
const extensions = { sigml: 'sigml', hsigml: 'sigml', gsigml: 'sigml', hamnosys: 'txt', formula: 'txt' };

function run(args) {
  return spawnSync(cli, args, { encoding: 'utf8' });
}
function specs(file) {
  const result = run(['check', file, '--spec']);
  return result.stdout.trim().split('\n').map((l) => JSON.parse(l)).filter((o) => !o.summary).map((o) => o.spec);
}

test('every target notation reads back as the same signs', () => {
  const dir = makeTempDir();
  const source = path.join(dir, 'signs.txt');
  fs.writeFileSync(source, signs);
  const expected = specs(source);
  assert.equal(expected.length, 2);
  for (const [format, extension] of Object.entries(extensions)) {
    const out = path.join(dir, `out-${format}.${extension}`);
    const result = run(['convert', source, '--to', format, '--out', out]);
    assert.equal(result.status, 0, `${format}: ${result.stderr}`);
    assert.match(result.stderr, /2 signs written/);
    assert.deepEqual(specs(out), expected, format);
  }
  const sigml = fs.readFileSync(path.join(dir, 'out-sigml.sigml'), 'utf8');
  assert.match(sigml, /<hns_sign gloss="GREET">/);
});

test('to stdout; a sign that does not parse is reported and not written; bad usage is 2', () => {
  const dir = makeTempDir();
  const source = path.join(dir, 'signs.txt');
  fs.writeFileSync(source, `${signs}\nBROKEN = R(H(flax))\n`);
  const result = run(['convert', source, '--to', 'formula']);
  assert.equal(result.status, 1);
  assert.equal(result.stdout.trim().split('\n').length, 2);
  assert.match(result.stderr, /line 3 'BROKEN' not converted: .*flax/);
  assert.equal(run(['convert', source, '--to', 'pdf']).status, 2);
  assert.equal(run(['convert', '--to', 'formula']).status, 2);
});
