// The JavaScript half of common/truth/truth_job_web.cpp: installs the tracers the wasm runner calls.
// A page calls installTruth(Module) before the lesson's script runs (web/shell.html).
//  - Module.shadowsPostTruthJob(bytes) / shadowsTakeTruthTrace(): Web Workers (worker.mjs),
//    one a core, trace the job in bands of rows while frames go on; the window loop posts a
//    job once the sliders rest and takes the answer, {trace: Uint8Array} or {error}, when it
//    is there (null before). Module.shadowsTruthProgress: the running job's fraction done, -1
//    when none runs; Module.shadowsTruthMs: each answered job's time (web/bench.mjs).
//  - Module.shadowsTraceTruth(bytes): the job traced on this thread (the job's bytes in, the
//    trace's out), for what must wait for it (a page without workers, an output asked for).
//  - Module.shadowsPostBakeJob(bytes) / shadowsTakeBakeTrace() / shadowsBakeProgress: the same
//    for lesson 15's light-map bakes, in workers of their own.
import { joinRows, parseJob, serializeTrace, traceTruth } from './truth.mjs';

// Bands a job is cut into per worker: small enough that the workers finish together (a sky
// row costs nothing, a row of area-lit floor 64 rays a pixel), large enough to cost little.
const kBandsPerWorker = 8;

export function installTruth(Module) {
  Module.shadowsTraceTruth = (bytes) => {
    // `bytes` views the wasm heap; parseJob reads it in place, the BVH keeps its own copy.
    const job = parseJob(bytes);
    return serializeTrace(job, traceTruth(job));
  };
  Module.shadowsTruthProgress = -1;
  Module.shadowsTruthMs = [];
  const count = Math.max(1, Math.min(globalThis.navigator?.hardwareConcurrency || 2, 8));
  const truth = pool(count, (progress) => { Module.shadowsTruthProgress = progress; },
                     (ms) => Module.shadowsTruthMs.push(ms));
  if (!truth) return Module;
  Module.shadowsPostTruthJob = truth.post;
  Module.shadowsTakeTruthTrace = truth.take;
  // Lesson 15's light-map bakes: a pool of their own (made on the first bake), so a bake and
  // the error's truth run side by side. shadowsBakeBusy: posted, and not taken yet.
  let bake = null;
  Module.shadowsBakeProgress = -1;
  Module.shadowsBakeBusy = false;
  Module.shadowsPostBakeJob = (bytes) => {
    bake ??= pool(count, (progress) => { Module.shadowsBakeProgress = progress; }, () => {});
    if (!bake) return false;
    Module.shadowsBakeBusy = true;
    return bake.post(bytes);
  };
  Module.shadowsTakeBakeTrace = () => {
    const taken = bake ? bake.take() : null;
    if (taken) Module.shadowsBakeBusy = false;
    return taken;
  };
  return Module;
}

// `count` workers tracing one job at a time in bands of rows; a job posted replaces the one
// running. null where the page cannot start workers.
function pool(count, onProgress, onAnswered) {
  const workers = [];
  try {
    for (let k = 0; k < count; ++k) {
      workers.push(new Worker(new URL('./worker.mjs', import.meta.url), { type: 'module' }));
    }
  } catch (e) {
    console.warn('shadows: no truth worker (' + e + '): the page traces on its main thread');
    for (const worker of workers) worker.terminate();
    return null;
  }

  let answer = null, failure = null;
  let generation = 0, running = null;  // running: {job, rows left to hand out, bands, ...}
  const finish = (result) => {
    answer = result;
    running = null;
    onProgress(-1);
  };
  const handOut = (worker) => {
    if (!running || running.next >= running.job.height) return;
    const y0 = running.next, y1 = Math.min(y0 + running.rows, running.job.height);
    running.next = y1;
    worker.postMessage({ generation, y0, y1 });
  };
  for (const worker of workers) {
    worker.onmessage = (event) => {
      const band = event.data;
      if (!running || band.generation !== generation) return;  // a replaced job's rows
      if (band.error !== undefined) {
        finish({ error: band.error });
        return;
      }
      running.bands.push(band);
      running.done += band.y1 - band.y0;
      onProgress(running.done / running.job.height);
      if (running.done < running.job.height) {
        handOut(worker);
        return;
      }
      onAnswered(performance.now() - running.postedAt);
      finish({ trace: serializeTrace(running.job, joinRows(running.job, running.bands)) });
    };
    // A worker that could not load its modules (or died) answers every job with the reason.
    worker.onerror = (event) => {
      event.preventDefault();
      failure = event.message || 'a truth worker did not start';
      finish({ error: failure });
    };
  }
  return {
    post: (bytes) => {
      answer = null;
      if (failure) {
        answer = { error: failure };
        return true;
      }
      ++generation;
      const job = parseJob(bytes);
      const rows = Math.max(1, Math.ceil(job.height / (workers.length * kBandsPerWorker)));
      running = { job, rows, next: 0, done: 0, bands: [], postedAt: performance.now() };
      onProgress(0);
      for (const worker of workers) worker.postMessage({ generation, job: bytes });  // copied
      for (const worker of workers) handOut(worker);
      return true;
    },
    take: () => {
      const taken = answer;
      answer = null;
      return taken;
    },
  };
}
