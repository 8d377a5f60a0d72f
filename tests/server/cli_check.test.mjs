// `signweave check` (build/native/signweave-cli check): every sign parsed and synthesised on the
// project avatar, one JSON object per sign. Besides depth and reach, the synthesise step reports
// how far a wrist or elbow moves in one frame and the largest change of that step, with the joint
// and frame (synthesis/clip_steps.h), so a pose that flips shows although no depth does.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { makeTempDir, repoRoot } from './server_harness.mjs';

const cli = process.env.SIGNWEAVE_CLI_BIN ?? path.join(repoRoot, 'build', 'native', 'signweave-cli');

function check(text) {
  const file = path.join(makeTempDir(), 'signs.txt');
  fs.writeFileSync(file, text);
  const result = spawnSync(cli, ['check', file], { encoding: 'utf8' });
  const lines = result.stdout.trim().split('\n').map((l) => JSON.parse(l));
  return { status: result.status, signs: lines.filter((o) => !o.summary), stderr: result.stderr };
}

test('check reports the arms\' largest per-frame step and its change, with the joint and frame', () => {
  const { status, signs, stderr } = check([
    'HELLO = R(H(flat, thumbacross), E(uo), P(l), Loc(forehead, right, touch), M(arc, or, bulge=u, small))',
    'STILL = R(H(fist), E(u), P(l), Loc(neutral, centre))',
  ].join('\n'));
  assert.equal(status, 0, stderr);
  assert.equal(signs.length, 2);
  for (const s of signs) {
    const d = s.steps.synthesise.detail;
    assert.ok(s.steps.synthesise.ok, `${s.gloss}: ${s.steps.synthesise.error}`);
    // From the rest pose and back: the arm moves, at a signer's speed (the smoothness tests'
    // bounds, 0.10 m a frame and 0.056 m of change at 30 fps).
    assert.ok(d.max_arm_step_m > 0.005 && d.max_arm_step_m < 0.10, `${s.gloss}: step ${d.max_arm_step_m} m`);
    assert.ok(d.max_arm_step_change_m > 0 && d.max_arm_step_change_m < 0.056, `${s.gloss}: change ${d.max_arm_step_change_m} m`);
    assert.match(d.max_arm_step_at, /^(left|right) (wrist|elbow) at frame \d+$/);
    assert.match(d.max_arm_step_change_at, /^(left|right) (wrist|elbow) at frame \d+$/);
    const frame = Number(d.max_arm_step_at.match(/\d+$/)[0]);
    assert.ok(frame >= 1 && frame < d.frames, `${s.gloss}: frame ${frame} of ${d.frames}`);
  }
});
