// One of a page's truth workers (web/truth/page.mjs starts them): it keeps the job it was last
// sent and traces the bands of rows it is asked for, off the page's main thread, so frames go
// on while the rays are cast. Messages in: {generation, job: Uint8Array}, then
// {generation, y0, y1}; out: {generation, y0, y1, visibility, light, airSum, airLit}, or
// {generation, error}.
import { parseJob, traceRows } from './truth.mjs';

let job = null, generation = -1;
self.onmessage = (event) => {
  const message = event.data;
  try {
    if (message.job) {
      job = parseJob(message.job);
      generation = message.generation;
      return;
    }
    if (message.generation !== generation) return;  // rows of a job since replaced
    const band = traceRows(job, message.y0, message.y1);
    self.postMessage({ generation, y0: message.y0, y1: message.y1, ...band },
                     [band.visibility.buffer, ...(band.light ? [band.light.buffer] : [])]);
  } catch (e) {
    self.postMessage({ generation: message.generation, error: String(e && e.stack ? e.stack : e) });
  }
};
