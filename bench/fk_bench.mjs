// FK on the synthetic 65-joint humanoid in WebAssembly, SIMD and scalar builds: ns per full update
// and per right-hand sub-tree update (the native figures come from bench/fk_bench.cpp), plus the
// cost of the same full update driven by one JS call per update, as the page does per frame.
import { FLAVOURS, loadCore, printResult, timeNsPerCall } from './wasm_common.mjs';

const INNER = 1000; // updates per JS->WASM call for the pure-FK figures

for (const flavour of FLAVOURS) {
  const core = await loadCore(flavour);
  const fk = new core.SyntheticHumanoidFk();
  fk.setPose(1);
  const hand = fk.find('rightHand');
  printResult(`fk_65_joints_wasm_${flavour}`, timeNsPerCall(() => fk.runRepeatedly(-1, INNER), { perCall: INNER }), 'ns/update');
  printResult(`fk_right_hand_subtree_wasm_${flavour}`, timeNsPerCall(() => fk.runRepeatedly(hand, INNER), { perCall: INNER }), 'ns/update');
  printResult(`fk_65_joints_wasm_${flavour}_per_js_call`, timeNsPerCall(() => fk.run(-1)), 'ns/update');
  fk.delete();
}
