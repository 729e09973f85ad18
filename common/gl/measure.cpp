#include "gl/measure.hpp"

#include "gl/caps.hpp"

#include <algorithm>

namespace shadows {

namespace {
long long g_draw_calls = 0;
double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}
}  // namespace

void countDrawCall() {
  ++g_draw_calls;
}
long long drawCallsSoFar() {
  return g_draw_calls;
}

std::string countText(const std::optional<long long>& count) {
  return count ? std::to_string(*count) : caps().unavailable();
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  double m = values[mid];
  if (values.size() % 2 == 0) {
    m = 0.5 *
        (m + *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid)));
  }
  return m;
}

Measure::Measure() {
  GLuint ids[2] = {0, 0};
  glGenQueries(2, ids);
  query_ = GlName<deleteQuery>(ids[0]);
  passed_query_ = GlName<deleteQuery>(ids[1]);
}

namespace {
// EXT_disjoint_timer_query_webgl2's names (glad's GLES 3.0 loader has no such extension).
constexpr GLenum kTimeElapsed = 0x88BF, kGpuDisjoint = 0x8FBB;
constexpr size_t kMostTimersAsked = 8;  // answers come a few frames late
}  // namespace

void Measure::beginFrame() {
  work_.clear();
  counts_.clear();
  unavailable_.clear();
  variants_.clear();
  if (!enabled_) return;
  glFinish();
  frame_start_ = std::chrono::steady_clock::now();
  if (caps().gpu_timer && timers_asked_.size() < kMostTimersAsked) {
    if (timers_free_.empty()) {
      GLuint id = 0;
      glGenQueries(1, &id);
      timers_free_.emplace_back(id);
    }
    glBeginQuery(kTimeElapsed, timers_free_.back().id());
    timing_gpu_ = true;
  }
}

void Measure::readGpuTimers() {
  // In the order asked: an answer not in yet holds the later ones back too.
  size_t read = 0;
  for (; read < timers_asked_.size(); ++read) {
    const GLuint id = timers_asked_[read].id();
    GLuint available = 0;
    glGetQueryObjectuiv(id, GL_QUERY_RESULT_AVAILABLE, &available);
    if (available == 0) break;
    GLuint nanoseconds = 0;
    glGetQueryObjectuiv(id, GL_QUERY_RESULT, &nanoseconds);
    GLint disjoint = 0;
    glGetIntegerv(kGpuDisjoint, &disjoint);
    if (disjoint == 0) gpu_frame_ms_.push_back(static_cast<double>(nanoseconds) * 1e-6);
  }
  for (size_t k = 0; k < read; ++k) timers_free_.push_back(std::move(timers_asked_[k]));
  timers_asked_.erase(timers_asked_.begin(), timers_asked_.begin() + static_cast<long>(read));
}

void Measure::endFrame() {
  if (!enabled_) return;
  if (timing_gpu_) {
    glEndQuery(kTimeElapsed);
    timers_asked_.push_back(std::move(timers_free_.back()));
    timers_free_.pop_back();
    timing_gpu_ = false;
  }
  if (caps().gpu_timer) readGpuTimers();
  glFinish();
  frame_ms_.push_back(msSince(frame_start_));
  last_work_ = work_;
  last_counts_ = counts_;
  last_unavailable_ = unavailable_;
  last_variants_ = variants_;
}

Measure::Pass::Pass(Measure* owner, std::string name, bool countPassed)
    : owner_(owner), name_(std::move(name)), count_passed_(countPassed) {
  if (owner_ == nullptr) return;
  glFinish();
  draws_at_start_ = drawCallsSoFar();
#if !SHADOWS_GLES
  if (caps().pipeline_statistics) {
    glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, owner_->query_.id());
  }
#endif
  if (count_passed_ && caps().samples_passed) {
    glBeginQuery(GL_SAMPLES_PASSED, owner_->passed_query_.id());
  }
  start_ = std::chrono::steady_clock::now();
}

namespace {
// The result of a query that has ended (waits for it). Desktop GL only: ES never starts one.
long long queryResult([[maybe_unused]] GLuint query) {
  GLuint64 value = 0;
#if !SHADOWS_GLES
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &value);
#endif
  return static_cast<long long>(value);
}
}  // namespace

Measure::Pass::~Pass() {
  if (owner_ == nullptr) return;
  const Caps& c = caps();
#if !SHADOWS_GLES
  if (c.pipeline_statistics) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
#endif
  if (count_passed_ && c.samples_passed) glEndQuery(GL_SAMPLES_PASSED);
  glFinish();
  owner_->pass_ms_[name_].push_back(msSince(start_));
  PassWork& work = owner_->work_[name_];
  work.draw_calls += drawCallsSoFar() - draws_at_start_;
  if (c.pipeline_statistics) {
    work.fragment_invocations =
        work.fragment_invocations.value_or(0) + queryResult(owner_->query_.id());
  }
  if (count_passed_) {
    work.counts_passed = true;
    if (c.samples_passed) {
      work.fragments_passed =
          work.fragments_passed.value_or(0) + queryResult(owner_->passed_query_.id());
    }
  }
}

void Measure::count(const std::string& name, long long amount) {
  if (enabled_) counts_[name] += amount;
}

void Measure::count(const std::string& name, std::optional<long long> amount) {
  if (!enabled_) return;
  if (amount) {
    counts_[name] += *amount;
  } else {
    unavailable_.insert(name);
  }
}

void Measure::clearHistory() {
  frame_ms_.clear();
  pass_ms_.clear();
  gpu_frame_ms_.clear();
}

double Measure::medianFrameMs() const {
  return median(frame_ms_);
}

std::map<std::string, double> Measure::medianPassMs() const {
  std::map<std::string, double> out;
  for (const auto& [name, times] : pass_ms_) out[name] = median(times);
  return out;
}

ShaderCounters::ShaderCounters(std::vector<std::string> names)
    : names_(std::move(names)), buffer_(static_cast<int>(names_.size())), last_(names_.size(), 0) {}

bool ShaderCounters::begin(const Measure& measure, bool wanted, GLuint binding) {
  wanted_ = wanted;
  counting_ = wanted && measure.enabled() && caps().storage_buffers;
  if (counting_) buffer_.zeroAndBind(binding);
  return counting_;
}

void ShaderCounters::end(Measure& measure) {
  if (counting_) {
    const std::vector<GLuint> counts = buffer_.read();
    for (size_t k = 0; k < names_.size(); ++k) {
      last_[k] = counts[k];
      measure.count(names_[k], static_cast<long long>(counts[k]));
    }
  } else if (wanted_ && measure.enabled()) {
    for (const std::string& name : names_) measure.count(name, std::optional<long long>());
  }
}

}  // namespace shadows
