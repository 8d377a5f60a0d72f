// dictionary.js — the dictionary pane: a search box with instant (debounced, cancel-previous) results
// from the server filtered by sign language, a keyboard-navigable result list, and the sign page
// (gloss, keywords, notation) whose sign the avatar plays in a loop. URLs: #/sign/ID.

const SEARCH_DEBOUNCE_MS = 140;

// The server's sign JSON, with the few field spellings it may use, as one shape for the page.
export function normalizeSign(raw) {
  const keywords = (raw.keywords || []).map((k) => (typeof k === 'string' ? k : k.word || k.keyword || k.text)).filter(Boolean);
  return {
    id: raw.id,
    gloss: raw.gloss || raw.name || `#${raw.id}`,
    language: raw.language || raw.lang || '',
    notation: raw.notation ?? raw.source ?? '',
    format: raw.format || raw.notation_format || 'formula',
    keywords,
    revision: raw.revision ?? raw.rev ?? null,
  };
}

export class Dictionary {
  constructor(elements, { api, language, onOpen, symbolNames = () => [], loadSign = (id) => api.sign(id) }) {
    this.el = elements;         // { input, status, results, page, gloss, languageLabel, share, keywords, format, notation, edit }
    this.api = api;
    this.language = language;   // () -> current language code
    this.onOpen = onOpen;       // (sign) -> void: play it
    this.symbolNames = symbolNames;  // (text, format) -> HamNoSys symbol names, for glyph notations
    this.loadSign = loadSign;   // id -> Promise<{ sign }> (the app hands over a sign it prefetched)
    this.timer = 0;
    this.inflight = null;
    this.current = null;
    elements.input.addEventListener('input', () => this.schedule());
    elements.input.addEventListener('keydown', (e) => {
      if (e.key === 'ArrowDown') {
        const first = elements.results.querySelector('a');
        if (first) { e.preventDefault(); first.focus(); }
      } else if (e.key === 'Enter') {
        const first = elements.results.querySelector('a');
        if (first) { e.preventDefault(); location.hash = first.getAttribute('href'); }
      }
    });
    elements.results.addEventListener('keydown', (e) => {
      const links = [...elements.results.querySelectorAll('a')];
      const i = links.indexOf(document.activeElement);
      if (e.key === 'ArrowDown' && i < links.length - 1) { e.preventDefault(); links[i + 1].focus(); }
      if (e.key === 'ArrowUp') { e.preventDefault(); (i > 0 ? links[i - 1] : elements.input).focus(); }
    });
  }

  schedule() {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.search(), SEARCH_DEBOUNCE_MS);
  }

  async search() {
    const q = this.el.input.value.trim();
    if (this.inflight) this.inflight.abort();
    if (!q) { this.el.results.replaceChildren(); this.setStatus(''); return; }
    const controller = new AbortController();
    this.inflight = controller;
    try {
      const found = (await this.api.searchSigns(q, this.language(), { signal: controller.signal })).map(normalizeSign);
      if (controller.signal.aborted) return;
      this.renderResults(found);
      this.setStatus(found.length ? `${found.length} sign${found.length === 1 ? '' : 's'}` : `No sign found for “${q}”.`);
    } catch (err) {
      if (err.kind === 'cancelled') return;
      this.setStatus(err.message, true);
    }
  }

  renderResults(signs) {
    const items = signs.map((s) => {
      const li = document.createElement('li');
      const a = document.createElement('a');
      a.href = `#/sign/${encodeURIComponent(s.id)}`;
      a.dataset.signId = s.id;
      if (this.current && String(this.current.id) === String(s.id)) a.setAttribute('aria-current', 'true');
      const gloss = document.createElement('span');
      gloss.className = 'gloss';
      gloss.textContent = s.gloss;
      const kw = document.createElement('div');
      kw.className = 'kw';
      kw.textContent = [s.language, s.keywords.slice(0, 6).join(', ')].filter(Boolean).join(' · ');
      a.append(gloss, kw);
      li.append(a);
      return li;
    });
    this.el.results.replaceChildren(...items);
  }

  setStatus(text, isError = false) {
    this.el.status.textContent = text;
    this.el.status.className = isError ? 'status error' : 'status';
  }

  async open(id) {
    try {
      const { sign } = await this.loadSign(id);
      const s = normalizeSign(sign);
      this.current = s;
      this.showPage(s);
      this.onOpen(s);
      return s;
    } catch (err) {
      this.setStatus(err.status === 404 ? `There is no sign ${id}.` : err.message, true);
      return null;
    }
  }

  showPage(s) {
    const el = this.el;
    el.page.hidden = false;
    el.gloss.textContent = s.gloss;
    el.languageLabel.textContent = s.language;
    el.share.href = `#/sign/${encodeURIComponent(s.id)}`;
    el.keywords.textContent = s.keywords.length ? s.keywords.join(', ') : '—';
    el.format.textContent = `(${s.format})`;
    el.notation.textContent = s.notation;
    const names = this.symbolNames(s.notation, s.format);
    if (names.length) {
      const list = document.createElement('span');
      list.className = 'symbol-names';
      list.textContent = names.join(' ');
      el.notation.append(document.createElement('br'), list);
    }
    for (const a of el.results.querySelectorAll('a')) {
      if (a.dataset.signId === String(s.id)) a.setAttribute('aria-current', 'true');
      else a.removeAttribute('aria-current');
    }
  }
}
