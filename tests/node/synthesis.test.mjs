// Synthesis in WebAssembly: the same clip as the native core (parity case "synthesis", to 1e-5),
// caption segments, the sample view's layout, exports, and errors as values (never an abort).
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, test } from 'node:test';

import { FLAVOURS, ROOT, loadCore, runNativeParity } from './wasm_loader.mjs';

const TOLERANCE = 1e-5;
const expected = runNativeParity('synthesis');
const MODEL = path.join(ROOT, 'models', 'signweave-avatar.glb');
const ALPHABET = path.join(ROOT, 'data', 'ase', 'alphabet.jsonl');

function quatDiff(a, b) {
  const same = Math.max(...a.map((v, i) => Math.abs(v - b[i])));
  const flipped = Math.max(...a.map((v, i) => Math.abs(v + b[i])));
  return Math.min(same, flipped);
}

for (const flavour of FLAVOURS) {
  describe(`synthesis (${flavour})`, async () => {
    const core = await loadCore(flavour);
    const ref = core.synthAvatarReference();

    // Both flavours: the SIMD build once ended 0.68 rad from native because the thumb-contact IK
    // took discrete accept/reject steps (docs/SYNTHESIS.md); the solve is now continuous.
    test('the parity phrase gives the native clip to 1e-5', () => {
      assert.ok(!expected.error, expected.error);
      assert.ok(ref.id > 0);
      const clip = core.synthCompile(ref.id, expected.inputs.text, {});
      assert.ok(!clip.error, clip.error);
      assert.equal(clip.frames, expected.outputs.frame_count);
      assert.equal(clip.joints, expected.outputs.joint_count);
      let worst = 0;
      for (const sample of expected.outputs.samples) {
        const locals = core.synthSample(clip.id, sample.t);
        assert.equal(locals.length, clip.joints * 10);
        for (let j = 0; j < clip.joints; ++j) {
          const q = Array.from(locals.subarray(j * 10 + 3, j * 10 + 7));
          worst = Math.max(worst, quatDiff(q, sample.rotations.slice(j * 4, j * 4 + 4)));
        }
      }
      assert.ok(worst < TOLERANCE, `worst rotation difference ${worst}`);
      core.synthClipFree(clip.id);
    });

    test('segments carry captions in time order', () => {
      const clip = core.synthCompile(ref.id, expected.inputs.text, { speed: 1 });
      const segments = JSON.parse(core.synthSegments(clip.id));
      assert.equal(segments.length, expected.outputs.segments);
      const signs = segments.filter((s) => s.kind === 'sign');
      assert.deepEqual(signs.map((s) => s.label), ['HELLO', 'OK']);
      for (let i = 1; i < segments.length; ++i) assert.ok(segments[i].start >= segments[i - 1].start);
      // The speed factor divides every duration, but above 1 a movement or transition keeps the
      // time its arm needs to stay within human accelerations (docs/SYNTHESIS.md, Phrase
      // timeline): a faster signer is shorter, by less than the factor. Below 1 nothing holds it.
      const fast = core.synthCompile(ref.id, expected.inputs.text, { speed: 2 });
      assert.ok(fast.duration < clip.duration * 0.9, `speed 2: ${fast.duration} vs ${clip.duration}`);
      const slow = core.synthCompile(ref.id, expected.inputs.text, { speed: 0.5 });
      assert.ok(slow.duration > clip.duration * 1.7, `speed 0.5: ${slow.duration} vs ${clip.duration}`);
      core.synthClipFree(clip.id);
      core.synthClipFree(fast.id);
      core.synthClipFree(slow.id);
    });

    test('exports BVH text and GLB bytes', () => {
      const clip = core.synthCompile(ref.id, expected.inputs.text, {});
      const bvh = core.synthExportBvh(clip.id);
      assert.match(bvh, /^HIERARCHY/);
      assert.match(bvh, /MOTION\s+Frames:\s+\d+/);
      const glb = core.synthExportGlb(clip.id);
      assert.ok(glb instanceof Uint8Array);
      assert.equal(new TextDecoder().decode(glb.subarray(0, 4)), 'glTF');
      core.synthClipFree(clip.id);
    });

    test('bad input is an error value', () => {
      assert.ok(core.synthCompile(ref.id, 'R(H(nonsense', {}).error);
      assert.ok(core.synthCompile(99999, 'R(H(flat))', {}).error);
      assert.equal(core.synthSample(99999, 0), null);
      assert.ok(core.synthAvatarLoad(new Uint8Array([1, 2, 3])).error);
      assert.equal(core.synthSegments(424242), '[]');
    });

    test('fingerspells typed text with the data alphabet on the project avatar', { skip: !existsSync(MODEL) || !existsSync(ALPHABET) }, () => {
      const avatar = core.synthAvatarLoad(readFileSync(MODEL));
      assert.ok(!avatar.error, avatar.error);
      assert.equal(core.synthSetAlphabet(avatar.id, readFileSync(ALPHABET, 'utf8')), '');
      const clip = core.synthCompile(avatar.id, 'hi, abc', {});
      assert.ok(!clip.error, clip.error);
      assert.equal(clip.fingerspelled, true);
      const segments = JSON.parse(core.synthSegments(clip.id));
      assert.deepEqual(segments.filter((s) => s.kind === 'letter').map((s) => s.label), ['H', 'I', 'A', 'B', 'C']);
      assert.ok(segments.some((s) => s.kind === 'pause'));
      assert.ok(clip.maxPenetrationM <= 0.005, `penetration ${clip.maxPenetrationM}`);
      core.synthClipFree(clip.id);
      core.synthAvatarFree(avatar.id);
    });
  });
}
