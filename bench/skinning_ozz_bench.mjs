// Our skinning against ozz-animation's SkinningJob on the same avatar data, natively and in
// WebAssembly SIMD, in the same run (issue 27). ../shared/peers/ozz-animation holds ozz's runtime
// (MIT, a benchmark reference only: never linked into or copied into the project); this script
// compiles bench/ozz/skinning_vs_ozz.cc with ozz's skinning sources and our
// src/skinning/skinning_job.cpp into build/ozz/ (g++ natively; em++ with SIMD), writes the
// avatar's skinning inputs with `signweave-bench skinning_inputs`, and runs both drivers. Flags:
// ours as the project builds it (native -O3; WASM -O3 -msimd128 -mbulk-memory
// -mnontrapping-fptoint), ozz natively at -O3 and in WASM at -O2 -msimd128 -msse2 (its SSE2 path
// on WebAssembly SIMD; em++ 3.1.6 has been seen to take over 10 minutes on -O3, see the peer's
// README), the harness itself at -O0 in WASM for the same reason; node runs the WASM driver with
// --no-experimental-fetch (Emscripten 3.1.6's glue would fetch() its .wasm by path). Skipped with
// a message when the peer or a compiler is absent.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, statSync, symlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';

import { ROOT, SHARED } from './real_signs.mjs';

const OZZ = path.join(SHARED, 'peers', 'ozz-animation');
const OUT = path.join(ROOT, 'build', 'ozz');
const INPUTS = path.join(ROOT, 'build', 'bench', 'skinning-inputs.bin');
const DRIVER = path.join(ROOT, 'bench', 'ozz', 'skinning_vs_ozz.cc');
const OURS = path.join(ROOT, 'src', 'skinning', 'skinning_job.cpp');
const OZZ_SOURCES = ['src/geometry/runtime/skinning_job.cc', 'src/base/maths/simd_math.cc', 'src/base/memory/allocator.cc',
  'src/base/platform.cc', 'src/base/log.cc'].map((f) => path.join(OZZ, f));
const DEFINES = ['-DNDEBUG', '-DGLM_FORCE_RADIANS', '-DGLM_ENABLE_EXPERIMENTAL'];

const say = (msg) => process.stderr.write(`skinning_vs_ozz: ${msg}\n`);
function run(cmd, args, options = {}) {
  const r = spawnSync(cmd, args, { encoding: 'utf8', maxBuffer: 1 << 26, ...options });
  if (r.status !== 0) throw new Error(`${cmd} ${args.join(' ')}\n${String(r.stderr || r.error).slice(-2000)}`);
  return r.stdout;
}
const newer = (target, sources) =>
  existsSync(target) && sources.every((s) => statSync(s).mtimeMs <= statSync(target).mtimeMs);
const has = (cmd) => spawnSync('sh', ['-c', `command -v ${cmd}`]).status === 0;

function buildNative() {
  const exe = path.join(OUT, 'native', 'skinning_vs_ozz');
  if (newer(exe, [DRIVER, OURS, ...OZZ_SOURCES])) return exe;
  mkdirSync(path.dirname(exe), { recursive: true });
  const includes = ['-I', path.join(OZZ, 'include'), '-I', path.join(OZZ, 'src'), '-I', path.join(ROOT, 'src')];
  run('g++', ['-std=c++17', '-O3', ...DEFINES, ...includes, DRIVER, OURS, ...OZZ_SOURCES, '-o', exe]);
  return exe;
}

function buildWasm() {
  const dir = path.join(OUT, 'wasm');
  const js = path.join(dir, 'skinning_vs_ozz.js');
  if (newer(js, [DRIVER, OURS, ...OZZ_SOURCES])) return js;
  mkdirSync(dir, { recursive: true });
  // Emscripten's glue is CommonJS; the repository's package.json says "type": "module".
  writeFileSync(path.join(dir, 'package.json'), '{ "type": "commonjs" }\n');
  // TOOLCHAIN.md trap 2: Emscripten hides /usr/include; give it glm alone.
  const sysinc = path.join(dir, 'sysinc');
  mkdirSync(sysinc, { recursive: true });
  if (!existsSync(path.join(sysinc, 'glm'))) symlinkSync('/usr/include/glm', path.join(sysinc, 'glm'));
  const includes = ['-I', path.join(OZZ, 'include'), '-I', path.join(OZZ, 'src'), '-I', path.join(ROOT, 'src'), '-isystem', sysinc];
  const env = { ...process.env, NODE_PATH: `/usr/share/nodejs${process.env.NODE_PATH ? `:${process.env.NODE_PATH}` : ''}` };
  const objects = [];
  for (const src of OZZ_SOURCES) {
    const obj = path.join(dir, `ozz_${path.basename(src, '.cc')}.o`);
    objects.push(obj);
    if (newer(obj, [src])) continue;
    run('em++', ['-std=c++17', '-O2', '-msimd128', '-msse2', ...DEFINES, ...includes, '-c', src, '-o', obj], { env });
  }
  const ours = path.join(dir, 'ours_skinning_job.o');
  run('em++', ['-std=c++17', '-O3', '-msimd128', '-mbulk-memory', '-mnontrapping-fptoint', '-DSIGNWEAVE_SIMD=1', ...DEFINES,
    ...includes, '-c', OURS, '-o', ours], { env });
  const driver = path.join(dir, 'driver.o');
  run('em++', ['-std=c++17', '-O0', '-msimd128', '-msse2', ...DEFINES, ...includes, '-c', DRIVER, '-o', driver], { env });
  run('em++', ['-O2', '-msimd128', driver, ours, ...objects, '-sNODERAWFS=1', '-sALLOW_MEMORY_GROWTH=1', '-o', js], { env });
  return js;
}

if (!existsSync(path.join(OZZ, 'include', 'ozz'))) {
  say(`skipped, ${OZZ} is absent`);
} else {
  const bench = path.join(ROOT, 'build', 'native', 'signweave-bench');
  run(bench, ['skinning_inputs']);
  if (!existsSync(INPUTS)) {
    say('skipped, no skinning inputs (models/signweave-avatar.glb absent?)');
  } else {
    if (has('g++')) process.stdout.write(run(buildNative(), [INPUTS, 'native']));
    else say('native skipped, no g++');
    if (has('em++')) process.stdout.write(run('node', ['--no-experimental-fetch', buildWasm(), INPUTS, 'wasm_simd']));
    else say('WebAssembly skipped, no em++');
  }
}
