// ./run.sh web: serves the built pages on a local address and says where.
//   node web/serve.mjs SITE_DIR [PORT]
// PORT: 1-65535 (default 8024), or 0 for any free one. What goes wrong before the first page is
// served is one line: exit 2 for what was asked (no such site, a site without index.html, a port
// that is no port), 1 for what the machine refuses (the port in use, or not ours to take).
import fs from 'node:fs';
import path from 'node:path';
import { serve } from './static_server.mjs';

const args = process.argv.slice(2);
const stop = (status, line) => {
  console.error(`serve.mjs: ${line}`);
  process.exit(status);
};
if (args.length < 1 || args.length > 2 || args[0] === '') {
  stop(2, 'usage: node web/serve.mjs SITE_DIR [PORT]  (./run.sh web [PORT] builds and serves the pages)');
}
const [site, portText = '8024'] = args;
if (!/^[0-9]{1,5}$/.test(portText) || Number(portText) > 65535) {
  stop(2, `'${portText}' is not a port: give a number from 1 to 65535 (0: any free one)`);
}
const port = Number(portText);
if (!fs.existsSync(site) || !fs.statSync(site).isDirectory()) {
  stop(2, `no site at ${site}: build it with scripts/setup_pages.sh (./run.sh web does)`);
}
if (!fs.existsSync(path.join(site, 'index.html'))) {
  stop(2, `${site} has no index.html: not a built site (scripts/setup_pages.sh builds one)`);
}

let server;
try {
  server = await serve(site, port);
} catch (e) {
  if (e.code === 'EADDRINUSE') stop(1, `port ${port} is in use: stop what serves there, or pass another port`);
  if (e.code === 'EACCES') stop(1, `port ${port} is not ours to take (below 1024?): pass another port`);
  stop(1, `cannot serve ${site} on port ${port}: ${e.message}`);
}
console.log(`run.sh: the lessons are at ${server.url}  (Ctrl-C stops)`);
console.log(`run.sh: ${site} is static files: copy it to any web server to put them online`);
