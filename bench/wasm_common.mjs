// Shared by bench/*_bench.mjs: load a WASM flavour, time a function, print a JSON line in the
// format of the native benches (bench/bench.h): {"name": ..., "value": ..., "unit": ...}.
import { FLAVOURS, loadCore } from '../tests/node/wasm_loader.mjs';

export { FLAVOURS, loadCore };

// Mean nanoseconds per call of `body` over at least minSeconds (after a warm-up that lets the JIT
// tier up); `body` may itself loop, then pass its inner count as perCall. The best of `repeats`
// such timings is returned: the machine is shared, and the fastest run estimates the work itself
// where a mean would mostly measure the neighbours (bench/fk_bench.cpp does the same natively).
export function timeNsPerCall(body, { minSeconds = 0.05, perCall = 1, repeats = 10 } = {}) {
  for (let i = 0; i < 20; ++i) body();
  let best = Infinity;
  for (let r = 0; r < repeats; ++r) {
    let iterations = 1;
    for (;;) {
      const start = process.hrtime.bigint();
      for (let i = 0; i < iterations; ++i) body();
      const elapsedNs = Number(process.hrtime.bigint() - start);
      if (elapsedNs >= minSeconds * 1e9) {
        best = Math.min(best, elapsedNs / (iterations * perCall));
        break;
      }
      iterations *= elapsedNs < (minSeconds * 1e9) / 10 ? 10 : 2;
    }
  }
  return best;
}

export function printResult(name, value, unit) {
  console.log(JSON.stringify({ name, value: Number(value.toPrecision(6)), unit }));
}
