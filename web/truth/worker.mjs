// The page's truth worker (web/truth/page.mjs starts it): traces each job it is sent with
// truth.mjs off the page's main thread, so frames go on while the rays are cast. Messages out:
// {progress} a few times a second, then {trace: Uint8Array} or {error: string}.
import { parseJob, serializeTrace, traceTruth } from './truth.mjs';

self.onmessage = (event) => {
  try {
    const job = parseJob(event.data);
    let reported = 0;
    const trace = traceTruth(job, (done) => {
      const now = performance.now();
      if (now - reported < 100) return;
      reported = now;
      self.postMessage({ progress: done });
    });
    const bytes = serializeTrace(job, trace);
    self.postMessage({ trace: bytes }, [bytes.buffer]);
  } catch (e) {
    self.postMessage({ error: String(e && e.stack ? e.stack : e) });
  }
};
