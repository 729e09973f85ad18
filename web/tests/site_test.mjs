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

// The students' site holds no solution (issue 55, 1): no command line of
// instructor/SOLUTIONS.md, no sentence of its answers, in any file of the site; built with
// --with-solutions, the instructor's page has them all (so the search can find them).
const solutions = [];
const answers = fs.readFileSync(path.join(root, 'instructor/SOLUTIONS.md'), 'utf8');
for (const [, text] of answers.matchAll(/^- [0-9]{2}, exercise [0-9]+: ((?:.|\n(?!- |\n))*)/gm)) {
  const words = text.replace(/`build\/[^`]*`/g, '').replace(/[`*]/g, '').replace(/\s+/g, ' ').trim();
  const commands = [...text.matchAll(/`build\/[0-9a-z_]+ (--grade [0-9]+(?: --set [^ `]+)+)`/g)].map((m) => m[1]);
  solutions.push({ words: words.slice(0, 48), commands });
}
if (solutions.length < 20) fail(`instructor/SOLUTIONS.md: only ${solutions.length} solutions read`);
const files = [];
const all = (dir) => {
  for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) all(p);
    else if (/\.(html|js|mjs|md|txt|json)$/.test(p)) files.push(p);
  }
};
const text = (file) => fs.readFileSync(file, 'utf8').replace(/<[^>]*>/g, '').replace(/&amp;/g, '&')
    .replace(/&quot;/g, '"').replace(/&#39;/g, "'").replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/\s+/g, ' ');
const leaks = (dir) => {
  files.length = 0;
  all(dir);
  const found = [];
  for (const file of files) {
    const t = text(file);
    for (const s of solutions) {
      for (const c of [s.words, ...s.commands]) {
        if (t.includes(c)) found.push(`${path.relative(dir, file)}: "${c}"`);
      }
    }
  }
  return found;
};
for (const leak of leaks(site)) fail(`the students' site carries a solution: ${leak}`);
const instructor = fs.mkdtempSync(path.join(os.tmpdir(), 'site_instructor_'));
execFileSync(process.execPath,
             [path.join(root, 'web/make_index.mjs'), root, instructor, '--with-solutions', ...lessons]);
const shownAnswers = leaks(instructor);
const expected = solutions.reduce((n, s) => n + 1 + s.commands.length, 0);
if (shownAnswers.length < expected) {
  fail(`--with-solutions: ${shownAnswers.length} of ${expected} answers found in the instructor's site`);
}
if (!fs.existsSync(path.join(instructor, 'instructor/SOLUTIONS.html'))) fail('--with-solutions wrote no SOLUTIONS.html');
fs.rmSync(instructor, { recursive: true, force: true });

fs.rmSync(site, { recursive: true, force: true });
console.log(failures ? `site: ${failures} failures` : `site: ok (${pages.length} pages, ${links} links)`);
process.exit(failures ? 1 : 0);
