// Test harness for tests/server: starts the real build/native/signweave-server on a free loopback
// port (--port 0; the server prints the port it bound) with a fresh database file in a temp
// directory, filled from tests/server/fixtures/data, and an admin token from
// SIGNWEAVE_ADMIN_TOKEN. Every test talks to it over real HTTP with fetch.
//
// SIGNWEAVE_SERVER_BIN overrides the binary (e.g. a sanitizer build).
import { spawn, spawnSync } from 'node:child_process';
import { randomBytes } from 'node:crypto';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const serverBin = process.env.SIGNWEAVE_SERVER_BIN ?? path.join(repoRoot, 'build', 'native', 'signweave-server');
export const fixturesData = path.join(repoRoot, 'tests', 'server', 'fixtures', 'data');

export function makeTempDir(prefix = 'signweave-server-test-') {
  return fs.mkdtempSync(path.join(os.tmpdir(), prefix));
}

// Starts a server. Options: dir (temp dir to reuse, e.g. for a restart), data, web, models,
// token, extraArgs. Resolves to { base, port, proc, dir, db, token, stderr(), stop(), kill9() }.
export async function startServer(options = {}) {
  const dir = options.dir ?? makeTempDir();
  const db = path.join(dir, 'test.db');
  const token = options.token ?? `test-admin-${randomBytes(16).toString('hex')}`;
  const web = options.web ?? path.join(dir, 'web-missing');
  const args = ['--port', '0', '--host', '127.0.0.1', '--db', db, '--data', options.data ?? fixturesData,
    '--web', web, ...(options.models ? ['--models', options.models] : []), ...(options.extraArgs ?? [])];
  const proc = spawn(serverBin, args, {
    env: { ...process.env, SIGNWEAVE_ADMIN_TOKEN: token },
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let stdout = '';
  let stderr = '';
  proc.stderr.on('data', (chunk) => { stderr += chunk; });
  const exited = new Promise((resolve) => proc.on('exit', (code, signal) => resolve({ code, signal })));
  const port = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`server did not start in 20 s; stderr:\n${stderr}`)), 20000);
    proc.stdout.on('data', (chunk) => {
      stdout += chunk;
      const match = /listening on http:\/\/127\.0\.0\.1:(\d+)/.exec(stdout);
      if (match) { clearTimeout(timer); resolve(Number(match[1])); }
    });
    proc.on('exit', (code) => { clearTimeout(timer); reject(new Error(`server exited (${code}) before listening:\n${stderr}`)); });
  });
  const base = `http://127.0.0.1:${port}`;
  return {
    base, port, proc, dir, db, token, exited,
    stderr: () => stderr,
    auth: { Authorization: `Bearer ${token}` },
    async stop() {
      if (proc.exitCode === null && proc.signalCode === null) proc.kill('SIGTERM');
      return exited;
    },
    async kill9() {
      if (proc.exitCode === null && proc.signalCode === null) proc.kill('SIGKILL');
      return exited;
    },
  };
}

// JSON request helper: returns { status, headers, body (parsed JSON or text) }.
export async function request(server, method, urlPath, { body, headers = {}, raw = false } = {}) {
  const init = { method, headers: { ...headers } };
  if (body !== undefined) {
    init.body = typeof body === 'string' || body instanceof Uint8Array ? body : JSON.stringify(body);
    if (!('Content-Type' in init.headers)) init.headers['Content-Type'] = 'application/json';
  }
  const response = await fetch(server.base + urlPath, init);
  const text = raw ? null : await response.text();
  let parsed = text;
  if (!raw && (response.headers.get('content-type') ?? '').startsWith('application/json')) parsed = JSON.parse(text);
  return { status: response.status, headers: response.headers, body: raw ? response : parsed };
}

// The store's content fingerprint (a SHA-256 over every table) and integrity check.
export async function fingerprint(server) {
  const response = await request(server, 'GET', '/healthz?deep=1');
  if (response.status !== 200) throw new Error(`healthz deep: ${response.status} ${JSON.stringify(response.body)}`);
  return response.body.fingerprint;
}

export function sqliteIntegrity(dbPath) {
  const result = spawnSync('sqlite3', [dbPath, 'PRAGMA integrity_check;'], { encoding: 'utf8' });
  if (result.error) return null;  // sqlite3 CLI not installed: the caller uses /healthz?deep=1
  return result.stdout.trim();
}

export function sqliteQuery(dbPath, sql) {
  const result = spawnSync('sqlite3', ['-json', dbPath, sql], { encoding: 'utf8' });
  if (result.error || result.status !== 0) throw new Error(`sqlite3 failed: ${result.stderr}`);
  return result.stdout.trim() ? JSON.parse(result.stdout) : [];
}

// A notation that parses (docs/NOTATION.md); `n` varies the location so signs differ.
const levels = ['forehead', 'chin', 'chest', 'stomach', 'waist', 'shoulders', 'neck', 'nose'];
export function validNotation(n = 0) {
  return `R(H(flat), E(u), P(o), Loc(${levels[n % levels.length]}, right, touch))`;
}
