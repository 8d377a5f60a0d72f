// core_loader.js — loads the Signweave WebAssembly core for the page, SIMD where the browser has it.
//
//   import { loadCore } from './core_loader.js';
//   const core = await loadCore();          // core.flavour is 'simd' or 'scalar'
//
// Two builds of the same C++ are served from web/gen/: signweave-simd.{js,wasm} (-msimd128) and
// signweave-scalar.{js,wasm}. WebAssembly SIMD needs Safari 16.4+ (Chrome 91+, Firefox 89+), so the
// loader validates a tiny SIMD module first and otherwise, or if the SIMD build fails to load or
// instantiate for any reason, falls back to the scalar build silently (a console.info says which).
//
// The generated .js is a classic script defining the global factory createSignweave (Emscripten
// MODULARIZE), so it is added with a <script> tag (importScripts in a worker).
//
// Does not: cache across page loads (the HTTP cache does), or load both flavours at once (they
// define the same global).

// (module (func (result v128) i32.const 0 i32x4.splat)) — valid only where SIMD is supported.
const SIMD_PROBE = new Uint8Array([
  0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, // magic, version 1
  0x01, 0x05, 0x01, 0x60, 0x00, 0x01, 0x7b, //       type section: () -> v128
  0x03, 0x02, 0x01, 0x00, //                         function section: one function of type 0
  0x0a, 0x08, 0x01, 0x06, 0x00, 0x41, 0x00, 0xfd, 0x11, 0x0b, // code: i32.const 0, i32x4.splat, end
]);

export function simdSupported() {
  try {
    return typeof WebAssembly === 'object' && WebAssembly.validate(SIMD_PROBE);
  } catch {
    return false;
  }
}

// Adds a classic script and resolves when it has run.
export function loadClassicScript(url) {
  if (typeof document === 'undefined') {
    if (typeof importScripts === 'function') {
      importScripts(url); // eslint-disable-line no-undef
      return Promise.resolve();
    }
    return Promise.reject(new Error('no document and no importScripts: cannot load ' + url));
  }
  return new Promise((resolve, reject) => {
    const script = document.createElement('script');
    script.src = url;
    script.async = true;
    script.onload = () => resolve();
    script.onerror = () => {
      script.remove();
      reject(new Error('failed to load ' + url));
    };
    document.head.appendChild(script);
  });
}

async function instantiate(flavour, baseUrl, loadScript, moduleArgs) {
  const jsUrl = new URL(`signweave-${flavour}.js`, baseUrl).href;
  delete globalThis.createSignweave;
  await loadScript(jsUrl);
  const factory = globalThis.createSignweave;
  if (typeof factory !== 'function') throw new Error(`${jsUrl} did not define createSignweave`);
  const extra = typeof moduleArgs === 'function' ? moduleArgs(flavour) : moduleArgs;
  const module = await factory({
    // The .wasm sits beside its .js; resolve it against baseUrl, not the page.
    locateFile: (file) => new URL(file, baseUrl).href,
    ...extra,
  });
  module.flavour = flavour;
  return module;
}

// Options (all optional):
//   baseUrl     where signweave-*.{js,wasm} are served; default: ../gen/ relative to this file
//   flavour     'simd' or 'scalar' to force one (tests); default: detect
//   loadScript  url -> Promise, to load the classic script (default: <script> tag)
//   moduleArgs  extra arguments for the Emscripten factory, or a function flavour -> arguments
export async function loadCore(options = {}) {
  const baseUrl = options.baseUrl ?? new URL('../gen/', import.meta.url).href;
  const loadScript = options.loadScript ?? loadClassicScript;
  const moduleArgs = options.moduleArgs ?? {};
  if (options.flavour) return instantiate(options.flavour, baseUrl, loadScript, moduleArgs);
  if (simdSupported()) {
    try {
      return await instantiate('simd', baseUrl, loadScript, moduleArgs);
    } catch (error) {
      console.info('signweave: SIMD core unavailable, using the scalar build:', error.message);
    }
  }
  return instantiate('scalar', baseUrl, loadScript, moduleArgs);
}
