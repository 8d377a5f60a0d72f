// phrase.js — typed phrase → signing: the server's /api/lookup plan (per word a sign, or the letters
// of the sign language's manual alphabet when no sign is known, and pauses at punctuation), shown as
// a list, handed to the core to synthesise into one clip, and a caption that highlights the word
// being signed. URL: #/phrase?text=…

// The lookup plan's tokens (server/store/search_index.h LookupToken) as the page uses them:
// { word, kind: sign|fingerspell|pause, signId, gloss, letters: [{letter, signId}], pause_s }.
export function planTokens(plan) {
  return (plan.tokens || []).map((t) => {
    const kind = normalKind(t.type ?? t.kind);
    return {
      word: t.text ?? t.word ?? '',
      kind,
      signId: t.sign_id ?? null,
      gloss: t.gloss ?? '',
      letters: (t.letters || []).map((l) => ({ letter: l.letter, signId: l.sign_id ?? null, gloss: l.gloss ?? '' })),
      pause_s: t.duration_s ?? t.pause_s ?? 0,
    };
  });
}

function normalKind(type) {
  const k = String(type || '').toLowerCase();
  if (k.startsWith('finger') || k === 'spell' || k === 'letters') return 'fingerspell';
  if (k === 'pause' || k === 'punctuation') return 'pause';
  return 'sign';
}

// The core's phrase items: every sign and letter with its notation (fetched by id, cached), and
// pauses. `word_index` is the token's index, which the clip's segments carry back for the caption.
export async function phraseItems(tokens, fetchSign) {
  const items = [];
  const missing = [];
  for (let i = 0; i < tokens.length; i++) {
    const t = tokens[i];
    if (t.kind === 'pause') {
      items.push({ kind: 'pause', label: t.word, word_index: i, pause_s: t.pause_s });
    } else if (t.kind === 'sign') {
      items.push({ kind: 'sign', signId: t.signId, label: t.gloss || t.word, word_index: i });
    } else {
      for (const l of t.letters) {
        if (l.signId === null) { missing.push(l.letter); continue; }
        items.push({ kind: 'letter', signId: l.signId, label: l.letter, word_index: i });
      }
    }
  }
  const signs = new Map();
  await Promise.all([...new Set(items.filter((it) => it.signId !== undefined && it.kind !== 'pause').map((it) => it.signId))]
    .map(async (id) => { signs.set(id, await fetchSign(id)); }));
  for (const it of items) {
    if (it.kind === 'pause') continue;
    const sign = signs.get(it.signId);
    it.notation = sign.notation;
    it.format = sign.format;
    delete it.signId;
  }
  return { items, missing };
}

export class PhrasePane {
  constructor({ form, text, status, plan, caption }, { api, language, onPlan, hashFor }) {
    this.el = { form, text, status, plan, caption };
    this.api = api;
    this.language = language;
    this.onPlan = onPlan;       // async (plan, tokens) -> { ok, errors, duration_s } once the core synthesised it
    this.tokens = [];
    this.controller = null;
    form.addEventListener('submit', (e) => {
      e.preventDefault();
      const value = text.value.trim();
      if (!value) return;
      const target = hashFor(value);
      if (location.hash === target) this.sign(value);
      else location.hash = target;
    });
    text.addEventListener('keydown', (e) => {
      if (e.key === 'Enter' && !e.shiftKey) { e.preventDefault(); form.requestSubmit(); }
    });
  }

  async sign(value) {
    this.el.text.value = value;
    if (this.controller) this.controller.abort();
    const controller = new AbortController();
    this.controller = controller;
    this.setStatus('Planning…');
    let plan;
    try {
      plan = await this.api.lookup(value, this.language(), { signal: controller.signal });
    } catch (err) {
      if (err.kind !== 'cancelled') this.setStatus(err.message, true);
      return null;
    }
    if (controller.signal.aborted) return null;
    this.tokens = planTokens(plan);
    this.renderPlan();
    let result;
    try {
      result = await this.onPlan(plan, this.tokens);
    } catch (err) {
      this.setStatus(err.message, true);
      return null;
    }
    if (controller.signal.aborted) return null;
    if (!result.ok) {
      this.setStatus(`The phrase could not be signed: ${(result.errors || []).map((e) => e.message).join('; ')}`, true);
    } else {
      const spelled = this.tokens.filter((t) => t.kind === 'fingerspell').length;
      const words = this.tokens.filter((t) => t.kind !== 'pause').length;
      const unspellable = result.missing?.length ? ` · no alphabet sign for ${result.missing.join(' ')}` : '';
      this.setStatus(`${words} word${words === 1 ? '' : 's'}, ${spelled} fingerspelled · ${result.duration_s.toFixed(1)} s${unspellable}`);
    }
    return { plan, result };
  }

  renderPlan() {
    const items = this.tokens.map((t, i) => {
      const li = document.createElement('li');
      li.dataset.word = String(i);
      const kind = document.createElement('span');
      kind.className = 'kind';
      if (t.kind === 'sign') {
        li.textContent = `${t.word} → ${t.gloss} `;
        kind.textContent = 'sign';
      } else if (t.kind === 'fingerspell') {
        li.textContent = `${t.word} → ${t.letters.map((l) => l.letter).join('-')} `;
        kind.textContent = 'fingerspelled';
      } else {
        li.textContent = `${t.word || '…'} `;
        kind.textContent = 'pause';
      }
      li.append(kind);
      return li;
    });
    this.el.plan.replaceChildren(...items);
    this.renderCaption();
  }

  renderCaption() {
    const spans = [];
    this.tokens.forEach((t, i) => {
      if (t.kind === 'pause') {
        // Punctuation follows its word outside the word's highlight.
        spans.push(document.createTextNode(t.word));
        return;
      }
      const span = document.createElement('span');
      span.className = t.kind === 'fingerspell' ? 'word spelled' : 'word';
      span.dataset.word = String(i);
      span.textContent = t.word;
      if (spans.length) spans.push(document.createTextNode(' '));
      spans.push(span);
    });
    this.el.caption.replaceChildren(...spans);
  }

  highlight(wordIndex) {
    for (const node of this.el.caption.querySelectorAll('.word')) node.classList.toggle('current', Number(node.dataset.word) === wordIndex);
    for (const node of this.el.plan.children) node.classList.toggle('current', Number(node.dataset.word) === wordIndex);
  }

  clearCaption() { this.el.caption.replaceChildren(); }

  setStatus(text, isError = false) {
    this.el.status.textContent = text;
    this.el.status.className = isError ? 'status error' : 'status';
  }
}
