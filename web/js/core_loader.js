// core_loader.js — loads the Signweave WebAssembly core for the page, SIMD where the browser has it.
//
//   import { loadCore } from './core_loader.js';
//   const { module, flavour } = await loadCore({ onProgress: (fraction) => ... });
//   // module: the instantiated Emscripten module (embind API); flavour: 'simd' or 'scalar'
//
// Two builds of the same C++ are served from web/gen/: signweave-simd.{js,wasm} (-msimd128) and
// signweave-scalar.{js,wasm}. WebAssembly SIMD needs Safari 16.4+ (Chrome 91+, Firefox 89+), so the
// loader validates a tiny SIMD module first and otherwise, or if the SIMD build fails to load or
// instantiate for any reason, falls back to the scalar build silently (a console.info says which).
//
// The generated .js is a classic script defining the global factory createSignweave (Emscripten
// MODULARIZE), so it is added with a <script> tag (importScripts in a worker). The .wasm is fetched
// and compiled here (streaming, while the script loads) rather than by Emscripten, so that the two
// downloads overlap and the download can be reported to onProgress.
//
// Does not: cache across page loads (the HTTP cache does), or load both flavours at once (they
// define the same global).

import { mark } from './startup_metrics.js';

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

// Downloads and compiles the .wasm in one go: WebAssembly.compileStreaming compiles while the bytes
// arrive (the server sends application/wasm, which streaming requires), instead of waiting for the
// whole file and then compiling it. Progress: a response with a plain Content-Length is counted as
// it streams through; a compressed one (Content-Encoding: gzip, which the Signweave server sends)
// has the COMPRESSED size in Content-Length while the stream yields decompressed bytes, so its
// length cannot measure progress and only the end is reported. Without streaming support or with
// another MIME type, the bytes are collected and compiled at the end.
async function fetchAndCompileWasm(url, onProgress) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  mark('wasm-response');
  const encoded = (response.headers.get('content-encoding') || 'identity') !== 'identity';
  const total = encoded ? 0 : Number(response.headers.get('content-length')) || 0;
  const streamable = typeof WebAssembly.compileStreaming === 'function' &&
    (response.headers.get('content-type') || '').split(';')[0].trim() === 'application/wasm';
  let body = response;
  if (total && response.body) {
    let received = 0;
    const counted = response.body.pipeThrough(new TransformStream({
      transform(chunk, controller) {
        received += chunk.length;
        if (received > total) throw new Error(`${url}: more bytes than its content-length`);
        onProgress(received / total);
        controller.enqueue(chunk);
      },
      flush() {
        if (received !== total) throw new Error(`${url}: ${received} of ${total} bytes received`);
      },
    }));
    body = new Response(counted, { headers: { 'content-type': 'application/wasm' } });
  }
  const compiled = streamable
    ? await WebAssembly.compileStreaming(body)
    : await WebAssembly.compile(await body.arrayBuffer());
  onProgress(1);
  return compiled;
}

async function instantiate(flavour, baseUrl, loadScript, moduleArgs, onProgress) {
  const jsUrl = new URL(`signweave-${flavour}.js`, baseUrl).href;
  const extra = typeof moduleArgs === 'function' ? moduleArgs(flavour) : moduleArgs;
  // The .wasm (download + compile) and the glue script load side by side: neither needs the other
  // until the module is instantiated.
  mark('wasm-fetch-start');
  // index.html may have started this flavour's compile already (before the WebGL2 context, so the
  // two overlap); that promise is used once, and a failure of it is this flavour's failure.
  const early = globalThis.signweaveEarlyCore;
  const earlyCompile = !extra.wasmBinary && early && early.flavour === flavour && early.wasm && baseUrl === early.baseUrl
    ? early.wasm : null;
  if (earlyCompile) early.wasm = null;
  const compiling = extra.wasmBinary ? null
    : earlyCompile ? earlyCompile.then((compiled) => { onProgress(1); return compiled; })
      : fetchAndCompileWasm(new URL(`signweave-${flavour}.wasm`, baseUrl).href, onProgress);
  compiling?.catch(() => {});  // a failure is reported by the await below, not as unhandled
  // Cleared rather than deleted: the glue declares it with `var`, which makes it a global that
  // cannot be deleted (a SIMD glue loaded before its .wasm failed would make delete throw).
  globalThis.createSignweave = undefined;
  await loadScript(jsUrl);
  mark('wasm-script-loaded');
  const factory = globalThis.createSignweave;
  if (typeof factory !== 'function') throw new Error(`${jsUrl} did not define createSignweave`);
  const compiled = compiling && (await compiling);
  if (compiled) mark('wasm-compiled');
  let instantiateFailed;
  const failure = new Promise((_, reject) => { instantiateFailed = reject; });
  const args = {
    // Anything else the module looks up sits beside its .js: resolve against baseUrl, not the page.
    locateFile: (file) => new URL(file, baseUrl).href,
    ...extra,
  };
  if (compiled) {
    // Emscripten's hook for a module compiled elsewhere: instantiate it with the glue's imports and
    // hand the instance back (an empty object tells the glue the exports come asynchronously).
    args.instantiateWasm = (imports, receive) => {
      WebAssembly.instantiate(compiled, imports).then((instance) => receive(instance, compiled), instantiateFailed);
      return {};
    };
  }
  const module = await Promise.race([factory(args), failure]);
  mark('wasm-instantiated');
  onProgress(1);
  return { module, flavour };
}

// Resolves to { module, flavour }. Options (all optional):
//   baseUrl     where signweave-*.{js,wasm} are served; default: ../gen/ relative to this file
//   flavour     'simd' or 'scalar' to force one (tests); default: detect
//   onProgress  fraction (0..1) of the .wasm download, for a loading bar
//   loadScript  url -> Promise, to load the classic script (default: <script> tag)
//   moduleArgs  extra arguments for the Emscripten factory, or a function flavour -> arguments
//               (a wasmBinary there skips the download: node tests pass the file's bytes)
export async function loadCore(options = {}) {
  const baseUrl = options.baseUrl ?? new URL('../gen/', import.meta.url).href;
  const loadScript = options.loadScript ?? loadClassicScript;
  const moduleArgs = options.moduleArgs ?? {};
  const onProgress = options.onProgress ?? (() => {});
  if (options.flavour) return instantiate(options.flavour, baseUrl, loadScript, moduleArgs, onProgress);
  if (simdSupported()) {
    try {
      return await instantiate('simd', baseUrl, loadScript, moduleArgs, onProgress);
    } catch (error) {
      console.info('signweave: SIMD core unavailable, using the scalar build:', error.message);
    }
  }
  return instantiate('scalar', baseUrl, loadScript, moduleArgs, onProgress);
}
