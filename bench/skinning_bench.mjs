// Skinning cost in WebAssembly, SIMD and scalar builds: LBS of positions + normals, 4 influences,
// ns per vertex, on the real avatar (models/signweave-avatar.glb) or — when it has not been
// generated — the synthetic avatar, named so. Plus a whole frame (FK, palette, morphs, LBS,
// anchors) from one JS call, as the page pays it. bench/skinning_bench.cpp is the native twin.
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';

import { ROOT } from '../tests/node/wasm_loader.mjs';
import { FLAVOURS, loadCore, printResult, timeNsPerCall } from './wasm_common.mjs';

const INNER = 50; // skinning passes per JS->WASM call
const modelPath = path.join(ROOT, 'models', 'signweave-avatar.glb');

for (const flavour of FLAVOURS) {
  const core = await loadCore(flavour);
  let label = 'avatar';
  let loaded = existsSync(modelPath) ? core.avatarLoad(readFileSync(modelPath)) : { error: 'absent' };
  if (loaded.error !== undefined) {
    loaded = core.avatarLoadSynthetic();
    label = 'synthetic';
  }
  const id = loaded.id;
  const vertices = core.avatarInfo(id).vertexCount;
  core.avatarSetSyntheticPose(id, 3, 0.5);
  core.avatarUpdate(id, true);
  const simd = flavour === 'simd';
  const lbs = timeNsPerCall(() => core.avatarSkinRepeatedly(id, simd, INNER, false), { perCall: INNER }) / vertices;
  printResult(`skinning_lbs_wasm_${flavour}_${label}`, lbs, 'ns/vertex');
  const four = timeNsPerCall(() => core.avatarSkinRepeatedly(id, simd, INNER, true), { perCall: INNER }) / vertices;
  printResult(`skinning_lbs_wasm_${flavour}_${label}_all_4_influences`, four, 'ns/vertex');
  // Process CPU time as well: the bench machines are shared, and wall time then counts the others.
  for (const allFour of [false, true]) {
    const cpuStart = process.cpuUsage();
    const wallStart = process.hrtime.bigint();
    let passes = 0;
    while (Number(process.hrtime.bigint() - wallStart) < 3e8) { core.avatarSkinRepeatedly(id, simd, INNER, allFour); passes += INNER; }
    const cpu = process.cpuUsage(cpuStart);
    printResult(`skinning_lbs_wasm_${flavour}_${label}${allFour ? '_all_4_influences' : ''}_process_cpu_time`,
      ((cpu.user + cpu.system) * 1000) / (passes * vertices), 'ns/vertex');
  }
  const frame = timeNsPerCall(() => core.avatarUpdate(id, simd)) / 1000;
  printResult(`skinning_frame_wasm_${flavour}_${label}_${vertices}_vertices`, frame, 'us/frame');
  core.avatarFree(id);
}
