// editor.js — the notation editor: a textarea with a highlight layer behind it that underlines each
// parse error at its position, the list of diagnostics with their messages, live preview as you type
// (the core parses and synthesises; the app plays the clip) and saving to the server with a token
// (POST for a new sign; PUT with If-Match on the revision for an edit, so a stale write is refused).
//
// Diagnostics carry UTF-8 byte offsets (src/notation/diagnostic.h); the textarea counts UTF-16 code
// units, so offsets are converted before marking (HamNoSys glyphs are 3 UTF-8 bytes, 1 code unit).

const PREVIEW_DEBOUNCE_MS = 180;

export function byteOffsetToIndex(text, byteOffset) {
  let bytes = 0;
  let i = 0;
  while (i < text.length && bytes < byteOffset) {
    const cp = text.codePointAt(i);
    bytes += cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4;
    i += cp > 0xffff ? 2 : 1;
  }
  return i;
}

function escapeHtml(s) {
  return s.replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' }[c]));
}

// HTML for the layer behind the textarea: the same text, errors wrapped in <mark>.
export function highlightHtml(text, diagnostics) {
  const ranges = diagnostics
    .filter((d) => d.severity !== 'warning')
    .map((d) => {
      const start = byteOffsetToIndex(text, d.offset);
      const end = byteOffsetToIndex(text, d.offset + (d.length || 0));
      return { start, end, message: d.message };
    })
    .sort((a, b) => a.start - b.start);
  let html = '';
  let at = 0;
  for (const r of ranges) {
    if (r.start < at) continue;   // overlapping diagnostics: the first one is marked
    html += escapeHtml(text.slice(at, r.start));
    if (r.end > r.start) {
      html += `<mark>${escapeHtml(text.slice(r.start, r.end))}</mark>`;
      at = r.end;
    } else {
      // A point error (missing ')' at the end...): mark a small box where something was expected.
      html += '<mark class="point"> </mark>';
      at = r.start;
    }
  }
  // A trailing newline needs a character after it or the layer is one line short of the textarea.
  return html + escapeHtml(text.slice(at)) + '\u200b';
}

export class NotationEditor {
  constructor({ textarea, highlight, format, gloss, list, keywords, token, saveButton, saveStatus }, { preview, save }) {
    this.el = { textarea, highlight, format, gloss, list, keywords, token, saveButton, saveStatus };
    this.preview = preview;   // (text, format) -> { ok, diagnostics, errors }
    this.save = save;         // async ({text, format, gloss, keywords, token}) -> message
    this.timer = 0;
    this.editing = null;      // { id, revision } when editing an existing sign
    textarea.addEventListener('input', () => this.schedule());
    textarea.addEventListener('scroll', () => { highlight.scrollTop = textarea.scrollTop; });
    format.addEventListener('change', () => this.schedule(0));
    saveButton.addEventListener('click', () => this.onSave());
    new ResizeObserver(() => { highlight.style.height = `${textarea.offsetHeight}px`; }).observe(textarea);
  }

  load({ text, format, gloss = '', keywords = [], id = null, revision = null }) {
    this.el.textarea.value = text;
    if (format) this.el.format.value = format;
    this.el.gloss.value = gloss;
    this.el.keywords.value = keywords.join(', ');
    this.editing = id !== null ? { id, revision } : null;
    this.schedule(0);
  }

  schedule(delay = PREVIEW_DEBOUNCE_MS) {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.run(), delay);
  }

  run() {
    const text = this.el.textarea.value;
    const result = this.preview(text, this.el.format.value);
    this.show(text, result);
    return result;
  }

  show(text, result) {
    const diagnostics = result.diagnostics || [];
    this.el.highlight.innerHTML = highlightHtml(text, diagnostics);
    this.el.highlight.scrollTop = this.el.textarea.scrollTop;
    const list = this.el.list;
    list.replaceChildren();
    for (const d of diagnostics) {
      const li = document.createElement('li');
      li.className = d.severity === 'warning' ? 'warning' : 'error';
      const where = `line ${d.line}, column ${d.column}`;
      const symbol = d.symbol && !d.message.includes(d.symbol) ? ` ('${d.symbol}')` : '';
      li.textContent = `${where}: ${d.message}${symbol}`;
      list.append(li);
    }
    for (const e of result.errors || []) {
      const li = document.createElement('li');
      li.className = 'error';
      li.textContent = `${e.where ? `${e.where}: ` : ''}${e.message}`;
      list.append(li);
    }
    if (result.ok) {
      const li = document.createElement('li');
      li.className = 'ok';
      li.textContent = `Parsed — previewing ${result.duration_s?.toFixed(2) ?? '?'} s of signing.`;
      list.append(li);
    }
    this.el.textarea.setAttribute('aria-invalid', result.ok ? 'false' : 'true');
  }

  async onSave() {
    const status = this.el.saveStatus;
    const token = this.el.token.value.trim();
    const gloss = this.el.gloss.value.trim();
    if (!token) { status.textContent = 'An API token is needed to save.'; status.className = 'status error'; return; }
    if (!gloss) { status.textContent = 'Give the sign a gloss first.'; status.className = 'status error'; return; }
    status.textContent = 'Saving…';
    status.className = 'status';
    try {
      const saved = await this.save({
        id: this.editing?.id,
        revision: this.editing?.revision,
        text: this.el.textarea.value,
        format: this.el.format.value,
        gloss,
        keywords: this.el.keywords.value.split(',').map((k) => k.trim()).filter(Boolean),
        token,
      });
      if (saved && saved.id !== undefined) this.editing = { id: saved.id, revision: saved.revision ?? null };
      status.textContent = `Saved${saved?.id !== undefined ? ` as sign ${saved.id}` : ''}.`;
    } catch (err) {
      status.className = 'status error';
      if (err.status === 409) status.textContent = 'Someone changed this sign since you opened it. Reload it, then apply your edit again.';
      else if (err.status === 401 || err.status === 403) status.textContent = 'The token was refused.';
      else status.textContent = `Not saved: ${err.message}`;
    }
  }
}
