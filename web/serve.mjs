// ./run.sh web: serves the built pages on a local address and says where.
//   node web/serve.mjs SITE_DIR [PORT]
import { serve } from './static_server.mjs';

const [site, port = '8024'] = process.argv.slice(2);
const server = await serve(site, Number(port));
console.log(`run.sh: the lessons are at ${server.url}  (Ctrl-C stops)`);
console.log(`run.sh: ${site} is static files: copy it to any web server to put them online`);
