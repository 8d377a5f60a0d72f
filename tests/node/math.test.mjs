// Native vs WebAssembly parity for src/math and src/skeleton: the same inputs give the same numbers
// (to 1e-5) in both WASM flavours as in the native core (ARCHITECTURE.md, "Determinism").
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';

import { FLAVOURS, loadCore, maxAbsDiff, runNativeParity } from './wasm_loader.mjs';

const TOLERANCE = 1e-5;
const euler = runNativeParity('euler');
const vectorRotation = runNativeParity('vector_rotation');
const fk = runNativeParity('fk');

// q and -q are the same rotation.
function quatDiff(a, b) {
  const same = Math.max(...a.map((v, i) => Math.abs(v - b[i])));
  const flipped = Math.max(...a.map((v, i) => Math.abs(v + b[i])));
  return Math.min(same, flipped);
}

for (const flavour of FLAVOURS) {
  describe(`core (${flavour})`, async () => {
    const core = await loadCore(flavour);

    test('reports its version and flavour', () => {
      assert.match(core.version(), /^\d+\.\d+\.\d+$/);
      assert.equal(core.simd(), flavour === 'simd');
    });

    test('quatFromEuler matches native in all six orders', () => {
      for (const [order, expected] of Object.entries(euler.orders)) {
        let worst = 0;
        euler.inputs_rad.forEach(([x, y, z], i) => {
          worst = Math.max(worst, quatDiff(core.quatFromEuler(x, y, z, order), expected.quat_from_euler[i]));
        });
        assert.ok(worst < TOLERANCE, `${order}: worst difference ${worst}`);
      }
    });

    test('eulerFromQuat matches native in all six orders, gimbal lock included', () => {
      for (const [order, expected] of Object.entries(euler.orders)) {
        expected.quat_from_euler.forEach(([w, x, y, z], i) => {
          const angles = core.eulerFromQuat(w, x, y, z, order);
          const diff = maxAbsDiff(angles, expected.euler_from_quat[i]);
          assert.ok(diff < TOLERANCE, `${order} input ${i}: ${angles} vs ${expected.euler_from_quat[i]}`);
        });
      }
    });

    test('eulerBetween (seed 004) matches native for random, parallel and opposite pairs', () => {
      for (const [order, expected] of Object.entries(vectorRotation.orders)) {
        vectorRotation.pairs.forEach(([a, b], i) => {
          const angles = core.eulerBetween(...a, ...b, order);
          assert.ok(maxAbsDiff(angles, expected[i]) < TOLERANCE, `${order} pair ${i}: ${angles} vs ${expected[i]}`);
        });
      }
    });

    test('an unknown order gives null, not an abort', () => {
      assert.equal(core.quatFromEuler(0, 0, 0, 'XXY'), null);
      assert.equal(core.eulerFromQuat(1, 0, 0, 0, 'ABC'), null);
      assert.equal(core.eulerBetween(1, 0, 0, 0, 1, 0, ''), null);
    });

    test('FK of the 65-joint humanoid matches native, full and partial', () => {
      const humanoid = new core.SyntheticHumanoidFk();
      try {
        assert.equal(humanoid.jointCount(), fk.joint_count);
        for (const pose of fk.full) {
          humanoid.setPose(pose.seed);
          assert.ok(humanoid.run(-1));
          const view = humanoid.modelView();
          const diff = maxAbsDiff(Array.from(view), pose.model.flat());
          assert.ok(diff < TOLERANCE, `seed ${pose.seed}: worst difference ${diff}`);
        }
        humanoid.setPose(fk.partial.base_seed);
        assert.ok(humanoid.run(-1));
        humanoid.setPose(fk.partial.subtree_seed);
        assert.ok(humanoid.run(humanoid.find(fk.partial.from)));
        const diff = maxAbsDiff(Array.from(humanoid.modelView()), fk.partial.model.flat());
        assert.ok(diff < TOLERANCE, `partial: worst difference ${diff}`);
        assert.equal(humanoid.run(1000), false, 'an invalid sub-tree root is refused');
      } finally {
        humanoid.delete();
      }
    });
  });
}
