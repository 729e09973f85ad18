// The site's index and README pages (web/make_index.mjs), built from this checkout into a
// temporary folder: every README is an HTML page (headings, tables and pictures rendered, no
// markdown left showing), every link and picture in them leads to a file of the site (and an
// anchor to a heading there), and the index shows each lesson's own picture from the top
// README's table, says where to start and no longer says the truth is native only.
// No build and no browser.
//   node web/tests/site_test.mjs
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const lessons = fs.readdirSync(root).filter((d) => /^[0-9][0-9]_/.test(d) &&
                                                fs.existsSync(path.join(root, d, 'main.cpp'))).sort();
const site = fs.mkdtempSync(path.join(os.tmpdir(), 'site_'));
let failures = 0;
const fail = (what) => { console.log('FAIL ' + what); ++failures; };

execFileSync(process.execPath, [path.join(root, 'web/make_index.mjs'), root, site, ...lessons]);

const pages = [];
const walk = (dir) => {
  for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) walk(p);
    else if (p.endsWith('.html')) pages.push(p);
  }
};
walk(site);

const ids = (html) => new Set([...html.matchAll(/\sid="([^"]+)"/g)].map((m) => m[1]));
const decode = (s) => s.replace(/&amp;/g, '&').replace(/&quot;/g, '"');
let links = 0;
for (const file of pages) {
  const html = fs.readFileSync(file, 'utf8');
  const name = path.relative(site, file);
  for (const [, attr, raw] of html.matchAll(/\s(href|src)="([^"]*)"/g)) {
    const url = decode(raw);
    if (/^(data:|[a-z]+:\/\/|mailto:)/i.test(url)) continue;
    // The lesson pages themselves (NN.html) are emscripten's, not built here.
    if (/^(\.\.\/)*[0-9][0-9]_[a-z0-9_]+\.html(\?.*)?$/.test(url)) continue;
    ++links;
    const [target, anchor] = url.split('#');
    const there = target ? path.resolve(path.dirname(file), target) : file;
    if (!fs.existsSync(there)) { fail(`${name}: ${attr}="${url}" leads nowhere`); continue; }
    if (anchor && there.endsWith('.html') && !ids(fs.readFileSync(there, 'utf8')).has(anchor)) {
      fail(`${name}: ${attr}="${url}": no heading #${anchor} there`);
    }
  }
}
if (links < 100) fail(`only ${links} local links and pictures in ${pages.length} pages`);

for (const lesson of lessons) {
  const file = path.join(site, 'lessons', lesson, 'README.html');
  if (!fs.existsSync(file)) { fail(`${lesson}: no README.html`); continue; }
  const html = fs.readFileSync(file, 'utf8');
  const body = html.replace(/<pre>[\s\S]*?<\/pre>/g, '').replace(/<code>[\s\S]*?<\/code>/g, '')
                   .replace(/<!--[\s\S]*?-->/g, '');
  if (!/<h1 id="[^"]+">/.test(html)) fail(`${lesson}: README.html has no <h1>`);
  if (!/<img src="pictures\/[^"]+\.png"/.test(html)) fail(`${lesson}: README.html shows no picture`);
  if (/^#{1,4} |^\|---|!\[[^\]]*\]\(/m.test(body)) fail(`${lesson}: markdown left in README.html`);
  if (/<table>/.test(fs.readFileSync(path.join(root, lesson, 'README.md'), 'utf8')) === false &&
      /^\|.*\|$/m.test(fs.readFileSync(path.join(root, lesson, 'README.md'), 'utf8')) &&
      !/<table>/.test(html)) {
    fail(`${lesson}: its README's table is not a <table>`);
  }
}

const index = fs.readFileSync(path.join(site, 'index.html'), 'utf8');
if (/native only/.test(index)) fail('index: still says the truth is native only');
if (!/Start with <a href="01_projected_planar\.html">/.test(index)) fail('index: does not say where to start');
const readme = fs.readFileSync(path.join(root, 'README.md'), 'utf8');
const shown = [];
for (const lesson of lessons) {
  const row = readme.split('\n').find((l) => l.startsWith(`| [${lesson}]`));
  const picture = row && /\]\(([^)]+\.png)\)/.exec(row.split('|')[2])?.[1];
  if (!picture) { fail(`README.md: no row with a picture for ${lesson}`); continue; }
  const src = `lessons/${lesson}/${picture.slice(lesson.length + 1)}`;
  if (!index.includes(`<img src="${src}"`)) fail(`index: ${lesson} does not show ${src}`);
  shown.push(src);
}
if (new Set(shown).size !== shown.length) fail('index: two lessons show the same picture');

fs.rmSync(site, { recursive: true, force: true });
console.log(failures ? `site: ${failures} failures` : `site: ok (${pages.length} pages, ${links} links)`);
process.exit(failures ? 1 : 0);
