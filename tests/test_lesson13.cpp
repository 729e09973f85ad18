// Lesson 13 end to end, headless: filterable maps (VSM, ESM, MSM) against lesson 05's PCF at the
// same filter width and the same matched area light. The golden and every view; VSM as close
// to the truth as PCF for one lookup instead of N x N taps; the blur run once per map, not per
// frame; ESM's exponent and its 16-bit break; the light-bleeding reduction trading bleeding for
// darker penumbrae, as seed 002's critique says it must; four moments bleeding less than two
// for the same bytes a texel (seed 002's "other approximating functional forms").
#include "harness.hpp"

namespace shadows {
namespace {

using testing::counter;
using testing::reportNumber;
using testing::startLesson;

const std::string kLesson = "13_filterable_maps";

TEST(Lesson13, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson13, EveryViewOfEveryMethodIsCleanAndDistinct) {
  for (const char* method : {"vsm", "esm", "msm"}) {
    auto runner = startLesson(kLesson, {std::string("filter.method=") + method});
    testing::expectEveryViewCleanAndDistinct(*runner, method);
  }
}

// The report of one setting at 640x480, after the truth.
nlohmann::ordered_json measured(const std::vector<std::string>& sets) {
  return testing::measuredReport(kLesson, sets, 640, 480);
}

TEST(Lesson13, VarianceMapsMatchPcfForOneLookupInsteadOfTwentyFive) {
  // Measured (README): stacked, vis_mae 0.0123 PCF, 0.0123 VSM; torus_pyramid 0.00215, 0.00212.
  for (const char* scene : {"stacked", "torus_pyramid"}) {
    const auto pcf = measured({std::string("scene=") + scene, "filter.method=pcf"});
    const auto vsm = measured({std::string("scene=") + scene, "filter.method=vsm"});
    EXPECT_EQ(pcf["taps_per_pixel"], 25) << scene;
    EXPECT_EQ(vsm["taps_per_pixel"], 1) << scene;
    // One truth: the same matched disk light for both.
    EXPECT_EQ(pcf["truth_area_radius"], vsm["truth_area_radius"]) << scene;
    const double p = pcf["error"]["vis_mae"], v = vsm["error"]["vis_mae"];
    EXPECT_LT(v, 1.1 * p) << scene;
    EXPECT_GT(v, 0.5 * p) << scene;
  }
}

TEST(Lesson13, TheBlurRunsOncePerMapNotPerFrame) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();  // the first frame renders the moments and blurs them
  EXPECT_EQ(counter(*runner, "blur_passes"), 2);
  runner->renderFrame();  // nothing moved: no map, no blur
  EXPECT_EQ(counter(*runner, "blur_passes"), 0);
  EXPECT_EQ(counter(*runner, "shadow_map_renders"), 0);
  ASSERT_EQ(runner->params().assign("filter.radius=6"), "");
  runner->renderFrame();  // a wider blur: the same moments blurred again
  EXPECT_EQ(counter(*runner, "blur_passes"), 2);
  EXPECT_EQ(counter(*runner, "shadow_map_renders"), 0);
  ASSERT_EQ(runner->params().assign("vsm.min_variance=0.0001"), "");
  runner->renderFrame();  // a lookup setting: neither
  EXPECT_EQ(counter(*runner, "blur_passes"), 0);
  ASSERT_EQ(runner->params().assign("filter.method=pcf"), "");
  runner->renderFrame();  // PCF filters every frame and blurs nothing
  EXPECT_EQ(counter(*runner, "blur_passes"), 0);
}

TEST(Lesson13, SixteenBitsBreakTheExponentialMapNotTheVarianceMap) {
  // exp(c (z - 1)) with c = 40 falls under the smallest 16-bit float a few tenths of the depth
  // range before the far plane: those texels read 0, as if a blocker touched every receiver.
  const auto esm32 = measured({"filter.method=esm"});
  const auto esm16 = measured({"filter.method=esm", "moments.bits=16"});
  EXPECT_EQ(esm16["moments_bits_used"], 16);
  EXPECT_LT(static_cast<double>(esm32["error"]["false_shadow_pct"]), 0.5);
  EXPECT_GT(static_cast<double>(esm16["error"]["false_shadow_pct"]), 20.0);
  const auto vsm16 = measured({"moments.bits=16"});
  EXPECT_LT(static_cast<double>(vsm16["error"]["false_shadow_pct"]), 0.5);
}

TEST(Lesson13, VarianceMapsBleedWherePcfDoesNot) {
  // Seed 002's halo: a wide filter over the brick's edge inside the board's umbra. At the same
  // width PCF lightens that floor too (its filter reaches the lit brick), VSM nearly twice as
  // much (0.98 % of the pixels against 0.57 %).
  const std::vector<std::string> wide = {"shadow.size=512", "filter.radius=8"};
  auto with = [&](const std::string& method) {
    std::vector<std::string> sets = wide;
    sets.push_back("filter.method=" + method);
    return static_cast<double>(measured(sets)["error"]["bleeding"]["share_pct"]);
  };
  EXPECT_GT(with("vsm"), 1.5 * with("pcf"));
}

// Seed 002's "other approximating functional forms": four moments (MSM) in the halo where two
// (VSM) bleed. At 16 bits a channel MSM takes VSM's 8 bytes a texel and still bleeds less
// (measured: 0.60 % and 0.65 % of the pixels at 16 and 32 bits, VSM 0.98 %), without darker
// penumbrae, which is what vsm.bleeding pays for the same.
TEST(Lesson13, FourMomentsBleedLessThanTwoForTheSameBytes) {
  const std::vector<std::string> wide = {"shadow.size=512", "filter.radius=8"};
  auto with = [&](std::vector<std::string> sets) {
    sets.insert(sets.end(), wide.begin(), wide.end());
    return measured(sets);
  };
  const auto vsm = with({});
  const auto msm = with({"filter.method=msm"});
  const auto msm16 = with({"filter.method=msm", "moments.bits=16"});
  EXPECT_EQ(vsm["moments_bytes_per_texel"], 8);
  EXPECT_EQ(msm["moments_bytes_per_texel"], 16);
  EXPECT_EQ(msm16["moments_bytes_per_texel"], 8);
  const auto share = [](const nlohmann::ordered_json& r) {
    return static_cast<double>(r["error"]["bleeding"]["share_pct"]);
  };
  const auto penumbra = [](const nlohmann::ordered_json& r) {
    return static_cast<double>(r["error"]["penumbra"]["vis_mae"]);
  };
  EXPECT_LT(share(msm), 0.75 * share(vsm));
  EXPECT_LT(share(msm16), 0.75 * share(vsm));
  EXPECT_LT(penumbra(msm16), 1.05 * penumbra(vsm));
  // At the defaults, as close to the truth as VSM (0.01218 against 0.01228).
  const double v = measured({})["error"]["vis_mae"],
               m = measured({"filter.method=msm"})["error"]["vis_mae"];
  EXPECT_LT(m, 1.02 * v);
}

TEST(Lesson13, BleedingReductionTradesBleedingForDarkerPenumbrae) {
  const auto plain = measured({});
  const auto reduced = measured({"vsm.bleeding=0.3"});
  const double bleeding = plain["error"]["bleeding"]["share_pct"];
  EXPECT_GT(bleeding, 0.05);
  EXPECT_LT(static_cast<double>(reduced["error"]["bleeding"]["share_pct"]), 0.3 * bleeding);
  EXPECT_GT(static_cast<double>(reduced["error"]["penumbra"]["vis_mae"]),
            1.1 * static_cast<double>(plain["error"]["penumbra"]["vis_mae"]));
}

TEST(Lesson13, MipmappedMomentsAreReadTrilinearAndNoWorse) {
  // What a compare map cannot have: a filtered map's mipmaps. Every level down to 1x1, the
  // lookup between them, and the shadow at least as close to the truth.
  const auto plain = measured({});
  const auto mipmapped = measured({"moments.mipmaps=true"});
  EXPECT_EQ(plain["moments_levels"], 1);
  EXPECT_EQ(mipmapped["moments_levels"], 11);  // 1024 .. 1
  EXPECT_LE(static_cast<double>(mipmapped["error"]["vis_mae"]),
            static_cast<double>(plain["error"]["vis_mae"]));
  EXPECT_NE(mipmapped["error"]["vis_mae"], plain["error"]["vis_mae"]);
}

using testing::CapsOff;

TEST(Lesson13, WithoutFloatFilteringTheMomentsAre16BitsAndSaySo) {
  nlohmann::ordered_json report;
  Image fallback;
  {
    const CapsOff off("float_linear,anisotropy");
    auto runner = startLesson(kLesson, {"moments.mipmaps=true"});
    runner->renderFrame();
    report = testing::report(*runner);
    fallback = runner->readImage();
    EXPECT_EQ(runner->glErrors(), 0);
  }
  EXPECT_EQ(report["moments_bits_used"], 16);
  EXPECT_EQ(report["anisotropy_used"], 1.0);
  // The very picture an explicit 16-bit run draws (trilinear, no anisotropy).
  Image asked;
  {
    const CapsOff off("anisotropy");
    auto runner = startLesson(kLesson, {"moments.mipmaps=true", "moments.bits=16"});
    runner->renderFrame();
    asked = runner->readImage();
  }
  EXPECT_EQ(testing::pixelsDiffering(fallback, asked, 0), 0u);
}

TEST(Lesson13, AWeakExponentLeaksLightThatAStrongOneHolds) {
  const auto weak = measured({"filter.method=esm", "esm.c=10"});
  const auto strong = measured({"filter.method=esm", "esm.c=80"});
  EXPECT_GT(static_cast<double>(weak["error"]["false_lit_pct"]),
            5.0 * static_cast<double>(strong["error"]["false_lit_pct"]));
}

}  // namespace
}  // namespace shadows
