// Server benchmark: a bounded wrk load on loopback against build/native/signweave-server, and the
// same load against nginx serving the same sign JSON as a static file (the "within 2x of nginx"
// comparison of issue 5). Prints JSON lines {"name", "value", "unit"} like every benchmark.
//
//   node bench/server_bench.mjs           (./signweave bench runs it)
//   SIGNWEAVE_BENCH_SECONDS=10 SIGNWEAVE_BENCH_CONNECTIONS=64 SIGNWEAVE_BENCH_THREADS=2
//
// The server gets a temp database filled from data/ (tests/server/fixtures/data if data/ is
// missing). wrk and the servers share the machine's cores, as they would on a small host; the
// figures are for loopback, keep-alive, no TLS.
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const serverBin = process.env.SIGNWEAVE_SERVER_BIN ?? path.join(root, 'build', 'native', 'signweave-server');
const seconds = Number(process.env.SIGNWEAVE_BENCH_SECONDS ?? 10);
const connections = Number(process.env.SIGNWEAVE_BENCH_CONNECTIONS ?? 64);
const threads = Number(process.env.SIGNWEAVE_BENCH_THREADS ?? 2);

function emit(name, value, unit, extra = {}) {
  console.log(JSON.stringify({ name, value: Number.isFinite(value) ? Math.round(value * 100) / 100 : value, unit, ...extra }));
}

function have(command) {
  return spawnSync('sh', ['-c', `command -v ${command}`]).status === 0;
}

function findNginx() {
  for (const candidate of ['/usr/sbin/nginx', '/usr/bin/nginx']) if (fs.existsSync(candidate)) return candidate;
  return have('nginx') ? 'nginx' : null;
}

function freePort() {
  return new Promise((resolve, reject) => {
    const probe = net.createServer();
    probe.listen(0, '127.0.0.1', () => {
      const { port } = probe.address();
      probe.close(() => resolve(port));
    });
    probe.on('error', reject);
  });
}

// wrk's text report -> requests/s and p99 latency in milliseconds.
function runWrk(url, duration_s = seconds) {
  const result = spawnSync('wrk', [`-t${threads}`, `-c${connections}`, `-d${duration_s}s`, '--latency', url], { encoding: 'utf8' });
  if (result.status !== 0) throw new Error(`wrk failed: ${result.stderr}`);
  const rps = Number(/Requests\/sec:\s+([\d.]+)/.exec(result.stdout)?.[1]);
  const p99Match = /\s99%\s+([\d.]+)(us|ms|s)\b/.exec(result.stdout);
  const scale = { us: 0.001, ms: 1, s: 1000 };
  const p99 = p99Match ? Number(p99Match[1]) * scale[p99Match[2]] : NaN;
  const non2xx = Number(/Non-2xx or 3xx responses:\s+(\d+)/.exec(result.stdout)?.[1] ?? 0);
  const errors = /Socket errors:([^\n]*)/.exec(result.stdout)?.[1]?.trim() ?? '';
  return { rps, p99, non2xx, errors };
}

async function startServer(dir) {
  const data = fs.existsSync(path.join(root, 'data', 'languages.json')) ? path.join(root, 'data') : path.join(root, 'tests', 'server', 'fixtures', 'data');
  const proc = spawn(serverBin, ['--port', '0', '--db', path.join(dir, 'bench.db'), '--data', data, '--web', path.join(root, 'web')], { stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '';
  const port = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('server did not start')), 30000);
    proc.stdout.on('data', (chunk) => {
      stdout += chunk;
      const match = /listening on http:\/\/127\.0\.0\.1:(\d+)/.exec(stdout);
      if (match) { clearTimeout(timer); resolve(Number(match[1])); }
    });
    proc.stderr.resume();
    proc.on('exit', (code) => { clearTimeout(timer); reject(new Error(`server exited ${code}`)); });
  });
  return { proc, port };
}

async function startNginx(nginx, dir, urlPath, body) {
  const port = await freePort();
  const docroot = path.join(dir, 'nginx-root');
  fs.mkdirSync(path.join(docroot, path.dirname(urlPath)), { recursive: true });
  fs.writeFileSync(path.join(docroot, urlPath), body);
  fs.mkdirSync(path.join(dir, 'nginx-tmp'), { recursive: true });
  // Workers drop to an unprivileged user when started as root: let them read the files.
  for (let p = path.join(docroot, urlPath); p.startsWith(dir); p = path.dirname(p)) fs.chmodSync(p, fs.statSync(p).isDirectory() ? 0o755 : 0o644);
  // nginx tuned as a fair static baseline: as many workers as cores, keep-alive, no access log,
  // sendfile, the file's MIME type application/json.
  const conf = `
worker_processes ${os.cpus().length};
daemon off;
master_process on;
pid ${dir}/nginx.pid;
error_log ${dir}/nginx-error.log warn;
events { worker_connections 1024; }
http {
  access_log off;
  sendfile on;
  tcp_nopush on;
  keepalive_requests 100000;
  client_body_temp_path ${dir}/nginx-tmp/body;
  proxy_temp_path ${dir}/nginx-tmp/proxy;
  fastcgi_temp_path ${dir}/nginx-tmp/fastcgi;
  uwsgi_temp_path ${dir}/nginx-tmp/uwsgi;
  scgi_temp_path ${dir}/nginx-tmp/scgi;
  default_type application/json;
  server {
    listen 127.0.0.1:${port};
    root ${docroot};
  }
}`;
  fs.writeFileSync(path.join(dir, 'nginx.conf'), conf);
  const proc = spawn(nginx, ['-c', path.join(dir, 'nginx.conf'), '-p', dir], { stdio: ['ignore', 'ignore', 'pipe'] });
  for (let attempt = 0; attempt < 50; ++attempt) {
    try {
      const response = await fetch(`http://127.0.0.1:${port}${urlPath}`);
      if (response.status === 200) return { proc, port };
    } catch { /* not up yet */ }
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
  proc.kill('SIGTERM');
  throw new Error(`nginx did not start: ${fs.existsSync(path.join(dir, 'nginx-error.log')) ? fs.readFileSync(path.join(dir, 'nginx-error.log'), 'utf8') : ''}`);
}

async function stop(proc) {
  if (proc.exitCode !== null || proc.signalCode !== null) return;
  const exited = new Promise((resolve) => proc.on('exit', resolve));
  proc.kill('SIGTERM');
  await exited;
}

async function main() {
  if (!fs.existsSync(serverBin)) { emit('server_bench_skipped', 0, 'none', { reason: `${serverBin} not built` }); return; }
  if (!have('wrk')) { emit('server_bench_skipped', 0, 'none', { reason: 'wrk not installed' }); return; }
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'signweave-bench-'));
  fs.chmodSync(dir, 0o755);
  const server = await startServer(dir);
  let nginx = null;
  try {
    const base = `http://127.0.0.1:${server.port}`;
    const found = await (await fetch(`${base}/api/signs?q=hello&limit=1`)).json();
    const id = found.hits[0]?.id ?? 1;
    const signPath = `/api/signs/${id}`;
    const signBody = await (await fetch(base + signPath)).text();

    // Warm-up (not measured): the server opens its pooled SQLite connections and compiles its
    // statements on first use; a cold start would show up as a tail in p99.
    runWrk(base + signPath, 2);
    const fetchResult = runWrk(base + signPath);
    emit('server_sign_fetch_rps', fetchResult.rps, 'req/s', { connections, threads, seconds, bytes: signBody.length });
    emit('server_sign_fetch_p99', fetchResult.p99, 'ms');
    if (fetchResult.non2xx || fetchResult.errors) emit('server_sign_fetch_errors', fetchResult.non2xx, 'responses', { socket: fetchResult.errors });

    const searchResult = runWrk(`${base}/api/signs?q=he&lang=ase`);
    emit('server_search_rps', searchResult.rps, 'req/s', { query: 'q=he&lang=ase' });
    emit('server_search_p99', searchResult.p99, 'ms');

    const lookupResult = runWrk(`${base}/api/lookup?lang=ase&text=${encodeURIComponent('Hello, thank you! My name is Bob.')}`);
    emit('server_lookup_rps', lookupResult.rps, 'req/s');
    emit('server_lookup_p99', lookupResult.p99, 'ms');

    const nginxBin = findNginx();
    if (!nginxBin) {
      emit('nginx_static_skipped', 0, 'none', { reason: 'nginx not installed (apt-get install nginx-light)' });
      return;
    }
    await stop(server.proc);  // nginx gets the cores to itself, as the server did
    nginx = await startNginx(nginxBin, dir, signPath, signBody);
    runWrk(`http://127.0.0.1:${nginx.port}${signPath}`, 2);
    const nginxResult = runWrk(`http://127.0.0.1:${nginx.port}${signPath}`);
    emit('nginx_static_sign_rps', nginxResult.rps, 'req/s', { bytes: signBody.length });
    emit('nginx_static_sign_p99', nginxResult.p99, 'ms');
    emit('server_vs_nginx_rps_ratio', fetchResult.rps / nginxResult.rps, 'ratio', { target: '>= 0.5' });
  } finally {
    await stop(server.proc);
    if (nginx) await stop(nginx.proc);
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

main().catch((error) => {
  console.error(`server_bench: ${error.message}`);
  process.exitCode = 1;
});
