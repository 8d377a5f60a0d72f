// Notation editor: bad notation is underlined at the parser's position with its message; good
// notation previews (the core synthesises and the avatar plays it) as you type.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import { TEST_TOKEN, launchBrowser, openPage, screenshot, startServer } from './harness.mjs';

let server, browser;
before(async () => { server = await startServer(); browser = await launchBrowser(); });
after(async () => { await browser?.close(); await server?.stop(); });

// The seed's letter В (docs/NOTATION.md).
const GOOD = 'R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))';

test('a parse error is underlined at its position with the message, and good notation previews', async () => {
  const { page, problems } = await openPage(browser, server.base, '#/editor');
  await page.selectOption('#editor-format', 'formula');
  // "Q7" is no item of a hand term: the error must be marked on it, not elsewhere.
  const bad = 'R(L1(0), Q7, F_0^2(1))';
  await page.fill('#editor-text', bad);
  await page.waitForSelector('#editor-diagnostics li.error', { timeout: 10_000 });
  const shown = await page.evaluate(() => ({
    marks: [...document.querySelectorAll('#editor-highlight mark')].map((m) => ({ text: m.textContent, point: m.classList.contains('point') })),
    before: document.getElementById('editor-highlight').textContent,
    messages: [...document.querySelectorAll('#editor-diagnostics li.error')].map((li) => li.textContent),
    invalid: document.getElementById('editor-text').getAttribute('aria-invalid'),
  }));
  assert.ok(shown.marks.length >= 1, 'an error is marked in the overlay');
  assert.ok(shown.messages[0].length > 10, `a message is shown: ${shown.messages[0]}`);
  assert.match(shown.messages[0], /line 1, column \d+/);
  const column = Number(shown.messages[0].match(/column (\d+)/)[1]);
  const at = bad.indexOf('Q7');
  assert.ok(Math.abs(column - 1 - at) <= 2, `the error is reported at column ${column}, 'Q7' is at ${at + 1}`);
  if (!shown.marks[0].point) assert.ok(bad.includes(shown.marks[0].text), 'the mark covers text of the input');
  assert.equal(shown.invalid, 'true');
  // The overlay holds exactly the same text as the textarea (or the marks would drift).
  assert.equal(shown.before.replace('\u200b', '').replace(/ $/, ''), bad.replace(/ $/, ''));
  await screenshot(page, 'editor-error.png');

  await page.fill('#editor-text', GOOD);
  await page.waitForSelector('#editor-diagnostics li.ok', { timeout: 10_000 });
  await page.waitForFunction(() => window.signweave.state.playing && window.signweave.state.clipDuration_s > 0);
  assert.equal(await page.$$eval('#editor-highlight mark', (m) => m.length), 0, 'no marks for good notation');
  assert.equal(await page.getAttribute('#editor-text', 'aria-invalid'), 'false');
  await page.waitForTimeout(600);
  await screenshot(page, 'editor-preview.png');
  assert.deepEqual(problems, []);
});

test('saving without a token is refused in the page with a clear message', async () => {
  const { page } = await openPage(browser, server.base, '#/editor');
  await page.fill('#editor-text', GOOD);
  await page.click('.save summary');
  await page.fill('#editor-gloss', 'TEST-V');
  await page.click('#editor-save');
  assert.match(await page.textContent('#editor-save-status'), /token/i);
  await page.fill('#editor-token', 'not-a-real-token');
  await page.click('#editor-save');
  await page.waitForFunction(() => /refused|Not saved/.test(document.getElementById('editor-save-status').textContent), null, { timeout: 10_000 });
});

test('a new sign is saved with a token, edited with If-Match, and a stale edit is refused', async () => {
  const { page } = await openPage(browser, server.base, '#/editor');
  await page.fill('#editor-text', GOOD);
  await page.click('.save summary');
  await page.fill('#editor-gloss', 'BROWSER-TEST-V');
  await page.fill('#editor-keywords', 'browsertestword');
  await page.fill('#editor-token', TEST_TOKEN);
  await page.click('#editor-save');
  await page.waitForFunction(() => /Saved as sign \d+/.test(document.getElementById('editor-save-status').textContent), null, { timeout: 10_000 });
  const id = Number((await page.textContent('#editor-save-status')).match(/sign (\d+)/)[1]);
  const stored = await (await fetch(`${server.base}/api/signs/${id}`)).json();
  assert.equal(stored.gloss, 'BROWSER-TEST-V');
  assert.equal(stored.notation, GOOD);

  // An edit in the page is a PUT on the revision it started from.
  const edited = GOOD.replace('F_0^1(0.5)', 'F_0^1(0.7)');
  await page.fill('#editor-text', edited);
  await page.click('#editor-save');
  await page.waitForFunction((n) => document.getElementById('editor-save-status').textContent === `Saved as sign ${n}.`, id);
  const after = await (await fetch(`${server.base}/api/signs/${id}`)).json();
  assert.equal(after.notation, edited);
  assert.equal(after.revision, stored.revision + 1);

  // Someone else changes the sign; the page's next save must be refused, not lost.
  const other = await fetch(`${server.base}/api/signs/${id}`, {
    method: 'PUT',
    headers: { 'Content-Type': 'application/json', Authorization: `Bearer ${TEST_TOKEN}`, 'If-Match': `"${after.revision}"` },
    body: JSON.stringify({ gloss: 'BROWSER-TEST-V', notation: GOOD, format: 'formula' }),
  });
  assert.equal(other.status, 200);
  await page.fill('#editor-text', edited.replace('F_0^1(0.7)', 'F_0^1(0.9)'));
  await page.click('#editor-save');
  await page.waitForFunction(() => /changed this sign/.test(document.getElementById('editor-save-status').textContent), null, { timeout: 10_000 });
  assert.equal((await (await fetch(`${server.base}/api/signs/${id}`)).json()).notation, GOOD, 'the other edit is kept');
});
