// The browser test of one lesson page (ctest WebPage.<lesson>): headless Chromium opens the page
// (built by emscripten into build/web/site) and checks what a student would see:
//  - every view renders frames with no exception and no GL error, and its picture is within the
//    golden tolerance (tests/golden/README.md: at most 16 of 320x240 pixels differ at all) of
//    the native gles30 lesson's picture of the same configuration;
//  - the page with its panel renders too (its screenshot is kept: README's picture);
//  - on one lesson's page (kShellLesson: the shell is every page's), a bad query parameter
//    shows the very line the command line prints for it and the lesson runs with its
//    defaults; a site without the tracer or its workers says so and goes on drawing; without
//    WebGL 2 the page says so instead of showing a blank canvas.
//
//   node web/tests/page_test.mjs LESSON SITE_DIR NATIVE_BINARY OUT_DIR [PICTURES_DIR]
//
// PICTURES_DIR: the native gles30 pictures of the lesson's defaults at 320x240, one VIEW.png a
// view (ctest's Flavour.gles30.<lesson> writes them, byte for byte what NATIVE_BINARY renders
// for each view); without it, each view is rendered by NATIVE_BINARY here.
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { decodePng, launch, meanDifference, open, pixelsDiffering, sideBySide } from './browser.mjs';
import { serve } from '../static_server.mjs';

const [lesson, site, native, outDir, picturesDir] = process.argv.slice(2);
if (!outDir) {
  console.error('usage: page_test.mjs LESSON SITE_DIR NATIVE_BINARY OUT_DIR [PICTURES_DIR]');
  process.exit(2);
}
const kSize = '320x240';
// What every page shares (shell.html, the query parser, the truth's JavaScript) is checked on
// this lesson's page only: the same code on every page, and seconds of browser time each.
const kShellLesson = '01_projected_planar';
// Two rasterizers (SwiftShader here, llvmpipe natively) agree on a picture only up to the
// rounding of shading and of edges: tests/golden/README.md, "The browser against native".
const kMoved8Fraction = Number(process.env.SHADOWS_WEB_MOVED8 ?? 0.002);  // of the pixels
const kMeanLevels = Number(process.env.SHADOWS_WEB_MEAN ?? 0.25);
// Views that show a depth's last bits, which SwiftShader and llvmpipe round differently: lesson
// 03 has no bias on purpose, and its lit casters show acne, a moire of those roundings
// (measured 750-1546 pixels moved, mean 0.8-2.5 levels); 06's difference view marks where 8
// bits and the exact depth disagree on the casters (243, mean 0.24); 07's digit views draw
// the little digit's contours (226-924 pixels, mean 0.5-0.9); 08's error view scales the air's
// difference from the truth up, and with it the two rasterizers' rounding of the air (453
// pixels, mean 0.27); 10's plane-optimal map is made
// for the floor, and the casters' lit faces above it show acne in the visibility view (593,
// mean 2.0). The error view marks that same acne where it differs from the truth (03: 760
// pixels, mean 2.3). Those views get room for it, no more than the control below leaves failing.
const kRoundingViews = {
  '03_shadow_map_basic': ['shaded', 'visibility', 'light_view', 'compare', 'error'],
  '06_dual_texture_8bit': ['difference'],
  '08_atmospherics': ['error'],
  '07_multidigit_16bit': ['big_digit', 'little_digit', 'passes'],
  '10_plane_optimal': ['visibility'],
  // 09's volumes view: translucent volume sides, many of them edge-on to the eye along the
  // torus's silhouette, whose coverage the two rasterizers round differently (81 pixels moved,
  // mean 0.40). Its overview view draws the same translucent sides and one-pixel lines, which
  // the two rasterizers place differently (72 pixels moved, mean 0.249: at the plain limit).
  '09_shadow_volumes': ['volumes', 'overview'],
  // 14's blocker search and filter compute each pixel's kernel width in floats neither
  // rasterizer is asked to keep `precise`, and taps along the penumbrae land on the other side
  // of a texel boundary (measured: visibility 414 pixels moved, mean 0.16; blockers 208, 0.35;
  // penumbra 171, 0.31). The truth view's area light is traced from the page's own surface
  // pass, whose edge pixels differ, and its penumbra changes fast across them (178, 0.15).
  '14_soft_shadows': ['visibility', 'blockers', 'penumbra', 'truth'],
  // 11's face_texels view colours dFdx/dFdy of each face's texel coordinates: SwiftShader and
  // llvmpipe take those differences differently across a 2x2 quad, most of all along the
  // faces' seams and silhouettes (measured: 168 pixels moved, mean 0.30).
  '11_omni_cube': ['face_texels'],
  // 12's street converges on the horizon: dozens of posts a few pixels wide and their shadows
  // one pixel thin, whose coverage the two rasterizers round differently (measured: shaded
  // 154 pixels moved, mean 0.10; visibility 168, 0.15; cascades 155, 0.10; texel_grid 156,
  // 0.10, its checker faded by dFdx/dFdy where a pixel spans a texel).
  '12_cascades': ['shaded', 'visibility', 'cascades', 'texel_grid'],
  // 15's texel_grid draws each light map texel's outline a pixel wide with fwidth of the
  // texel coordinate, which the two rasterizers take differently across a 2x2 quad (measured:
  // 31 pixels moved, mean 0.44).
  '15_light_maps': ['texel_grid'],
};
const kRoundingMoved8Fraction = 0.03, kRoundingMeanLevels = 3.5;
// "" when `web` is within that tolerance of `native`, else what is off.
function compare(web, native, name, view = 'shaded') {
  const rounding = (kRoundingViews[lesson] ?? []).includes(view);
  const fraction = rounding ? kRoundingMoved8Fraction : kMoved8Fraction;
  const meanLimit = rounding ? kRoundingMeanLevels : kMeanLevels;
  const moved8 = pixelsDiffering(web, native, 8), mean = meanDifference(web, native);
  const limit = Math.floor(fraction * web.width * web.height);
  console.log(`${lesson} ${name}: ${pixelsDiffering(web, native, 0)} pixels differ from native ` +
              `gles30, ${moved8} by more than 8 levels (at most ${limit}), mean ${mean.toFixed(3)} ` +
              `levels (at most ${meanLimit})`);
  if (moved8 <= limit && mean <= meanLimit) return '';
  fs.writeFileSync(path.join(outDir, `${lesson}.${name}.diff.png`), sideBySide(web, native));
  return `${moved8} pixels moved by more than 8 levels (at most ${limit}), mean ${mean.toFixed(3)} ` +
         `(at most ${meanLimit}); web | native | moved: ${lesson}.${name}.diff.png`;
}
fs.mkdirSync(outDir, { recursive: true });
let failures = 0;
const fail = (what) => { console.log(`FAIL ${lesson}: ${what}`); ++failures; };
// Where a page test's seconds go (tests/README.md, the suite's budget): each part's wall time.
let partStart = performance.now();
const partDone = (what) => {
  const now = performance.now();
  console.log(`${lesson} time: ${what} ${((now - partStart) / 1000).toFixed(1)} s (native runs so far ${nativeSeconds.toFixed(1)} s)`);
  partStart = now;
};

// The views the lesson offers, as its own --list-params says.
const views = (() => {
  const list = execFileSync(native, ['--list-params'], { encoding: 'utf8' });
  const line = list.split('\n').find((l) => /^view\b/.test(l));
  const choices = line?.match(/\{([^}]*)\}|one of ([^\s].*)$/);
  const names = (choices?.[1] ?? choices?.[2] ?? '').split(/[|, ]+/).filter(Boolean);
  if (!names.includes('shaded')) throw new Error(`no views in --list-params: ${line}`);
  return names;
})();

// The native gles30 lesson's picture (and, for bad input, its message and exit code). The
// truth and error views are Embree's there, three-mesh-bvh's in the page.
let nativeSeconds = 0;
function nativeRun(sets, out, extra = ['--no-truth']) {
  const args = ['--headless', ...extra, '--size', kSize, '--frames', '1', '--out', out];
  for (const s of sets) args.push('--set', s);
  const started = performance.now();
  const run = spawnSync(native, args, { encoding: 'utf8', env: { ...process.env, MESA_GLES_VERSION_OVERRIDE: '3.0' } });
  nativeSeconds += (performance.now() - started) / 1000;
  return run;
}

// The native gles30 picture of one view of the defaults at kSize (its truth and error views
// traced by Embree), from PICTURES_DIR or rendered now; null (and a failure) if there is none.
const nativePictures = new Map();
function nativePicture(view, traced) {
  if (!nativePictures.has(view)) {
    const ref = path.join(outDir, `${lesson}.${view}.native.png`);
    if (picturesDir) {
      const file = path.join(picturesDir, `${view}.png`);
      if (!fs.existsSync(file)) {
        fail(`view=${view}: no native gles30 picture ${file}`);
        return null;
      }
      fs.copyFileSync(file, ref);
    } else {
      const run = nativeRun([`view=${view}`], ref, traced ? [] : ['--no-truth']);
      if (run.status !== 0) {
        fail(`view=${view}: native gles30 run failed (${run.status}): ${run.stderr.trim()}`);
        return null;
      }
    }
    nativePictures.set(view, decodePng(fs.readFileSync(ref)));
  }
  return nativePictures.get(view);
}

// Renders `settle` frames, asks for a screenshot (the F12 key's: out/screenshots/<lesson>_N.png
// in the page's file system), returns it decoded.
const shotsTaken = new Map();
async function screenshot(page, name, settle = 3) {
  const frames = await page.evaluate('shadowsPage.frames');
  await page.waitFor(`shadowsPage.frames >= ${frames + settle}`);
  const n = (shotsTaken.get(page) ?? 0) + 1;
  shotsTaken.set(page, n);
  const file = `/out/screenshots/${lesson}_${n}.png`;
  await page.evaluate('Module._shadows_screenshot()');
  await page.waitFor(`Module.FS.analyzePath('${file}').exists`);
  const b64 = await page.evaluate(`(() => {
    Module.FS.chmod('${file}', 0o644);  // written 0000 in MEMFS, which has no umask
    const bytes = Module.FS.readFile('${file}');
    let s = '';
    for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(s);
  })()`);
  const png = Buffer.from(b64, 'base64');
  fs.writeFileSync(path.join(outDir, name), png);
  return decodePng(png);
}

// How far a page's tallies are (checkClean's `since`: what came before is another view's).
const tallies = async (page) => ({
  ...(await page.evaluate('({frames: shadowsPage.frames, glErrors: shadowsPage.glErrors, errors: shadowsPage.errors.length})')),
  exceptions: page.exceptions.length, console: page.console.length,
});

// What every page must show: frames, no exception, no GL error, no failure line; with
// `since` (tallies()), only what came after it.
async function checkClean(page, what, since = { frames: 0, glErrors: 0, errors: 0, exceptions: 0, console: 0 }) {
  const state = await page.evaluate('({frames: shadowsPage.frames, glErrors: shadowsPage.glErrors, errors: shadowsPage.errors})');
  if (state.frames - since.frames < 3) fail(`${what}: ${state.frames - since.frames} frames rendered`);
  if (state.glErrors !== since.glErrors) fail(`${what}: ${state.glErrors - since.glErrors} GL errors`);
  for (const e of state.errors.slice(since.errors)) fail(`${what}: page error: ${e}`);
  for (const e of page.exceptions.slice(since.exceptions)) fail(`${what}: exception: ${e}`);
  for (const c of page.console.slice(since.console)) {
    if (c.type === 'error' || /GL error|GL_INVALID|WebGL: /.test(c.text)) fail(`${what}: console ${c.type}: ${c.text}`);
  }
}

const server = await serve(site);
const browser = await launch();
try {
  // Every view against the native gles30 picture of the same configuration, in two pages, each
  // view switched in place (shadows_set, as --set parses it): the views without the truth in one
  // (?no-truth: its worker would only take a core), the truth and error views in the other,
  // which share one trace. A page load costs SwiftShader about a second, a trace three or four.
  const isTraced = (view) => view === 'truth' || view === 'error';
  for (const group of [views.filter((v) => !isTraced(v)), views.filter(isTraced)]) {
    if (group.length === 0) continue;
    const traced = isTraced(group[0]);
    const page = await open(browser, `${server.url}${lesson}.html?size=${kSize}&hide-panel&view=${group[0]}${traced ? '' : '&no-truth'}`);
    try {
      // The truth views show the page's truth once its worker has traced it (sliders at rest).
      // Lesson 15 bakes its light map in workers of its own first: the views wait for it.
      await page.waitFor(traced ? 'shadowsPage.truths >= 1 || shadowsPage.errors.length + shadowsPage.notices.length > 0'
                                : '(shadowsPage.frames >= 5 && !Module.shadowsBakeBusy) || shadowsPage.errors.length > 0', 240000);
      const traces = 'Module.shadowsTruthMs.length + (Module.shadowsTruthProgress >= 0 ? 1 : 0)';
      const tracedBefore = await page.evaluate(traces);
      for (const view of group) {
        let since;  // the first view's page is its own; a switched view's, since the switch
        if (view !== group[0]) {
          since = await tallies(page);
          const said = await page.evaluate(`Module.ccall('shadows_set', 'string', ['string'], ['view=${view}'])`);
          if (said !== '') fail(`view=${view}: the page refused it: ${said}`);
          const now = await page.evaluate(`Module.ccall('shadows_get', 'string', ['string'], ['view'])`);
          if (now !== view) fail(`view=${view}: the page's view is ${now} after the switch`);
        }
        const web = await screenshot(page, `${lesson}.${view}.web.png`);
        await checkClean(page, `view=${view}`, since);
        // Jobs answered, and one running: none without the truth, and a view's change is no
        // reason to trace again. A page traces once its settings have rested 300 ms
        // (window.cpp): the count is read after longer than that.
        if (since && traced) await new Promise((r) => setTimeout(r, 500));  // ?no-truth: never
        const tracedNow = await page.evaluate(traces);
        if (!traced && tracedNow !== 0) fail(`view=${view}&no-truth: the page traced ${tracedNow} truths`);
        if (traced && tracedNow !== tracedBefore) fail(`view=${view}: a change of view traced the truth again (${tracedBefore} then ${tracedNow} jobs)`);
        const ref = nativePicture(view, traced);
        if (!ref) continue;
        const why = compare(web, ref, `view=${view}`, view);
        if (why) fail(`view=${view}: ${why}`);
        if (view === 'shaded') {
          // The control: the same comparison must tell a 1-degree zoom (camera.fov) apart, or
          // the tolerance above would pass pictures that differ.
          const fov = Number(execFileSync(native, ['--list-params'], { encoding: 'utf8' })
                                 .match(/^camera\.fov\s+float\s+default\s+([0-9.]+)/m)[1]);
          const zoomed = path.join(outDir, `${lesson}.zoomed.native.png`);
          nativeRun([`camera.fov=${fov + 1}`], zoomed);
          if (!compare(web, decodePng(fs.readFileSync(zoomed)), 'control (camera.fov+1)', view)) {
            fail('the tolerance cannot tell the picture from one zoomed by camera.fov+1');
          }
        }
      }
    } finally {
      await page.close();
    }
    partDone(traced ? 'the truth views' : 'the views without the truth');
  }

  // The page as a student opens it: panel and all, the canvas filling a laptop-sized window
  // (1024x700: the picture about 680x600 beside the panel's 340-pixel column).
  {
    const page = await open(browser, `${server.url}${lesson}.html`, { width: 1024, height: 700 });
    // A frame of the page costs SwiftShader half a second or more at this size (08: 1.7 s): it
    // waits for the frames it needs (three drawn; the drag's two, and one after it; a
    // screenshot is the frame after it is asked for).
    await page.waitFor('shadowsPage.frames >= 3 || shadowsPage.errors.length > 0', 60000);
    const before = await screenshot(page, `${lesson}.page.png`, 0);
    const canvasBox = `(() => { const r = document.getElementById('canvas').getBoundingClientRect(); return {x: r.x, y: r.y, w: r.width, h: r.height, page: document.documentElement.clientWidth}; })()`;
    const box = await page.evaluate(canvasBox);
    // The canvas fills the window's width, the picture left of the panel's column.
    if (Math.abs(box.w - box.page) > 1 || box.h < 500) fail(`the canvas is ${box.w}x${box.h} in a ${box.page}-wide window: it does not fill it`);
    if (before.width !== Math.round(box.w)) fail(`the screenshot is ${before.width} wide, the canvas ${box.w}`);
    // The orbit camera: a drag across the picture, left of the panel's column, turns the view.
    const at = (fx, fy) => ({ x: box.x + fx * box.w, y: box.y + fy * box.h });
    await page.send('Input.dispatchMouseEvent', { type: 'mouseMoved', ...at(0.2, 0.5) });
    // The window reads the mouse once a frame (window.cpp): the frame after the press starts
    // the drag, the frame after the move turns the view.
    const nextFrame = async () => {
      const frames = await page.evaluate('shadowsPage.frames');
      await page.waitFor(`shadowsPage.frames > ${frames}`, 60000);
    };
    await page.send('Input.dispatchMouseEvent', { type: 'mousePressed', button: 'left', buttons: 1, clickCount: 1, ...at(0.2, 0.5) });
    await nextFrame();
    await page.send('Input.dispatchMouseEvent', { type: 'mouseMoved', button: 'left', buttons: 1, ...at(0.36, 0.5) });
    await nextFrame();
    await page.send('Input.dispatchMouseEvent', { type: 'mouseReleased', button: 'left', buttons: 0, clickCount: 1, ...at(0.36, 0.5) });
    const after = await screenshot(page, `${lesson}.page.orbited.png`, 1);
    const turned = pixelsDiffering(before, after, 8);
    if (lesson === kShellLesson) {
      // Resizing the window resizes the canvas: the lesson follows the page's stage.
      await page.send('Emulation.setDeviceMetricsOverride', { width: 1200, height: 800, deviceScaleFactor: 1, mobile: false });
      await page.waitFor(`document.getElementById('canvas').getBoundingClientRect().width >= document.documentElement.clientWidth - 1 &&
                          document.documentElement.clientWidth > 1100`, 30000)
          .catch(() => fail('the canvas did not follow the window from 1024 to 1200 wide'));
      const frames = await page.evaluate('shadowsPage.frames');
      await page.waitFor(`shadowsPage.frames > ${frames + 2}`, 60000);
    }
    console.log(`${lesson} orbit: a drag moved ${turned} pixels by more than 8 levels`);
    if (turned < 0.05 * before.width * before.height) fail(`a drag on the canvas did not orbit the camera (${turned} pixels moved)`);
    await checkClean(page, 'page with panel');
    // At rest (after the drag too), the workers trace the truth: its progress, then its error
    // numbers come under the canvas. The line is the shell's (page_main.cpp), every page's: the
    // shell lesson waits for the numbers; the others for the trace of their own job at this
    // size to be under way (their truth's numbers are checked at 320x240 above, in the truth
    // and error views). An area light's trace at 680x600 takes SwiftShader's machine half a
    // minute, which twelve pages cannot spend in a test phase of eight.
    // Read in the same evaluation that saw the line: a truth traced anew (the resize above)
    // replaces the numbers with its progress line.
    const numbers = /error against the ray-traced truth/;
    const underWay = lesson === kShellLesson ? numbers : /tracing the truth \(three-mesh-bvh, in Web Workers\): [1-9][0-9]* %|error against the ray-traced truth/;
    const status = await page.waitFor(`(() => { const t = document.getElementById('status').textContent;
                                                return ${underWay}.test(t) || shadowsPage.errors.length > 0 ? t : false; })()`, 240000);
    if (!/shown every [0-9.]+ ms/.test(status)) fail(`page with panel: no frame interval on the page ("${status}")`);
    // The frame on the GPU (EXT_disjoint_timer_query_webgl2, which this Chromium has), never a
    // glFinish wall time, which in a browser counts only the calls (issue 55, 7).
    const gpu = /GPU frame ([0-9.]+) ms \(median of [0-9]+\)/.exec(status);
    if (!gpu || !(Number(gpu[1]) > 0)) fail(`page with panel: no GPU frame time ("${status}")`);
    // Numbers, or (a drag that leaves no lit surface in view) the reason there are none.
    if (numbers.test(status) &&
        !/error against the ray-traced truth: (false shadow [0-9.]+ %, false lit [0-9.]+ %|none counted \(.+\))/.test(status)) {
      fail(`page with panel: no error numbers on the page ("${status}")`);
    }
    if (!underWay.test(status)) fail(`page with panel: the truth is not traced ("${status}")`);
    console.log(`${lesson} page with panel: ${status.split('\n').pop()}`);
    await page.close();
    partDone('the page with its panel');
  }

  // An exercise graded in the page, from a link with a solution and one without: the verdict
  // under the canvas is the native grader's (instructor/SOLUTIONS.md's solution for 04).
  if (lesson === '04_bias_offset') {
    for (const [query, verdict] of [['exercise=1&bias.mode=gradient', 'MET'], ['exercise=1', 'NOT MET']]) {
      const page = await open(browser, `${server.url}${lesson}.html?${query}`);
      const status = await page.waitFor(`(() => { const t = document.getElementById('status').textContent;
                                                  return /exercise 1 [(][^)]*[)]: (MET|NOT MET): /.test(t) || shadowsPage.errors.length > 0 ? t : false; })()`, 240000);
      const said = /exercise 1 [(][^)]*[)]: (MET|NOT MET): /.exec(status)?.[1];
      if (said !== verdict) fail(`?${query}: the page says ${said ?? 'nothing'}, the grader ${verdict} ("${status}")`);
      const graded = spawnSync(native, ['--grade', '1', ...query.split('&').slice(1).flatMap((q) => ['--set', q]), '--out', '/dev/null'], { encoding: 'utf8' });
      const natively = /: (MET|NOT MET): /.exec(graded.stdout)?.[1];
      if (natively !== verdict) fail(`?${query}: the native gles30 grader says ${natively} (${graded.stdout.trim()})`);
      console.log(`${lesson} ?${query}: ${said} in the page and natively`);
      await checkClean(page, `?${query}`);
      await page.close();
    }
  }

  // Bad input: an unknown parameter and one out of range, each the command line's line. The
  // page's shell, parser and notices are every lesson's: one lesson checks them (kShellLesson).
  for (const bad of lesson === kShellLesson ? ['no.such.param=1', 'camera.fov=500'] : []) {
    const run = nativeRun([bad], path.join(outDir, 'unused.png'));
    const expected = run.stderr.trim();
    if (run.status !== 2 || expected.split('\n').length !== 1) fail(`native --set ${bad}: exit ${run.status}, "${expected}"`);
    const page = await open(browser, `${server.url}${lesson}.html?size=${kSize}&hide-panel&${bad}`);
    await page.waitFor('shadowsPage.frames >= 5 || shadowsPage.errors.length > 0');
    const shown = await page.evaluate(`({notices: shadowsPage.notices, box: document.getElementById('notice').textContent})`);
    if (shown.notices[0] !== expected || !shown.box.includes(expected)) {
      fail(`?${bad}: page says ${JSON.stringify(shown.notices)}, the command line "${expected}"`);
    }
    page.console = page.console.filter((c) => c.text !== expected);  // the line is in the console too
    await checkClean(page, `?${bad}`);
    const web = await screenshot(page, `${lesson}.bad.web.png`);
    const ref = nativePicture('shaded', false);
    if (!ref || compare(web, ref, `?${bad}`)) {
      fail(`?${bad}: the picture is not the defaults' picture`);
    }
    await page.close();
  }

  // A value the query hides a NUL or a right-to-left override in: the parser sees all of it
  // (the NUL as the four characters \x00, as a native message prints it) and the notice shows
  // the override escaped.
  if (lesson === kShellLesson) {
    const hidden = [['camera.fov=45%00garbage', 'camera.fov=45\\x00garbage'],
                    ['camera.fov=%00', 'camera.fov=\\x00'],
                    ['camera.fov=4%E2%80%AE5', 'camera.fov=4\u202E5']];
    for (const [query, set] of hidden) {
      const expected = nativeRun([set], path.join(outDir, 'unused.png')).stderr.trim();
      const page = await open(browser, `${server.url}${lesson}.html?size=${kSize}&hide-panel&${query}`);
      await page.waitFor('shadowsPage.frames >= 3 || shadowsPage.errors.length > 0');
      const notices = await page.evaluate('shadowsPage.notices');
      if (notices[0] !== expected || /\u202E/.test(notices[0])) {
        fail(`?${query}: page says ${JSON.stringify(notices)}, the command line "${expected}"`);
      }
      page.console = page.console.filter((c) => c.text !== expected);
      await checkClean(page, `?${query}`);
      await page.close();
    }
    // A size the parser takes (8192 a side) but the browser cannot draw: refused up front, the
    // lesson at its default size, no lost context.
    const page = await open(browser, `${server.url}${lesson}.html?size=8192x8192&hide-panel`);
    await page.waitFor('shadowsPage.frames >= 3 || shadowsPage.errors.length > 0');
    const said = await page.evaluate(`({notices: shadowsPage.notices, width: Module.canvas.width})`);
    if (!/size=8192x8192: this browser/.test(said.notices[0] ?? '') || said.width >= 8192) {
      fail(`?size=8192x8192: page says ${JSON.stringify(said.notices)}, canvas ${said.width} wide`);
    }
    page.console = page.console.filter((c) => !/size=8192x8192/.test(c.text));
    await checkClean(page, '?size=8192x8192');
    await page.close();
    // A size the browser draws but whose truth and read-backs a page cannot hold (4096x4096
    // showed std::bad_alloc after the first frame; 3000x3000 is within every side's limit):
    // refused up front as well (issue 53, 1).
    const big = await open(browser, `${server.url}${lesson}.html?size=3000x3000&hide-panel`);
    await big.waitFor('shadowsPage.frames >= 3 || shadowsPage.errors.length > 0');
    const bigSaid = await big.evaluate(`({notices: shadowsPage.notices, width: Module.canvas.width})`);
    if (!/size=3000x3000: a page holds the truth/.test(bigSaid.notices[0] ?? '') || bigSaid.width >= 3000) {
      fail(`?size=3000x3000: page says ${JSON.stringify(bigSaid.notices)}, canvas ${bigSaid.width} wide`);
    }
    big.console = big.console.filter((c) => !/size=3000x3000/.test(c.text));
    await checkClean(big, '?size=3000x3000');
    await big.close();
  }
} finally {
  await browser.close();
}

// A site without the ray tracer's libraries (a copy missing vendor/): the page says so, the
// lesson runs, and the truth view is the plain "not available" picture. Like the checks below,
// the shell's and the truth's JavaScript are every lesson's: one lesson checks them.
if (lesson === kShellLesson) {
  const partial = await serve(site, 0, /^\/vendor\//);
  const bare = await launch();
  try {
    const page = await open(bare, `${partial.url}${lesson}.html?size=${kSize}&hide-panel&view=truth`);
    await page.waitFor('shadowsPage.frames >= 20 || shadowsPage.errors.length > 0');
    const said = await page.evaluate(`({notices: shadowsPage.notices, truths: shadowsPage.truths,
                                        status: document.getElementById('status').textContent})`);
    if (!said.notices.some((n) => /ray tracer did not load/.test(n))) fail(`without vendor/ the page says ${JSON.stringify(said.notices)}`);
    if (!/could not load its ray tracer/.test(said.status)) fail(`without vendor/ the status says "${said.status}"`);
    if (said.truths !== 0) fail(`without vendor/ the page measured ${said.truths} truths`);
    page.console = page.console.filter((c) => !/vendor\/|Failed to load resource/.test(c.text));
    await checkClean(page, 'without vendor/');
    const web = await screenshot(page, `${lesson}.no-tracer.web.png`);
    const first = web.rgba.subarray(0, 4);
    let plain = true;
    for (let i = 0; i < web.rgba.length; i += 4) plain &&= web.rgba[i] === first[0] && web.rgba[i + 1] === first[1];
    if (!plain) fail('without vendor/ the truth view is not the plain "truth not available" picture');
  } finally {
    await bare.close();
    await partial.close();
  }
}

// A site whose workers cannot start (truth/worker.js missing): the page says the ray tracer
// failed, on the page and in the console, and goes on drawing.
if (lesson === kShellLesson) {
  const partial = await serve(site, 0, /^\/truth\/worker\.js$/);
  const bare = await launch();
  try {
    const page = await open(bare, `${partial.url}${lesson}.html?size=${kSize}&hide-panel&view=truth`);
    await page.waitFor(`/ray tracer failed/.test(document.getElementById('status').textContent) ||
                        shadowsPage.errors.length > 0`, 60000);
    const frames = await page.evaluate('shadowsPage.frames');
    await page.waitFor(`shadowsPage.frames >= ${frames + 5}`);
    const failedLines = page.console.filter((c) => /the truth worker failed/.test(c.text));
    if (failedLines.length === 0) fail('without truth/worker.js the console does not say the worker failed');
    page.console = page.console.filter((c) => !/the truth worker failed|worker\.js|Failed to load resource/.test(c.text));
    await checkClean(page, 'without truth/worker.js');
  } catch (e) {
    fail(`without truth/worker.js: ${e.message}`);
  } finally {
    await bare.close();
    await partial.close();
  }
}

// Without WebGL 2: a clear message, no blank canvas.
if (lesson === kShellLesson) {
  const bare = await launch(['--disable-webgl2', '--disable-webgl']);
  try {
    const page = await open(bare, `${server.url}${lesson}.html`);
    await page.waitFor(`document.readyState === 'complete'`);
    const said = await page.evaluate(`shadowsPage.errors.join(' ')`);
    if (!/needs WebGL 2/.test(said)) fail(`without WebGL 2 the page says "${said}"`);
  } finally {
    await bare.close();
  }
}
await server.close();
console.log(failures === 0 ? `PASS ${lesson}` : `${failures} failure(s)`);
process.exit(failures === 0 ? 0 : 1);
