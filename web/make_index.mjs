// Writes the site's index.html (where to start, then every lesson: its own picture, one line,
// its page and README) and each lesson's README as an HTML page beside its pictures, with the
// documents under docs/ they link to, all from the repository's own files: a lesson's line
// and picture are its row in the top README's table.
// The instructor's solutions (instructor/SOLUTIONS.md) are left out unless asked for.
//   node web/make_index.mjs REPO_ROOT SITE_DIR [--with-solutions] LESSON...
import fs from 'node:fs';
import path from 'node:path';
import { Marked } from 'marked';

const [root, site, ...rest] = process.argv.slice(2);
const withSolutions = rest.includes('--with-solutions');
const lessons = rest.filter((a) => a !== '--with-solutions');
const readme = fs.readFileSync(path.join(root, 'README.md'), 'utf8');
const escape = (s) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
// Markdown's `code` and [text](link) as plain text for one line of HTML.
const plain = (s) => s.replace(/\[([^\]]*)\]\([^)]*\)/g, '$1').replace(/`/g, '');

// Where a repository file lands in the site (null: not in the site, say a source file).
function sitePath(repoPath) {
  const p = repoPath.split(path.sep).join('/');
  let m;
  if (p === 'README.md') return 'index.html';
  if ((m = /^([0-9][0-9]_[a-z0-9_]+)\/README\.md$/.exec(p)) && lessons.includes(m[1])) {
    return `lessons/${m[1]}/README.html`;
  }
  if ((m = /^([0-9][0-9]_[a-z0-9_]+)\/pictures\/([^/]+)$/.exec(p)) && lessons.includes(m[1])) {
    return `lessons/${m[1]}/pictures/${m[2]}`;
  }
  if ((m = /^docs\/([^/]+)\.md$/.exec(p))) return `docs/${m[1]}.html`;
  if (p === 'instructor/SOLUTIONS.md' && withSolutions) return 'instructor/SOLUTIONS.html';
  if ((m = /^docs\/([^/]+\.(png|svg|csv))$/.exec(p))) return `docs/${m[1]}`;
  return null;
}

// GitHub's heading anchors, so a README's links to its own sections (#why-...) still work.
function slug(text) {
  return text.toLowerCase().replace(/<[^>]*>/g, '').replace(/&(#\d+|[a-z]+);/g, '')
      .replace(/[^\p{L}\p{N}\- _]/gu, '')
      .replace(/ /g, '-');
}

// One markdown file of the repository as an HTML page at its site path.
function page(repoPath, title) {
  const from = path.posix.dirname(sitePath(repoPath));
  // A link's target, resolved in the repository and re-pointed into the site.
  const target = (href) => {
    if (/^([a-z]+:|#)/i.test(href)) return href;
    const [file, anchor] = href.split('#');
    const resolved = path.posix.normalize(path.posix.join(path.posix.dirname(repoPath), file));
    const there = sitePath(resolved);
    if (there === null) return null;
    return path.posix.relative(from, there) + (anchor ? '#' + anchor : '');
  };
  const seen = new Map();
  const marked = new Marked({
    gfm: true,
    renderer: {
      heading({ tokens, depth }) {
        const text = this.parser.parseInline(tokens);
        let id = slug(text);
        const n = seen.get(id) ?? 0;
        seen.set(id, n + 1);
        if (n) id += '-' + n;
        return `<h${depth} id="${id}">${text}</h${depth}>\n`;
      },
      link({ href, title: t, tokens }) {
        const text = this.parser.parseInline(tokens);
        const to = target(href);
        // A source file is not in the site: its name stays, as text.
        if (to === null) return `<span class="source" title="${escape(href)}">${text}</span>`;
        return `<a href="${escape(to)}"${t ? ` title="${escape(t)}"` : ''}>${text}</a>`;
      },
      image({ href, text }) {
        const to = target(href);
        return to === null ? escape(text) : `<img src="${escape(to)}" alt="${escape(text)}">`;
      },
    },
  });
  const body = marked.parse(fs.readFileSync(path.join(root, repoPath), 'utf8'));
  const index = path.posix.relative(from, 'index.html');
  const lesson = /^([0-9][0-9]_[a-z0-9_]+)\//.exec(repoPath)?.[1];
  const open = lesson ? ` · <a href="${path.posix.relative(from, lesson + '.html')}">open the lesson</a>` : '';
  const out = path.join(site, sitePath(repoPath));
  fs.mkdirSync(path.dirname(out), { recursive: true });
  fs.writeFileSync(out, `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>${escape(title)}</title>
<style>
  body { font: 16px/1.5 system-ui, sans-serif; margin: 16px auto; max-width: 900px; padding: 0 12px; background: #f4f4f2; color: #222; }
  img { max-width: 100%; height: auto; }
  table { border-collapse: collapse; display: block; overflow-x: auto; }
  th, td { border: 1px solid #ccc; padding: 3px 6px; vertical-align: top; }
  td img { max-width: 240px; }
  pre { background: #fff; border: 1px solid #ddd; padding: 8px; overflow-x: auto; }
  code { font: 14px ui-monospace, monospace; }
  .source { font-family: ui-monospace, monospace; }
  nav { margin-bottom: 1em; }
</style>
</head>
<body>
<nav><a href="${index}">all lessons</a>${open}</nav>
<main>
${body}
</main>
</body>
</html>
`);
}

const rows = [];
const documents = new Set();
for (const lesson of lessons) {
  // | [lesson](its README) | ![what you see](its picture) | what you learn | follows |
  const row = readme.split('\n').find((l) => l.startsWith(`| [${lesson}]`));
  const cells = row ? row.split('|').map((c) => c.trim()) : [];
  const picture = /\]\(([^)]+\.png)\)/.exec(cells[2] ?? '')?.[1];
  const line = plain(cells[3] ?? '');
  const follows = plain(cells[4] ?? '');
  const dest = path.join(site, 'lessons', lesson);
  fs.mkdirSync(dest, { recursive: true });
  if (fs.existsSync(path.join(root, lesson, 'pictures'))) {
    fs.cpSync(path.join(root, lesson, 'pictures'), path.join(dest, 'pictures'), { recursive: true });
  }
  const own = path.join(lesson, 'README.md');
  if (fs.existsSync(path.join(root, own))) {
    page(own, `${lesson}: real-time shadows`);
    for (const [, href] of fs.readFileSync(path.join(root, own), 'utf8').matchAll(/\]\((\.\.\/docs\/[^)#\s]+)/g)) {
      documents.add(path.posix.normalize(path.posix.join(lesson, href)));
    }
  }
  const shown = picture ? sitePath(picture) : null;
  rows.push(`<li>
  <a href="${lesson}.html">${shown ? `<img src="${shown}" alt="${lesson}" width="320" height="240" loading="lazy">` : ''}</a>
  <div><a href="${lesson}.html"><strong>${escape(lesson)}</strong></a>
  <p>${escape(line)}</p>
  ${follows ? `<p class="follows">follows ${escape(follows)}</p>` : ''}
  <a href="${lesson}.html">open the lesson</a> · <a href="lessons/${lesson}/README.html">README</a></div>
</li>`);
}
// The documents the lessons link to, and what those pages show.
for (const [, href] of readme.matchAll(/\]\((docs\/[^)#\s]+)/g)) documents.add(href);
for (const doc of documents) {
  if (!fs.existsSync(path.join(root, doc))) continue;
  if (doc.endsWith('.md')) {
    page(doc, `${path.basename(doc, '.md')}: real-time shadows`);
  } else {
    fs.mkdirSync(path.join(site, 'docs'), { recursive: true });
    fs.copyFileSync(path.join(root, doc), path.join(site, sitePath(doc)));
  }
}
if (withSolutions) page('instructor/SOLUTIONS.md', 'Solutions, for the instructor: real-time shadows');
for (const file of fs.readdirSync(path.join(root, 'docs'))) {
  if (/\.(png|svg|csv)$/.test(file)) {
    fs.mkdirSync(path.join(site, 'docs'), { recursive: true });
    fs.copyFileSync(path.join(root, 'docs', file), path.join(site, 'docs', file));
  }
}

fs.writeFileSync(path.join(site, 'index.html'), `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>Real-time shadows, one technique at a time</title>
<style>
  body { font: 15px/1.4 system-ui, sans-serif; margin: 16px auto; max-width: 1100px; padding: 0 12px; background: #f4f4f2; color: #222; }
  ul { list-style: none; padding: 0; display: grid; grid-template-columns: repeat(auto-fill, minmax(330px, 1fr)); gap: 18px; }
  li { background: #fff; border: 1px solid #ddd; padding: 6px; }
  img { display: block; width: 100%; height: auto; }
  p { margin: 4px 0; }
  .follows { color: #666; font-size: 13px; }
</style>
</head>
<body>
<h1>Real-time shadows, one technique at a time</h1>
<p>One shadow technique a lesson, each running here in the browser (WebGL 2) with its panel and
sliders: drag to orbit, wheel to zoom. Every shadow is scored against a ray-traced truth,
traced in this page (the panel's error, the <code>truth</code> and <code>error</code> views).
<strong>Start with <a href="${lessons[0]}.html">${escape(lessons[0] ?? '')}</a></strong> and go
in order: each lesson is the one before plus one idea (<a href="docs/CURRICULUM.html">the
curriculum</a>). Settings go in the address, so a link hands out a configuration:
<code>03_shadow_map_basic.html?scene=dueling&amp;shadow.size=256</code>.</p>
<ul>
${rows.join('\n')}
</ul>
</body>
</html>
`);
