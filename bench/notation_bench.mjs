// WASM notation parse time per sign (notationParse: parse + JSON of SignSpec and diagnostics),
// printed as JSON lines {"name", "value", "unit"}; skipped, saying so on stderr, when the module
// has not been built.
import fs from 'node:fs';
import path from 'node:path';

import { GEN_DIR, loadCore } from '../tests/node/wasm_loader.mjs';

const flavour = ['simd', 'scalar'].find((f) => fs.existsSync(path.join(GEN_DIR, `signweave-${f}.wasm`)));
if (!flavour) {
  console.error('notation_bench: WASM module not built (./signweave build), skipped');
  process.exit(0);
}
const core = await loadCore(flavour);

function usPerCall(fn, minSeconds = 0.5) {
  // Warm up past V8's tier-up (Liftoff -> TurboFan) so the figure is the steady state.
  const warmEnd = Date.now() + 1000;
  while (Date.now() < warmEnd) fn();
  let n = 1;
  for (;;) {
    const start = process.hrtime.bigint();
    for (let i = 0; i < n; ++i) fn();
    const s = Number(process.hrtime.bigint() - start) / 1e9;
    if (s >= minSeconds) return (s * 1e6) / n;
    n *= s < minSeconds / 10 ? 10 : 2;
  }
}

const letter = 'R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))';
const hamnosys = 'hamsymmlr,hamfinger2,hamthumboutmod,hamextfingeruo,hampalmdl,hamshoulders,hamlrat,hamclose,hamcirclei,hamrepeatfromstart';
for (const [name, text, format] of [
  ['wasm_formula_parse_seed_letter', letter, 'formula'],
  ['wasm_hamnosys_parse_names', hamnosys, 'hamnosys'],
]) {
  console.log(JSON.stringify({ name: `${name}_${flavour}`, value: usPerCall(() => core.notationParse(text, format)), unit: 'us/sign' }));
}
