// api_client.js — the page's only door to the Signweave server's JSON API (issue 5):
// languages, sign search, one sign, phrase lookup plans, and authoring with a bearer token and
// optimistic concurrency (If-Match). Every failure becomes an ApiError whose `kind` tells the UI
// what to say: 'unreachable' (no server), 'http' (the server answered with an error JSON), 'timeout'.

const DEFAULT_TIMEOUT_MS = 8000;

export class ApiError extends Error {
  constructor(kind, message, { status = 0, body = null } = {}) {
    super(message);
    this.kind = kind;
    this.status = status;
    this.body = body;
  }
}

export class ApiClient {
  constructor(base = '') {
    this.base = base;
  }

  async request(path, { method = 'GET', body, headers = {}, signal, timeout_ms = DEFAULT_TIMEOUT_MS } = {}) {
    const controller = new AbortController();
    const timer = setTimeout(() => controller.abort('timeout'), timeout_ms);
    if (signal) signal.addEventListener('abort', () => controller.abort('cancelled'), { once: true });
    let response;
    try {
      response = await fetch(this.base + path, {
        method,
        headers: body !== undefined ? { 'Content-Type': 'application/json', ...headers } : headers,
        body: body !== undefined ? JSON.stringify(body) : undefined,
        signal: controller.signal,
      });
    } catch (err) {
      if (controller.signal.aborted) {
        const reason = controller.signal.reason;
        throw new ApiError(reason === 'cancelled' ? 'cancelled' : 'timeout',
          reason === 'cancelled' ? 'request cancelled' : `the server did not answer within ${timeout_ms / 1000} s`);
      }
      throw new ApiError('unreachable', 'The Signweave server cannot be reached. Is it running?');
    } finally {
      clearTimeout(timer);
    }
    const text = await response.text();
    let json = null;
    try { json = text ? JSON.parse(text) : null; } catch { json = null; }
    if (!response.ok) {
      const message = (json && (json.message || json.error)) || `${response.status} ${response.statusText}`;
      throw new ApiError('http', message, { status: response.status, body: json });
    }
    return { json, etag: response.headers.get('ETag') };
  }

  async languages() {
    const { json } = await this.request('/api/languages');
    return Array.isArray(json) ? json : (json.languages || []);
  }

  async searchSigns(q, lang, { limit = 30, signal } = {}) {
    const params = new URLSearchParams({ q, limit: String(limit) });
    if (lang) params.set('lang', lang);
    const { json } = await this.request(`/api/signs?${params}`, { signal });
    return Array.isArray(json) ? json : (json.hits || json.signs || []);
  }

  async sign(id) {
    const { json, etag } = await this.request(`/api/signs/${encodeURIComponent(id)}`);
    return { sign: json.sign || json, etag };
  }

  async lookup(text, lang, { signal } = {}) {
    const params = new URLSearchParams({ text });
    if (lang) params.set('lang', lang);
    const { json } = await this.request(`/api/lookup?${params}`, { signal });
    return json;
  }

  // Create (no id) or update (id + revision for If-Match) a sign; the server compiles the notation
  // with the same core and answers 422 with the parser's message and position when it is invalid.
  async saveSign({ id, revision, fields, token }) {
    const headers = { Authorization: `Bearer ${token}` };
    if (id !== undefined && id !== null && id !== '') {
      if (revision !== undefined && revision !== null) headers['If-Match'] = `"${revision}"`;
      const { json } = await this.request(`/api/signs/${encodeURIComponent(id)}`, { method: 'PUT', body: fields, headers });
      return json;
    }
    const { json } = await this.request('/api/signs', { method: 'POST', body: fields, headers });
    return json;
  }
}
