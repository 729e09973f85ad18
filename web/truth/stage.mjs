// Copies the browser's truth into a site (web/CMakeLists.txt runs it after the pages):
//   SITE/truth/{truth,page,worker}.js     from web/truth/*.mjs
//   SITE/vendor/three.core.js             three's core (all three-mesh-bvh takes from 'three')
//   SITE/vendor/three-mesh-bvh.module.js  three-mesh-bvh's ES module build
// Browsers resolve no bare names ('three') in a Web Worker (import maps stop at the page), so
// the copies import by relative path instead; the sources keep the bare names for node. And
// .js, not .mjs: a module script must come with a JavaScript MIME type, which every web server
// gives .js and not every one .mjs.
//
//   node web/truth/stage.mjs SITE WEB_DIR
import fs from 'node:fs';
import path from 'node:path';

const [site, web] = process.argv.slice(2);
if (!web) {
  console.error('usage: stage.mjs SITE WEB_DIR');
  process.exit(2);
}
const modules = path.join(web, 'node_modules');
const vendor = {
  'three.core.js': path.join(modules, 'three/build/three.core.js'),
  'three-mesh-bvh.module.js': path.join(modules, 'three-mesh-bvh/build/index.module.js'),
};
for (const from of Object.values(vendor)) {
  if (!fs.existsSync(from)) {
    console.error(`stage.mjs: no ${from}: run scripts/setup_web.sh (npm ci in web/)`);
    process.exit(1);
  }
}

// `from 'name'` to `from 'to'`, each name at least once where `expected`; source map lines
// dropped (the maps are not copied).
function rewrite(text, names, file) {
  let out = text.replace(/^\/\/# sourceMappingURL=.*$/m, '');
  for (const [name, to] of Object.entries(names)) {
    const pattern = new RegExp(`from\\s+(['"])${name.replace(/[-/.]/g, '\\$&')}\\1`, 'g');
    if (!pattern.test(out)) {
      console.error(`stage.mjs: ${file} imports nothing from '${name}' (has its build changed?)`);
      process.exit(1);
    }
    out = out.replace(pattern, `from '${to}'`);
  }
  return out;
}

function write(file, text) {
  fs.mkdirSync(path.dirname(file), { recursive: true });
  fs.writeFileSync(file, text);
}

const read = (file) => fs.readFileSync(file, 'utf8');
write(path.join(site, 'vendor/three.core.js'), rewrite(read(vendor['three.core.js']), {}, 'three.core.js'));
write(path.join(site, 'vendor/three-mesh-bvh.module.js'),
      rewrite(read(vendor['three-mesh-bvh.module.js']), { three: './three.core.js' }, 'three-mesh-bvh'));
// The sources' own names for each other, as the copies are named.
function renameLocal(text, file) {
  let out = text;
  for (const name of ['truth', 'worker']) {
    out = out.replaceAll(`'./${name}.mjs'`, `'./${name}.js'`);
  }
  if (/\.mjs'/.test(out)) {
    console.error(`stage.mjs: ${file} names a .mjs this script does not copy`);
    process.exit(1);
  }
  return out;
}
write(path.join(site, 'truth/truth.js'),
      renameLocal(rewrite(read(path.join(web, 'truth/truth.mjs')),
                          { three: '../vendor/three.core.js', 'three-mesh-bvh': '../vendor/three-mesh-bvh.module.js' },
                          'truth.mjs'), 'truth.mjs'));
for (const name of ['page', 'worker']) {
  write(path.join(site, `truth/${name}.js`),
        renameLocal(read(path.join(web, `truth/${name}.mjs`)), `${name}.mjs`));
}
