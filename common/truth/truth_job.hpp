// What the truth traces, as data: one job in, the visibility (and lesson 08's air light) out.
// The native tracer is Embree (truth.cpp); a browser traces the same job with three-mesh-bvh
// (web/truth/). Either way the metrics and the truth and error pictures come from the same
// C++ (error_metrics.cpp) fed by the returned trace. The job's bytes are one format for a file
// (--truth-job) and for memory handed to JavaScript; web/truth/README.md spells it out.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/spotlight.hpp"
#include "truth/truth.hpp"

namespace shadows {

struct TruthJob {
  // The scene's world-space triangles (every object, casters and receivers alike).
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;
  float scene_radius = 0.0f;  // sets the ray offset: rayOffset()
  float rayOffset() const { return Truth::rayOffsetFor(scene_radius); }
  // What each pixel sees, from the runner's geometry pass: the light's frustum rule is already
  // applied there (position.w = -1 outside it), so a tracer only applies countedPixel().
  SurfaceBuffer surface;
  TruthLight light;
  // Lesson 08: single scattering along the eye rays. medium.spot is unused here: `spot` is
  // the job's own copy (null in a medium = light 1 everywhere).
  struct Air {
    glm::vec3 eye{0.0f};
    glm::mat4 inverse_view_projection{1.0f};
    AirMedium medium;
    std::optional<SpotTexture> spot;
  };
  std::optional<Air> air;

  // FNV-1a of the triangles (a tracer may keep its BVH while it does not change) and of the
  // whole job (a trace names the job it answers).
  std::uint64_t sceneId() const;
  std::uint64_t id() const;
};

// What a tracer returns for a job.
struct TruthTrace {
  std::uint64_t job_id = 0;
  int width = 0, height = 0;
  std::vector<float> visibility;        // Truth::visibility's image
  std::optional<Truth::AirResult> air;  // Truth::airLight's, when the job has air
};

// A trace given for a job it does not answer (bad input: exit 2).
struct TruthMismatch : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A tracer for one scene (built from a job's triangles, reused for jobs of the same sceneId).
class TruthTracer {
 public:
  virtual ~TruthTracer() = default;
  virtual TruthTrace trace(const TruthJob& job) const = 0;
  virtual std::uint64_t sceneId() const = 0;
};

// Embree natively (truth.cpp), the page's JavaScript under emscripten (truth_job_web.cpp).
std::shared_ptr<const TruthTracer> makeTruthTracer(const TruthJob& job);
// Whether makeTruthTracer can answer: always natively; in a page, once it installed its tracer
// (web/truth/page.mjs), which a page that could not load it has not.
bool truthTracerAvailable();

#ifdef __EMSCRIPTEN__
// A page has no threads: its Web Worker traces a job while frames go on (web/truth/page.mjs).
// Post a job's bytes (false: the page has no worker); then take its answer once it is there.
bool postTruthJob(const std::vector<std::uint8_t>& job_bytes);
struct PageTraceAnswer {
  enum class State { kNone, kDone, kFailed } state = State::kNone;
  std::vector<std::uint8_t> trace_bytes;  // kDone
};
PageTraceAnswer takeTruthTrace();
// The running job's progress in [0, 1], or -1 when none runs.
double truthTraceProgress();
// The same for lesson 15's light-map bakes, in workers of their own (LightMapBaker).
bool postBakeJob(const std::vector<std::uint8_t>& job_bytes);
PageTraceAnswer takeBakeTrace();
double bakeTraceProgress();
#endif

// The job's and the trace's bytes (little-endian, 4-byte fields; web/truth/README.md).
std::vector<std::uint8_t> serializeTruthJob(const TruthJob& job);
// Throw std::invalid_argument with a one-line reason on anything malformed.
TruthJob parseTruthJob(const std::vector<std::uint8_t>& bytes);
std::vector<std::uint8_t> serializeTruthTrace(const TruthTrace& trace);
TruthTrace parseTruthTrace(const std::vector<std::uint8_t>& bytes);
// A trace file (a regular file); std::invalid_argument with a one-line reason.
TruthTrace readTruthTrace(const std::string& path);
// Writes a trace file whole, then renames it into place (its folder made if missing), so a
// write cut short or a second writer never leaves half a file under `path`: whether it was kept.
bool keepTruthTrace(const std::string& path, const TruthTrace& trace);

}  // namespace shadows
