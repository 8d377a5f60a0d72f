// Synthesis time on real signs in WebAssembly (SIMD and scalar), and the reference engine on the
// same signs in the same run (issue 27). The sample is bench/real_signs.mjs's (every k-th sign of
// the three dev corpora); each sign is compiled as the page's dictionary look-up compiles it
// (synthCompile: parse + synthesis from rest and back, on the project's avatar), CPU ms per sign
// as the mean of CALLS calls after one warm-up call: mean, median, p95 and worst per corpus and
// overall, and per clip frame. bench/synthesis_real_bench.cpp is the native twin.
//
// Animgen (UEA's SiGML engine, ../shared/peers/cwasa-animgen, when present) is timed by its own
// batch driver (tools/agbatch.cjs: engine and avatar loaded once, each sign its own sequence from
// the neutral pose) on the same signs: the G-SiGML signs as they are, the H-SiGML and HamNoSys
// signs after CWASA's HtoG (HamNoSys -> gestural SiGML, done once beforehand and kept under
// build/bench/animgen/; not timed). Each sign's figure is Animgen's own CPU ms for it
// (SetSequence + GenerateFrames + EndSequence, the driver's ag_cpu_ms), taken from a second pass
// over the whole sample so that the engine's asm.js is as warm as our WebAssembly is. The ratio
// Animgen / ours is over the signs both engines animated. What differs in the work: our clip
// starts and ends at rest (two transitions), Animgen's starts at neutral and stays on the last
// posture; both at 30 frames a second.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';

import { realSignSample, ROOT, SHARED } from './real_signs.mjs';
import { FLAVOURS, loadCore, printResult } from './wasm_common.mjs';

const CALLS = Number(process.env.SIGNWEAVE_BENCH_CALLS || 3);
const MODEL = path.join(ROOT, 'models', 'signweave-avatar.glb');
const ANIMGEN = path.join(SHARED, 'peers', 'cwasa-animgen');
const WORK = path.join(ROOT, 'build', 'bench', 'animgen');

const quantile = (sorted, q) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
function printStats(prefix, values, unit) {
  const sorted = [...values].sort((a, b) => a - b);
  printResult(`${prefix}_mean`, sorted.reduce((a, b) => a + b, 0) / sorted.length, unit);
  printResult(`${prefix}_median`, quantile(sorted, 0.5), unit);
  printResult(`${prefix}_p95`, quantile(sorted, 0.95), unit);
  printResult(`${prefix}_max`, sorted[sorted.length - 1], unit);
}

// Per corpus and 'all': count, failures, per-sign and per-frame statistics. `timed` maps a sign's
// key to {corpus, ms, frames}.
function printCorpusStats(label, signs, timed, engine) {
  for (const corpus of ['all', ...new Set(signs.map((s) => s.corpus))]) {
    const inCorpus = signs.filter((s) => corpus === 'all' || s.corpus === corpus);
    const ok = inCorpus.map((s) => timed.get(key(s))).filter(Boolean);
    if (ok.length === 0) continue;
    printResult(`${label}_${corpus}_signs`, ok.length, 'signs');
    printResult(`${label}_${corpus}_failed`, inCorpus.length - ok.length, 'signs');
    printStats(`${label}_${corpus}_per_sign_${engine}`, ok.map((t) => t.ms), 'ms/sign');
    printStats(`${label}_${corpus}_per_frame_${engine}`, ok.map((t) => (1000 * t.ms) / t.frames), 'us/frame');
  }
}

const key = (s) => `${s.corpus}:${s.index}`;
const cpuMs = () => {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
};

function timeOurs(core, avatarId, signs) {
  const timed = new Map();
  for (const s of signs) {
    const warm = core.synthCompile(avatarId, s.text, {});
    if (warm.error !== undefined) continue;
    core.synthClipFree(warm.id);
    const start = cpuMs();
    for (let i = 0; i < CALLS; ++i) core.synthClipFree(core.synthCompile(avatarId, s.text, {}).id);
    timed.set(key(s), { corpus: s.corpus, ms: (cpuMs() - start) / CALLS, frames: warm.frames, gloss: s.gloss });
  }
  return timed;
}

const agbatch = (args) =>
  spawnSync('node', [path.join(ANIMGEN, 'tools', 'agbatch.cjs'), '--cache', path.join(WORK, 'cache'), ...args], {
    encoding: 'utf8',
    maxBuffer: 1 << 28,
  });
const readResultsPlain = (file) => readFileSync(file, 'utf8').split('\n').filter(Boolean).map((l) => JSON.parse(l));
const readResults = (file) =>
  readFileSync(file, 'utf8').split('\n').filter(Boolean).map((l) => JSON.parse(l)).filter((r) => r.type === 'sign');

// One gestural SiGML file per sign under WORK/gestural (HtoG for the HamNoSys ones, once: HtoG costs
// a third of a second a sign here and is not what is compared); returns {key: file}.
function gesturalFiles(signs) {
  const dir = path.join(WORK, 'gestural');
  const hdir = path.join(WORK, 'hamnosys');
  mkdirSync(dir, { recursive: true });
  mkdirSync(hdir, { recursive: true });
  const files = new Map();
  const toConvert = [];
  // Signs HtoG rejected in an earlier run are not tried again.
  const rejectedFile = path.join(WORK, 'htog-rejected.txt');
  const rejected = new Set(existsSync(rejectedFile) ? readFileSync(rejectedFile, 'utf8').split('\n') : []);
  for (const s of signs) {
    const base = `${s.corpus}-${String(s.index).padStart(5, '0')}`;
    const out = path.join(dir, `${base}.sigml`);
    if (s.sigml.includes('<hamgestural_sign')) writeFileSync(out, s.sigml);
    else if (!existsSync(out) && !rejected.has(out)) {
      writeFileSync(path.join(hdir, `${base}.sigml`), s.sigml);
      toConvert.push(path.join(hdir, `${base}.sigml`));
    }
    files.set(key(s), out);
  }
  if (toConvert.length > 0) {
    process.stderr.write(`synthesis_real: HtoG on ${toConvert.length} HamNoSys signs (once; kept in ${dir})\n`);
    writeFileSync(path.join(WORK, 'htog-list.txt'), toConvert.join('\n') + '\n');
    agbatch(['--gsigml', dir, '--results', path.join(WORK, 'htog.results.jsonl'), '--list', path.join(WORK, 'htog-list.txt')]);
  }
  for (const [k, f] of files) {
    if (existsSync(f)) continue;
    rejected.add(f);  // HtoG rejected it
    files.delete(k);
  }
  writeFileSync(rejectedFile, [...rejected].filter(Boolean).join('\n') + '\n');
  return files;
}

function timeAnimgen(signs) {
  if (!existsSync(path.join(ANIMGEN, 'tools', 'agbatch.cjs'))) {
    process.stderr.write(`synthesis_real: Animgen skipped, ${ANIMGEN} is absent\n`);
    return null;
  }
  const setup = spawnSync(path.join(ANIMGEN, 'tools', 'setup.sh'), [path.join(WORK, 'cache')], { encoding: 'utf8' });
  if (setup.status !== 0) {
    process.stderr.write(`synthesis_real: Animgen skipped, its setup failed: ${setup.stderr}\n`);
    return null;
  }
  const files = gesturalFiles(signs);
  const ordered = signs.filter((s) => files.has(key(s)));
  // The list twice: the first pass warms the engine up, the second is timed.
  const list = ordered.map((s) => files.get(key(s)));
  writeFileSync(path.join(WORK, 'timed-list.txt'), [...list, ...list].join('\n') + '\n');
  const results = path.join(WORK, 'timed.results.jsonl');
  writeFileSync(results, '');
  agbatch(['--results', results, '--list', path.join(WORK, 'timed-list.txt')]);
  const timed = new Map();
  for (const r of readResults(results)) {
    if (r.fi < list.length || !r.ok) continue;
    const s = ordered[r.fi - list.length];
    timed.set(key(s), { corpus: s.corpus, ms: r.ag_cpu_ms, frames: r.nframes });
  }
  return timed;
}

// Over the signs both engines animated, per corpus and overall: Animgen's mean and median CPU ms
// over ours (above 1: ours is faster).
function printRatios(signs, animgen, ours, engine) {
  if (!ours) return;
  for (const corpus of ['all', ...new Set(signs.map((s) => s.corpus))]) {
    const both = signs.filter((s) => (corpus === 'all' || s.corpus === corpus) && animgen.has(key(s)) && ours.has(key(s)));
    if (both.length === 0) continue;
    const mean = (m) => both.reduce((a, s) => a + m.get(key(s)).ms, 0) / both.length;
    const median = (m) => quantile(both.map((s) => m.get(key(s)).ms).sort((a, b) => a - b), 0.5);
    printResult(`synthesis_real_${corpus}_animgen_and_${engine}_signs`, both.length, 'signs');
    printResult(`synthesis_real_${corpus}_animgen_over_${engine}_mean`, mean(animgen) / mean(ours), 'x');
    printResult(`synthesis_real_${corpus}_animgen_over_${engine}_median`, median(animgen) / median(ours), 'x');
  }
}

const { signs, missing } = realSignSample();
for (const m of missing) process.stderr.write(`synthesis_real: skipped ${m}, absent\n`);
if (signs.length === 0 || !existsSync(MODEL)) {
  process.stderr.write('synthesis_real: skipped, no corpus sample or no models/signweave-avatar.glb\n');
} else {
  const ours = {};
  for (const flavour of FLAVOURS) {
    if (!existsSync(path.join(ROOT, 'web', 'gen', `signweave-${flavour}.wasm`))) {
      process.stderr.write(`synthesis_real: WebAssembly ${flavour} skipped, not built (./signweave build)\n`);
      continue;
    }
    const core = await loadCore(flavour);
    const avatar = core.synthAvatarLoad(readFileSync(MODEL));
    if (avatar.error !== undefined) throw new Error(`avatar: ${avatar.error}`);
    ours[flavour] = timeOurs(core, avatar.id, signs);
    printCorpusStats('synthesis_real', signs, ours[flavour], `wasm_cpu_${flavour}`);
    // The slowest signs on stderr (stdout stays JSON lines): where the next profile should look.
    const slowest = [...ours[flavour]].sort((a, b) => b[1].ms - a[1].ms).slice(0, 5);
    for (const [k, t] of slowest) {
      process.stderr.write(`synthesis_real_wasm_${flavour}: ${k} ${t.gloss} ${t.ms.toFixed(2)} ms, ${t.frames} frames\n`);
    }
  }
  const animgen = timeAnimgen(signs);
  // The native bench's per-sign figures of this run (bench/synthesis_real_bench.cpp), when written.
  const nativeFile = path.join(ROOT, 'build', 'bench', 'real-signs-native.jsonl');
  const native = existsSync(nativeFile) ? new Map(readResultsPlain(nativeFile).map((r) => [key(r), r])) : null;
  if (animgen) {
    printCorpusStats('synthesis_real', signs, animgen, 'animgen_cpu');
    printRatios(signs, animgen, ours.simd, 'wasm_simd');
    printRatios(signs, animgen, native, 'native');
  }
}
