// phrase.js — typed phrase → signing: the server's /api/lookup plan (per word a sign, or the letters
// of the sign language's manual alphabet when no sign is known, and pauses at punctuation), shown as
// a list, handed to the core to synthesise into one clip, and a caption that highlights the word
// being signed. URL: #/phrase?text=…

// The lookup plan's tokens as the page shows them: { word, kind: sign|fingerspell|pause, gloss, letters }.
export function planTokens(plan) {
  const tokens = plan.tokens || plan.items || plan.plan || [];
  return tokens.map((t) => {
    const kind = t.kind || t.type || (t.sign ? 'sign' : t.letters ? 'fingerspell' : 'pause');
    return {
      word: t.word ?? t.text ?? t.token ?? '',
      kind,
      gloss: t.sign?.gloss ?? t.gloss ?? '',
      letters: (t.letters || []).map((l) => (typeof l === 'string' ? l : l.letter ?? l.gloss ?? '')),
    };
  });
}

export class PhrasePane {
  constructor({ form, text, status, plan, caption }, { api, language, onPlan }) {
    this.el = { form, text, status, plan, caption };
    this.api = api;
    this.language = language;
    this.onPlan = onPlan;       // (plan) -> { ok, errors, segments } after the core synthesised it
    this.tokens = [];
    this.controller = null;
    form.addEventListener('submit', (e) => {
      e.preventDefault();
      const value = text.value.trim();
      if (!value) return;
      const target = `#/phrase?text=${encodeURIComponent(value)}`;
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
    const result = this.onPlan(plan);
    if (!result.ok) {
      this.setStatus(`The phrase could not be signed: ${(result.errors || []).map((e) => e.message).join('; ')}`, true);
    } else {
      const spelled = this.tokens.filter((t) => t.kind === 'fingerspell').length;
      this.setStatus(`${this.tokens.filter((t) => t.kind !== 'pause').length} words, ${spelled} fingerspelled · ${result.duration_s.toFixed(1)} s`);
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
        li.textContent = `${t.word} → ${t.letters.join('-')} `;
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
        if (spans.length) spans[spans.length - 1].textContent += t.word;
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
