// The real-sign sample the synthesis benches time (issue 27): every k-th sign of each dev corpus in
// ../shared/corpus (HamNoSys strings, H-SiGML, G-SiGML), about 120 signs a file, always the same
// signs. Each sign carries the text our engine compiles and a one-sign SiGML document for the
// reference engine (Animgen): the SiGML element itself, or for a HamNoSys string its symbols as an
// H-SiGML <hns_sign> (names from ../shared/docs/hamnosys-symbols.tsv).
//
// Run as a script it writes the sample as JSON lines to build/bench/real-signs.jsonl (or argv[2])
// for the native bench (bench/synthesis_real_bench.cpp), and says so on stderr; when the corpus is
// absent it writes nothing and says why. The corpus is never copied into the repository: the
// sample lives under build/, which git ignores.
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const SHARED = path.resolve(ROOT, '..', 'shared');
export const CORPUS = path.join(SHARED, 'corpus');
export const SAMPLE_PATH = path.join(ROOT, 'build', 'bench', 'real-signs.jsonl');

// corpus name, file, notation, step k (every k-th sign from the first: about 120 signs a file).
export const CORPORA = [
  { corpus: 'hamnosys', file: 'hamnosys-dev.jsonl', notation: 'hamnosys', step: 37 },
  { corpus: 'hsigml', file: path.join('sigml-dev', 'dgs-collection.sigml'), notation: 'hsigml', step: 15 },
  { corpus: 'gsigml', file: path.join('sigml-dev', 'ngt-gestural-dev.sigml'), notation: 'gsigml', step: 9 },
];

const escapeXml = (s) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

function symbolNames() {
  const table = new Map();
  const tsv = path.join(SHARED, 'docs', 'hamnosys-symbols.tsv');
  if (!existsSync(tsv)) return table;
  for (const line of readFileSync(tsv, 'utf8').split('\n').slice(1)) {
    const [codepoint, name] = line.split('\t');
    if (codepoint && name) table.set(parseInt(codepoint.replace('U+', ''), 16), name.trim());
  }
  return table;
}

// A HamNoSys string as an H-SiGML document; null when a code point has no name in the table.
function hamnosysToHsigml(gloss, hamnosys, names) {
  const elements = [];
  for (const ch of hamnosys) {
    if (/\s/.test(ch)) continue;
    const name = names.get(ch.codePointAt(0));
    if (!name) return null;
    elements.push(`<${name}/>`);
  }
  return `<sigml><hns_sign gloss="${escapeXml(gloss)}"><hamnosys_manual>${elements.join('')}</hamnosys_manual></hns_sign></sigml>`;
}

function hamnosysSigns(text, names) {
  return text.split('\n').filter((l) => l.trim() !== '').map((line) => {
    const entry = JSON.parse(line);
    const hamnosys = String(entry.hamnosys || '').replace(/[\r\n]/g, ' ');
    const gloss = String(entry.gloss || entry.id || '');
    return { gloss, text: hamnosys, sigml: hamnosysToHsigml(gloss, hamnosys, names) };
  });
}

// Each <hns_sign>/<hamgestural_sign> element of a SiGML collection, as its own document (both
// engines read one sign a document).
function sigmlSigns(text) {
  const out = [];
  const re = /<(hns_sign|hamgestural_sign)\b[^>]*?(\/>|>[\s\S]*?<\/\1\s*>)/g;
  for (const m of text.matchAll(re)) {
    const gloss = /gloss="([^"]*)"/.exec(m[0]);
    const doc = `<sigml>${m[0]}</sigml>`;
    out.push({ gloss: gloss ? gloss[1] : '', text: doc, sigml: doc });
  }
  return out;
}

// The sample: [{corpus, index, gloss, text, sigml}], and the corpora that were absent.
export function realSignSample() {
  const signs = [];
  const missing = [];
  const names = symbolNames();
  for (const c of CORPORA) {
    const file = path.join(CORPUS, c.file);
    if (!existsSync(file)) {
      missing.push(file);
      continue;
    }
    const text = readFileSync(file, 'utf8');
    const all = c.notation === 'hamnosys' ? hamnosysSigns(text, names) : sigmlSigns(text);
    for (let i = 0; i < all.length; i += c.step) signs.push({ corpus: c.corpus, index: i, ...all[i] });
  }
  return { signs, missing };
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const out = process.argv[2] || SAMPLE_PATH;
  const { signs, missing } = realSignSample();
  for (const m of missing) process.stderr.write(`real-sign sample: skipped, ${m} is absent\n`);
  if (signs.length > 0) {
    mkdirSync(path.dirname(out), { recursive: true });
    writeFileSync(out, signs.map((s) => JSON.stringify(s)).join('\n') + '\n');
    process.stderr.write(`real-sign sample: ${signs.length} signs -> ${out}\n`);
  }
}
