#include "measure.hpp"

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

void Measure::beginFrame() {
  work_.clear();
  counts_.clear();
  variants_.clear();
  if (!enabled_) return;
  glFinish();
  frame_start_ = std::chrono::steady_clock::now();
}

void Measure::endFrame() {
  if (!enabled_) return;
  glFinish();
  frame_ms_.push_back(msSince(frame_start_));
  last_work_ = work_;
  last_counts_ = counts_;
  last_variants_ = variants_;
}

Measure::Pass::Pass(Measure* owner, std::string name, bool countPassed)
    : owner_(owner), name_(std::move(name)), count_passed_(countPassed) {
  if (owner_ == nullptr) return;
  glFinish();
  draws_at_start_ = drawCallsSoFar();
  glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, owner_->query_.id());
  if (count_passed_) glBeginQuery(GL_SAMPLES_PASSED, owner_->passed_query_.id());
  start_ = std::chrono::steady_clock::now();
}

Measure::Pass::~Pass() {
  if (owner_ == nullptr) return;
  glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
  if (count_passed_) glEndQuery(GL_SAMPLES_PASSED);
  glFinish();
  owner_->pass_ms_[name_].push_back(msSince(start_));
  GLuint64 fragments = 0;
  glGetQueryObjectui64v(owner_->query_.id(), GL_QUERY_RESULT, &fragments);
  PassWork& work = owner_->work_[name_];
  work.draw_calls += drawCallsSoFar() - draws_at_start_;
  work.fragment_invocations += static_cast<long long>(fragments);
  if (count_passed_) {
    GLuint64 passed = 0;
    glGetQueryObjectui64v(owner_->passed_query_.id(), GL_QUERY_RESULT, &passed);
    work.fragments_passed = std::max(work.fragments_passed, 0LL) + static_cast<long long>(passed);
  }
}

void Measure::count(const std::string& name, long long amount) {
  if (enabled_) counts_[name] += amount;
}

void Measure::clearHistory() {
  frame_ms_.clear();
  pass_ms_.clear();
}

double Measure::medianFrameMs() const {
  return median(frame_ms_);
}

std::map<std::string, double> Measure::medianPassMs() const {
  std::map<std::string, double> out;
  for (const auto& [name, times] : pass_ms_) out[name] = median(times);
  return out;
}

}  // namespace shadows
