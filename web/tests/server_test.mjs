// The pages' server (ctest WebServer): `node web/serve.mjs SITE PORT`, the server `./run.sh web`
// gives a student, on a small site made here (no build, no browser), asked what a careless or
// hostile visitor asks (issue 31):
//  - a request that does not decode (`/%`), a NUL (`/index.html%00.png`), a broken UTF-8
//    sequence, an unparsable request line, a POST: 400/404/405 for that request, and the same
//    server still serves the next one;
//  - `..` in every spelling (`/../`, `%2e%2e`, `..%2f`, `..%5c`), and symbolic links inside the
//    site to a file or folder outside it: never the file outside;
//  - `/` and a folder serve their index.html as text/html, a folder without its slash is
//    redirected to it (relatively: `//sub` never leaves the site); .html .js .mjs .wasm .md .png .json .css .data each get their type;
//  - the command line: a port that is no port (exit 2), a port in use (exit 1), no site or a
//    folder without index.html (exit 2) each say so in one line, with no stack trace and no
//    address announced.
//
//   node web/tests/server_test.mjs
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const serveScript = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', 'serve.mjs');
let failures = 0;
const fail = (what) => { console.log(`FAIL ${what}`); ++failures; };

// The site: one file of each type the pages have, a folder with its own index, and links out.
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'shadows-server-'));
const site = path.join(tmp, 'site');
const kIndex = '<!doctype html><title>index</title>';
const kSecret = 'SECRET outside the site';
fs.mkdirSync(path.join(site, 'sub'), { recursive: true });
fs.writeFileSync(path.join(site, 'index.html'), kIndex);
fs.writeFileSync(path.join(site, 'sub', 'index.html'), '<!doctype html><title>sub</title>');
fs.writeFileSync(path.join(tmp, 'secret.txt'), kSecret);
const kTypes = {
  'a.html': 'text/html', 'a.js': 'text/javascript', 'a.mjs': 'text/javascript',
  'a.wasm': 'application/wasm', 'a.md': 'text/markdown; charset=utf-8', 'a.png': 'image/png',
  'a.json': 'application/json', 'a.css': 'text/css', 'a.data': 'application/octet-stream',
};
for (const file of Object.keys(kTypes)) fs.writeFileSync(path.join(site, file), `contents of ${file}`);
fs.symlinkSync(path.join(tmp, 'secret.txt'), path.join(site, 'leak.txt'));
fs.symlinkSync(tmp, path.join(site, 'out'));
fs.symlinkSync('index.html', path.join(site, 'alias.html'));  // inside: served

// One request, its path sent as written (no normalizing): { status, headers, body } or { error }.
function request(base, target, method = 'GET') {
  return new Promise((resolve) => {
    const req = http.request({ host: '127.0.0.1', port: base.port, path: target, method, agent: false },
      (res) => {
        let body = '';
        res.setEncoding('latin1');
        res.on('data', (d) => { body += d; });
        res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body }));
        res.on('error', (e) => resolve({ error: e.code ?? e.message }));
      });
    req.setTimeout(5000, () => req.destroy(new Error('no answer in 5 s')));
    req.on('error', (e) => resolve({ error: e.code ?? e.message }));
    req.end();
  });
}

// `node web/serve.mjs SITE 0` (any free port), running; restarted by alive() once it has died,
// so each request's check below stands on its own.
let server = null;
async function start() {
  const proc = spawn(process.execPath, [serveScript, site, '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  const state = { proc, port: 0, output: '', exited: false };
  proc.on('exit', () => { state.exited = true; });
  const collect = (d) => { state.output += d; };
  proc.stderr.on('data', collect);
  await new Promise((resolve) => {
    const timer = setTimeout(resolve, 10000);
    proc.stdout.on('data', (d) => {
      collect(d);
      const m = state.output.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (m && !state.port) { state.port = Number(m[1]); clearTimeout(timer); resolve(); }
    });
    proc.on('exit', () => { clearTimeout(timer); resolve(); });
  });
  if (!state.port) throw new Error(`serve.mjs did not start: ${state.output}`);
  return state;
}
// After `what`: the server still answers; if not, what it said as it died, and a new one.
async function alive(what) {
  const r = await request(server, '/index.html');
  if (r.status === 200 && !server.exited) return;
  await new Promise((res) => setTimeout(res, 200));  // its last words
  const last = server.output.split('\n').filter((l) => /Error|error/.test(l))[0] ?? r.error;
  fail(`after ${what} the server no longer serves (${last})`);
  server.proc.kill();
  server = await start();
}

server = await start();

// ---------------------------------------------------------------- bad requests (issue 31, 1)
const kBad = ['/%', '/index.html%00.png', '/%E0%A4%A', '/%zz', '/index.html%5c..%5c..%5csecret.txt'];
for (const target of kBad) {
  const r = await request(server, target);
  if (!(r.status >= 400 && r.status < 500)) fail(`GET ${target}: ${r.status ?? r.error}, not 400/404`);
  await alive(`GET ${target}`);
}
const post = await request(server, '/', 'POST');
if (post.status !== 405) fail(`POST /: ${post.status ?? post.error}, not 405`);
await alive('POST /');
// What Node's parser itself rejects: that connection closed, the server not.
await new Promise((resolve) => {
  const socket = net.connect(server.port, '127.0.0.1', () => socket.write('GET /\0 HTTP/1.1\r\nHost: x\r\n\r\n'));
  socket.on('data', () => {});
  socket.on('close', resolve);
  socket.on('error', resolve);
  socket.setTimeout(3000, () => socket.destroy());
});
await alive('an unparsable request line');

// ---------------------------------------------------------------- out of the site
const kOutside = ['/../secret.txt', '/%2e%2e/secret.txt', '/%2E%2E/secret.txt', '/..%2fsecret.txt',
  '/%2e%2e%2fsecret.txt', '/sub/../../secret.txt', '/sub/%2e%2e/%2e%2e/secret.txt', '/..%5csecret.txt',
  '//../secret.txt', '/leak.txt', '/out/secret.txt', '/out/', '/sub/../out/secret.txt'];
for (const target of kOutside) {
  const r = await request(server, target);
  if (r.status === 200 || (r.body ?? '').includes('SECRET')) {
    fail(`GET ${target}: ${r.status}, the file outside the site served`);
  } else if (!(r.status >= 400 && r.status < 500)) {
    fail(`GET ${target}: ${r.status ?? r.error}, not refused (400/403/404)`);
  }
  await alive(`GET ${target}`);
}
const alias = await request(server, '/alias.html');
if (alias.status !== 200 || alias.body !== kIndex) fail(`GET /alias.html (a link inside the site): ${alias.status ?? alias.error}`);

// ---------------------------------------------------------------- index and types (issue 31, 2)
const media = (r) => (r.headers?.['content-type'] ?? '').split(';')[0].trim();
for (const [target, body] of [['/', kIndex], ['/?view=shaded', kIndex], ['/sub/', 'sub']]) {
  const r = await request(server, target);
  if (r.status !== 200 || media(r) !== 'text/html' || !r.body.includes(body)) {
    fail(`GET ${target}: ${r.status ?? r.error} ${r.headers?.['content-type']}, not its index.html as text/html`);
  }
}
const head = await request(server, '/', 'HEAD');
if (head.status !== 200 || media(head) !== 'text/html' || head.body !== '') {
  fail(`HEAD /: ${head.status ?? head.error} ${head.headers?.['content-type']}, not text/html without a body`);
}
// A folder's redirect is relative to the folder's own address (`./sub/`), so it stays on this
// site whatever the request's path: `//sub` or `/%2fsub` must never send a browser to the host
// `sub` (`Location: //sub/`, issue 53), and a site served under a prefix keeps its prefix.
for (const [target, location] of [['/sub?x=1', './sub/?x=1'], ['//sub', './sub/'], ['/%2fsub', './sub/'],
  ['///sub', './sub/'], ['/sub//sub', null], ['/%2f%2fsub', './sub/']]) {
  const r = await request(server, target);
  const where = r.headers?.location;
  if (location === null) {
    if (r.status === 301 && !where?.startsWith('./')) fail(`GET ${target}: 301 to ${where}, off the site`);
    continue;
  }
  if (r.status !== 301 || where !== location) {
    fail(`GET ${target}: ${r.status ?? r.error} to ${where}, not 301 to ${location}`);
  }
  const followed = new URL(where ?? '', `http://127.0.0.1:${server.port}${target}`);
  if (followed.host !== `127.0.0.1:${server.port}`) fail(`GET ${target}: its redirect leaves the site for ${followed.host}`);
}
// Near misses of containment: a sibling folder whose name begins with the site's, a link to it,
// and separators spelt as escapes.
const sibling = `${site}2`;
fs.mkdirSync(sibling);
fs.writeFileSync(path.join(sibling, 'secret.txt'), kSecret);
fs.symlinkSync(sibling, path.join(site, 'twin'));
for (const target of ['/twin/secret.txt', '/twin/', '/%2e%2e%2fsite2%2fsecret.txt', '/..%2Fsite2/secret.txt',
  '/twin%2fsecret.txt', '/sub/..%2f..%2fsite2%2fsecret.txt']) {
  const r = await request(server, target);
  if (r.status === 200 || (r.body ?? '').includes('SECRET')) fail(`GET ${target}: the sibling folder's file served`);
  await alive(`GET ${target}`);
}
for (const [file, type] of Object.entries(kTypes)) {
  const r = await request(server, `/${file}`);
  const got = type.includes(';') ? r.headers?.['content-type'] : media(r);
  if (r.status !== 200 || got !== type || r.body !== `contents of ${file}`) {
    fail(`GET /${file}: ${r.status ?? r.error} ${r.headers?.['content-type']}, not ${type}`);
  }
}
const missing = await request(server, '/no_such_page.html');
if (missing.status !== 404) fail(`GET /no_such_page.html: ${missing.status ?? missing.error}, not 404`);
if (/URIError|Error:/.test(server.output)) fail(`the server printed an error: ${server.output.trim()}`);

// ---------------------------------------------------------------- the command line
// `args` must end at once with `status` and one line saying `says`, no address, no stack trace.
function refuses(args, status, says, what) {
  const r = spawnSync(process.execPath, [serveScript, ...args], { encoding: 'utf8', timeout: 10000 });
  const lines = `${r.stdout}${r.stderr}`.split('\n').filter((l) => l.trim() !== '');
  const shown = JSON.stringify(lines.slice(0, 3).join(' | ')).slice(0, 300);
  if (r.error || r.signal) {
    fail(`serve.mjs ${args.join(' ')} (${what}): still running after 10 s: ${shown}`);
  } else if (r.status !== status || lines.length !== 1 || !says.test(lines[0]) ||
             /lessons are at|^\s+at /m.test(`${r.stdout}${r.stderr}`)) {
    fail(`serve.mjs ${args.join(' ')} (${what}): exit ${r.status} and ${lines.length} lines ${shown}; ` +
         `expected exit ${status} and one line matching ${says}`);
  }
}
refuses([site, 'abc'], 2, /abc/, 'a port that is no port');
refuses([site, '70000'], 2, /70000/, 'a port above 65535');
refuses([site, String(server.port)], 1, new RegExp(`${server.port}.*in use`), 'a port in use');
refuses([path.join(tmp, 'no_such_site'), '0'], 2, /no_such_site/, 'no such site');
fs.mkdirSync(path.join(tmp, 'empty'));
refuses([path.join(tmp, 'empty'), '0'], 2, /index\.html/, 'a folder without index.html');
refuses([], 2, /usage/, 'no arguments');

server.proc.kill();
fs.rmSync(tmp, { recursive: true, force: true });
if (failures) {
  console.log(`web server: ${failures} failures`);
  process.exit(1);
}
console.log('web server: ok');
