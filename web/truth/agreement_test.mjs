#!/usr/bin/env node
// The web truth against Embree's, for one lesson: its defaults and two other configurations
// (another scene; a directional light in a third scene, where the lesson has one). Each runs
// the native lesson once to write the job and Embree's trace, traces the job with
// three-mesh-bvh (truth.mjs), and runs the lesson again with that trace (--truth-from), so
// the error numbers of both come from the same C++ metrics. Passes when the visibility is
// equal on >= 99.9 % of counted pixels (either tracer's), the air light on as many lit
// pixels, and every error number agrees within 0.05 points.
// With --seam SEAM.cjs the job goes through the browser's seam instead (common/truth/truth_job_web.cpp
// built with emscripten as tests/web/truth_seam.cpp: C++ hands the job's bytes to truth.mjs and
// takes the trace back), the path a page takes.
//   node web/truth/agreement_test.mjs BUILD_DIR LESSON [--size WxH] [--seam SEAM.cjs]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { createRequire } from 'node:module';
import { installTruth } from './page.mjs';
import { joinRows, parseJob, parseTrace, serializeTrace, traceRows, traceTruth } from './truth.mjs';

const [buildDir, lesson, ...rest] = process.argv.slice(2);
const option = (name, fallback) => {
  const at = rest.indexOf(name);
  return at >= 0 ? rest[at + 1] : fallback;
};
if (!buildDir || !lesson) {
  console.error('usage: agreement_test.mjs BUILD_DIR LESSON [--size WxH] [--seam SEAM.cjs]');
  process.exit(2);
}
const size = option('--size', '160x120');
const seamPath = option('--seam', null);
// The seam's program (emscripten's MODULARIZE factory, CommonJS), instantiated once with the
// page's JavaScript tracer installed. Its wasm is handed over as bytes: emscripten 3.1.6 would
// fetch() a file path, which node's fetch refuses.
const seam = seamPath
  ? await createRequire(import.meta.url)(resolve(seamPath))(
      installTruth({ wasmBinary: readFileSync(seamPath.replace(/\.c?js$/, '.wasm')) }))
  : null;
const MIN_EQUAL = 0.999;
const MAX_POINTS = 0.05;
const binary = join(buildDir, lesson);

function runLesson(args) {
  const r = spawnSync(binary, ['--headless', '--size', size, '--frames', '1', ...args], { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`${lesson} ${args.join(' ')}: exit ${r.status}\n${r.stdout}${r.stderr}`);
  return r;
}

// The configurations, from the lesson's own parameter list.
function configurations() {
  const list = spawnSync(binary, ['--list-params'], { encoding: 'utf8' }).stdout;
  const choices = (name) => {
    const line = list.split('\n').find((l) => l.startsWith(name + ' '));
    const m = line && line.match(/default (\S+).*one of (.*)$/);
    return m ? { fallback: m[1], all: m[2].split(', ') } : null;
  };
  const scene = choices('scene');
  const others = scene ? scene.all.filter((s) => s !== scene.fallback) : [];
  const configs = [[]];
  if (others.length > 0) configs.push([`scene=${others.includes('dueling') ? 'dueling' : others[0]}`]);
  const third = others.find((s) => !configs[1] || configs[1][0] !== `scene=${s}`);
  const light = choices('light.type');
  const last = [];
  if (third) last.push(`scene=${third}`);
  if (light && light.all.includes('directional')) last.push('light.type=directional');
  if (last.length > 0) configs.push(last);
  return configs;
}

// Report fields compared, in points: percentages as they are, fractions times 100.
const FIELDS = [
  ['false_shadow_pct', 1], ['false_lit_pct', 1], ['vis_mae', 100], ['shade_mae', 100],
  ['air_mae', 100], ['air_rel_rmse', 100],
];

const dir = mkdtempSync(join(tmpdir(), `web_truth_${lesson}_`));
let failures = 0;
try {
  const configs = configurations();
  if (configs.length < 3) console.log(`${lesson}: only ${configs.length} configuration(s) to vary`);
  for (const config of configs) {
    const sets = config.flatMap((s) => ['--set', s]);
    const name = config.length ? config.join(' ') : 'defaults';
    const file = (f) => join(dir, f);
    runLesson([...sets, '--out', file('a.png'), '--report', file('embree.json'),
               '--truth-job', file('job'), '--truth-result', file('embree.trace')]);
    const job = parseJob(readFileSync(file('job')));
    const started = process.hrtime.bigint();
    let web;
    if (seam) {
      const status = seam.callMain([file('job'), file('web.trace')]);
      if (status !== 0) throw new Error(`the seam's program exited ${status}`);
      web = parseTrace(readFileSync(file('web.trace')));
    } else {
      web = traceTruth(job);
      writeFileSync(file('web.trace'), serializeTrace(job, web));
    }
    const ms = Number(process.hrtime.bigint() - started) / 1e6;
    runLesson([...sets, '--out', file('b.png'), '--report', file('web.json'),
               '--truth-from', file('web.trace'), '--truth-result', file('used.trace')]);

    const embree = parseTrace(readFileSync(file('embree.trace')));
    const used = parseTrace(readFileSync(file('used.trace')));
    const problems = [];
    if (!seam) {
      // A page's workers trace bands of rows (web/truth/page.mjs): joined, the same trace.
      const cuts = [0, 1, Math.floor(job.height / 3), job.height - 2, job.height];
      const bands = cuts.slice(1).map((y1, k) => ({ y0: cuts[k], y1, ...traceRows(job, cuts[k], y1) }));
      const joined = joinRows(job, bands.reverse());
      const same = (a, b) => a.length === b.length && a.every((v, i) => Object.is(v, b[i]));
      if (!same(joined.visibility, web.visibility) ||
          (job.air && (!same(joined.air.light, web.air.light) ||
                       Math.abs(joined.air.noise - web.air.noise) > 1e-12 * web.air.noise))) {
        problems.push('bands of rows joined are not the whole trace');
      }
    }
    // The second run measured against the web's trace, not a fresh Embree one.
    if (!used.visibility.every((v, i) => Object.is(v, web.visibility[i]))) {
      problems.push('--truth-from did not use the web trace');
    }
    let counted = 0, equal = 0;
    for (let i = 0; i < web.visibility.length; i++) {
      const a = embree.visibility[i], b = web.visibility[i];
      if (a < 0 && b < 0) continue;
      counted++;
      if (a === b) equal++;
    }
    const visShare = counted ? equal / counted : 0;
    if (counted === 0) problems.push('no counted pixel: nothing compared');
    if (visShare < MIN_EQUAL) problems.push(`visibility equal on ${(100 * visShare).toFixed(3)} % of counted pixels`);
    let airNote = '';
    if (job.air) {
      if (!web.air || !embree.air) {
        problems.push('a job with air came back without air light');
      } else {
        let lit = 0, same = 0;
        for (let i = 0; i < web.air.light.length; i++) {
          const a = embree.air.light[i], b = web.air.light[i];
          if (a === 0 && b === 0) continue;
          lit++;
          if (a === b) same++;
        }
        if (lit === 0) problems.push('no air light: nothing compared');
        else if (same / lit < MIN_EQUAL) problems.push(`air light equal on ${(100 * same / lit).toFixed(3)} % of lit pixels`);
        airNote = `, air equal on ${lit ? (100 * same / lit).toFixed(3) : '-'} % of ${lit}`;
      }
    }
    const a = JSON.parse(readFileSync(file('embree.json'), 'utf8')).error;
    const b = JSON.parse(readFileSync(file('web.json'), 'utf8')).error;
    if (a.counted_pixels !== b.counted_pixels) problems.push(`counted_pixels ${a.counted_pixels} vs ${b.counted_pixels}`);
    let worst = 0;
    for (const [field, scale] of FIELDS) {
      if (!(field in a) && !(field in b)) continue;
      const d = Math.abs((a[field] ?? NaN) - (b[field] ?? NaN)) * scale;
      if (!(d <= MAX_POINTS)) problems.push(`${field}: ${a[field]} (Embree) vs ${b[field]} (web)`);
      else worst = Math.max(worst, d);
    }
    // A lesson's regions (error.<name>, docs/CONTRACTS.md): the same figures, region by region.
    const regions = Object.keys(a).filter((k) => a[k] !== null && typeof a[k] === 'object');
    for (const region of regions) {
      const ra = a[region], rb = b[region] ?? {};
      if (ra.counted_pixels !== rb.counted_pixels) {
        problems.push(`${region}.counted_pixels ${ra.counted_pixels} vs ${rb.counted_pixels}`);
      }
      for (const field of ['false_shadow_pct', 'false_lit_pct']) {
        const d = Math.abs((ra[field] ?? NaN) - (rb[field] ?? NaN));
        if (!(d <= MAX_POINTS)) problems.push(`${region}.${field}: ${ra[field]} (Embree) vs ${rb[field]} (web)`);
        else worst = Math.max(worst, d);
      }
    }
    console.log(`${lesson} [${name}] truth ${a.truth}: visibility equal on ${(100 * visShare).toFixed(3)} % ` +
                `of ${counted} counted pixels${airNote}; error numbers${regions.length ? ` (${regions.join(', ')} too)` : ''} within ${worst.toFixed(4)} points; ` +
                `web trace ${ms.toFixed(0)} ms${seam ? ' through the wasm seam' : ''}`);
    for (const p of problems) console.log(`  FAIL: ${p}`);
    failures += problems.length;
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
process.exit(failures > 0 ? 1 : 0);
