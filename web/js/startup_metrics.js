// startup_metrics.js — the page's start-up timeline: named performance marks (User Timing, so they
// also show in the browser's performance panel under "sw:") from navigation to the first signing
// frame, and a breakdown that tools read from window.signweave.metrics.startup (bench/web_bench.mjs
// prints it; tests/browser/startup_metrics.test.mjs checks that it is complete and ordered).
//
//   mark('wasm-compiled');                   // a moment, in ms since navigation start
//   measure('avatar-parse', 'avatar-fetched', 'avatar-parsed');
//   startupBreakdown() -> { marks: { name: ms }, measures: { name: ms }, resources: [...] }
//
// Times are performance.now() values: milliseconds since the navigation started (timeOrigin). The
// first value of a mark wins: the start-up happens once, and a mark re-sent later (a second sign
// fetched, a shader program re-linked) must not move it.

const PREFIX = 'sw:';
const marks = new Map();

export function mark(name) {
  if (marks.has(name)) return marks.get(name);
  const at = performance.now();
  marks.set(name, at);
  try { performance.mark(PREFIX + name, { startTime: at }); } catch { /* old browsers: the Map suffices */ }
  return at;
}

export function markTime(name) {
  return marks.has(name) ? marks.get(name) : null;
}

const measures = new Map();

// The span between two marks already made (a missing mark: nothing is measured).
export function measure(name, startMark, endMark) {
  if (measures.has(name) || !marks.has(startMark) || !marks.has(endMark)) return;
  const duration = marks.get(endMark) - marks.get(startMark);
  measures.set(name, duration);
  try { performance.measure(PREFIX + name, PREFIX + startMark, PREFIX + endMark); } catch { /* as above */ }
}

// A span timed directly (work that has no mark of its own at both ends).
export function record(name, duration_ms) {
  if (!measures.has(name)) measures.set(name, duration_ms);
}

const round = (x) => Math.round(x * 10) / 10;

// The page's own files from Resource Timing: when each was requested and finished, how many bytes
// crossed the wire. Shows the loading waterfall without a network panel.
function resourceTimeline() {
  if (typeof performance.getEntriesByType !== 'function') return [];
  return performance.getEntriesByType('resource')
    .filter((e) => /\/(js|gen|models|css|api)\//.test(e.name))
    .map((e) => ({
      name: new URL(e.name).pathname.replace(/^\//, ''),
      start_ms: round(e.startTime),
      end_ms: round(e.responseEnd),
      transfer_bytes: e.transferSize,
    }));
}

export function startupBreakdown() {
  const navigation = typeof performance.getEntriesByType === 'function' ? performance.getEntriesByType('navigation')[0] : null;
  const out = { marks: {}, measures: {}, resources: resourceTimeline() };
  if (navigation) {
    out.marks['html-received'] = round(navigation.responseEnd);
    out.marks['dom-interactive'] = round(navigation.domInteractive);
  }
  for (const [name, at] of [...marks].sort((a, b) => a[1] - b[1])) out.marks[name] = round(at);
  for (const [name, duration] of measures) out.measures[name] = round(duration);
  return out;
}
