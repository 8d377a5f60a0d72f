// web/js/core_loader.js: SIMD detection and the silent fallback to the scalar build, run in node
// with a script loader that evaluates the generated classic script the way a <script> tag would.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { test } from 'node:test';
import vm from 'node:vm';

import { loadCore, simdSupported } from '../../web/js/core_loader.js';
import { GEN_DIR } from './wasm_loader.mjs';

const baseUrl = pathToFileURL(GEN_DIR + path.sep).href;

// Stands in for <script src>: runs the file and publishes its factory as the page's global would be.
function nodeScriptLoader(log) {
  return async (url) => {
    log.push(path.basename(fileURLToPath(url)));
    const file = fileURLToPath(url);
    const source = readFileSync(file, 'utf8');
    const run = vm.compileFunction(source, ['module', 'exports', 'require', '__dirname', '__filename']);
    const module = { exports: {} };
    run(module, module.exports, createRequire(file), path.dirname(file), file);
    globalThis.createSignweave = module.exports;
  };
}

// TOOLCHAIN.md trap 3: in node the .wasm bytes are passed in rather than fetched.
const wasmBytes = (flavour) => ({ wasmBinary: readFileSync(path.join(GEN_DIR, `signweave-${flavour}.wasm`)) });

test('node 20 validates the SIMD probe module', () => {
  assert.equal(simdSupported(), true);
});

test('loads the SIMD build where SIMD validates', async () => {
  const log = [];
  const progress = [];
  const { module, flavour } = await loadCore({
    baseUrl, loadScript: nodeScriptLoader(log), moduleArgs: wasmBytes, onProgress: (f) => progress.push(f),
  });
  assert.equal(flavour, 'simd');
  assert.equal(module.simd(), true);
  assert.equal(progress.at(-1), 1, 'progress ends at 1');
  assert.deepEqual(log, ['signweave-simd.js']);
});

test('falls back to scalar silently when the SIMD build fails to load', async () => {
  const log = [];
  const load = nodeScriptLoader(log);
  const failingSimd = async (url) => {
    if (url.includes('simd')) throw new Error('404');
    return load(url);
  };
  const info = console.info;
  console.info = () => {};
  try {
    const { module, flavour } = await loadCore({ baseUrl, loadScript: failingSimd, moduleArgs: wasmBytes });
    assert.equal(flavour, 'scalar');
    assert.equal(module.simd(), false);
    assert.deepEqual(module.quatFromEuler(0, 0, 0, 'XYZ'), [1, 0, 0, 0]);
  } finally {
    console.info = info;
  }
});

test('a forced flavour is loaded as asked', async () => {
  const { flavour } = await loadCore({ baseUrl, flavour: 'scalar', loadScript: nodeScriptLoader([]), moduleArgs: wasmBytes });
  assert.equal(flavour, 'scalar');
});
