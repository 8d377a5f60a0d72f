// The notation module in WebAssembly against the native core: the same texts parsed by
// notationParse (WASM) and natively (the `notation_parse` parity case, and `signweave-cli check
// --spec` for corpus files) must give the same SignSpec JSON and the same diagnostics (positions
// and messages), in every built flavour. Skips, saying why, when the WASM module or the native CLI
// has not been built.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';

import { FLAVOURS, GEN_DIR, NATIVE_CLI, ROOT, loadCore, runNativeParity } from './wasm_loader.mjs';

const root = ROOT;
const cli = NATIVE_CLI;
const built = FLAVOURS.filter((f) => fs.existsSync(path.join(GEN_DIR, `signweave-${f}.wasm`)));
const skip = built.length === 0 ? 'WASM module not built (./signweave build)' : !fs.existsSync(cli) ? 'native CLI not built' : false;

let modulePromise = null;
function wasmModule() {
  if (!modulePromise) modulePromise = loadCore(built.includes('simd') ? 'simd' : 'scalar');
  return modulePromise;
}

// Native: the CLI's check --spec, one JSON object per sign.
function nativeParse(text, extension) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'sw-notation-'));
  const file = path.join(dir, `input${extension}`);
  fs.writeFileSync(file, text);
  let out;
  try {
    out = execFileSync(cli, ['check', file, '--spec'], { encoding: 'utf8' });
  } catch (e) {
    out = e.stdout; // exit code 1 when a sign has errors
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
  return out.trim().split('\n').map((l) => JSON.parse(l)).filter((o) => !o.summary);
}

function assertSameAsNative(result, native, what) {
  assert.equal(result.signs.length, native.length, `${what}: sign count`);
  result.signs.forEach((sign, i) => {
    const n = native[i];
    assert.equal(sign.gloss, n.gloss, `${what}: gloss of sign ${i}`);
    // The WASM call parses only; native `check` also synthesises, so compare the parse result.
    assert.equal(sign.ok, n.parsed, `${what}: parse result of sign ${i} (${sign.gloss})`);
    assert.deepEqual(sign.spec, n.spec ?? null, `${what}: SignSpec of sign ${i} (${sign.gloss})`);
    assert.deepEqual(
      sign.diagnostics.map((d) => [d.line, d.column, d.symbol, d.message, d.severity]),
      n.diagnostics.map((d) => [d.line, d.column, d.symbol, d.message, d.severity]),
      `${what}: diagnostics of sign ${i}`,
    );
  });
}


test('WASM parse equals native parse: the notation_parse parity case, every flavour', { skip }, async () => {
  const expected = runNativeParity('notation_parse');
  assert.ok(expected.cases.length >= 6);
  for (const flavour of built) {
    const core = await loadCore(flavour);
    for (const c of expected.cases) {
      const got = JSON.parse(core.notationParse(c.text, c.format));
      assert.deepEqual(got, c.result, `${flavour}: ${c.format}: ${c.text.slice(0, 60)}`);
    }
  }
  // The broken inputs really are broken: the parity holds for diagnostics too.
  const broken = expected.cases.find((c) => c.text.includes('hamzzz')).result;
  assert.ok(broken.diagnostics.some((d) => d.symbol === 'hamzzz'));
});

const formulaText = [
  '# seed 004 Table 2',
  'В = R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))',
  'Г = R(L1(0), D5, F_0^1(1), F_0^2(1), F_0^3(0), F_0^4(0), F_0^5(0))',
  'HELLO = R(H(flat, thumbacross), E(uo), P(l), Loc(forehead, right, touch), M(arc, or, bulge=u, small)) N(mouth="hallo")',
  'BAD = R(F_0^1(1.5))',
].join('\n');

const hamnosysText = [
  'HOUSE = hamflathand,hamextfingerul,hampalmdr,hamparbegin,hammovedr,hamplus,hammovedl,hamparend',
  'SIGN = hamsymmlr,hamfinger2,hamthumboutmod,hamextfingeruo,hampalmdl,hamshoulders,hamlrat,hamclose,hamcirclei,hamrepeatfromstart',
  'BROKEN = hamfist,hamzzz,hamextfingeru,hamparbegin,hammoveu',
].join('\n');

const gsigmlText = `<?xml version="1.0" encoding="UTF-8"?>
<sigml>
<hamgestural_sign gloss="TIEN_10">
  <sign_nonmanual><mouthing_tier><mouth_picture picture="tIn"/></mouthing_tier></sign_nonmanual>
  <sign_manual>
    <handconfig handshape="finger2345" thumbpos="out"/>
    <handconfig extfidir="u"/>
    <handconfig palmor="d"/>
    <location_bodyarm location="shoulders" side="right_beside"/>
    <rpt_motion repetition="fromstart"><circularmotion axis="l" size="small"/></rpt_motion>
  </sign_manual>
</hamgestural_sign>
</sigml>
`;

test('WASM parse equals native parse: formula', { skip }, async () => {
  const m = await wasmModule();
  const result = JSON.parse(m.notationParse(formulaText, 'formula'));
  assert.equal(result.format, 'formula');
  assert.equal(result.signs.length, 4);
  assert.equal(result.signs[0].spec.dominant.orientation.seed_palm, 'D1');
  assert.equal(result.signs[3].ok, false);
  assertSameAsNative(result, nativeParse(formulaText, '.txt'), 'formula');
});

test('WASM parse equals native parse: HamNoSys names with errors', { skip }, async () => {
  const m = await wasmModule();
  const result = JSON.parse(m.notationParse(hamnosysText, ''));
  assert.equal(result.format, 'hamnosys');
  const broken = result.signs[2];
  assert.equal(broken.ok, false);
  assert.ok(broken.diagnostics.some((d) => d.symbol === 'hamzzz' && d.column === 18));
  assertSameAsNative(result, nativeParse(hamnosysText, '.txt'), 'hamnosys');
});

test('WASM parse equals native parse: G-SiGML', { skip }, async () => {
  const m = await wasmModule();
  assert.equal(m.notationDetect(gsigmlText), 'gsigml');
  const result = JSON.parse(m.notationParse(gsigmlText, 'gsigml'));
  assert.equal(result.signs[0].spec.repetition.kind, 'fromstart');
  assertSameAsNative(result, nativeParse(gsigmlText, '.sigml'), 'gsigml');
});

test('WASM print -> parse gives the same SignSpec in every notation', { skip }, async () => {
  const m = await wasmModule();
  const spec = JSON.parse(m.notationParse(hamnosysText, 'hamnosys')).signs[1].spec;
  for (const format of ['formula', 'hamnosys', 'hsigml', 'gsigml']) {
    const printed = JSON.parse(m.notationPrint(JSON.stringify(spec), format));
    assert.equal(printed.ok, true, format);
    const again = JSON.parse(m.notationParse(printed.text, format)).signs[0].spec;
    if (format === 'hamnosys' || format === 'hsigml') assert.deepEqual(again, spec, format);
    else assert.deepEqual(again.dominant.orientation, spec.dominant.orientation, format);
  }
  const bad = JSON.parse(m.notationPrint('{"gloss": 3}', 'formula'));
  assert.equal(bad.ok, false);
  assert.match(bad.error, /expected/);
});

test('WASM parse equals native parse on corpus HamNoSys (first 300 signs)', { skip }, async (t) => {
  const corpus = path.resolve(root, '../shared/corpus/hamnosys-dev.jsonl');
  if (!fs.existsSync(corpus)) {
    t.skip('../shared/corpus not present');
    return;
  }
  const lines = fs.readFileSync(corpus, 'utf8').split('\n').filter(Boolean).slice(0, 300);
  const text = lines.map((l) => JSON.parse(l).hamnosys).join('\n');
  const m = await wasmModule();
  const result = JSON.parse(m.notationParse(text, 'hamnosys'));
  assertSameAsNative(result, nativeParse(text, '.txt'), 'corpus');
});

test('hostile input never aborts the module', { skip }, async () => {
  const m = await wasmModule();
  const inputs = ['', '(((((', 'R(', '<sigml><hns_sign>', '<'.repeat(5000), '\u{E0E2}'.repeat(3000), '\uFFFF\u0000R(F_0^1(1))'];
  for (const text of inputs) {
    for (const format of ['formula', 'hamnosys', 'hsigml', 'gsigml', '']) {
      const r = JSON.parse(m.notationParse(text, format));
      assert.equal(typeof r.ok, 'boolean');
    }
  }
});
