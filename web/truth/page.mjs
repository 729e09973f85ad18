// The JavaScript half of common/truth_job_web.cpp: installs the tracer the wasm runner calls
// (Module.shadowsTraceTruth: the job's bytes in, the trace's bytes out). A page calls
// installTruth(Module) before the runner's first truth, e.g. in the Module object it passes
// to the emscripten factory.
import { parseJob, serializeTrace, traceTruth } from './truth.mjs';

export function installTruth(Module) {
  Module.shadowsTraceTruth = (bytes) => {
    // `bytes` views the wasm heap; parseJob reads it in place, the BVH keeps its own copy.
    const job = parseJob(bytes);
    return serializeTrace(job, traceTruth(job));
  };
  return Module;
}
