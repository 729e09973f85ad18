// One lesson on this build's GL API (gl45, gl41 or gles30), headless at the goldens' size with
// its defaults: every view as a picture and the report of the shaded view, into a directory.
// With --reference (gl45's directory for the same lesson) it also checks what issue 23 asks of
// a flavour: no GL error in any view, every picture within the golden tolerance of gl45's, the
// error numbers within 0.02 points, and every counter either gl45's number or null and said
// to be unavailable. Exit 0 when all hold, 1 (with one line per failure) when not.
//
//   flavour_views LESSON OUT_DIR [--reference REF_DIR] [--levels N] [--set name=value ...]
//                [--backend NAME] [--device N] [--counters-differ]
//
// --levels N: a pixel counts as moved only when a channel differs by more than N levels (0 by
// default, as for the goldens). Only lesson 02 on gles30 takes 1 (tests/CMakeLists.txt: why).
// The same comparison checks a GPU against llvmpipe (scripts/gpu_check.sh, docs/GPU.md):
// --backend egl-device --device N picks the GPU, and --counters-differ prints the counters
// that differ as NOTE lines instead of failing (a GPU counts fragment invocations its own way).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "core/json.hpp"
#include "gl/caps.hpp"
#include "run/runner.hpp"

namespace {

using shadows::Image;
using Json = nlohmann::json;

int g_failures = 0;
bool g_counters_differ = false;  // --counters-differ

void fail(const std::string& what) {
  std::printf("FAIL %s\n", what.c_str());
  ++g_failures;
}

void note(const std::string& what) {
  std::printf("NOTE %s\n", what.c_str());
}

// Pixels whose largest colour difference is above `levels` (0: harness.hpp's golden
// comparison), and the largest difference of any pixel.
size_t pixelsDiffering(const Image& a, const Image& b, int levels, int& largest) {
  largest = 255;
  if (a.width != b.width || a.height != b.height) return a.rgba.size() / 4 + 1;
  largest = 0;
  size_t differing = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.rgba[i + c] - b.rgba[i + c]));
    largest = std::max(largest, worst);
    differing += worst > levels;
  }
  return differing;
}

// The golden tolerance (tests/harness.hpp, kGoldenMovedPixels).
constexpr size_t kMovedPixels = 16;

// Counters an emulation changes on purpose, with why: they are compared only for presence.
const std::set<std::string> kEmulated = {
    "counters/readback_bytes",       // OpenGL ES reads the map's digits as RGBA: 4 bytes a texel
    "counters/readback/draw_calls",  // ... after a pass that writes them into colour
};

Json readJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return Json::parse(in, nullptr, false);
}

// Every counter of the reference is here: equal, or null and named in "unavailable".
void compareCounters(const Json& ref, const Json& own, const Json& unavailable,
                     const std::string& flavour, const std::string& where) {
  for (const auto& [name, value] : ref.items()) {
    const std::string at = where + "/" + name;
    if (!own.contains(name)) {
      fail(at + ": missing");
    } else if (value.is_object()) {
      compareCounters(value, own.at(name), unavailable, flavour, at);
    } else if (own.at(name).is_null()) {
      const bool said =
          unavailable.contains(name) && unavailable.at(name) == "unavailable on " + flavour;
      if (!said) fail(at + ": null, but \"unavailable\" does not say it");
    } else if (value != own.at(name) && kEmulated.count(at) == 0) {
      (g_counters_differ ? note
                         : fail)(at + ": " + own.at(name).dump() + ", reference " + value.dump());
    }
  }
}

// The flavour table of docs/PLATFORMS.md ("One source, three APIs"): the counters each flavour must
// report as unavailable, by lesson ("" for every lesson). Exactly these, so that a counter nulled
// where the table says it is counted fails, as does one counted where the table says it cannot
// be. fragment_invocations on a desktop flavour depends on ARB_pipeline_statistics_query
// (Mesa has it, macOS not): allowed either way there.
const std::map<std::string, std::map<std::string, std::set<std::string>>> kUnavailable = {
    {"gl45", {}},
    {"gl41",
     {{"05_pcf_dithered",
       {"pcf_taps", "pcf_filtered_fragments", "pcf_stopped_early", "pcf_skipped_facing_away"}},
      {"14_soft_shadows",
       {"pcss_search_taps", "pcss_no_blocker", "pcss_all_blockers", "pcss_skipped_facing_away",
        "pcf_taps", "pcf_filtered_fragments"}}}},
    {"gles30",
     {{"", {"fragment_invocations", "fragments_passed"}},
      {"05_pcf_dithered",
       {"pcf_taps", "pcf_filtered_fragments", "pcf_stopped_early", "pcf_skipped_facing_away"}},
      {"06_dual_texture_8bit", {"pass2_lit_fragments"}},
      {"07_multidigit_16bit", {"pass2_lit_fragments", "pass3_lit_fragments"}},
      {"08_atmospherics",
       {"air_fragments_passed", "air_fragments_shaded", "air_fragments_skipped"}},
      {"14_soft_shadows",
       {"pcss_search_taps", "pcss_no_blocker", "pcss_all_blockers", "pcss_skipped_facing_away",
        "pcf_taps", "pcf_filtered_fragments"}}}},
};

void checkFlavourTable(const std::string& lesson, const Json& own) {
  const std::string flavour = own.value("flavour", "?");
  const auto table = kUnavailable.find(flavour);
  if (table == kUnavailable.end()) return fail("report: flavour " + flavour + " not in the table");
  std::set<std::string> expected;
  for (const char* row : {"", lesson.c_str()}) {
    if (const auto it = table->second.find(row); it != table->second.end()) {
      expected.insert(it->second.begin(), it->second.end());
    }
  }
  std::set<std::string> said;
  const Json unavailable = own.value("unavailable", Json::object());
  for (const auto& [name, why] : unavailable.items()) {
    said.insert(name);
    if (why != "unavailable on " + flavour) fail("unavailable/" + name + ": " + why.dump());
  }
  for (const std::string& name : expected) {
    if (!said.count(name))
      fail("counters: " + name + " counted, but docs/PLATFORMS.md's table says " + flavour +
           " cannot");
  }
  for (const std::string& name : said) {
    const bool optional = flavour != "gles30" && name == "fragment_invocations";
    if (!expected.count(name) && !optional) {
      fail("counters: " + name + " unavailable, but docs/PLATFORMS.md's table says " + flavour +
           " counts it");
    }
  }
}

// The read-back the flavour table describes, on a frame that renders the map (06, 07):
// through the CPU, gl45 and gl41 read the depth itself (1 byte a texel for 06's 8 bits, 2 for
// 07's 16) while OpenGL ES, which reads colour as RGBA only, first writes the digits into
// colour in a pass of its own (06's linear encoding has them in colour already) and reads 4
// bytes a texel; a copy moves every texel on the GPU and reads nothing back.
void checkReadback(shadows::Runner& runner, const std::string& lesson) {
  shadows::Params& params = runner.params();
  if (params.find("map.path") == nullptr) return;
  const std::string flavour = shadows::caps().flavour;
  params.set("shadow.cache", "false");  // this frame renders the map
  runner.renderFrame();
  const int digits = lesson.rfind("07", 0) == 0 ? 2 : 1;
  const long long size = params.at("shadow.size").i();
  const long long height =
      params.at("shadow.height").i() > 0 ? params.at("shadow.height").i() : size;
  const long long texels = size * height;
  const auto& counts = runner.measure().lastFrameCounts();
  const auto& work = runner.measure().lastFrameWork();
  const auto count = [&](const char* name) {
    const auto it = counts.find(name);
    return it == counts.end() ? -1LL : it->second;
  };
  const long long digit_draws = work.count("readback") ? work.at("readback").draw_calls : 0;
  const std::string path = params.at("map.path").choice();
  const bool es = flavour == "gles30";
  std::printf(
      "readback: %s, %lld texels: readback_bytes %lld, copied_texels %lld, digit pass draws %lld\n",
      path.c_str(), texels, count("readback_bytes"), count("copied_texels"), digit_draws);
  if (path == "read_pixels") {
    const long long expected = texels * (es ? 4 : digits);
    if (count("readback_bytes") != expected) {
      fail("readback_bytes " + std::to_string(count("readback_bytes")) + ", the table says " +
           std::to_string(expected) + " (" + std::to_string(es ? 4 : digits) + " a texel)");
    }
  } else if (path == "copy_texture") {
    if (count("readback_bytes") != -1)
      fail("copy_texture read " + std::to_string(count("readback_bytes")) + " bytes back");
    if (count("copied_texels") != texels)
      fail("copied_texels " + std::to_string(count("copied_texels")) + ", expected " +
           std::to_string(texels));
  }
  // 06's linear encoding writes its 8 bits into colour in the light pass already: no pass.
  const shadows::Param* encoding = params.find("map.encoding");
  const bool digit_pass = es && !(encoding != nullptr && encoding->choice() == "linear");
  if (path != "render_to_texture" && (digit_draws > 0) != digit_pass) {
    fail("the read-back pass draws " + std::to_string(digit_draws) +
         (digit_pass ? " times: OpenGL ES writes the depth's digits into colour first"
                     : " times: only OpenGL ES reading a depth draws there"));
  }
}

void compareReports(const Json& ref, const Json& own) {
  const std::string flavour = own.value("flavour", "?");
  if (own.value("gl_errors", -1) != 0) fail("report: gl_errors " + own["gl_errors"].dump());
  if (!own.contains("error") || !ref.contains("error")) return fail("report: no error block");
  const Json& e = own.at("error");
  const Json& r = ref.at("error");
  if (!e.is_object() || !r.is_object()) return fail("report: no error block");
  if (e["truth"] != r["truth"])
    fail("error/truth " + e["truth"].dump() + ", reference " + r["truth"].dump());
  // "Within 0.02 points": percentages directly, mean errors as percentages of full scale.
  const std::pair<const char*, double> numbers[] = {
      {"false_shadow_pct", 0.02}, {"false_lit_pct", 0.02}, {"vis_mae", 2e-4},
      {"shade_mae", 2e-4},        {"air_mae", 2e-4},       {"air_rel_rmse", 2e-4}};
  for (const auto& [name, tolerance] : numbers) {
    if (!r.contains(name)) continue;
    const double a = e.value(name, NAN), b = r[name].get<double>();
    std::printf("error/%s %g, reference %g\n", name, a, b);
    if (!(std::abs(a - b) <= tolerance)) {
      fail(std::string("error/") + name + " " + std::to_string(a) + ", reference " +
           std::to_string(b));
    }
  }
  for (const char* name : {"nonfinite_pixels", "counted_pixels", "covered_pixels", "air_pixels"}) {
    if (!r.contains(name)) continue;
    const long long a = e.value(name, -1LL), b = r[name].get<long long>();
    const long long limit = std::string(name) == "nonfinite_pixels" ? 0 : kMovedPixels;
    if (std::llabs(a - b) > limit) {
      fail(std::string("error/") + name + " " + std::to_string(a) + ", reference " +
           std::to_string(b));
    }
  }
  compareCounters(ref["counters"], own["counters"], own.value("unavailable", Json::object()),
                  flavour, "counters");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s LESSON OUT_DIR [--reference DIR] [--levels N] [--set ...]\n",
                 argv[0]);
    return 2;
  }
  const std::string lesson = argv[1];
  const std::filesystem::path out = argv[2];
  std::filesystem::path reference;
  std::vector<std::string> sets;
  int levels = 0;
  shadows::RunOptions options;
  for (int i = 3; i < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--counters-differ") {
      g_counters_differ = true;
      --i;  // a flag without a value
    } else if (i + 1 >= argc) {
      break;
    } else if (flag == "--backend") {
      options.backend = argv[i + 1];
    } else if (flag == "--device") {
      options.device = std::atoi(argv[i + 1]);
    } else if (flag == "--reference") {
      reference = argv[i + 1];
    } else if (flag == "--levels") {
      levels = std::atoi(argv[i + 1]);
    } else if (flag == "--set") {
      sets.emplace_back(argv[i + 1]);
    }
  }
  std::filesystem::create_directories(out);
  try {
    options.headless = true;
    options.width = 320;  // the goldens' size
    options.height = 240;
    options.frames = 1;
    shadows::Runner runner(lesson, shadows::makeLesson(lesson), options);
    if (const std::string why = runner.applySets(sets); !why.empty()) {
      std::fprintf(stderr, "%s\n", why.c_str());
      return 2;
    }
    runner.initHeadless();
    const std::vector<std::string> views = runner.params().at("view").choices;
    for (const std::string& view : views) {
      runner.params().set("view", view);
      const int errors_before = runner.glErrors();
      runner.renderFrame();
      if (runner.glErrors() != errors_before) fail(view + ": GL errors");
      const Image image = runner.readImage();
      shadows::writePng((out / (view + ".png")).string(), image);
      if (reference.empty()) continue;
      const Image ref = shadows::readPng((reference / (view + ".png")).string());
      int largest = 0;
      const size_t moved = pixelsDiffering(image, ref, levels, largest);
      std::printf("view %s: %zu pixels differ by more than %d levels, largest difference %d\n",
                  view.c_str(), moved, levels, largest);
      if (moved > kMovedPixels) {
        fail(view + ": " + std::to_string(moved) + " pixels differ from the reference's by more " +
             "than " + std::to_string(levels) + " levels (at most " + std::to_string(kMovedPixels) +
             ")");
      }
    }
    runner.params().set("view", "shaded");
    runner.renderFrame();
    runner.measureError();
    shadows::JsonWriter json;
    runner.writeReport(json);
    std::ofstream(out / "report.json") << json.str() << "\n";
    if (const Json own = Json::parse(json.str(), nullptr, false); !own.is_discarded()) {
      checkFlavourTable(lesson, own);
    }
    checkReadback(runner, lesson);
    if (!reference.empty()) {
      const Json own = Json::parse(json.str(), nullptr, false);
      const Json ref = readJson(reference / "report.json");
      if (own.is_discarded() || ref.is_discarded()) {
        fail("report: not JSON");
      } else {
        compareReports(ref, own);
      }
    }
  } catch (const std::exception& e) {
    fail(std::string("runtime failure: ") + e.what());
  }
  std::printf("%s: %s, %d failures\n", lesson.c_str(), out.string().c_str(), g_failures);
  return g_failures == 0 ? 0 : 1;
}
