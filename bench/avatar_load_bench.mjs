// Avatar start-up cost in WebAssembly (the page's real cost): core.avatarLoad on
// models/signweave-avatar.glb — glTF load, body anchors and the skinning instance in one call, as
// the page makes it — per flavour. "cold" is the first call in a fresh module (what a page load
// pays: the code has not tiered up yet); "warm" the median of later calls. `player_` figures are
// the page's own call, Player.loadAvatar (the same load plus the rig check and the Synthesizer's
// measurements of the avatar), in a module of its own; node shares the compiled code of one
// flavour between its instances, so that "cold" figure is not cold (it is not the page's cost). Process CPU time too:
// the machine is shared, and wall time then counts the neighbours. bench/avatar_load_bench.cpp is
// the native twin with the parts split. `player_pack` is Player.loadAvatar on the avatar pack the
// page downloads instead (web/gen/signweave-avatar.swavatar, src/avatar/avatar_pack.h), in the same
// module as `player_` (so only its warm figure compares).
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';

import { ROOT } from '../tests/node/wasm_loader.mjs';
import { FLAVOURS, loadCore, printResult } from './wasm_common.mjs';

const modelPath = path.join(ROOT, 'models', 'signweave-avatar.glb');
const packPath = path.join(ROOT, 'web', 'gen', 'signweave-avatar.swavatar');
const WARM_RUNS = 7;
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

for (const [flavour, api] of FLAVOURS.flatMap((f) => [[f, 'core'], [f, 'player'], [f, 'pack']])) {
  const core = await loadCore(flavour);
  const player = api !== 'core' ? new core.Player() : null;
  const file = api === 'pack' ? packPath : modelPath;
  const real = existsSync(file);
  const bytes = real ? new Uint8Array(readFileSync(file)) : null;
  if (player && !real) continue;  // the Player takes bytes: without the real avatar, nothing to give it
  const label = { core: '', player: 'player_', pack: 'player_pack_' }[api] + (real ? 'avatar' : 'synthetic');
  const load = player ? () => {
    const error = player.loadAvatar(bytes);
    if (error) throw new Error(error);
  } : () => {
    const r = real ? core.avatarLoad(bytes) : core.avatarLoadSynthetic();
    if (r.error !== undefined) throw new Error(r.error);
    core.avatarFree(r.id);
  };
  const time = () => {
    const cpu = process.cpuUsage();
    const start = process.hrtime.bigint();
    load();
    const wall = Number(process.hrtime.bigint() - start) / 1e6;
    const used = process.cpuUsage(cpu);
    return { wall, cpu: (used.user + used.system) / 1000 };
  };
  const cold = time();
  printResult(`avatar_load_wasm_${flavour}_${label}_cold_ms`, cold.wall, 'ms');
  printResult(`avatar_load_wasm_${flavour}_${label}_cold_process_cpu_ms`, cold.cpu, 'ms');
  const warm = Array.from({ length: WARM_RUNS }, time);
  printResult(`avatar_load_wasm_${flavour}_${label}_warm_ms`, median(warm.map((t) => t.wall)), 'ms');
  printResult(`avatar_load_wasm_${flavour}_${label}_warm_process_cpu_ms`, median(warm.map((t) => t.cpu)), 'ms');
}
