// The web pages' benchmark (issue 24's targets; timings, so a benchmark and not a test):
//  - 03's default frame in headless Chromium (SwiftShader) against the native lesson on
//    llvmpipe at the same size, interleaved rounds, medians (the report's frame_ms, bracketed
//    by glFinish; the page's time between shown frames, frame rate limit lifted);
//  - each page's download, gzip-compressed as a web server would send it (the truth's modules
//    and libraries included: every page loads them);
//  - page load to first frame (navigation start to the first frame the page reports);
//  - the truth at each page's defaults: its worker's time from the job to the answer.
//   node web/bench.mjs [--rounds N] [--size WxH]   (after scripts/setup_pages.sh and a build)
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { serve } from './static_server.mjs';
import { launch, open } from './tests/browser.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..');
const site = path.join(root, 'build/web/site');
const rounds = Number(arg('--rounds', 5));
const size = arg('--size', '640x480');
const lesson = '03_shadow_map_basic';
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const lessons = fs.readdirSync(site).filter((f) => /^\d\d_.*\.html$/.test(f)).map((f) => f.slice(0, -5));
console.log(`load average at start: ${os.loadavg().map((x) => x.toFixed(2)).join(' ')} on ${os.cpus().length} cores`);

// Downloads: what a browser fetches for one page, compressed (gzip -9, as a server might).
let largest = 0;
const truthFiles = ['truth/page.js', 'truth/truth.js', 'truth/worker.js', 'vendor/three.core.js',
                    'vendor/three-mesh-bvh.module.js'];
for (const l of lessons) {
  let raw = 0, gz = 0;
  for (const file of [...['.html', '.js', '.wasm', '.data'].map((ext) => l + ext), ...truthFiles]) {
    const bytes = fs.readFileSync(path.join(site, file));
    raw += bytes.length;
    gz += zlib.gzipSync(bytes, { level: 9 }).length;
  }
  largest = Math.max(largest, gz);
  console.log(`download ${l}: ${(raw / 1e6).toFixed(2)} MB, ${(gz / 1e6).toFixed(2)} MB gzip`);
}
console.log(`largest page download: ${(largest / 1e6).toFixed(2)} MB compressed (target <= 5 MB)`);

const server = await serve(site);
const browser = await launch(['--disable-gpu-vsync', '--disable-frame-rate-limit']);
// The default frame, and what it is made of: the same frame unshadowed (shadow.off), and a
// 64x48 frame (next to nothing to shade: what a frame costs the browser, or the native run,
// whatever it draws).
const kCases = [{ name: 'defaults', sets: [], size }, { name: 'shadow.off', sets: ['shadow.off=true'], size },
                { name: 'at 64x48', sets: [], size: '64x48' }];
const frames = Object.fromEntries(kCases.map((c) => [c.name, { web: [], native: [] }]));
const frame = frames.defaults, firstFrame = [];
const report = path.join(os.tmpdir(), `shadows_bench_${process.pid}.json`);
try {
  for (let r = 0; r < rounds; ++r) {
    for (const c of kCases) {
      const timed = frames[c.name];
      // Native: the report's frame_ms (median of 30 timed frames), llvmpipe, no truth.
      const run = spawnSync(path.join(root, 'build/gles30', lesson),
        ['--headless', '--no-truth', '--size', c.size, '--frames', '30', '--out', '/dev/null', '--report', report,
         ...c.sets.flatMap((s) => ['--set', s])],
        { encoding: 'utf8', env: { ...process.env, MESA_GLES_VERSION_OVERRIDE: '3.0' } });
      if (run.status !== 0) throw new Error(`native run failed: ${run.stderr}`);
      timed.native.push(JSON.parse(fs.readFileSync(report, 'utf8')).frame_ms);
      // Web: the same frame and the same median, read from the page once 30 frames are timed.
      // No truth: its worker would take a core from the frames being timed.
      const query = [`size=${c.size}`, 'hide-panel', 'no-truth', ...c.sets].join('&');
      const page = await open(browser, `${server.url}${lesson}.html?${query}`);
      await page.waitFor('shadowsPage.frames >= 1', 60000);
      if (c === kCases[0]) firstFrame.push(await page.evaluate('shadowsPage.firstFrameMs'));
      await page.waitFor('shadowsPage.frames >= 45', 120000);
      // The median time between shown frames, the browser's frame rate limit lifted: WebGL's
      // glFinish does not wait for the GPU process, so the runner's own median counts only calls.
      timed.web.push(await page.evaluate('shadowsPage.medianInterval()'));
      await page.close();
      console.log(`round ${r + 1} ${c.name}: native ${timed.native.at(-1).toFixed(2)} ms, web ${timed.web.at(-1).toFixed(2)} ms` +
                  (c === kCases[0] ? `, first frame ${firstFrame.at(-1).toFixed(0)} ms after navigation` : ''));
    }
  }
  // Every page's load to first frame, once each, then its first truth (at rest, as a student
  // opens it: the panel's size, the lesson's defaults).
  for (const l of lessons) {
    const page = await open(browser, `${server.url}${l}.html`);
    await page.waitFor('shadowsPage.frames >= 1', 60000);
    console.log(`load to first frame ${l}: ${(await page.evaluate('shadowsPage.firstFrameMs')).toFixed(0)} ms`);
    await page.waitFor('Module.shadowsTruthMs.length >= 1', 600000);
    console.log(`truth ${l}: ${(await page.evaluate('Module.shadowsTruthMs[0]')).toFixed(0)} ms in its workers (${await page.evaluate("navigator.hardwareConcurrency")} cores)`);
    await page.close();
  }
} finally {
  await browser.close();
  await server.close();
  fs.rmSync(report, { force: true });
}
for (const c of kCases.slice(1)) {
  const t = frames[c.name];
  console.log(`${lesson} ${c.name}: web median ${median(t.web).toFixed(2)} ms, native median ` +
              `${median(t.native).toFixed(2)} ms: ${(median(t.web) / median(t.native)).toFixed(2)}x`);
}
const ratio = median(frame.web) / median(frame.native);
console.log(`${lesson} at ${size}: web median ${median(frame.web).toFixed(2)} ms, native median ` +
            `${median(frame.native).toFixed(2)} ms: ${ratio.toFixed(2)}x (target <= 2x), ${rounds} interleaved rounds`);
console.log(`${lesson} load to first frame: median ${median(firstFrame).toFixed(0)} ms (target <= 3000 ms)`);
console.log(`load average at end: ${os.loadavg().map((x) => x.toFixed(2)).join(' ')}`);
