// The JavaScript half of common/truth_job_web.cpp: installs the tracers the wasm runner calls.
// A page calls installTruth(Module) before the lesson's script runs (web/shell.html).
//  - Module.shadowsPostTruthJob(bytes) / shadowsTakeTruthTrace(): a Web Worker (worker.mjs)
//    traces the job while frames go on; the window loop posts a job once the sliders rest and
//    takes the answer, {trace: Uint8Array} or {error}, when it is there (null before).
//    Module.shadowsTruthProgress: the running job's fraction done, -1 when none runs;
//    Module.shadowsTruthMs: each answered job's time from post to answer (web/bench.mjs).
//  - Module.shadowsTraceTruth(bytes): the job traced on this thread (the job's bytes in, the
//    trace's out), for what must wait for it (a page without workers, an output asked for).
import { parseJob, serializeTrace, traceTruth } from './truth.mjs';

export function installTruth(Module) {
  Module.shadowsTraceTruth = (bytes) => {
    // `bytes` views the wasm heap; parseJob reads it in place, the BVH keeps its own copy.
    const job = parseJob(bytes);
    return serializeTrace(job, traceTruth(job));
  };
  Module.shadowsTruthProgress = -1;
  let worker;
  try {
    worker = new Worker(new URL('./worker.mjs', import.meta.url), { type: 'module' });
  } catch (e) {
    console.warn('shadows: no truth worker (' + e + '): the page traces on its main thread');
    return Module;
  }
  let answer = null, failure = null, postedAt = 0;
  Module.shadowsTruthMs = [];
  worker.onmessage = (event) => {
    if (typeof event.data.progress === 'number') {
      Module.shadowsTruthProgress = event.data.progress;
      return;
    }
    answer = event.data;
    Module.shadowsTruthProgress = -1;
    Module.shadowsTruthMs.push(performance.now() - postedAt);
  };
  // A worker that could not load its modules (or died) answers every job with the reason.
  worker.onerror = (event) => {
    event.preventDefault();
    failure = event.message || 'the truth worker did not start';
    answer = { error: failure };
    Module.shadowsTruthProgress = -1;
  };
  Module.shadowsPostTruthJob = (bytes) => {
    answer = failure ? { error: failure } : null;
    if (failure) return true;
    Module.shadowsTruthProgress = 0;
    postedAt = performance.now();
    worker.postMessage(bytes, [bytes.buffer]);  // a copy of the heap's bytes, handed over
    return true;
  };
  Module.shadowsTakeTruthTrace = () => {
    const taken = answer;
    answer = null;
    return taken;
  };
  return Module;
}
