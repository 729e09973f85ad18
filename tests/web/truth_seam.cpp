// The browser's truth seam, end to end under node: this program is built with emscripten
// (no Embree), reads a job a native lesson wrote, traces it through makeTruthTracer
// (common/truth/truth_job_web.cpp: the job's bytes handed to web/truth's JavaScript, the trace's
// bytes back) and writes the trace; web/truth/seam_test.mjs compares it with Embree's and
// feeds it to the lesson's --truth-from.
//   truth_seam JOB TRACE
#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>

#include "truth/truth_job.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: truth_seam JOB TRACE\n");
    return 2;
  }
  try {
    std::ifstream in(argv[1], std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    const shadows::TruthJob job = shadows::parseTruthJob(bytes);
    shadows::TruthTrace trace = shadows::makeTruthTracer(job)->trace(job);
    trace.job_id = job.id();
    const std::vector<std::uint8_t> out = shadows::serializeTruthTrace(trace);
    std::ofstream(argv[2], std::ios::binary)
        .write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
    std::printf("truth_seam: traced %dx%d through the page's tracer\n", trace.width, trace.height);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "truth_seam: %s\n", e.what());
    return 1;
  }
  return 0;
}
