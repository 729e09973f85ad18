// The students' site as one folder a course serves under a path of its own (issue 55, 2):
// scripts/publish_site.sh writes build/web/site into <tmp>/course/shadows, Python's standard
// http.server (not ours) serves <tmp>, and headless Chromium opens the index, a README page
// with its pictures and a lesson's page under /course/shadows/, until the page's truth has been
// traced by its Web Worker. The folder holds no solution unless asked (--with-solutions).
//   node web/tests/publish_test.mjs   (after the pages are built: scripts/setup_pages.sh)
import { execFileSync, spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launch, open } from './browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'published_'));
const folder = path.join(tmp, 'course', 'shadows');
let failures = 0;
const fail = (what) => { console.log('FAIL ' + what); ++failures; };

const publish = (out, ...flags) =>
  execFileSync(path.join(root, 'scripts/publish_site.sh'), [out, '--no-build', ...flags],
               { encoding: 'utf8' });
console.log(publish(folder).trim());
if (!fs.existsSync(path.join(folder, 'index.html'))) fail('no index.html published');
if (fs.existsSync(path.join(folder, 'instructor'))) fail('the students\' folder has the solutions');
for (const f of ['truth/worker.js', 'truth/truth.js', '03_shadow_map_basic.wasm', '.nojekyll']) {
  if (!fs.existsSync(path.join(folder, f))) fail(`no ${f} published`);
}
// Asked for, the instructor's copy has them; a folder of someone else's is never written over.
const instructor = path.join(tmp, 'instructor');
publish(instructor, '--with-solutions');
if (!fs.existsSync(path.join(instructor, 'instructor/SOLUTIONS.html'))) fail('--with-solutions: no SOLUTIONS.html');
fs.mkdirSync(path.join(tmp, 'theirs'));
fs.writeFileSync(path.join(tmp, 'theirs', 'notes.txt'), 'mine');
try {
  publish(path.join(tmp, 'theirs'));
  fail('published over a folder that was not ours');
} catch (e) {
  if (e.status !== 2) fail(`over a folder not ours: exit ${e.status}, not 2`);
}
if (fs.readFileSync(path.join(tmp, 'theirs', 'notes.txt'), 'utf8') !== 'mine') fail('their file changed');

// Python's http.server on any free port, serving the folder above the course's path.
const server = spawn('python3', ['-u', '-m', 'http.server', '0', '--bind', '127.0.0.1', '--directory', tmp],
                     { stdio: ['ignore', 'pipe', 'pipe'] });
const port = await new Promise((resolve, reject) => {
  let said = '';
  server.stdout.on('data', (d) => {
    said += d;
    const m = /port (\d+)/.exec(said);
    if (m) resolve(Number(m[1]));
  });
  server.on('exit', (code) => reject(new Error(`http.server exited ${code}`)));
  setTimeout(() => reject(new Error('http.server said no port')), 10000);
});
const base = `http://127.0.0.1:${port}/course/shadows/`;
const browser = await launch();
try {
  // The index and a README page, with their pictures, under the prefix.
  for (const [at, what] of [['', 'index'], ['lessons/03_shadow_map_basic/README.html', 'README']]) {
    const page = await open(browser, base + at);
    await page.waitFor('document.readyState === "complete"');
    // Fetched, not waited for: the index's pictures load lazily, below the fold.
    const pictures = await page.evaluate(
        'Promise.all([...document.images].map((i) => fetch(i.src).then((r) => r.ok && i.src.startsWith(' +
        `${JSON.stringify(base)}), () => false)))`);
    if (pictures.length === 0 || pictures.includes(false)) {
      fail(`${what}: ${pictures.filter((p) => !p).length} of ${pictures.length} pictures did not load`);
    }
    const link = await page.evaluate(
        '[...document.links].map((a) => a.href).find((h) => h.endsWith("03_shadow_map_basic.html")) ?? ""');
    if (!link.startsWith(base)) fail(`${what}: the lesson's link leaves the course's path: ${link}`);
    await page.close();
  }
  // A lesson's page, its truth traced by its worker (three-mesh-bvh) loaded from the prefix.
  const page = await open(browser, base + '03_shadow_map_basic.html?size=160x120');
  try {
    await page.waitFor('shadowsPage.truths >= 1 || shadowsPage.errors.length > 0', 180000);
  } catch (e) {
    fail(`03's page: ${e.message}`);
  }
  const state = await page.evaluate(
      '({frames: shadowsPage.frames, truths: shadowsPage.truths, glErrors: shadowsPage.glErrors, errors: shadowsPage.errors})');
  console.log(`03 under ${base}: ${state.frames} frames, ${state.truths} truth(s) traced, ` +
              `${state.glErrors} GL errors`);
  if (state.errors.length) fail(`03's page: ${state.errors.join('; ')}`);
  if (state.glErrors) fail(`03's page: ${state.glErrors} GL errors`);
  if (page.exceptions.length) fail(`03's page: ${page.exceptions.join('; ')}`);
  await page.close();
} finally {
  await browser.close();
  server.kill();
  fs.rmSync(tmp, { recursive: true, force: true });
}
console.log(failures ? `published: ${failures} failures` : 'published: ok');
process.exit(failures ? 1 : 0);
