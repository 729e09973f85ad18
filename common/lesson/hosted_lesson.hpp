// A lesson run inside another: lesson 16 draws one scene with the technique of each lesson that
// teaches one, by running that lesson's own code, not a copy of it. The hosted lesson keeps
// Params of its own, so two lessons' parameters never meet (05's pcf.taps is not 14's), and
// draws through the host's frame. What it takes from the host, each frame:
//   - the runner's parameters (scene, view, light, camera) and any of the host's own that it
//     also declares (dimming, shadow.off), by the same name;
//   - its knobs: parameters of its own the host offers as `key/name` (pcf/pcf.taps);
//   - its ties: a host parameter under another name (light.radius -> pcss.light_radius).
// Everything else stays at the lesson's defaults, or at the settings its Spec gives.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lesson/lesson.hpp"

namespace shadows {

class HostedLesson {
 public:
  struct Spec {
    std::string key;                 // the host's name for it, and its knobs' prefix
    std::string lesson;              // as registered: "05_pcf_dithered"
    std::vector<std::string> sets;   // its settings here (name=value), before any knob
    std::vector<std::string> knobs;  // its parameters the host offers, as key/name
    std::vector<std::pair<std::string, std::string>> ties;  // host name -> the lesson's name
  };
  explicit HostedLesson(Spec spec);
  HostedLesson(const HostedLesson&) = delete;  // its knobs' reasons point at it
  HostedLesson& operator=(const HostedLesson&) = delete;

  const Spec& spec() const { return spec_; }
  Lesson& lesson() { return *lesson_; }
  const Lesson& lesson() const { return *lesson_; }
  Params& params() { return params_; }
  const Params& params() const { return params_; }
  // The host's name for one of its parameters: "pcf/pcf.taps".
  std::string knob(const std::string& name) const { return spec_.key + "/" + name; }

  // Declares the lesson into its own Params (with the host's scene and view, and its Spec's
  // settings) and its knobs into the host's, at the lesson's values. On the host's panel a knob
  // is not drawn while `idle` gives a reason ("" while this lesson is the one in use), and is
  // greyed out for the lesson's own. Throws std::logic_error on a Spec that names what the
  // lesson does not have.
  void declare(Params& host, std::function<std::string(const Params&)> idle);
  // GL resources, once the runner has declared its shared parameters into `host` (the lesson
  // gets a copy of each it does not declare itself).
  void init(const Params& host);
  // The host's values into the lesson's parameters. Values only: a host hands the lesson its
  // own dirty bits (markDirty), which every change to its parameters sets as this lesson's
  // parameter of the same name (or knob, or tie) would.
  void sync(const Params& host);
  // A map to render again, a texture to re-create: what the host was told (its dirty bits,
  // which it consumes once for all the lessons it hosts) is this lesson's to act on too.
  void markDirty(std::uint32_t bits) { params_.markDirty(bits); }
  // Renders the lesson into `f`'s target with its own parameters; its outputs go into `f`.
  void render(Frame& f);
  // The texture storage it holds now (its maps, their copies and blurs), created in its init
  // and render.
  long long textureBytes() const { return bytes_.bytes(); }

 private:
  Spec spec_;
  TextureBytes bytes_;  // before the lesson: its textures leave the tally as they go
  std::unique_ptr<Lesson> lesson_;
  Params params_;
};

}  // namespace shadows
