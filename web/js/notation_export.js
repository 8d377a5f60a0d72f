// notation_export.js — "Export as SiGML / HamNoSys / formula" on a dictionary sign. The server
// prints the stored sign in that notation with the core's printers (GET /api/signs/{id}?format=,
// docs/API.md) and the file downloads under the name the server gives (the gloss, any script).
//
// Does not: export the editor's unsaved text (save it first; `signweave convert` does files).

import { download } from './export.js';

export const EXPORT_FORMATS = [
  { value: 'sigml', label: 'SiGML (for CWASA / JASigning)' },
  { value: 'hamnosys', label: 'HamNoSys' },
  { value: 'formula', label: 'Formula (seed 004)' },
];

// The file name of a Content-Disposition header: filename*=UTF-8''… first, then filename="…".
export function dispositionFileName(header, fallback) {
  const extended = /filename\*=UTF-8''([^;]+)/i.exec(header || '');
  if (extended) {
    try { return decodeURIComponent(extended[1]); } catch { /* malformed: try the plain name */ }
  }
  const plain = /filename="([^"]+)"/i.exec(header || '');
  return plain ? plain[1] : fallback;
}

// select: the format <select>; button: starts the download; status: where a failure is said;
// currentSign(): the sign on show ({id, gloss}) or null.
export function installNotationExport({ select, button, status, currentSign, base = '' }) {
  select.replaceChildren(...EXPORT_FORMATS.map(({ value, label }) => new Option(label, value)));
  button.addEventListener('click', async () => {
    const sign = currentSign();
    if (!sign) return;
    const format = select.value;
    status.textContent = '';
    try {
      const response = await fetch(`${base}/api/signs/${sign.id}?format=${encodeURIComponent(format)}`);
      if (!response.ok) {
        const body = await response.json().catch(() => null);
        throw new Error((body && body.error) || `${response.status} ${response.statusText}`);
      }
      const name = dispositionFileName(response.headers.get('Content-Disposition'), `sign-${sign.id}.${format}.txt`);
      download(await response.blob(), name);
      status.textContent = `Downloaded ${name}`;
    } catch (error) {
      status.textContent = `Export failed: ${error.message}`;
    }
  });
}
