// Every parameter of every lesson does something: moved away from its default it changes
// the picture, a counter or a derived report field, and moved back it gives the very same
// frame again (a toggle that forgets to re-render, a cache key that misses an input, fail).
// Read from the lessons' own declarations, so a new parameter is covered by itself. Where a
// parameter acts only in some setting (near/far with the fit off), the setting is named here.
#include <map>
#include <set>

#include "harness.hpp"

namespace shadows {
namespace {

using testing::startLesson;

// What a frame shows and reports, less its timings and the compile count that only grows.
struct Signature {
  std::vector<std::uint8_t> pixels;
  std::string report;
  bool operator==(const Signature&) const = default;
};

Signature signature(Runner& runner) {
  runner.renderFrame();
  runner.renderFrame();  // the second frame: a cached map shows in its counters
  nlohmann::ordered_json json = testing::report(runner);
  // Timings, and the error block: there once the truth was traced, and with it every figure
  // derived from the truth (CONTRACTS.md, "Truth and error"), so none may be anywhere else.
  for (const char* timing : {"frame_ms", "pass_ms", "baseline_frame_ms", "shadow_overhead",
                             "shader_variants_compiled", "params", "error"}) {
    json.erase(timing);
  }
  // Lesson 15: how long its bake took, and whether this one came from the cache (a value
  // moved and moved back finds its bake there).
  if (json.contains("lightmap")) {
    json["lightmap"].erase("bake_seconds");
    json["lightmap"].erase("from_cache");
  }
  return {runner.readImage().rgba, json.dump()};
}

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Values other than the default, as --set text: each other choice, the other bool, and a
// number (or each component) moved well inside its range.
std::vector<std::string> otherValues(const Param& p) {
  std::vector<std::string> values;
  const double v = p.value[0];
  const double moved = v - p.min > p.max - v ? p.min + 0.1 * (v - p.min) : v + 0.1 * (p.max - v);
  switch (p.kind) {
    case ParamKind::Choice:
      for (const std::string& c : p.choices) {
        if (c != p.choice()) values.push_back(c);
      }
      break;
    case ParamKind::Bool:
      values.push_back(v != 0.0 ? "false" : "true");
      break;
    case ParamKind::Int: {
      // A narrow range (air.downsample, 1-4) rounds a tenth of it back to the default: one step.
      const double step = std::round(moved) != v   ? std::round(moved)
                          : p.max - v >= v - p.min ? v + 1.0
                                                   : v - 1.0;
      values.push_back(format(step));
      break;
    }
    case ParamKind::Float:
      values.push_back(format(moved));
      break;
    case ParamKind::Vec3:
      values.push_back(format(p.value[0] + 1.0) + "," + format(p.value[1]) + "," +
                       format(p.value[2]));
      values.push_back(format(p.value[0]) + "," + format(p.value[1] + 1.0) + "," +
                       format(p.value[2]));
      break;
    case ParamKind::String:
      break;  // image paths: the lessons' own tests load PNGs
  }
  return values;
}

// The settings in which a parameter acts, where the defaults are not one of them (each is
// what the parameter's help or its lesson's README says).
const std::vector<std::string> kNearLight = {"shadow.fit=false", "light.near=0.001"};
const std::vector<std::string> kLowProjector = {
    "light.pos=-1.2,0.5,1.8", "light.target=1.6,1.4,-1.2", "light.fov=80", "falloff=0"};
std::vector<std::string> with(std::vector<std::string> sets, const std::vector<std::string>& more) {
  sets.insert(sets.end(), more.begin(), more.end());
  return sets;
}
const std::map<std::string, std::vector<std::string>> kActsWhen = {
    // The frustum: near and far when it is not fitted to the casters, a box for directional.
    {"light.near", {"shadow.fit=false"}},
    {"light.far", {"shadow.fit=false"}},
    {"light.extent", {"light.type=directional"}},
    // 01: a point light has no target; each fix where its artifact shows.
    {"light.target", {"light.type=directional"}},
    {"fix.offset", {"fix.receiver=false"}},
    {"fix.clip", {"plane.offset=1"}},
    {"fix.homogeneous", {"light.pos=2.5,1.1,2.5"}},
    // 02: reverse projection with the other fixes off; a projector with the sphere behind it.
    {"fix.q_test", with(kLowProjector, {"fix.behind=off"})},
    {"fix.behind", {"light.pos=0.6,0.6,0.9", "light.target=0,0.6,-3"}},  // the sphere behind
    // Depth precision shows with a near plane close to the light.
    {"shadow.format", kNearLight},
    {"map.depth_bits", kNearLight},
    // 04's clamp is the gradient bias's; 05's taps are the grid's and Poisson's.
    {"bias.clamp", {"bias.mode=gradient"}},
    {"05_pcf_dithered/pcf.taps", {"pcf.mode=poisson"}},
    // 15: the map (and its frustum, bias and filter) is read in the map and hybrid modes; what
    // moves shows once something moved; baking where things stand differs once they moved.
    {"15_light_maps/shadow.size", {"lightmap.mode=map"}},
    {"15_light_maps/shadow.height", {"lightmap.mode=map"}},
    {"15_light_maps/shadow.format", with(kNearLight, {"lightmap.mode=map"})},
    {"15_light_maps/shadow.filter", {"lightmap.mode=map"}},
    {"15_light_maps/shadow.fit", {"lightmap.mode=map"}},
    {"15_light_maps/shadow.cache", {"lightmap.mode=map"}},
    {"15_light_maps/inset", {"lightmap.mode=map"}},
    {"15_light_maps/bias.factor", {"lightmap.mode=map"}},
    {"15_light_maps/bias.units", {"lightmap.mode=map"}},
    {"15_light_maps/light.fov", {"lightmap.mode=map"}},
    {"15_light_maps/light.near", {"lightmap.mode=map", "shadow.fit=false"}},
    {"15_light_maps/light.far", {"lightmap.mode=map", "shadow.fit=false"}},
    {"15_light_maps/light.extent", {"lightmap.mode=map", "light.type=directional"}},
    {"15_light_maps/move.object", {"move.x=1"}},
    {"15_light_maps/lightmap.bake_at", {"move.x=1"}},
    // 13: the depth map, its bias and its filter are PCF's; the exponent ESM's.
    {"13_filterable_maps/bias.factor", {"filter.method=pcf"}},
    {"13_filterable_maps/bias.units", {"filter.method=pcf"}},
    {"13_filterable_maps/shadow.filter", {"filter.method=pcf"}},
    {"13_filterable_maps/shadow.format", with(kNearLight, {"filter.method=pcf"})},
    {"13_filterable_maps/esm.c", {"filter.method=esm"}},
    {"13_filterable_maps/msm.bias", {"filter.method=msm"}},
    // 14: the one width is the fixed mode's (pcss derives its own).
    {"14_soft_shadows/pcf.radius", {"pcss.mode=fixed"}},
    // How the copy is made shows in its counters, on frames that render the map.
    {"map.path", {"shadow.cache=false"}},
    // 09: the caps and the far distance act in z-fail and with a finite far plane; the method
    // where auto picks z-fail for one caster; the clamp past 255 volumes; culling where a
    // volume lies out of view.
    {"volume.light_cap", {"volume.method=zfail"}},
    {"volume.dark_cap", {"volume.method=zfail"}},
    {"volume.far_distance", {"volume.far=finite"}},
    {"volume.method", {"scene=eye_in_shadow"}},
    {"stencil.op", {"scene=fence"}},
    {"volume.cull", {"camera.pos=5,3,6", "camera.target=6,0,8"}},
    // 10: plane-optimal (the default) builds its own light projection from the plane, so the
    // frustum's own settings act in the projections that use them.
    {"10_plane_optimal/light.fov", {"light.projection=uniform"}},
    {"10_plane_optimal/light.extent", {"light.projection=uniform", "light.type=directional"}},
    // The depth format shows where the warp spends depth unevenly, nothing replaces it, and the
    // near plane is close.
    {"10_plane_optimal/shadow.format",
     with(kNearLight, {"light.projection=lispsm", "depth.replace=false"})},
    {"10_plane_optimal/lispsm.n", {"light.projection=lispsm"}},
    // 11: near and far scale what the cube stores (its cross view shows it); the world bias
    // where texels are big and no normal offset hides the acne; seamless filtering where a
    // linear lookup straddles big faces' edges.
    {"11_omni_cube/light.near", {"view=cube_cross"}},
    {"11_omni_cube/light.far", {"view=cube_cross"}},
    {"11_omni_cube/bias.world", {"bias.normal=0", "cube.size=16"}},
    {"11_omni_cube/cube.seamless", {"cube.filter=linear", "cube.size=16"}},
    // 24 and 32 bits store the same 4 bytes; they differ where hyperbolic depth runs out of
    // precision: the depth store, a near plane close to the light, no bias to hide it.
    {"11_omni_cube/cube.bits",
     {"cube.store=depth", "light.near=0.001", "bias.world=0", "bias.normal=0"}},
    // 11's slope-scaled offset moves the depth store's depths, where no other bias hides it.
    {"11_omni_cube/bias.slope", {"cube.store=depth", "bias.world=0", "bias.normal=0"}},
    // 12: the depth bias acts where no normal offset already lifts the lookup off the surface.
    {"12_cascades/bias.depth", {"bias.normal=0"}},
    // Kept cascades show only while the eye moves: in the shimmer along the path, of boxes
    // that move freely.
    {"12_cascades/cascades.update", {"cascades.fit=slice", "cascades.snap=false"}},
    // 16: a knob acts while its technique draws (below, for every other knob); these also
    // need what their own lesson needs: 05's taps a Poisson disk; 14's search a light with a
    // size; cascades a sun; LiSPSM's n its projection.
    {"16_choose_your_shadow/pcf/pcf.taps", {"technique=pcf", "pcf/pcf.mode=poisson"}},
    {"16_choose_your_shadow/move.object", {"move.x=1"}},
    {"16_choose_your_shadow/pcss/pcss.search_taps", {"technique=pcss", "light.radius=0.3"}},
    {"16_choose_your_shadow/pcss/pcf.taps", {"technique=pcss", "light.radius=0.3"}},
    {"16_choose_your_shadow/cascades/cascades.count", {"technique=cascades", "scene=street"}},
    {"16_choose_your_shadow/cascades/cascades.size", {"technique=cascades", "scene=street"}},
    {"16_choose_your_shadow/cascades/cascades.blend", {"technique=cascades", "scene=street"}},
    {"16_choose_your_shadow/warped/lispsm.n",
     {"technique=warped", "warped/light.projection=lispsm"}},
};

// Lesson 16's knobs (technique/name) act while that technique draws.
std::vector<std::string> actsWhen(const std::string& lesson, const std::string& name) {
  auto it = kActsWhen.find(lesson + "/" + name);  // this lesson's own context first
  if (it != kActsWhen.end()) return it->second;
  if (const size_t slash = name.find('/'); slash != std::string::npos) {
    return {"technique=" + name.substr(0, slash)};
  }
  it = kActsWhen.find(name);
  return it != kActsWhen.end() ? it->second : std::vector<std::string>{};
}

class ParamEffects : public ::testing::TestWithParam<std::string> {};

TEST_P(ParamEffects, EveryParameterChangesSomethingAndComesBack) {
  const std::string lesson = GetParam();
  auto probe = startLesson(lesson, {}, 8, 8);
  std::vector<std::string> names;
  for (const Param& p : probe->params().all()) names.push_back(p.name);
  probe.reset();
  // One runner (one GL context) at a time: the default settings first, then each setting
  // some parameter needs.
  std::map<std::vector<std::string>, std::vector<std::string>> by_context;
  for (const std::string& name : names) by_context[actsWhen(lesson, name)].push_back(name);
  for (const auto& [context, group] : by_context) {
    auto runner = startLesson(lesson, context, 80, 60);
    for (const std::string& name : group) {
      Param& p = runner->params().at(name);
      const std::string original = p.text();  // as --set takes it
      const Signature before = signature(*runner);
      for (const std::string& value : otherValues(p)) {
        ASSERT_EQ(runner->params().set(name, value), "") << name << "=" << value;
        const Signature changed = signature(*runner);
        EXPECT_FALSE(changed == before) << lesson << ": " << name << "=" << value
                                        << " changed nothing (from " << original << ")";
        ASSERT_EQ(runner->params().set(name, original), "") << name;
        const Signature back = signature(*runner);
        EXPECT_EQ(back.report, before.report)
            << lesson << ": " << name << " back to " << original << " after " << value;
        EXPECT_TRUE(back.pixels == before.pixels)
            << lesson << ": " << name << " back to " << original << " after " << value
            << " is not the picture it was";
      }
      EXPECT_EQ(runner->glErrors(), 0) << lesson << " " << name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Lessons, ParamEffects, ::testing::ValuesIn(registeredLessons()),
                         [](const ::testing::TestParamInfo<std::string>& lesson) {
                           return lesson.param;
                         });

}  // namespace
}  // namespace shadows

namespace shadows {
namespace {

// The panel greys out what does nothing in the current settings, and says why (issue 19):
// the same settings the effects test above needs to see those parameters act.
TEST(ParamEffects, SlidersThatDoNothingNowSaySo) {
  auto runner = testing::startLesson("03_shadow_map_basic", {"shadow.fit=true"}, 8, 8);
  Params& p = runner->params();
  const auto why = [&](const std::string& name) {
    const Param& param = p.at(name);
    return param.inactive ? param.inactive(p) : std::string();
  };
  EXPECT_NE(why("light.near"), "");
  EXPECT_NE(why("light.far"), "");
  EXPECT_NE(why("light.extent"), "") << "spot by default";
  EXPECT_EQ(why("light.fov"), "");
  ASSERT_EQ(p.set("shadow.fit", "false"), "");
  ASSERT_EQ(p.set("light.type", "directional"), "");
  EXPECT_EQ(why("light.near"), "");
  EXPECT_EQ(why("light.far"), "");
  EXPECT_EQ(why("light.extent"), "");
  EXPECT_NE(why("light.fov"), "");
}

// A preset's light and eye go in as the parameters' defaults, which are clamped to their
// ranges: one outside them (lesson 12's sun first aimed 96 units down the street, past
// light.target's 50) would silently become another light. Each lesson's scenes, as placed.
TEST(ScenePresets, EveryLessonsScenesPlaceTheLightAndTheEyeWhereThePresetSays) {
  for (const std::string& lesson : registeredLessons()) {
    for (const std::string& name : makeLesson(lesson)->scenes()) {
      RunOptions options;
      options.headless = true;
      Runner runner(lesson, makeLesson(lesson), options);  // no GL: parameters only
      ASSERT_EQ(runner.applySets({"scene=" + name}), "") << lesson << " " << name;
      const Scene scene = makeScene(name);
      const Params& p = runner.params();
      const std::string where = lesson + " scene=" + name;
      EXPECT_EQ(p.at("light.pos").v(), scene.light.position) << where;
      if (const Param* target = p.find("light.target")) {
        EXPECT_EQ(target->v(), scene.light.target) << where;
      }
      EXPECT_EQ(p.at("camera.pos").v(), scene.camera.position) << where;
      EXPECT_EQ(p.at("camera.target").v(), scene.camera.target) << where;
      EXPECT_EQ(p.at("camera.fov").f(), scene.camera.fov) << where;
    }
  }
}

}  // namespace
}  // namespace shadows
