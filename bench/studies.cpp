// The studies across lessons: sweeps whose bundles pick the lesson that renders them
// (`lesson=NAME`). A lesson's own sweep is in its directory (NN_name/sweep.cpp).
#include <algorithm>

#include "bench.hpp"

namespace shadows::bench {
namespace {

// What a shadow costs (issue 10): every lesson with a shadow.off baseline, at its defaults,
// its frame against the same frame with no shadow work, interleaved in one run, with the map
// cached (a static scene) and re-rendered every frame. A new lesson with the baseline joins by
// itself; instrumentation (a `*.count` switch) is off, since it is not the shadow.
Sweep shadowCostSweep() {
  Axis lessons{"lesson_tag", {}};
  const std::vector<std::string> hosts = registeredHosts();
  for (const std::string& name : registeredLessons()) {
    // A lesson that hosts others (16) costs what its techniques cost, each measured here as
    // its own lesson.
    if (std::find(hosts.begin(), hosts.end(), name) != hosts.end()) continue;
    Runner probe(name, makeLesson(name), RunOptions{});  // parameters only, no GL
    // A map to cache is what the study's shadow.cache axis varies: lesson 09's volumes have
    // none (their cost against 03 and 05 is volumes_vs_maps below).
    if (probe.params().find("shadow.off") == nullptr) continue;
    if (probe.params().find("shadow.cache") == nullptr) continue;
    std::string bundle = name.substr(0, 2) + ":lesson=" + name;
    for (const Param& p : probe.params().all()) {
      if (p.kind == ParamKind::Bool && p.name.ends_with(".count"))
        bundle += " " + p.name + "=false";
    }
    lessons.values.push_back(bundle);
  }
  return {.scenes = {"torus_pyramid", "grazing", "dueling", "cubes"},
          .axes = {{"shadow.off", {"false", "true"}}, lessons, {"shadow.cache", {"true", "false"}}},
          .fixed = {"inset=false"},
          .plot_metrics = {"vis_mae"},
          .study = true};
}

// Seed 000's claim in numbers, one variable at a time: a light "too close throws away
// valuable depth map precision when using a projective frustum". With projective depth one
// step at distance z is z^2 (f - n) / (f n 2^bits): near decides, far barely matters. So near
// moves with far held at 100, and far moves with near held at 1; every point sets its own
// frustum (no fit), every map is 1024², every technique keeps its own lesson's default bias
// (04's back faces + (1.1, 4) for the depth textures).
std::vector<std::string> precisionMaps() {
  return {"8bit_projective:lesson=06_dual_texture_8bit",
          "8bit_linear:lesson=06_dual_texture_8bit map.encoding=linear",
          "16bit_two_digits:lesson=07_multidigit_16bit",
          "D16:lesson=04_bias_offset shadow.format=16",
          "D24:lesson=04_bias_offset shadow.format=24",
          "D32F:lesson=04_bias_offset shadow.format=32f"};
}

Sweep precisionStudy(Axis along) {
  return {.scenes = {"torus_pyramid", "dueling"},
          .axes = {std::move(along), {"map", precisionMaps()}},
          .fixed = {"shadow.cache=false", "inset=false", "shadow.size=1024", "shadow.fit=false"},
          .plot_metrics = {"false_shadow_pct", "false_lit_pct"},
          .plot_along = true,
          .study = true};
}

Sweep precisionNearStudy() {
  Axis near{"light_near", {}};
  for (const char* n : {"4", "2", "1", "0.5", "0.3", "0.2", "0.1", "0.05"}) {
    near.values.push_back(std::string(n) + ":light.near=" + n + " light.far=100");
  }
  return precisionStudy(near);
}

Sweep precisionFarStudy() {
  Axis far{"light_far", {}};
  for (const char* f : {"12", "24", "50", "100", "250", "1000"}) {
    far.values.push_back(std::string(f) + ":light.near=1 light.far=" + f);
  }
  return precisionStudy(far);
}

// What PCF's taps cost (issues 10, 20): lesson 05's eye pass against the same pass with no
// shadow work, for one tap, a 3x3 grid with every tap taken, the grid with its early out, the
// default 4 dithered taps and a 16-tap Poisson disk (early out); the map rendered every frame,
// the counting off, on the preset of cubes and the default one.
Sweep pcfCostStudy() {
  const std::string lesson = "lesson=05_pcf_dithered pcf.radius=1.5 ";
  const std::string grid = lesson + "pcf.mode=grid pcf.taps=9";
  return {.scenes = {"cubes", "torus_pyramid"},
          .axes = {{"shadow.off", {"false", "true"}},
                   {"kernel",
                    {"none:lesson=05_pcf_dithered pcf.mode=none",
                     "grid3x3:" + grid + " pcf.early_out=false",
                     "grid3x3_early_out:" + grid + " pcf.early_out=true",
                     // The same every-tap grid read by the shader's fetch or by gathers (issue
                     // 40): on llvmpipe within 4 % of the compare; a GPU's texture units decide.
                     "grid3x3_fetch:" + grid + " pcf.early_out=false pcf.lookup=fetch",
                     "grid3x3_gather:" + grid + " pcf.early_out=false pcf.lookup=gather",
                     "dithered:" + lesson + "pcf.mode=dithered",
                     "poisson16:" + lesson + "pcf.mode=poisson pcf.taps=16"}}},
          .fixed = {"inset=false", "shadow.cache=false", "pcf.count=false"},
          .plot_metrics = {"vis_mae"},
          .study = true};
}

// Time against error, shadow volumes beside the maps (issue 21): lesson 03 (no bias) and 05
// (PCF) at three map sizes, each map rendered every frame; lesson 09 is exact by construction
// and pays in fill instead: silhouette volumes by z-pass, auto and z-fail, and one volume per
// triangle ("trivial but bad").
Sweep volumesVsMapsStudy() {
  Axis technique{"technique", {}};
  for (const char* lesson : {"03_shadow_map_basic", "05_pcf_dithered"}) {
    for (const char* size : {"512", "1024", "2048"}) {
      technique.values.push_back(std::string(lesson).substr(0, 2) + "_map" + size +
                                 ":lesson=" + lesson + " shadow.size=" + size +
                                 " shadow.cache=false inset=false");
    }
  }
  for (const char* method : {"zpass", "auto", "zfail"}) {
    technique.values.push_back(std::string("09_") + method +
                               ":lesson=09_shadow_volumes volume.method=" + method);
  }
  technique.values.push_back(
      "09_per_triangle:lesson=09_shadow_volumes volume.method=auto volume.geometry=per_triangle");
  return {.scenes = {"torus_pyramid", "dueling"},
          .axes = {technique},
          .fixed = {},
          .plot_metrics = {"false_shadow_pct", "false_lit_pct"},
          .study = true};
}

// Issue 36: an omni light through lesson 11's cube (three face sizes, and the paraboloids) and
// through lesson 09's volumes, exact for omni lights, scored by the one truth and timed as the
// casters around the bulb grow from 9 to 33 to 105. Every cube rendered every frame.
Sweep omniVolumesVsCubeStudy() {
  Axis technique{"technique", {}};
  for (const char* size : {"256", "512", "1024"}) {
    technique.values.push_back(std::string("11_cube") + size +
                               ":lesson=11_omni_cube shadow.cache=false cube.size=" + size);
  }
  technique.values.push_back(
      "11_paraboloid512:lesson=11_omni_cube shadow.cache=false omni.method=paraboloid");
  for (const char* method : {"zpass", "zfail"}) {
    technique.values.push_back(std::string("09_") + method +
                               ":lesson=09_shadow_volumes volume.method=" + method);
  }
  return {.scenes = {"bulb", "bulb_crowd", "bulb_throng"},
          .axes = {technique},
          .fixed = {},
          .plot_metrics = {"false_shadow_pct", "false_lit_pct"},
          .study = true};
}

}  // namespace

std::map<std::string, Sweep> studies() {
  // Built on first use, not at start-up: shadow_cost asks the lessons, which register
  // themselves while the program starts.
  return {{"precision_near", precisionNearStudy()},
          {"precision_far", precisionFarStudy()},
          {"shadow_cost", shadowCostSweep()},
          {"pcf_cost", pcfCostStudy()},
          {"volumes_vs_maps", volumesVsMapsStudy()},
          {"omni_volumes_vs_cube", omniVolumesVsCubeStudy()}};
}

}  // namespace shadows::bench
