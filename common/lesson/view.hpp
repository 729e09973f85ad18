// A view a frame renders (`--set view=NAME`), as a typed handle: a lesson declares each of its
// views once as a constant and compares frames against the constant, so a misspelled view is a
// compile error, not a branch that never runs. A string does not convert to a View.
#pragma once

#include <string>
#include <string_view>

namespace shadows {

class View {
 public:
  // `name` must outlive the View: a string literal, as every declared view's is.
  constexpr explicit View(std::string_view name) : name_(name) {}
  constexpr std::string_view name() const { return name_; }
  std::string str() const { return std::string(name_); }
  friend constexpr bool operator==(View a, View b) { return a.name_ == b.name_; }

 private:
  std::string_view name_;
};

// The views every lesson has, and those the shared code draws for the lessons that offer them.
namespace views {
inline constexpr View kShaded{"shaded"};
inline constexpr View kVisibility{"visibility"};   // the shadow term alone
inline constexpr View kTruth{"truth"};             // the ray-traced visibility (the runner's)
inline constexpr View kError{"error"};             // rendered against the truth (the runner's)
inline constexpr View kAliasing{"aliasing"};       // texels per pixel over the shaded frame
inline constexpr View kTexels{"texels"};           // the texel pass, never offered as a choice
inline constexpr View kLightDepth{"light_depth"};  // the map, as ShadowMap::drawDepthView shows it
inline constexpr View kAir{"air"};  // a medium's in-scattered light alone (08; Frame::medium)
}  // namespace views

}  // namespace shadows
