// A parameter is declared once (name, default, range, help). From that one declaration it
// gets its ImGui widget, `--set name=value`, its `--list-params` line and its report value.
// Changing one marks what depends on it dirty, so lessons redo only that work.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace shadows {

class JsonWriter;

// What a parameter change invalidates. Lessons test these bits to skip work.
enum DirtyBits : std::uint32_t {
  kDirtyNothing = 0,
  kDirtyShadowMap = 1u << 0,  // the shadow map must be rendered again
  kDirtyScene = 1u << 1,      // objects or the scene preset changed
  kDirtyResources = 1u << 2,  // textures must be re-created (size, format)
  kDirtyView = 1u << 3,       // only the eye view changes
  kDirtyAll = 0xffffffffu,
};

class Params;

enum class ParamKind { Float, Int, Bool, Vec3, Choice, String };

struct Param {
  std::string name;
  std::string help;
  ParamKind kind = ParamKind::Float;
  double value[3] = {0, 0, 0};
  double fallback[3] = {0, 0, 0};  // the declared default
  double min = 0, max = 1;
  bool logarithmic = false;
  std::vector<std::string> choices;
  std::string string_value, string_fallback;  // String kind (e.g. a file path)
  std::uint32_t affects = kDirtyView;
  // Declared by a technique several lessons share (common/shadow: the map's size, format,
  // filter, ...), not by the lesson's own main.cpp: the panel folds these below the lesson's
  // own sliders, unless the lesson claims them as its idea (Params::claim).
  bool shared = false;
  // Optional extra check of a value that already parsed (say, a file that must load):
  // returns "" or what is wrong, and set() then refuses the value with that message.
  std::function<std::string(const std::string&)> check;
  // Optional: "" while the parameter acts, else why it does nothing in the current settings
  // (light.near while shadow.fit is on). The panel greys the widget out and says why.
  std::function<std::string(const Params&)> inactive;
  // Optional: true while the panel should not draw the widget at all (lesson 16: the knobs of
  // the techniques not in use), where greyed widgets would only crowd it.
  std::function<bool(const Params&)> hidden;
  // Where the panel drew its widget last frame (ImGui screen coordinates, y down), so a test
  // or a tutorial script can aim the mouse at it.
  glm::vec2 widget_min{0.0f}, widget_max{0.0f};

  float f() const { return static_cast<float>(value[0]); }
  int i() const { return static_cast<int>(value[0]); }
  bool b() const { return value[0] != 0.0; }
  glm::vec3 v() const {
    return {static_cast<float>(value[0]), static_cast<float>(value[1]),
            static_cast<float>(value[2])};
  }
  const std::string& choice() const { return choices[static_cast<size_t>(value[0])]; }
  const std::string& s() const { return string_value; }
  bool is(const std::string& choiceName) const { return choice() == choiceName; }
  std::string text() const;  // the value as --set would take it
  bool atDefault() const {   // the declared (or the preset's) default
    return std::equal(std::begin(value), std::end(value), std::begin(fallback)) &&
           string_value == string_fallback;
  }
  // Declaration helpers: p.addFloat(...).logScale(), p.addString(...).checkedBy(fn).
  Param& logScale() {  // a slider that moves in decades
    logarithmic = true;
    return *this;
  }
  Param& checkedBy(std::function<std::string(const std::string&)> extraCheck) {
    check = std::move(extraCheck);
    return *this;
  }
  // The value as shader #defines, named after the parameter ("pcf.mode" -> PCF_MODE): a
  // choice defines one name per choice and itself as the current one (PCF_MODE_NONE 0, ...,
  // PCF_MODE PCF_MODE_GRID), so a shader reads `#if PCF_MODE == PCF_MODE_GRID`; a bool or an
  // int defines its value (PCF_EARLY_OUT 1).
  std::vector<std::string> defines() const;
};

// The #defines for a choice `macro` among `choices` set to `current` (Param::defines' rule,
// for choices that are not one parameter, like the frame's view).
std::vector<std::string> choiceDefines(const std::string& macro,
                                       const std::vector<std::string>& choices,
                                       const std::string& current);

// A declared parameter as a lesson keeps it from declare(): typed, and read while rendering
// without a lookup by name. `dimming_ = p.addFloat("dimming", ...)`, then `dimming_()`.
template <typename T>
class ParamRef {
 public:
  ParamRef() = default;
  ParamRef(Param& p);  // NOLINT(google-explicit-constructor): from Params::add*()
  T operator()() const;
  Param& param() const { return *param_; }
  std::vector<std::string> defines() const { return param_->defines(); }

 private:
  Param* param_ = nullptr;
};
using FloatParam = ParamRef<float>;
using IntParam = ParamRef<int>;
using BoolParam = ParamRef<bool>;
using Vec3Param = ParamRef<glm::vec3>;
using StringParam = ParamRef<std::string>;

// A choice read as the enum whose order its declaration lists (or as an index).
template <typename Enum = int>
class ChoiceParam {
 public:
  ChoiceParam() = default;
  ChoiceParam(Param& p);  // NOLINT(google-explicit-constructor): from Params::addChoice()
  Enum operator()() const { return static_cast<Enum>(param_->i()); }
  const std::string& name() const { return param_->choice(); }
  bool valid() const { return param_ != nullptr; }  // declared (some lessons leave one out)
  Param& param() const { return *param_; }
  std::vector<std::string> defines() const { return param_->defines(); }

 private:
  Param* param_ = nullptr;
};

// Levenshtein distance: the edits between two names, for "did you mean" (at most 3).
size_t editDistance(const std::string& a, const std::string& b);

class Params {
 public:
  Param& addFloat(const std::string& name, float def, float min, float max, const std::string& help,
                  std::uint32_t affects = kDirtyView);
  Param& addInt(const std::string& name, int def, int min, int max, const std::string& help,
                std::uint32_t affects = kDirtyView);
  Param& addBool(const std::string& name, bool def, const std::string& help,
                 std::uint32_t affects = kDirtyView);
  Param& addVec3(const std::string& name, glm::vec3 def, float min, float max,
                 const std::string& help, std::uint32_t affects = kDirtyView);
  Param& addChoice(const std::string& name, const std::vector<std::string>& choices,
                   const std::string& def, const std::string& help,
                   std::uint32_t affects = kDirtyView);
  // Free text (a file path, say): --set name=any text; an InputText in the panel, applied
  // on Enter. Give the returned Param a `check` to refuse values that cannot be used.
  Param& addString(const std::string& name, const std::string& def, const std::string& help,
                   std::uint32_t affects = kDirtyView);

  // Adds a parameter declared elsewhere (the runner's shared ones), default included.
  Param& add(Param p);
  // While one lives, what is declared is marked shared (Param::shared): the shared
  // techniques' constructors hold one.
  class SharedScope {
   public:
    explicit SharedScope(Params& p) : params_(p), was_(p.sharing_) { p.sharing_ = true; }
    ~SharedScope() { params_.sharing_ = was_; }
    SharedScope(const SharedScope&) = delete;
    SharedScope& operator=(const SharedScope&) = delete;

   private:
    Params& params_;
    bool was_;
  };
  // While set, a parameter for which `why` says something is drawn locked (greyed, its
  // tooltip saying why): an exercise's sliders that are not the student's to move. --set and
  // the program itself still change it.
  void lockWidgets(std::function<std::string(const Param&)> why) { locked_ = std::move(why); }
  // A lesson whose idea is a shared technique's settings (03: the shadow map itself) claims
  // them: the parameters whose names start with `prefix` are its own on the panel.
  void claim(const std::string& prefix);
  Param* find(const std::string& name);
  const Param* find(const std::string& name) const;
  Param& at(const std::string& name);  // throws std::out_of_range naming the parameter
  const Param& at(const std::string& name) const;
  const std::deque<Param>& all() const { return params_; }

  // Parses and applies `value`; returns "" on success, else one line naming the parameter
  // and what is allowed. A failed set changes nothing.
  std::string set(const std::string& name, const std::string& value);
  // Applies "name=value"; same contract.
  std::string assign(const std::string& assignment);
  // Programmatic updates (slider drags, presets); clamps to range and marks dirty.
  void setFloat(Param& p, double v);
  void setVec3(Param& p, glm::vec3 v);
  void setChoice(Param& p, const std::string& choiceName);
  // Every parameter back to its default (the preset's, where a preset set one).
  void resetToDefaults();
  // A preset changes a default too, so "reset" goes back to the preset's value.
  void setDefaultVec3(Param& p, glm::vec3 v);
  void setDefaultFloat(Param& p, double v);
  void setDefaultChoice(Param& p, const std::string& choiceName);

  // One ImGui widget per parameter whose name starts with `prefix` ("" = all).
  // Returns true when any changed.
  bool drawWidgets(const std::string& prefix = {});
  // One widget per parameter `which` accepts.
  bool drawWidgets(const std::function<bool(const Param&)>& which);
  std::string listText() const;  // --list-params
  void writeJson(JsonWriter& json) const;

  std::uint32_t dirty() const { return dirty_; }
  void markDirty(std::uint32_t bits) { dirty_ |= bits; }
  // Returns whether any of `bits` were dirty and clears them.
  bool consume(std::uint32_t bits) {
    const bool any = (dirty_ & bits) != 0;
    dirty_ &= ~bits;
    return any;
  }

 private:
  void changed(Param& p) { dirty_ |= p.affects; }
  std::deque<Param> params_;  // deque: references stay valid as params are added
  // String widgets: the text being typed (applied on Enter) and the last refusal.
  std::map<std::string, std::string> editing_, refused_;
  std::uint32_t dirty_ = kDirtyAll;
  bool sharing_ = false;  // a SharedScope is open
  std::function<std::string(const Param&)> locked_;
};

// Handles check their parameter's kind once, when the lesson takes them (a wrong kind is a
// programming error: std::logic_error naming the parameter).
void requireKind(const Param& p, ParamKind kind);

template <typename T>
constexpr ParamKind kindOf() {
  if constexpr (std::is_same_v<T, float>) return ParamKind::Float;
  if constexpr (std::is_same_v<T, int>) return ParamKind::Int;
  if constexpr (std::is_same_v<T, bool>) return ParamKind::Bool;
  if constexpr (std::is_same_v<T, glm::vec3>) return ParamKind::Vec3;
  if constexpr (std::is_same_v<T, std::string>) return ParamKind::String;
}

template <typename T>
ParamRef<T>::ParamRef(Param& p) : param_(&p) {
  requireKind(p, kindOf<T>());
}

template <typename T>
T ParamRef<T>::operator()() const {
  if constexpr (std::is_same_v<T, float>) return param_->f();
  if constexpr (std::is_same_v<T, int>) return param_->i();
  if constexpr (std::is_same_v<T, bool>) return param_->b();
  if constexpr (std::is_same_v<T, glm::vec3>) return param_->v();
  if constexpr (std::is_same_v<T, std::string>) return param_->s();
}

template <typename Enum>
ChoiceParam<Enum>::ChoiceParam(Param& p) : param_(&p) {
  requireKind(p, ParamKind::Choice);
}

}  // namespace shadows
