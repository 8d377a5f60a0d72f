// Shared by every node test: load the WebAssembly core, and run the native CLI's parity cases.
//
//   import { loadCore, runNativeParity, FLAVOURS } from './wasm_loader.mjs';
//   const core = await loadCore('simd');          // or 'scalar'
//   const expected = runNativeParity('euler');    // JSON printed by build/native/signweave-cli
//
// The module comes from web/gen/ (copied there by ./signweave build). TOOLCHAIN.md trap 3: the
// Emscripten 3.1.6 loader fetch()es its .wasm when fetch exists, which fails under Node 18+, so the
// bytes are read here and passed in as wasmBinary.
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import vm from 'node:vm';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const FLAVOURS = ['simd', 'scalar'];
export const GEN_DIR = path.join(ROOT, 'web', 'gen');
export const NATIVE_CLI = path.join(ROOT, 'build', 'native', 'signweave-cli');

const factories = new Map();

// The generated .js is a CommonJS script (module.exports = createSignweave). The repository's
// package.json says "type": "module", under which require() refuses a .js file, so the script is
// compiled here as the CommonJS wrapper would, with its own require/__dirname.
function loadFactory(jsPath) {
  if (!factories.has(jsPath)) {
    const source = readFileSync(jsPath, 'utf8');
    const wrapper = vm.compileFunction(source, ['module', 'exports', 'require', '__dirname', '__filename'], {
      filename: jsPath,
    });
    const module = { exports: {} };
    wrapper(module, module.exports, createRequire(jsPath), path.dirname(jsPath), jsPath);
    const factory = typeof module.exports === 'function' ? module.exports : module.exports.createSignweave;
    if (typeof factory !== 'function') throw new Error(`${jsPath} does not export createSignweave`);
    factories.set(jsPath, factory);
  }
  return factories.get(jsPath);
}

// Resolves to an instantiated module of the given flavour. Each call makes a fresh instance (its
// own memory), so tests cannot leak state into each other.
export async function loadCore(flavour = 'simd') {
  if (!FLAVOURS.includes(flavour)) throw new Error(`unknown flavour '${flavour}' (expected simd or scalar)`);
  const jsPath = path.join(GEN_DIR, `signweave-${flavour}.js`);
  const wasmPath = path.join(GEN_DIR, `signweave-${flavour}.wasm`);
  for (const p of [jsPath, wasmPath]) {
    if (!existsSync(p)) throw new Error(`${p} is missing: run ./signweave build first`);
  }
  const createSignweave = loadFactory(jsPath);
  return createSignweave({ wasmBinary: readFileSync(wasmPath) });
}

// Runs `signweave-cli parity <caseName>` and returns its parsed JSON.
export function runNativeParity(caseName) {
  if (!existsSync(NATIVE_CLI)) throw new Error(`${NATIVE_CLI} is missing: run ./signweave build first`);
  const stdout = execFileSync(NATIVE_CLI, ['parity', caseName], {
    encoding: 'utf8',
    maxBuffer: 256 * 1024 * 1024,
  });
  return JSON.parse(stdout);
}

// Largest absolute difference between two equally shaped nested arrays of numbers.
export function maxAbsDiff(a, b) {
  if (typeof a === 'number' && typeof b === 'number') return Math.abs(a - b);
  if (!Array.isArray(a) || !Array.isArray(b) || a.length !== b.length) {
    return Infinity;
  }
  let worst = 0;
  for (let i = 0; i < a.length; ++i) worst = Math.max(worst, maxAbsDiff(a[i], b[i]));
  return worst;
}
