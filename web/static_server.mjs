// The static file server of the pages: the one `./run.sh web` (web/serve.mjs) gives a student
// and the one the browser tests and the web benchmark load the pages from. Node's standard
// library only.
//
// A bad request costs only its own answer: a path that does not decode (`/%`), one with a NUL
// or a backslash, `..` in any spelling (`/../`, `%2e%2e`, `..%2f`) get 400; a file outside the
// site, also through a symbolic link, is not found (404); a method other than GET and HEAD gets
// 405. `/` and any folder serve their index.html (a folder named without its slash is
// redirected to it, relatively, so the page's relative links work and the redirect stays on the
// site), with the type its extension says.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

export const kTypes = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8', '.wasm': 'application/wasm',
  '.data': 'application/octet-stream', '.png': 'image/png', '.md': 'text/markdown; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.json': 'application/json', '.svg': 'image/svg+xml',
  '.txt': 'text/plain; charset=utf-8', '.csv': 'text/csv; charset=utf-8',
};

// The decoded path of a request's target (`/a/b.html` of `/a/b.html?x=1`), or null when it is
// not one a careful server answers: not absolute, not decodable, a NUL, a backslash, a `..`.
export function requestPath(target) {
  const raw = String(target ?? '').split(/[?#]/, 1)[0];
  if (!raw.startsWith('/')) return null;
  let decoded;
  try {
    decoded = decodeURIComponent(raw);
  } catch (e) {  // URIError: `%`, `%zz`, a broken UTF-8 sequence
    return null;
  }
  if (/[\0\\]/.test(decoded)) return null;
  if (decoded.split('/').includes('..')) return null;
  return decoded;
}

// Serves `root` on 127.0.0.1 (`port`, or a free one with 0); resolves to { url, port, close() },
// rejects when the port cannot be had (error.code EADDRINUSE, EACCES) or `root` is no folder.
// Paths matching `hide` (a RegExp, tried on the decoded path) are not found, as on a server
// missing those files.
export async function serve(root, port = 0, hide = null) {
  const base = await fs.promises.realpath(path.resolve(root));
  if (!(await fs.promises.stat(base)).isDirectory()) throw new Error(`${root} is not a folder`);
  const inside = (file) => file === base || file.startsWith(base + path.sep);

  const answer = (req, res, status, text, headers = {}) => {
    const body = Buffer.from(text + '\n');
    res.writeHead(status, { 'Content-Type': 'text/plain; charset=utf-8',
                            'Content-Length': body.length, ...headers });
    res.end(req.method === 'HEAD' ? undefined : body);
  };

  async function handle(req, res) {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      return answer(req, res, 405, 'only GET and HEAD', { Allow: 'GET, HEAD' });
    }
    const rel = requestPath(req.url);
    if (rel === null) return answer(req, res, 400, 'bad request');
    if (hide && hide.test(rel)) return answer(req, res, 404, 'not found');
    let file;
    let stat;
    try {
      // Where it really is, every link followed: it must still be inside the site.
      file = await fs.promises.realpath(path.join(base, rel));
      if (!inside(file)) return answer(req, res, 404, 'not found');
      stat = await fs.promises.stat(file);
      if (stat.isDirectory()) {
        if (!rel.endsWith('/')) {
          const query = req.url.slice(req.url.split(/[?#]/, 1)[0].length);
          // Relative to the folder's own address (`./name/`): never `//host/`, however many
          // slashes the request had (an open redirect), and a site under a prefix keeps it.
          const name = rel.split('/').filter((part) => part !== '').pop() ?? '';
          const location = `./${encodeURIComponent(name)}/${query}`;
          return answer(req, res, 301, 'moved', { Location: location });
        }
        file = await fs.promises.realpath(path.join(file, 'index.html'));
        if (!inside(file)) return answer(req, res, 404, 'not found');
        stat = await fs.promises.stat(file);
      }
    } catch (e) {  // ENOENT, ENOTDIR, ELOOP, EACCES...: nothing to serve there
      return answer(req, res, 404, 'not found');
    }
    if (!stat.isFile()) return answer(req, res, 404, 'not found');
    const data = await fs.promises.readFile(file);
    res.writeHead(200, {
      'Content-Type': kTypes[path.extname(file).toLowerCase()] || 'application/octet-stream',
      'Content-Length': data.length,
      'X-Content-Type-Options': 'nosniff',
      'Cache-Control': 'no-cache',
    });
    res.end(req.method === 'HEAD' ? undefined : data);
  }

  const server = http.createServer((req, res) => {
    handle(req, res).catch((e) => {  // a file that vanished while read, say: this request only
      if (res.headersSent) res.destroy();
      else answer(req, res, 500, `server error: ${e.code ?? e.message}`);
    });
  });
  // A request Node cannot even parse: 400 and that connection closed, the server goes on.
  server.on('clientError', (e, socket) => {
    if (socket.writable && !socket.destroyed) socket.end('HTTP/1.1 400 Bad Request\r\nConnection: close\r\n\r\n');
    else socket.destroy();
  });
  await new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', () => {
      server.off('error', reject);
      resolve();
    });
  });
  const actual = server.address().port;
  return {
    url: `http://127.0.0.1:${actual}/`,
    port: actual,
    close: () => new Promise((r) => {
      server.close(r);
      server.closeAllConnections?.();
    }),
  };
}
