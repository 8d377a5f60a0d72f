// The avatar runtime through WebAssembly: loading (the synthetic avatar, every models/*.glb, and
// bad bytes), native parity of the whole pose -> morph -> skin -> anchors pipeline (to 1e-5), and
// SIMD == scalar across the two module flavours.
import assert from 'node:assert/strict';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, test } from 'node:test';

import { FLAVOURS, ROOT, loadCore, maxAbsDiff, runNativeParity } from './wasm_loader.mjs';

const TOLERANCE = 1e-5;
const native = runNativeParity('avatar_skinning');

// The canonical joints a model must have (skeleton/humanoid_names.h humanoid_joint_required) and
// the fingertip points the project's own avatar has.
const REQUIRED = ['hips', 'spine', 'neck', 'head'];
for (const side of ['left', 'right']) {
  REQUIRED.push(`${side}UpperArm`, `${side}LowerArm`, `${side}Hand`,
    `${side}ThumbMetacarpal`, `${side}ThumbProximal`, `${side}ThumbDistal`);
  for (const finger of ['Index', 'Middle', 'Ring', 'Little']) {
    for (const segment of ['Proximal', 'Intermediate', 'Distal']) REQUIRED.push(`${side}${finger}${segment}`);
  }
}
const TIPS = ['left', 'right'].flatMap((s) => ['Thumb', 'Index', 'Middle', 'Ring', 'Little'].map((f) => `${s}${f}Tip`));

function sampled(view, stride) {
  const out = [];
  for (let v = 0; 3 * v + 2 < view.length; v += stride) out.push([view[3 * v], view[3 * v + 1], view[3 * v + 2]]);
  return out;
}

for (const flavour of FLAVOURS) {
  describe(`avatar runtime (${flavour})`, async () => {
    const core = await loadCore(flavour);

    test('the SIMD skinning loop is in the simd flavour only', () => {
      assert.equal(core.avatarSimdAvailable(), flavour === 'simd');
    });

    test('the synthetic avatar loads with the native counts and names', () => {
      const r = core.avatarLoadSynthetic();
      assert.equal(r.error, undefined, r.error);
      const info = core.avatarInfo(r.id);
      assert.equal(info.vertexCount, native.vertex_count);
      assert.equal(info.triangleCount, native.triangle_count);
      assert.equal(info.anchorCount, native.anchor_count);
      assert.deepEqual(core.avatarJointNames(r.id), native.joint_names);
      assert.deepEqual(core.avatarMorphNames(r.id), native.morph_names);
      assert.equal(core.avatarIndices(r.id).length, 3 * info.triangleCount);
      assert.equal(core.avatarRestPositions(r.id).length, 3 * info.vertexCount);
      assert.equal(core.avatarSkinJoints(r.id).length, 4 * info.vertexCount);
      assert.equal(core.avatarLocals(r.id).length, 10 * info.jointCount);
      assert.equal(core.avatarJointParents(r.id)[0], -1);
      assert.ok(core.avatarAnchorNames(r.id).includes('body/chin/centre'));
      assert.equal(core.avatarCanonicalJoint(r.id, 'mixamorig:LeftForeArm'), core.avatarJointNames(r.id).indexOf('leftLowerArm'));
      assert.ok(core.avatarFree(r.id));
    });

    test('posed, morphed and skinned like the native core (to 1e-5)', () => {
      const { id } = core.avatarLoadSynthetic();
      const weights = core.avatarMorphWeights(id);
      native.inputs.morph_weights.forEach((w, k) => { weights[k] = w; });
      for (const pose of native.poses) {
        assert.ok(core.avatarSetSyntheticPose(id, pose.seed, native.inputs.max_angle_rad));
        assert.ok(core.avatarUpdate(id, true), core.avatarError(id));
        const stride = native.inputs.vertex_stride;
        const worst = {
          positions: maxAbsDiff(sampled(core.avatarSkinnedPositions(id), stride), pose.positions),
          normals: maxAbsDiff(sampled(core.avatarSkinnedNormals(id), stride), pose.normals),
          anchors: maxAbsDiff(sampled(core.avatarAnchorPositions(id), 1), pose.anchors),
        };
        const matrices = core.avatarJointMatrices(id);
        const translations = [];
        for (let j = 0; 16 * j < matrices.length; ++j) translations.push(matrices[16 * j + 12], matrices[16 * j + 13], matrices[16 * j + 14]);
        worst.joints = maxAbsDiff(translations, pose.joint_translations);
        for (const [what, diff] of Object.entries(worst)) assert.ok(diff < TOLERANCE, `seed ${pose.seed} ${what}: ${diff}`);
      }
      core.avatarFree(id);
    });

    test('bad bytes give an error message, and the module keeps working', () => {
      const good = core.avatarLoadSynthetic();
      for (const bytes of [new Uint8Array(0), new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0, 255, 255, 0, 0]),
        new TextEncoder().encode('{"asset": {"version": "2.0"}, "nodes": ['), new TextEncoder().encode('[[[[[[[[]]]]]]]]')]) {
        const r = core.avatarLoad(bytes);
        assert.equal(r.id, undefined);
        assert.equal(typeof r.error, 'string');
        assert.ok(r.error.length > 0);
      }
      assert.ok(core.avatarUpdate(good.id, true));
      core.avatarFree(good.id);
    });

    // Player.loadAvatar copies the bytes in with one TypedArray.set (the page's start-up): it must
    // take what the page and tools hand it, and answer anything else with the loader's message.
    test('the player takes the avatar as a Uint8Array or an ArrayBuffer; other values get a message', () => {
      const file = path.join(ROOT, 'models', 'signweave-avatar.glb');
      const bytes = readFileSync(file);
      const fromView = new core.Player();
      assert.equal(fromView.loadAvatar(new Uint8Array(bytes)), '');
      const fromBuffer = new core.Player();
      assert.equal(fromBuffer.loadAvatar(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length)), '');
      assert.deepEqual(Array.from(fromBuffer.positions()), Array.from(fromView.positions()), 'same avatar either way');
      assert.ok(JSON.parse(fromView.avatarInfoJson()).vertex_count > 1000);
      for (const bad of ['a string', null, 42, new Uint8Array([1, 2, 3])]) {
        const message = new core.Player().loadAvatar(bad);
        assert.ok(typeof message === 'string' && message.length > 0, `loadAvatar(${String(bad)}) answers ${message}`);
      }
      assert.equal(new core.Player().loadAvatar(new Uint8Array(bytes)), '', 'the module still works');
    });

    test('an unknown id gives null, empty views and false — no abort', () => {
      assert.equal(core.avatarInfo(9999), null);
      assert.equal(core.avatarSkinnedPositions(9999).length, 0);
      assert.equal(core.avatarUpdate(9999, true), false);
      assert.equal(core.avatarFree(9999), false);
      assert.match(core.avatarError(9999), /no avatar/);
    });

    const modelsDir = path.join(ROOT, 'models');
    const models = existsSync(modelsDir) ? readdirSync(modelsDir).filter((f) => f.endsWith('.glb')) : [];
    test('models/*.glb load with the canonical joints, within budget, with face morphs', (t) => {
      if (models.length === 0) {
        t.skip('no models/*.glb yet (the avatar-model branch generates models/signweave-avatar.glb)');
        return;
      }
      for (const file of models) {
        const r = core.avatarLoad(readFileSync(path.join(modelsDir, file)));
        assert.equal(r.error, undefined, `${file}: ${r.error}`);
        const info = core.avatarInfo(r.id);
        assert.ok(info.triangleCount <= 30000, `${file}: ${info.triangleCount} triangles > 30,000`);
        assert.ok(info.jointCount >= 55 && info.jointCount <= 80, `${file}: ${info.jointCount} joints (55-80)`);
        for (const name of [...REQUIRED, ...TIPS]) {
          assert.ok(core.avatarCanonicalJoint(r.id, name) >= 0, `${file}: no ${name}`);
        }
        const morphs = core.avatarMorphNames(r.id);
        assert.ok(morphs.length >= 32, `${file}: ${morphs.length} morph targets (20 face + 12 visemes at least)`);
        for (const name of ['jawOpen', 'eyeBlinkLeft', 'eyeBlinkRight', 'browInnerUp', 'viseme_aa', 'viseme_PP']) {
          assert.ok(morphs.includes(name), `${file}: no morph ${name}`);
        }
        // The rest pose skins to the bind pose.
        core.avatarResetPose(r.id);
        core.avatarMorphWeights(r.id).fill(0);
        assert.ok(core.avatarUpdate(r.id, true));
        assert.ok(maxAbsDiff(Array.from(core.avatarSkinnedPositions(r.id)), Array.from(core.avatarRestPositions(r.id))) < TOLERANCE);
        core.avatarFree(r.id);
      }
    });
  });
}

describe('SIMD and scalar flavours agree', async () => {
  const [simd, scalar] = await Promise.all(FLAVOURS.map((f) => loadCore(f)));
  const modelPath = path.join(ROOT, 'models', 'signweave-avatar.glb');
  const bytes = existsSync(modelPath) ? readFileSync(modelPath) : null;

  test(`on ${bytes ? 'models/signweave-avatar.glb' : 'the synthetic avatar'}, posed and morphed`, () => {
    const results = [simd, scalar].map((core) => {
      const { id, error } = bytes ? core.avatarLoad(bytes) : core.avatarLoadSynthetic();
      assert.equal(error, undefined, error);
      core.avatarSetSyntheticPose(id, 4, 0.6);
      core.avatarMorphWeights(id).fill(0.4);
      assert.ok(core.avatarUpdate(id, true));
      return { positions: Array.from(core.avatarSkinnedPositions(id)), normals: Array.from(core.avatarSkinnedNormals(id)) };
    });
    assert.ok(results[0].positions.length > 0);
    assert.ok(maxAbsDiff(results[0].positions, results[1].positions) < TOLERANCE);
    assert.ok(maxAbsDiff(results[0].normals, results[1].normals) < TOLERANCE);
  });
});
