// Shared by bench/*_bench.mjs: load a WASM flavour, time a function, print a JSON line in the
// format of the native benches (bench/bench.h): {"name": ..., "value": ..., "unit": ...}.
import { FLAVOURS, loadCore } from '../tests/node/wasm_loader.mjs';

export { FLAVOURS, loadCore };

// Runs `body` repeatedly for at least minSeconds (after a warm-up that lets the JIT tier up) and
// returns mean nanoseconds per call; `body` may itself loop, then pass its inner count as perCall.
export function timeNsPerCall(body, { minSeconds = 0.3, perCall = 1 } = {}) {
  for (let i = 0; i < 20; ++i) body();
  let iterations = 1;
  for (;;) {
    const start = process.hrtime.bigint();
    for (let i = 0; i < iterations; ++i) body();
    const elapsedNs = Number(process.hrtime.bigint() - start);
    if (elapsedNs >= minSeconds * 1e9) return elapsedNs / (iterations * perCall);
    iterations *= elapsedNs < (minSeconds * 1e9) / 10 ? 10 : 2;
  }
}

export function printResult(name, value, unit) {
  console.log(JSON.stringify({ name, value: Number(value.toPrecision(6)), unit }));
}
