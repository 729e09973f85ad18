// A lesson inside another (hosted_lesson.hpp): its own parameters, the host's frame.
#include "lesson/hosted_lesson.hpp"

#include <algorithm>
#include <stdexcept>

namespace shadows {

namespace {

// `from`'s value into `to` (a parameter of the same name, a knob's or a tie's), clamped to
// `to`'s range. A choice goes by its name, and only to a choice `to` has (the host's view `air`
// is not a hosted lesson's).
void copyValue(const Param& from, Param& to) {
  if (from.kind != to.kind) return;
  if (to.kind == ParamKind::Choice) {
    const auto it = std::find(to.choices.begin(), to.choices.end(), from.choice());
    if (it != to.choices.end()) to.value[0] = static_cast<double>(it - to.choices.begin());
  } else if (to.kind == ParamKind::String) {
    to.string_value = from.string_value;
  } else {
    for (int i = 0; i < (to.kind == ParamKind::Vec3 ? 3 : 1); ++i) {
      to.value[i] = std::clamp(from.value[i], to.min, to.max);
    }
  }
}

}  // namespace

HostedLesson::HostedLesson(Spec spec) : spec_(std::move(spec)) {}

void HostedLesson::declare(Params& host, std::function<std::string(const Params&)> idle) {
  lesson_ = makeLesson(spec_.lesson);  // throws std::invalid_argument for an unknown name
  // The runner's two choices before a lesson declares, as the runner declares them for it: the
  // scene, and every view the lesson has (its shaders #define each: OpenGL ES refuses an
  // undefined name in #if).
  params_.add(host.at("scene"));
  std::vector<std::string> names;
  for (const View& v : lesson_->views()) names.push_back(v.str());
  params_.addChoice("view", names, names.front(), host.at("view").help);
  lesson_->declare(params_);
  for (const std::string& s : spec_.sets) {
    if (std::string e = params_.assign(s); !e.empty()) {
      throw std::logic_error(spec_.lesson + " hosted as " + spec_.key + ": " + e);
    }
  }
  for (const std::string& name : spec_.knobs) {
    Param p = params_.at(name);  // throws, naming it, where the lesson has no such parameter
    p.name = knob(name);
    p.shared = false;
    p.hidden = [idle](const Params& h) { return !idle(h).empty(); };
    p.inactive = [this, idle, name](const Params& h) {
      std::string why = idle(h);
      if (!why.empty()) return why;
      const Param& mine = params_.at(name);
      return mine.inactive ? mine.inactive(params_) : std::string();
    };
    host.add(std::move(p));
  }
  for (const auto& [from, to] : spec_.ties) params_.at(to);  // throws where it has none
}

void HostedLesson::init(const Params& host) {
  for (const Param& p : host.all()) {
    if (p.name.find('/') == std::string::npos && params_.find(p.name) == nullptr) params_.add(p);
  }
  const TextureBytes::Scope counted(bytes_);
  lesson_->init();
}

void HostedLesson::sync(const Params& host) {
  // Values only: what a change dirties reaches this lesson as the host's dirty bits
  // (markDirty), the same bits as its own parameter's. So what changes the host silently
  // stays silent here too: the runner's frames without shadow turn shadow.off on and off and
  // leave the map alone (CONTRACTS.md, baseline_frame_ms).
  const auto take = [&](const Param* from, const std::string& name) {
    Param* to = params_.find(name);
    if (from != nullptr && to != nullptr) copyValue(*from, *to);
  };
  for (const Param& mine : params_.all()) {
    const bool knob =
        std::find(spec_.knobs.begin(), spec_.knobs.end(), mine.name) != spec_.knobs.end();
    take(host.find(knob ? this->knob(mine.name) : mine.name), mine.name);
  }
  for (const auto& [from, to] : spec_.ties) take(host.find(from), to);
}

void HostedLesson::render(Frame& f) {
  Frame mine(f.runner, params_, f.scene, f.measure, f.light);
  mine.view = f.view;
  mine.projection = f.projection;
  mine.eye = f.eye;
  mine.width = f.width;
  mine.height = f.height;
  mine.target = f.target;
  mine.shown = f.shown;
  mine.input_moving = f.input_moving;
  {
    const TextureBytes::Scope counted(bytes_);
    lesson_->render(mine);
  }
  f.light_view_projection = mine.light_view_projection;
  f.light_reach = mine.light_reach;
  f.truth_area_radius = mine.truth_area_radius;
  f.medium = mine.medium;
  f.shadow_sampling = mine.shadow_sampling;
}

}  // namespace shadows
