// Synthesis time in WebAssembly (SIMD and scalar builds): one sign from rest and back, and a
// 20-sign phrase, on the project's avatar (else the reference humanoid); and every sign of the ASL
// starter lexicon from rest and back, as a dictionary look-up pays it (mean, median, p90 and max CPU
// ms per sign; the slowest signs on stderr). Same workloads as bench/synthesis_bench.cpp; target:
// under 1 ms per sign.
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';

import { FLAVOURS, loadCore, printResult, timeNsPerCall } from './wasm_common.mjs';
import { ROOT } from '../tests/node/wasm_loader.mjs';

const SIGNS = [
  'R(H(fist), F_9^1, E(u), P(o), Loc(shoulders, right, none))',
  'R(H(flat, thumbacross), E(u), P(o), Loc(shoulders, right, none))',
  'R(H(ceeall), E(u), P(l), Loc(shoulders, right, none))',
  'R(H(finger2), E(u), P(o), Loc(chin, centre, touch))',
  'R(H(flat), E(u), P(i), Loc(forehead, right, close), M(straight o))',
  'R(H(pinch12), E(u), P(l), Loc(chest, right, none), M(circle axis=o cw small))',
  'R(H(finger23spread), E(u), P(o), Loc(shoulders, right, none))',
  'R(H(flat), E(l), P(d), Loc(neutral, centre, none), M(wavy r))',
  'R(H(fist), E(l), P(i), Loc(chest, left, touch))',
  'R(H(finger2), E(o), P(d), Loc(neutral, right, none), M(arc r bulge=u))',
  'R(H(flat), E(u), P(o), Loc(shoulders, right, none), M(nod))',
  'R(H(flat), E(u), P(l), Loc(chest, right, none), M(replace H(fist)))',
  'R(H(finger2345), E(u), P(o), Loc(neutral, centre, none), M(fingerplay))',
  'R(H(fist), E(u), P(o), Loc(cheeks, right, touch))',
  'R(H(flat), E(o), P(u), Loc(neutral, centre, none), M(straight u)) Sym(lr)',
  'R(H(finger2), E(u), P(o), Loc(mouth, centre, close), M(zigzag d))',
  'R(H(ceeall), E(o), P(l), Loc(neutral, right, none), M(spiral axis=o ccw))',
  'R(H(flat), E(u), P(o), Loc(shoulders, right, none), M(twist))',
  'R(H(pinchall), E(u), P(o), Loc(chin, centre, close), M(straight o fast))',
  'R(H(flat), E(u), P(o), Loc(eyebrows, right, close), M(ellipse axis=o cw))',
];
const PHRASE = SIGNS.map((s, i) => `S${i} = ${s}`).join('\n');
const MODEL = path.join(ROOT, 'models', 'signweave-avatar.glb');
// The starter lexicon's notations and glosses (data/ase/lexicon.jsonl, one JSON object a line).
const LEXICON = readFileSync(path.join(ROOT, 'data', 'ase', 'lexicon.jsonl'), 'utf8')
  .split('\n')
  .filter((line) => line.trim() !== '')
  .map((line) => JSON.parse(line))
  .filter((entry) => typeof entry.notation === 'string');
// Calls per lexicon sign: its CPU time is the mean of these (as bench/synthesis_bench.cpp does).
const LEXICON_CALLS = 5;

for (const flavour of FLAVOURS) {
  const core = await loadCore(flavour);
  let avatar = existsSync(MODEL) ? core.synthAvatarLoad(readFileSync(MODEL)) : { error: 'no model' };
  const which = avatar.error ? 'reference' : 'avatar';
  if (avatar.error) avatar = core.synthAvatarReference();
  let next = 0;
  const perSign = timeNsPerCall(() => {
    const clip = core.synthCompile(avatar.id, SIGNS[next++ % SIGNS.length], {});
    if (clip.error) throw new Error(clip.error);
    core.synthClipFree(clip.id);
  });
  printResult(`synthesis_per_sign_wasm_${flavour}_${which}`, perSign / 1e6, 'ms/sign');
  const phrase = timeNsPerCall(() => {
    const clip = core.synthCompile(avatar.id, PHRASE, {});
    if (clip.error) throw new Error(clip.error);
    core.synthClipFree(clip.id);
  }, { minSeconds: 1.0 });
  printResult(`synthesis_20_sign_phrase_wasm_${flavour}_${which}`, phrase / 1e6, 'ms/phrase');
  printResult(`synthesis_20_sign_phrase_per_sign_wasm_${flavour}_${which}`, phrase / 20e6, 'ms/sign');
  // CPU time of this process (the machine may be shared: wall time also counts other processes).
  const cpu0 = process.cpuUsage();
  for (let i = 0; i < 100; ++i) {
    const clip = core.synthCompile(avatar.id, SIGNS[i % SIGNS.length], {});
    core.synthClipFree(clip.id);
  }
  const cpu = process.cpuUsage(cpu0);
  printResult(`synthesis_per_sign_wasm_cpu_${flavour}_${which}`, (cpu.user + cpu.system) / 1000 / 100, 'ms/sign');

  // Every lexicon sign from rest and back: CPU ms per sign over LEXICON_CALLS calls each, after
  // one warm-up call (the JIT has tiered up on the loops above already).
  const ms = [];
  const slowest = [];
  for (const entry of LEXICON) {
    const warm = core.synthCompile(avatar.id, entry.notation, {});
    if (warm.error) throw new Error(`${entry.gloss}: ${warm.error}`);
    core.synthClipFree(warm.id);
    const start = process.cpuUsage();
    for (let i = 0; i < LEXICON_CALLS; ++i) {
      const clip = core.synthCompile(avatar.id, entry.notation, {});
      core.synthClipFree(clip.id);
    }
    const used = process.cpuUsage(start);
    const perSign = (used.user + used.system) / 1000 / LEXICON_CALLS;
    ms.push(perSign);
    slowest.push([perSign, entry.gloss]);
  }
  const mean = ms.reduce((a, b) => a + b, 0) / ms.length;
  ms.sort((a, b) => a - b);
  const at = (q) => ms[Math.min(ms.length - 1, Math.floor(q * ms.length))];
  slowest.sort((a, b) => b[0] - a[0]);
  for (const [t, gloss] of slowest.slice(0, 5)) {
    process.stderr.write(`synthesis_lexicon_wasm_${flavour}: ${gloss} ${t.toFixed(2)} ms\n`);
  }
  printResult(`synthesis_lexicon_signs_wasm_${flavour}_${which}`, ms.length, 'signs');
  printResult(`synthesis_lexicon_per_sign_mean_wasm_cpu_${flavour}_${which}`, mean, 'ms/sign');
  printResult(`synthesis_lexicon_per_sign_median_wasm_cpu_${flavour}_${which}`, at(0.5), 'ms/sign');
  printResult(`synthesis_lexicon_per_sign_p90_wasm_cpu_${flavour}_${which}`, at(0.9), 'ms/sign');
  printResult(`synthesis_lexicon_per_sign_max_wasm_cpu_${flavour}_${which}`, ms[ms.length - 1], 'ms/sign');
}
