#!/usr/bin/env node
// Traces a job file (a lesson's --truth-job) with three-mesh-bvh and writes the trace, which
// the lesson reads back with --truth-from: node web/truth/trace_job.mjs JOB TRACE
import { readFileSync, writeFileSync } from 'node:fs';
import { parseJob, serializeTrace, traceTruth } from './truth.mjs';

const [jobPath, tracePath] = process.argv.slice(2);
if (!jobPath || !tracePath) {
  console.error('usage: trace_job.mjs JOB TRACE');
  process.exit(2);
}
let job;
try {
  job = parseJob(readFileSync(jobPath));
} catch (e) {
  console.error(`trace_job: ${jobPath}: ${e.message}`);
  process.exit(2);
}
writeFileSync(tracePath, serializeTrace(job, traceTruth(job)));
