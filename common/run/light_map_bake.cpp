#include "run/light_map_bake.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/text.hpp"
#include "truth/truth_job.hpp"

namespace shadows {

struct LightMapBaker::Running {
  TruthJob job;
  TraceControl control;
  std::future<std::vector<float>> result;
  std::chrono::steady_clock::time_point began = std::chrono::steady_clock::now();
  std::string cache_path;
  bool page = false;  // traced by the page's bake workers: no future, poll() takes the answer
};

namespace {

std::string hex(std::uint64_t id) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(id));
  return text;
}

bool terminal() {
  return isatty(STDERR_FILENO) != 0;
}

// The cache keeps the newest bakes up to 256 MB: `bake_at=current` bakes again at every move.
void trimCache(const std::filesystem::path& dir) {
  constexpr std::uintmax_t kKeep = 256u << 20;
  std::error_code ec;
  std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> bakes;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("lightmap-", 0) == 0 && entry.path().extension() == ".trace") {
      bakes.emplace_back(entry.last_write_time(ec), entry.path());
    }
  }
  std::sort(bakes.begin(), bakes.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::uintmax_t total = 0;
  for (const auto& [time, path] : bakes) {
    total += std::filesystem::file_size(path, ec);
    if (total > kKeep) std::filesystem::remove(path, ec);
  }
}

// A bake kept on disk for job `id` (`texels` values), or none: no file, or one that is
// damaged or answers another bake, which is never believed (said once, baked again and
// written over).
std::optional<std::vector<float>> readCachedBake(const std::string& path, std::uint64_t id,
                                                 size_t texels) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::string damage;
  try {
    // readTruthTrace refuses a size its header does not give, and values no bake can have
    // (NaN, outside [0, 1]).
    TruthTrace trace = readTruthTrace(path);
    if (trace.job_id == id && trace.visibility.size() == texels) {
      return std::move(trace.visibility);
    }
    damage = "it answers another bake";
  } catch (const std::exception& e) {
    damage = e.what();
  }
  std::fprintf(stderr, "light map: the cached bake is damaged (%s): baking it again\n",
               printable(damage).c_str());
  return std::nullopt;
}

}  // namespace

LightMapBaker::LightMapBaker() = default;

LightMapBaker::~LightMapBaker() {
  cancel();
}

LightMapBaker::CacheDirectory LightMapBaker::cacheDirectory() {
#ifdef __EMSCRIPTEN__
  return {"", "a page keeps no disk cache"};
#else
  if (const char* dir = std::getenv("SHADOWS_CACHE"); dir != nullptr && *dir != '\0') {
    if (std::string(dir) == "off") return {"", "SHADOWS_CACHE=off"};
    return {dir, ""};
  }
  // A folder of the user's that is there and writable; never one this run would have to create.
  const auto usable = [](const char* dir) {
    std::error_code ec;
    return dir != nullptr && *dir == '/' && std::filesystem::is_directory(dir, ec) &&
           access(dir, W_OK | X_OK) == 0;
  };
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (usable(xdg)) return {std::string(xdg) + "/shadows", ""};
  const char* home = std::getenv("HOME");
  if (usable(home)) return {std::string(home) + "/.cache/shadows", ""};
  std::string why = "HOME (unset)";
  if (home != nullptr) why = "HOME '" + std::string(home) + "'";
  why += " is not a folder this user can write, nor is XDG_CACHE_HOME";
  return {"", why};
#endif
}

void LightMapBaker::start(BakeRequest request, bool wait) {
  TruthJob job;
  job.positions = std::move(request.positions);
  job.triangles = std::move(request.triangles);
  job.scene_radius = request.scene_radius;
  job.surface = std::move(request.texels);
  job.light = request.light;
  const std::uint64_t id = job.id();
  if (state_.id == id &&
      (state_.stage == BakeState::Stage::kRunning || state_.stage == BakeState::Stage::kDone)) {
    return;  // running or done for these very inputs (a failed or cancelled one starts again)
  }
  cancel();
  state_ = BakeState{};
  state_.id = id;
  state_.stage = BakeState::Stage::kRunning;
  // The texels the tracer casts rays from: on a surface that faces the light (countedPixel).
  long long texels = 0;
  for (size_t i = 0; i < job.surface.position.size(); ++i) {
    glm::vec3 p, n;
    float ndotl = 0.0f;
    texels += countedPixel(job.surface, i, job.light, p, n, ndotl) ? 1 : 0;
  }
  state_.rays = texels * job.light.raysPerPoint();

  auto running = std::make_unique<Running>();
  const CacheDirectory dir = cacheDirectory();
  if (!dir.path.empty()) {
    running->cache_path = dir.path + "/lightmap-" + hex(id) + ".trace";
    if (std::optional<std::vector<float>> kept =
            readCachedBake(running->cache_path, id, job.surface.position.size())) {
      state_.stage = BakeState::Stage::kDone;
      state_.from_cache = true;
      state_.progress = 1.0;
      state_.message = "loaded from " + running->cache_path;
      state_.visibility = std::make_shared<const std::vector<float>>(std::move(*kept));
      return;
    }
  } else {
    state_.message = "no disk cache: " + dir.why;
    static bool said = false;  // once a run: a window may bake many times
    if (!said && dir.why != "SHADOWS_CACHE=off") {
      said = true;
      std::fprintf(stderr, "light map: no disk cache (%s); bakes are not kept\n",
                   printable(dir.why).c_str());
    }
  }
  running->job = std::move(job);
#ifdef __EMSCRIPTEN__
  // The page's bake workers, while frames go on; where it has none (or must wait), this thread.
  if (!wait && postBakeJob(serializeTruthJob(running->job))) {
    running->page = true;
    running_ = std::move(running);
    return;
  }
  running_ = std::move(running);
  std::promise<std::vector<float>> answer;
  try {
    answer.set_value(makeTruthTracer(running_->job)->trace(running_->job).visibility);
  } catch (...) {
    answer.set_exception(std::current_exception());
  }
  running_->result = answer.get_future();
  finish();
#else
  Running* r = running.get();
  r->result = std::async(std::launch::async, [r] {
    const Truth truth(r->job.positions, r->job.triangles, r->job.scene_radius);
    return truth.visibility(r->job.surface, r->job.light, &r->control);
  });
  running_ = std::move(running);
  if (!wait) return;
  while (running_->result.wait_for(std::chrono::milliseconds(250)) != std::future_status::ready) {
    poll();
  }
  finish();
#endif
}

const BakeState& LightMapBaker::poll() {
  if (!running_) return state_;
#ifdef __EMSCRIPTEN__
  if (running_->page) {
    PageTraceAnswer answer = takeBakeTrace();
    if (answer.state == PageTraceAnswer::State::kNone) {
      state_.progress = std::max(bakeTraceProgress(), 0.0);
      return state_;
    }
    std::promise<std::vector<float>> result;
    if (answer.state == PageTraceAnswer::State::kFailed) {
      result.set_exception(std::make_exception_ptr(
          std::runtime_error("the page's bake workers failed (see the console)")));
    } else {
      TruthTrace trace = parseTruthTrace(answer.trace_bytes);
      if (trace.job_id != state_.id) return state_;  // a replaced bake's answer
      result.set_value(std::move(trace.visibility));
    }
    running_->result = result.get_future();
    finish();
    return state_;
  }
#endif
  if (running_->result.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    finish();
    return state_;
  }
  const int rows = std::max(running_->job.surface.height, 1);
  state_.progress = static_cast<double>(running_->control.rows_done.load()) / rows;
  const auto now = std::chrono::steady_clock::now();
  if (terminal() && now - printed_ > std::chrono::milliseconds(500)) {
    printed_ = now;
    std::fprintf(stderr, "\rbaking the light map: %3.0f %% (%.1f s)", 100.0 * state_.progress,
                 std::chrono::duration<double>(now - running_->began).count());
    std::fflush(stderr);
  }
  return state_;
}

void LightMapBaker::finish() {
  std::unique_ptr<Running> r = std::move(running_);
  state_.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - r->began).count();
  if (terminal() && printed_ != std::chrono::steady_clock::time_point{}) {
    std::fprintf(stderr, "\r%60s\r", "");  // the progress line goes, the report says the rest
  }
  printed_ = {};
  try {
    std::vector<float> visibility = r->result.get();
    if (r->control.cancel.load()) {
      state_.stage = BakeState::Stage::kCancelled;
      state_.message = "cancelled";
      return;
    }
    state_.stage = BakeState::Stage::kDone;
    state_.progress = 1.0;
    if (!r->cache_path.empty()) {
      TruthTrace trace;
      trace.job_id = state_.id;
      trace.width = r->job.surface.width;
      trace.height = r->job.surface.height;
      trace.visibility = visibility;
      // Written whole, then renamed: a bake cut short leaves no half file behind.
      const bool kept = keepTruthTrace(r->cache_path, trace);
      state_.message =
          kept ? "kept in " + r->cache_path : "not kept: cannot write " + r->cache_path;
      if (kept) trimCache(std::filesystem::path(r->cache_path).parent_path());
    }
    state_.visibility = std::make_shared<const std::vector<float>>(std::move(visibility));
  } catch (const std::exception& e) {
    state_.stage = BakeState::Stage::kFailed;
    state_.message = e.what();
  }
}

void LightMapBaker::cancel() {
  if (!running_) return;
  if (running_->page) {  // the workers finish it; a later bake's post replaces it there
    running_.reset();
    state_.stage = BakeState::Stage::kCancelled;
    state_.message = "cancelled";
    return;
  }
  running_->control.cancel = true;
  running_->result.wait();
  finish();
}

}  // namespace shadows
