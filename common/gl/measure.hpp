// Timing and work counters. Wall time bracketed by glFinish (llvmpipe's GL_TIME_ELAPSED is
// wrong by orders of magnitude); fragment-shader invocations from
// GL_ARB_pipeline_statistics_query; draw calls counted by Mesh::draw and friends.
#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gl/gl.hpp"

namespace shadows {

struct PassWork {
  long long draw_calls = 0;
  // llvmpipe counts every rasterized fragment here, before the depth test, early or not.
  // Empty where the context cannot count them (Caps::pipeline_statistics).
  std::optional<long long> fragment_invocations;
  // GL_SAMPLES_PASSED, for passes that ask: the fragments that passed the depth test; with
  // the tests early, the only ones whose shading ran. Empty where the context has no counting
  // occlusion queries (OpenGL ES).
  bool counts_passed = false;
  std::optional<long long> fragments_passed;
};

// Every draw the lessons issue goes through here, so passes can count them.
void countDrawCall();
long long drawCallsSoFar();

double median(std::vector<double> values);

class Measure {
 public:
  Measure();
  // When off (the runner's own truth renders), nothing is timed or counted.
  void setEnabled(bool enabled) { enabled_ = enabled; }
  bool enabled() const { return enabled_; }

  void beginFrame();
  void endFrame();  // glFinish, then the frame's wall time

  class Pass {
   public:
    Pass(Measure* owner, std::string name, bool countPassed);
    Pass(Pass&&) = delete;
    ~Pass();

   private:
    Measure* owner_;
    std::string name_;
    std::chrono::steady_clock::time_point start_;
    long long draws_at_start_ = 0;
    bool count_passed_ = false;
  };
  // RAII: `auto timing = measure.pass("shadow");` around one pass. With `countPassed` it also
  // counts fragments_passed (a pass that runs its own GL_SAMPLES_PASSED query must not).
  [[nodiscard]] Pass pass(const std::string& name, bool countPassed = false) {
    return Pass(enabled_ ? this : nullptr, name, countPassed);
  }

  // An event counter for this frame, e.g. "shadow_map_renders". An empty amount is a number
  // this context cannot count: the report says null, "unavailable on <flavour>".
  void count(const std::string& name, long long amount = 1);
  void count(const std::string& name, std::optional<long long> amount);

  // Drop everything recorded so far (after the warm-up frame).
  void clearHistory();
  double medianFrameMs() const;
  size_t timedFrames() const { return frame_ms_.size(); }
  std::map<std::string, double> medianPassMs() const;
  const std::map<std::string, PassWork>& lastFrameWork() const { return last_work_; }
  // The work of a pass that already ended in the frame in progress (null if none, or when
  // measuring is off): a lesson can derive counters from it.
  const PassWork* frameWork(const std::string& pass) const {
    const auto it = work_.find(pass);
    return enabled_ && it != work_.end() ? &it->second : nullptr;
  }
  const std::map<std::string, long long>& lastFrameCounts() const { return last_counts_; }
  // The counters of the last frame this context could not count (pass work included).
  const std::set<std::string>& lastFrameUnavailable() const { return last_unavailable_; }
  // The shader variants the frame ran (ProgramVariants::takeUsed), kept like the counts.
  void variants(std::vector<std::string> used) { variants_ = std::move(used); }
  const std::vector<std::string>& lastFrameVariants() const { return last_variants_; }
  double lastFrameMs() const { return frame_ms_.empty() ? 0.0 : frame_ms_.back(); }
  // A page's frames on the GPU (Caps::gpu_timer): each frame's GL_TIME_ELAPSED query, read a
  // few frames later when its answer is in, the disjoint ones (the GPU's clock reset) dropped.
  // None where there is no timer.
  double medianGpuFrameMs() const { return median(gpu_frame_ms_); }
  double lastGpuFrameMs() const { return gpu_frame_ms_.empty() ? 0.0 : gpu_frame_ms_.back(); }
  size_t gpuTimedFrames() const { return gpu_frame_ms_.size(); }

 private:
  bool enabled_ = true;
  GlName<deleteQuery> query_, passed_query_;
  std::chrono::steady_clock::time_point frame_start_;
  std::vector<double> frame_ms_;
  std::map<std::string, std::vector<double>> pass_ms_;
  std::map<std::string, PassWork> work_, last_work_;
  std::map<std::string, long long> counts_, last_counts_;
  std::set<std::string> unavailable_, last_unavailable_;
  std::vector<std::string> variants_, last_variants_;
  std::vector<GlName<deleteQuery>> timers_free_, timers_asked_;  // the GPU timer's queries
  bool timing_gpu_ = false;                                      // one is running this frame
  std::vector<double> gpu_frame_ms_;
  void readGpuTimers();
};

// A count as the panel says it: the number, or "unavailable on <flavour>".
std::string countText(const std::optional<long long>& count);

// Counters a shader adds to per fragment (a storage buffer, GL 4.3; lessons 05 and 14), read
// back after the pass into the Measure under their names. Where the context has no storage
// buffers the counts are unavailable, never a wrong number.
class ShaderCounters {
 public:
  ShaderCounters() = default;
  explicit ShaderCounters(std::vector<std::string> names);  // a context is current
  // Before the pass: whether this frame counts (`wanted`, the measure on, storage buffers);
  // if so the counters are zeroed and bound to storage binding `binding`.
  bool begin(const Measure& measure, bool wanted, GLuint binding = 0);
  // After it: the counts into `measure` and last(), or each said unavailable where counting
  // was wanted and cannot be done. Nothing while the measure is off (the runner's renders
  // for the truth), and last() keeps the counted frame's.
  void end(Measure& measure);
  GLuint last(size_t k) const { return last_[k]; }

 private:
  std::vector<std::string> names_;
  CounterBuffer buffer_;
  std::vector<GLuint> last_;
  bool wanted_ = false, counting_ = false;
};

}  // namespace shadows
