// Writes the site's index.html (every lesson: its picture, one line, its page and README) and
// copies each lesson's README.md and pictures/ beside it, from the repository's own files: the
// line is the lesson's row in the top README's table, the picture the first in its README.
//   node web/make_index.mjs REPO_ROOT SITE_DIR LESSON...
import fs from 'node:fs';
import path from 'node:path';

const [root, site, ...lessons] = process.argv.slice(2);
const readme = fs.readFileSync(path.join(root, 'README.md'), 'utf8');
const escape = (s) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
// Markdown's `code` and [text](link) as plain text for one line of HTML.
const plain = (s) => s.replace(/\[([^\]]*)\]\([^)]*\)/g, '$1').replace(/`/g, '');

const rows = [];
for (const lesson of lessons) {
  const row = readme.split('\n').find((l) => l.startsWith(`| [${lesson}]`));
  const line = row ? plain(row.split('|')[2].trim()) : '';
  const own = path.join(root, lesson, 'README.md');
  const text = fs.existsSync(own) ? fs.readFileSync(own, 'utf8') : '';
  const picture = text.match(/!\[[^\]]*\]\((pictures\/[^)]+\.png)\)/)?.[1];
  const dest = path.join(site, 'lessons', lesson);
  fs.mkdirSync(dest, { recursive: true });
  if (text) fs.writeFileSync(path.join(dest, 'README.md'), text);
  if (fs.existsSync(path.join(root, lesson, 'pictures'))) {
    fs.cpSync(path.join(root, lesson, 'pictures'), path.join(dest, 'pictures'), { recursive: true });
  }
  rows.push(`<li>
  <a href="${lesson}.html">${picture ? `<img src="lessons/${lesson}/${picture}" alt="${lesson}" width="320" height="240" loading="lazy">` : ''}</a>
  <div><a href="${lesson}.html"><strong>${escape(lesson)}</strong></a>
  <p>${escape(line)}</p>
  <a href="${lesson}.html">open the lesson</a> · <a href="lessons/${lesson}/README.md">README</a></div>
</li>`);
}

fs.writeFileSync(path.join(site, 'index.html'), `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>Real-time shadows, one technique at a time</title>
<style>
  body { font: 15px/1.4 system-ui, sans-serif; margin: 16px auto; max-width: 1100px; background: #f4f4f2; color: #222; }
  ul { list-style: none; padding: 0; display: grid; grid-template-columns: repeat(auto-fill, minmax(330px, 1fr)); gap: 18px; }
  li { background: #fff; border: 1px solid #ddd; padding: 6px; }
  img { display: block; width: 100%; height: auto; }
  p { margin: 4px 0; }
</style>
</head>
<body>
<h1>Real-time shadows, one technique at a time</h1>
<p>Every lesson runs in the browser (WebGL 2): its panel and sliders, the orbit camera (drag,
wheel) and every view. Settings go in the address, so a link hands out a configuration:
<code>03_shadow_map_basic.html?scene=dueling&amp;shadow.size=256</code>. The ray-traced truth
and error views are native only for now.</p>
<ul>
${rows.join('\n')}
</ul>
</body>
</html>
`);
