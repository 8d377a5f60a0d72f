// app.js — the page's entry point and state: boots the renderer, the WebAssembly core and the
// avatar with visible progress, routes the shareable URLs (#/sign/ID, #/phrase?text=…, #/editor),
// wires the dictionary, phrase, editor, player and export controls, and runs the frame loop
// (advance the clock → the core poses and skins → upload views → draw).
//
// Playback state is exposed for tests and tools as window.signweave.state
// { currentSign, currentWord, time_s, playing, clipDuration_s, ready }.

import { ApiClient } from './api_client.js';
import { OrbitCamera, attachCameraControls } from './camera.js';
import { Dictionary, normalizeSign } from './dictionary.js';
import { NotationEditor } from './editor.js';
import { download, recordWebm, safeFileStem, webmSupported } from './export.js';
import { installNotationExport } from './notation_export.js';
import { PhrasePane, phraseItems } from './phrase.js';
import { transformPoint } from './mat4.js';
import { Playback } from './playback.js';
import { Renderer, WebGL2Unavailable } from './renderer.js';
import { SigningCore } from './signing_core.js';
import { mark, markTime, measure, startupBreakdown } from './startup_metrics.js';

mark('app-start');

// The avatar as a pack (src/avatar/avatar_pack.h; ./signweave build makes it from the .glb, body
// anchors included): the core reads it by copying arrays, where the .glb would run the glTF parser
// on this thread while the browser is still compiling that code (0.5-1.3 s measured). The .glb
// itself is the fallback when the pack is missing (a server without the generated files).
const AVATAR_URLS = ['gen/signweave-avatar.swavatar', 'models/signweave-avatar.glb'];
const $ = (id) => document.getElementById(id);

const metrics = {
  firstSigningFrame_ms: null,   // performance.now() of the first frame drawn while a clip plays
  frameWork_ms: 0,              // last frame's pose + skinning + upload on the main thread
  frameWorkSamples: [],         // the last 240 of them (bench/web_bench.mjs reads percentiles)
  frameUpdateSamples: [],       // the same frames' core.update alone (sample + FK + skinning in WASM)
  frameUploadSamples: [],       // and their bufferSubData uploads alone
  frames: 0,
  framesSkipped: 0,             // frames not drawn because the GPU was still busy with earlier ones
  // The start-up timeline (startup_metrics.js): marks in ms since navigation, measured spans, and
  // the Resource Timing waterfall of the page's files.
  get startup() { return startupBreakdown(); },
};
const api = new ApiClient();
const camera = new OrbitCamera();
const playback = new Playback();
// Live views of the playback (getters), so a test reading right after an action sees its effect
// without waiting for the next frame.
const state = {
  ready: false,
  error: null,
  flavour: null,         // which WebAssembly build runs: 'simd' or 'scalar'
  get time_s() { return playback.time_s; },
  get playing() { return playback.playing; },
  get clipDuration_s() { return playback.duration_s; },
  // Gloss (or letter) of the sign segment under the play head; null in transitions and pauses.
  get currentSign() {
    const segment = playback.currentSegment();
    return segment && segment.kind !== 'transition' && segment.kind !== 'pause' ? segment.label : null;
  },
  // The word of the typed phrase being signed.
  get currentWord() {
    const i = playback.currentWordIndex();
    return i >= 0 && tokens[i] ? tokens[i].word : null;
  },
};
let renderer = null;
let core = null;
let signerReady = false;        // core, avatar and shader programs in: frames can pose and draw
let source = null;              // what the clip was made from, to re-synthesise (left-handed, face)
let clipLabel = 'signweave';
let debugVisible = false;
let poseDirty = true;
let tokens = [];

window.signweave = {
  state, metrics, playback, camera, api,
  get core() { return core; },
  get renderer() { return renderer; },
  playSign: (id) => { location.hash = `#/sign/${encodeURIComponent(id)}`; },
  // Where a joint (canonical name) is drawn, in drawing-buffer pixels with the origin bottom-left
  // (readPixels' convention); for tests that look at the hands.
  projectJoint: (name) => {
    const index = core?.info?.named?.[name];
    if (index === undefined || index < 0) return null;
    const p = core.current().jointPositions;
    const clip = transformPoint(camera.viewProjection, [p[index * 3], p[index * 3 + 1], p[index * 3 + 2]]);
    const canvas = $('view');
    return { x: (clip[0] * 0.5 + 0.5) * canvas.width, y: (clip[1] * 0.5 + 0.5) * canvas.height };
  },
  // Statistics of a rectangle of the drawn canvas (drawing-buffer pixels, origin bottom-left).
  readRegion: (x, y, width, height) => {
    const gl = renderer.gl;
    const x0 = Math.max(0, Math.round(x)), y0 = Math.max(0, Math.round(y));
    const w = Math.max(1, Math.min(gl.drawingBufferWidth - x0, Math.round(width)));
    const h = Math.max(1, Math.min(gl.drawingBufferHeight - y0, Math.round(height)));
    const pixels = new Uint8Array(w * h * 4);
    gl.readPixels(x0, y0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return { x: x0, y: y0, width: w, height: h, pixels: Array.from(pixels) };
  },
  signPhrase: (text) => { location.hash = phraseHash(text); },
};

// ------------------------------------------------------------------------------------- messages
function banner(text, kind = 'error') {
  const el = $('banner');
  el.hidden = !text;
  el.textContent = text || '';
  el.className = kind === 'info' ? 'banner info' : 'banner';
}

function setProgress(fraction, text) {
  $('loading-progress').value = fraction;
  if (text) $('loading').querySelector('.loading-text').textContent = text;
}

// ------------------------------------------------------------------------------------ loading
async function fetchWithProgress(urls, onFraction) {
  let url, response;
  for (url of urls) {
    response = await fetch(url);
    if (response.status !== 404) break;   // anything else is this file's error, not a missing file
  }
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  // A gzip response's Content-Length is the compressed size, while the stream yields decompressed
  // bytes: only an identity response measures progress.
  const encoded = (response.headers.get('Content-Encoding') || 'identity') !== 'identity';
  const total = encoded ? 0 : Number(response.headers.get('Content-Length')) || 0;
  if (!response.body || !total) return new Uint8Array(await response.arrayBuffer());
  const reader = response.body.getReader();
  const chunks = [];
  let received = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    chunks.push(value);
    received += value.length;
    onFraction(Math.min(1, received / total));
  }
  const bytes = new Uint8Array(received);
  let at = 0;
  for (const c of chunks) { bytes.set(c, at); at += c.length; }
  return bytes;
}

// The sign a #/sign/ID link opens, requested at start-up beside the core and the avatar rather than
// after them; the dictionary takes it once (a later visit to the same sign asks the server again,
// so an edit saved meanwhile shows).
let prefetchedSign = null;
function routedSignId() {
  const path = location.hash.replace(/^#/, '').split('?')[0];
  return path.startsWith('/sign/') ? decodeURIComponent(path.slice('/sign/'.length)) : null;
}

function prefetchRoutedSign() {
  const id = routedSignId();
  if (id === null) return;
  mark('sign-requested');
  const promise = api.sign(id);
  promise.then(() => mark('sign-arrived'), () => {});   // the dictionary reports a failure when it takes the answer
  prefetchedSign = { id, promise };
}

function loadSign(id) {
  if (prefetchedSign && prefetchedSign.id === id) {
    const { promise } = prefetchedSign;
    prefetchedSign = null;
    return promise;
  }
  mark('sign-requested');
  return api.sign(id).then((answer) => { mark('sign-arrived'); return answer; });
}

async function boot() {
  // Everything the first signing frame needs is requested before anything waits: the core (its
  // .wasm compiles while it streams in), the avatar, the routed sign and the languages. The
  // renderer's shader programs then build in the GPU process while those downloads run.
  let coreFraction = 0, avatarFraction = 0;
  const progress = () => setProgress(0.5 * coreFraction + 0.5 * avatarFraction, 'Loading the signer…');
  const corePromise = SigningCore.create({ onProgress: (f) => { coreFraction = f; progress(); } });
  const avatarPromise = fetchWithProgress(AVATAR_URLS, (f) => { avatarFraction = f; progress(); })
    .then((bytes) => { mark('avatar-fetched'); return bytes; });
  prefetchRoutedSign();
  // The dictionary needs no 3D view: languages load whatever happens to WebGL2 or the core.
  const languagesPromise = loadLanguages();
  // A failure while the renderer is checked must not leave these to reject unheard.
  corePromise.catch(() => {});
  avatarPromise.catch(() => {});
  try {
    mark('renderer-start');
    renderer = new Renderer($('view'));
    mark('renderer-created');
  } catch (err) {
    fail(rendererFailure(err));
    return;
  }
  let avatarBytes;
  // The routed sign (a few hundred bytes, answered in milliseconds) is taken in before the avatar
  // parse blocks the main thread for the better part of a second: otherwise its answer, though it
  // has arrived, waits behind that parse and the first frames (measured: arriving at ~1.0 s, read
  // at 2.3-3.4 s), and the first signing frame with it. Its failure is the dictionary's to report.
  const routedSign = prefetchedSign ? prefetchedSign.promise.catch(() => null) : null;
  try {
    [core, avatarBytes] = await Promise.all([corePromise, avatarPromise, routedSign]);
  } catch (err) {
    fail(err instanceof TypeError && /fetch/i.test(err.message)
      ? 'The Signweave server cannot be reached, so the signer cannot load. Is it running?'
      : `Loading failed: ${err.message}`);
    return;
  }
  state.flavour = core.flavour;
  mark('avatar-parse-start');
  const avatarError = core.loadAvatar(avatarBytes);
  if (avatarError) { fail(`The avatar could not be loaded: ${avatarError}`); return; }
  mark('avatar-parsed');
  const info = core.info;
  renderer.setMesh({ vertexCount: info.vertex_count, indices: core.indices(), primitives: info.primitives, materials: info.materials });
  mark('mesh-uploaded');
  try {
    renderer.finishPrograms();   // built meanwhile; a compile error is reported here, not mid-frame
  } catch (err) {
    fail(rendererFailure(err));
    return;
  }
  mark('programs-linked');
  renderer.bodyHeight_m = info.height_m || 1.7;
  camera.fitTo(info.height_m);
  setupFace(info);
  setProgress(1);
  $('loading').hidden = true;
  signerReady = true;
  mark('signer-ready');
  // A #/sign/ID link plays as soon as the signer can: it needs no language list. Other routes (a
  // phrase or a search depends on the language) wait for it below.
  const early = location.hash;
  const earlySign = routedSignId();
  if (earlySign !== null) {
    showPane('dictionary');
    dictionary.open(earlySign);
  }
  await languagesPromise;
  state.ready = true;
  mark('ready');
  if (earlySign === null || location.hash !== early) route();
}

function rendererFailure(err) {
  return err instanceof WebGL2Unavailable
    ? 'This browser cannot draw the avatar: WebGL2 is missing or disabled. Try a current Firefox, Chrome, Edge or Safari, or enable hardware acceleration.'
    : `The 3D view could not start: ${err.message}`;
}

function fail(message) {
  state.error = message;
  banner(message);
  $('loading').querySelector('.loading-text').textContent = message;
  $('loading-progress').hidden = true;
}

async function loadLanguages() {
  const select = $('language');
  try {
    const languages = await api.languages();
    const saved = localStorage.getItem('signweave.lang');
    select.replaceChildren(...languages.map((l) => {
      const code = l.code || l.id || l.lang;
      const option = new Option(l.name ? `${l.name}` : code, code);
      return option;
    }));
    if (saved && languages.some((l) => (l.code || l.id || l.lang) === saved)) select.value = saved;
  } catch (err) {
    banner(err.kind === 'unreachable'
      ? 'The Signweave server cannot be reached: search and phrases are unavailable. The editor still works offline.'
      : `The server answered with an error: ${err.message}`);
  }
}

const language = () => $('language').value || '';
const phraseHash = (text) => `#/phrase?text=${encodeURIComponent(text)}${language() ? `&lang=${encodeURIComponent(language())}` : ''}`;
$('language').addEventListener('change', () => {
  localStorage.setItem('signweave.lang', language());
  dictionary.schedule();
});

// -------------------------------------------------------------------------------- the clip
function synthesisOptions() {
  const options = { left_handed: $('left-handed').checked };
  if (faceEnabled) {
    options.emotion = $('emotion').value;
    options.intensity = Number($('intensity').value);
    options.mouthing = $('mouthing').checked;
  }
  return options;
}

function applyResult(result, { autoplay = true } = {}) {
  if (!result.ok) return result;
  playback.setClip(result.duration_s, result.segments || []);
  poseDirty = true;
  if (autoplay) playback.play();
  return result;
}

function playNotation(text, format, label, { loop = true } = {}) {
  if (!core) return { ok: false, errors: [{ message: 'the signer is still loading' }] };
  source = { kind: 'notation', text, format };
  tokens = [];
  clipLabel = label || 'sign';
  playback.loop = loop;
  $('loop').checked = loop;
  return applyResult(core.setNotation(text, format, { ...synthesisOptions(), label: clipLabel }));
}

// A cache of sign notations by id: a phrase often repeats letters, and re-signing a phrase with
// another option must not refetch.
const signCache = new Map();
async function fetchSign(id) {
  if (!signCache.has(id)) {
    signCache.set(id, api.sign(id).then(({ sign }) => normalizeSign(sign)).catch((err) => { signCache.delete(id); throw err; }));
  }
  return signCache.get(id);
}

async function playPlan(plan, planned) {
  if (!core) return { ok: false, errors: [{ message: 'the signer is still loading' }] };
  const { items, missing } = await phraseItems(planned, fetchSign);
  source = { kind: 'phrase', items };
  tokens = planned;
  clipLabel = planned.map((t) => t.word).join('_') || 'phrase';
  playback.loop = $('loop').checked;
  const result = applyResult(core.setPhrase({ items }, synthesisOptions()));
  return { ...result, missing };
}

function resynthesise() {
  if (!core || !source) return;
  const t = playback.time_s, wasPlaying = playback.playing;
  const result = source.kind === 'phrase'
    ? core.setPhrase({ items: source.items }, synthesisOptions())
    : core.setNotation(source.text, source.format, { ...synthesisOptions(), label: clipLabel });
  if (!result.ok) return;
  playback.setClip(result.duration_s, result.segments || []);
  playback.seek(Math.min(t, result.duration_s));
  if (wasPlaying) playback.play();
  poseDirty = true;
}

// ------------------------------------------------------------------------------------ panes
const dictionary = new Dictionary({
  input: $('search'), status: $('search-status'), results: $('results'), page: $('sign-page'),
  gloss: $('sign-gloss'), languageLabel: $('sign-language'), share: $('sign-share'),
  keywords: $('sign-keywords'), format: $('sign-format'), notation: $('sign-notation'),
}, {
  api, language, loadSign,
  symbolNames: (text, format) => (core && (format === 'hamnosys' || format === 'hsigml') ? core.hamnosysNames(text) : []),
  onOpen: (sign) => {
    mark('sign-fetched');
    phrase.clearCaption();
    const result = playNotation(sign.notation, sign.format, sign.gloss, { loop: true });
    mark('sign-synthesised');
    if (!result.ok) dictionary.setStatus(`This sign cannot be played: ${describeFailure(result)}`, true);
  },
});

const phrase = new PhrasePane({
  form: $('phrase-form'), text: $('phrase-text'), status: $('phrase-status'), plan: $('plan'), caption: $('caption'),
}, { api, language, onPlan: playPlan, hashFor: (text) => phraseHash(text) });

const editor = new NotationEditor({
  textarea: $('editor-text'), highlight: $('editor-highlight'), format: $('editor-format'),
  gloss: $('editor-gloss'), list: $('editor-diagnostics'), keywords: $('editor-keywords'),
  token: $('editor-token'), saveButton: $('editor-save'), saveStatus: $('editor-save-status'),
}, {
  preview: (text, format) => {
    if (!core) return { ok: false, diagnostics: [], errors: [{ message: 'the signer is still loading' }] };
    const result = playNotation(text, format, $('editor-gloss').value || 'preview', { loop: true });
    return result;
  },
  save: ({ id, revision, text, format, gloss, keywords, token }) => api.saveSign({
    id, revision, token,
    fields: { gloss, language: language(), notation: text, format, keywords },
  }),
});

$('sign-edit').addEventListener('click', () => {
  const s = dictionary.current;
  if (!s) return;
  location.hash = '#/editor';
  editor.load({ text: s.notation, format: s.format, gloss: s.gloss, keywords: s.keywords, id: s.id, revision: s.revision });
});

installNotationExport({
  select: $('sign-export-format'), button: $('sign-export'), status: $('sign-export-status'),
  currentSign: () => dictionary.current,
});

function describeFailure(result) {
  const first = (result.diagnostics || []).find((d) => d.severity !== 'warning') || (result.errors || [])[0];
  return first ? first.message : 'unknown error';
}

// ----------------------------------------------------------------------------------- routing
function showPane(name) {
  for (const pane of document.querySelectorAll('.pane')) pane.hidden = pane.dataset.pane !== name;
  for (const tab of document.querySelectorAll('.tab')) {
    if (tab.dataset.tab === name) tab.setAttribute('aria-current', 'page');
    else tab.removeAttribute('aria-current');
  }
}

function route() {
  const hash = location.hash.replace(/^#/, '') || '/';
  const [path, query = ''] = hash.split('?');
  const params = new URLSearchParams(query);
  const lang = params.get('lang');
  if (lang && [...$('language').options].some((o) => o.value === lang)) $('language').value = lang;
  if (path.startsWith('/sign/')) {
    showPane('dictionary');
    if (state.ready) dictionary.open(decodeURIComponent(path.slice('/sign/'.length)));
  } else if (path === '/phrase') {
    showPane('phrase');
    const text = params.get('text');
    if (text && state.ready) phrase.sign(text);
  } else if (path === '/editor') {
    showPane('editor');
    if (state.ready) editor.schedule(0);
  } else {
    showPane('dictionary');
  }
}
window.addEventListener('hashchange', route);

// ------------------------------------------------------------------------------------ player UI
$('play').addEventListener('click', () => playback.toggle());
$('loop').addEventListener('change', (e) => { playback.loop = e.target.checked; });
$('speed').addEventListener('change', (e) => playback.setSpeed(e.target.value));
$('left-handed').addEventListener('change', resynthesise);
$('timeline').addEventListener('input', (e) => {
  playback.seek(Number(e.target.value) * playback.duration_s);
  poseDirty = true;
});
document.addEventListener('keydown', (e) => {
  // Space toggles playback unless the user is typing.
  if (e.key === ' ' && !/^(INPUT|TEXTAREA|SELECT|BUTTON|SUMMARY)$/.test(e.target.tagName)) {
    e.preventDefault();
    playback.toggle();
  }
});
playback.onChange(() => {
  const play = $('play');
  play.textContent = playback.playing ? '❚❚' : '▶';
  play.setAttribute('aria-label', playback.playing ? 'Pause' : 'Play');
  poseDirty = true;
});

for (const button of document.querySelectorAll('[data-preset]')) {
  button.addEventListener('click', () => camera.applyPreset(button.dataset.preset));
}
attachCameraControls($('view'), camera, (name) => camera.applyPreset(name));
$('debug-toggle').addEventListener('click', (e) => {
  debugVisible = !debugVisible;
  e.currentTarget.setAttribute('aria-pressed', String(debugVisible));
  poseDirty = true;
});

let faceEnabled = false;
function setupFace(info) {
  const face = info.face;
  const controls = $('face-controls');
  if (!face || !Array.isArray(face.emotions) || !face.emotions.length) { controls.hidden = true; return; }
  $('emotion').replaceChildren(...face.emotions.map((e) => new Option(e, e)));
  controls.hidden = false;
  faceEnabled = true;
  for (const id of ['emotion', 'intensity', 'mouthing']) {
    $(id).disabled = false;
    $(id).addEventListener('change', resynthesise);
  }
}

// ------------------------------------------------------------------------------------ export
// The menu closes once a choice is made.
for (const id of ['export-bvh', 'export-glb', 'export-webm']) {
  $(id).addEventListener('click', (e) => { e.currentTarget.closest('details').open = false; });
}
$('export-bvh').addEventListener('click', () => {
  if (!core || !source) return;
  download(core.exportBvh(), `${safeFileStem(clipLabel)}.bvh`, 'text/plain');
});
$('export-glb').addEventListener('click', () => {
  if (!core || !source) return;
  download(core.exportGlb(), `${safeFileStem(clipLabel)}.glb`, 'model/gltf-binary');
});
if (!webmSupported()) $('export-webm').hidden = true;
$('export-webm').addEventListener('click', async (e) => {
  if (!core || !source) return;
  const button = e.currentTarget;
  button.disabled = true;
  button.textContent = 'Recording…';
  try {
    const blob = await recordWebm($('view'), () => new Promise((resolve) => {
      const wasLoop = playback.loop;
      playback.loop = false;
      playback.seek(0);
      playback.play();
      const check = () => (playback.playing ? requestAnimationFrame(check) : (playback.loop = wasLoop, resolve()));
      requestAnimationFrame(check);
    }));
    download(blob, `${safeFileStem(clipLabel)}.webm`, 'video/webm');
  } catch (err) {
    banner(err.message);
  } finally {
    button.disabled = false;
    button.textContent = 'Video (WebM)';
  }
});

// --------------------------------------------------------------------------------- the frame loop
let last = performance.now();
let idleDrawn = false;
function frame(now) {
  const dt = (now - last) / 1000;
  last = now;
  if (playback.tick(dt)) poseDirty = true;
  camera.update(dt);
  if (signerReady && !renderer.gpuCaughtUp()) {
    // The GPU is behind: neither pose nor draw this time (see Renderer.gpuCaughtUp).
    metrics.framesSkipped++;
  } else if (signerReady) {
    if (poseDirty) {
      const start = performance.now();
      const views = core.update(playback.time_s);
      const updated = performance.now();
      renderer.upload(views.positions, views.normals);
      const end = performance.now();
      metrics.frameWork_ms = end - start;
      pushSample(metrics.frameWorkSamples, metrics.frameWork_ms);
      pushSample(metrics.frameUpdateSamples, updated - start);
      pushSample(metrics.frameUploadSamples, end - updated);
      if (debugVisible) renderer.setDebugGeometry(views.jointPositions, core.info.parents, views.anchorPositions);
      updateFraming(views.jointPositions, views.anchorPositions);
      poseDirty = false;
    }
    renderer.draw(camera, { showDebug: debugVisible });
    metrics.frames++;
    if (markTime('first-avatar-frame') === null) {
      mark('first-avatar-frame');
      renderer.startDeferredPrograms();
    }
    if (metrics.firstSigningFrame_ms === null && playback.playing && playback.time_s > 0) {
      metrics.firstSigningFrame_ms = mark('first-signing-frame');
      measureStartup();
    }
  } else if (renderer && !state.error && renderer.programsReady() && !idleDrawn) {
    // While loading, the background is drawn once (it does not change): redrawing it every frame
    // would take the CPU that SwiftShader or a weak GPU shares with the downloads and compiles.
    renderer.draw(camera);
    idleDrawn = true;
  }
  publishState();
  requestAnimationFrame(frame);
}

function pushSample(samples, value) {
  samples.push(value);
  if (samples.length > 240) samples.shift();
}

// The spans of the start-up worth reading at a glance (the marks themselves hold the rest).
function measureStartup() {
  measure('renderer-create', 'renderer-start', 'renderer-created');
  measure('programs-wait', 'mesh-uploaded', 'programs-linked');
  measure('wasm-download-and-compile', 'wasm-fetch-start', 'wasm-compiled');
  measure('wasm-instantiate', 'wasm-compiled', 'wasm-instantiated');
  measure('avatar-parse', 'avatar-parse-start', 'avatar-parsed');
  measure('mesh-upload', 'avatar-parsed', 'mesh-uploaded');
  measure('sign-fetch', 'sign-requested', 'sign-arrived');
  measure('sign-wait-for-signer', 'sign-arrived', 'sign-fetched');
  measure('synthesis', 'sign-fetched', 'sign-synthesised');
  measure('to-first-signing-frame', 'sign-synthesised', 'first-signing-frame');
}

// The hands close-up frames neutral signing space (the body anchor space/centre, where most signs
// happen), so it stays put between signs instead of chasing hands that drop to rest; the floor
// shadow follows the hips.
function updateFraming(jointPositions, anchorPositions) {
  const j = core.info.named;
  const space = core.info.anchors.indexOf('space/centre');
  if (space >= 0 && anchorPositions) {
    camera.handsCentre = [anchorPositions[space * 3], anchorPositions[space * 3 + 1], anchorPositions[space * 3 + 2]];
  }
  if (j && j.hips >= 0) renderer.shadowCentre = [jointPositions[j.hips * 3], jointPositions[j.hips * 3 + 2]];
}

let shownWord = -2;
function publishState() {
  const wordIndex = playback.currentWordIndex();
  if (wordIndex !== shownWord) { phrase.highlight(wordIndex); shownWord = wordIndex; }
  const timeline = $('timeline');
  if (document.activeElement !== timeline || playback.playing) {
    timeline.value = playback.duration_s > 0 ? String(playback.time_s / playback.duration_s) : '0';
  }
  $('time').textContent = `${playback.time_s.toFixed(2)} s`;
}

requestAnimationFrame(frame);
boot();
