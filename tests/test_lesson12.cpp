// Lesson 12 end to end, headless: cascaded maps for the sun against the truth. The splits'
// formulas and the boxes' snapping (cascade_math.hpp); goldens of the shaded and cascade
// views; the cascade colouring where the splits say; the error bound at the defaults and for
// suns no other test uses; shimmer with snapped spheres against free slices; each cascade
// rendered once and culled on its own; the maps kept while nothing moves; the slices fitted to
// the depths in view (cascades.range=visible).
#include "harness.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "../12_cascades/cascade_math.hpp"
#include "../12_cascades/visible_depths.hpp"

namespace shadows {
namespace {

using testing::counter;
using testing::reportNumber;
using testing::reportValue;
using testing::startLesson;

const std::string kLesson = "12_cascades";

TEST(CascadeMath, SplitsFollowTheirFormulas) {
  const float n = 0.5f, f = 128.0f;
  for (int i = 0; i <= 4; ++i) {
    const float t = static_cast<float>(i) / 4.0f;
    EXPECT_FLOAT_EQ(cascade::splitDistance(cascade::Split::Uniform, i, 4, n, f, 0.3f),
                    n + (f - n) * t);
    EXPECT_FLOAT_EQ(cascade::splitDistance(cascade::Split::Logarithmic, i, 4, n, f, 0.3f),
                    n * std::pow(f / n, t));
  }
  // Logarithmic: every slice as many times deeper than the last (here 4x: 0.5, 2, 8, 32, 128).
  EXPECT_NEAR(cascade::splitDistance(cascade::Split::Logarithmic, 2, 4, n, f, 0.0f), 8.0f, 1e-4f);
  // Practical: λ = 1 is the logarithmic split, λ = 0 the uniform one, between them the blend.
  for (int i = 0; i <= 3; ++i) {
    const float u = cascade::splitDistance(cascade::Split::Uniform, i, 3, n, f, 0.0f);
    const float l = cascade::splitDistance(cascade::Split::Logarithmic, i, 3, n, f, 0.0f);
    EXPECT_FLOAT_EQ(cascade::splitDistance(cascade::Split::Practical, i, 3, n, f, 1.0f), l);
    EXPECT_FLOAT_EQ(cascade::splitDistance(cascade::Split::Practical, i, 3, n, f, 0.0f), u);
    EXPECT_NEAR(cascade::splitDistance(cascade::Split::Practical, i, 3, n, f, 0.25f),
                0.25f * l + 0.75f * u, 1e-4f);
  }
}

TEST(CascadeMath, ASnappedSphereBoxKeepsItsSizeAndMovesByWholeTexelsWhateverTheEyeDoes) {
  const glm::mat4 light = cascade::lightRotation(glm::normalize(glm::vec3(-0.4f, -0.8f, 0.3f)));
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 1.7f, 8), glm::vec3(0, 1.2f, -30), {0, 1, 0});
  const float fov = glm::radians(50.0f);
  const auto fit = [&](const glm::mat4& v, bool sphere, bool snap) {
    return cascade::fitCascade(cascade::sliceCorners(v, fov, 4.0f / 3.0f, 3.0f, 12.0f), light, 1024,
                               sphere, snap, glm::vec3(0, 0, -96), 120.0f);
  };
  const cascade::Fit a = fit(view, true, true);
  // Twenty-four eyes, each walked and turned a little further: float noise in the corners
  // must not reach the box's size.
  for (int k = 1; k <= 24; ++k) {
    const float s = static_cast<float>(k);
    const glm::mat4 moved = glm::rotate(glm::mat4(1.0f), glm::radians(0.37f * s), {0, 1, 0}) *
                            view * glm::translate(glm::mat4(1.0f), {-0.013f * s, 0.0f, 0.029f * s});
    const cascade::Fit b = fit(moved, true, true);
    EXPECT_EQ(a.max - a.min, b.max - b.min) << k;  // the same size, to the bit
    const glm::vec2 texels = (b.min - a.min) / a.texel_world;
    EXPECT_NEAR(texels.x, std::round(texels.x), 1e-3f) << k;
    EXPECT_NEAR(texels.y, std::round(texels.y), 1e-3f) << k;
  }
  const glm::mat4 moved = glm::rotate(glm::mat4(1.0f), glm::radians(0.7f), {0, 1, 0}) * view *
                          glm::translate(glm::mat4(1.0f), {-0.05f, 0.0f, 0.11f});
  const cascade::Fit b = fit(moved, true, true);
  EXPECT_GT(glm::length((b.min - a.min) / a.texel_world), 1.0f);  // it did move
  // Fitted to the slice, the box changes size as the eye turns; unsnapped, it slides.
  const cascade::Fit c = fit(view, false, false), d = fit(moved, false, false);
  EXPECT_GT(glm::length((d.max - d.min) - (c.max - c.min)), 1e-3f);
  // The slice's own box is the tighter one.
  EXPECT_LT((c.max - c.min).x * (c.max - c.min).y, (a.max - a.min).x * (a.max - a.min).y);
}

// The shimmer pass's texels per pixel in bytes (scene.frag's VIEW_SHIMMER, mirrored): any value
// from 2^-16 to 2^16 comes back within a step (0.07 %), its bytes keep the sunlit bit, and
// nothing clamps at the 16 (or 1/16) an 8-bit level over [-4, 4] did (issue 53, 7).
// The reduction reads window depths back; viewDepth turns them into the view depths the splits
// need, the inverse of the eye's glm::perspective.
TEST(CascadeMath, AWindowDepthReadsBackAsItsViewDepth) {
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 4.0f / 3.0f, 0.1f, 250.0f);
  for (const float d : {0.1f, 0.5f, 3.55f, 15.9f, 120.0f, 249.0f}) {
    const glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, -d, 1.0f);
    const float window = 0.5f * clip.z / clip.w + 0.5f;
    EXPECT_NEAR(VisibleDepths::viewDepth(projection, window), d, 1e-5f * d * d) << d;
  }
}

TEST(CascadeMath, TexelsPerPixelGoThroughTheirBytesWithinAStep) {
  for (const double texels :
       {1.0 / 60000, 0.01, 1.0 / 16, 0.3, 1.0, 1.704, 13.7, 16.0, 40.0, 900.0, 60000.0}) {
    const int level = cascade::texelLevelOf(texels);
    const auto blue = static_cast<unsigned char>(level / 128);
    for (const int sunlit : {0, 1}) {
      const auto alpha = static_cast<unsigned char>(128 * sunlit + level % 128);
      EXPECT_EQ(alpha >= 128, sunlit == 1);
      EXPECT_EQ(cascade::texelLevel(blue, alpha), level);
    }
    EXPECT_NEAR(cascade::texelsFromLevel(level) / texels, 1.0, 0.0004) << texels;
  }
  EXPECT_EQ(cascade::texelLevelOf(1e9), cascade::kTexelLevels);  // the reach's ends
  EXPECT_EQ(cascade::texelLevelOf(0.0), 0);
}

TEST(Lesson12, SnapshotsMatchTheirGoldens) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  ASSERT_EQ(runner->params().set("view", "cascades"), "");
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson + "_cascades");
  EXPECT_EQ(runner->glErrors(), 0);
}

// Down the middle of the road, each pixel's view depth (the ray's hit on the road, y = 0)
// says which slice it is in; the cascades view must paint it that slice's colour.
TEST(Lesson12, TheCascadeColouringChangesWhereTheSplitsSay) {
  for (const char* split : {"uniform", "logarithmic", "practical"}) {
    const int w = 320, h = 240;
    auto runner = startLesson(
        kLesson, {"view=cascades", std::string("cascades.split=") + split, "dimming=1"}, w, h);
    runner->renderFrame();
    const Image image = runner->readImage();
    const nlohmann::ordered_json splits = reportValue(*runner, "cascade_splits");
    ASSERT_EQ(splits.size(), 5u);
    const glm::vec3 eye = runner->params().at("camera.pos").v();
    const glm::mat4 view = glm::lookAt(eye, runner->params().at("camera.target").v(), {0, 1, 0});
    const glm::mat4 inverse =
        glm::inverse(glm::perspective(glm::radians(runner->params().at("camera.fov").f()),
                                      static_cast<float>(w) / h, 0.1f, 300.0f) *
                     view);
    const glm::vec3 colors[4] = {
        {0.95f, 0.35f, 0.3f}, {0.35f, 0.85f, 0.35f}, {0.35f, 0.5f, 0.95f}, {0.95f, 0.8f, 0.25f}};
    int checked = 0, agreed = 0;
    std::set<int> seen;
    for (int y = 0; y < h; ++y) {  // image rows, bottom up as GL reads them
      const float ndc_y = 2.0f * (static_cast<float>(y) + 0.5f) / h - 1.0f;
      const float ndc_x = 2.0f * (w / 2 + 0.5f) / w - 1.0f;
      glm::vec4 a = inverse * glm::vec4(ndc_x, ndc_y, -1.0f, 1.0f);
      glm::vec4 b = inverse * glm::vec4(ndc_x, ndc_y, 1.0f, 1.0f);
      const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
      if (p1.y >= p0.y) continue;  // the ray never reaches the road
      const glm::vec3 hit = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
      const float depth = -(view * glm::vec4(hit, 1.0f)).z;
      int expected = -1;
      bool near_split = false;
      for (int i = 0; i < 4; ++i) {
        const float d0 = splits[static_cast<size_t>(i)].get<float>();
        const float d1 = splits[static_cast<size_t>(i) + 1].get<float>();
        if (depth > d0 && depth <= d1) expected = i;
        near_split = near_split || std::abs(depth - d1) < 0.02f * d1;
      }
      if (expected < 0 || near_split) continue;
      const std::uint8_t* px = &image.rgba[4 * (static_cast<size_t>(y) * w + w / 2)];
      const glm::vec3 c(px[0], px[1], px[2]);
      int nearest = 0;
      float best = 10.0f;
      for (int i = 0; i < 4; ++i) {
        const float d = glm::length(glm::normalize(c) - glm::normalize(colors[i]));
        if (d < best) best = d, nearest = i;
      }
      ++checked;
      agreed += nearest == expected ? 1 : 0;
      seen.insert(expected);
    }
    EXPECT_GT(checked, 40) << split;
    EXPECT_GE(agreed, checked * 95 / 100) << split << ": " << agreed << " of " << checked;
    // The road crosses three slices at least; the logarithmic split's first ends 0.6 m from the
    // eye, before the road comes into view.
    EXPECT_GE(seen.size(), std::string(split) == "logarithmic" ? 2u : 3u) << split;
    EXPECT_EQ(runner->glErrors(), 0);
  }
}

TEST(Lesson12, SnappedSpheresShimmerATenthOfWhatFreeSlicesDo) {
  double free_slices = 0.0;
  {
    auto runner = startLesson(kLesson, {"cascades.fit=slice", "cascades.snap=false"}, 640, 480);
    runner->renderFrame();
    free_slices = reportNumber(*runner, "shimmer_pct");
    EXPECT_GT(reportNumber(*runner, "shimmer_pixels"), 100000);
  }
  auto runner = startLesson(kLesson, {}, 640, 480);
  runner->renderFrame();
  const double snapped = reportNumber(*runner, "shimmer_pct");
  EXPECT_GT(free_slices, 0.05);
  EXPECT_LE(snapped, free_slices / 10.0) << snapped << " against " << free_slices;
  // Snapping alone is not enough while the slice's box changes size as the eye turns.
  runner.reset();
  auto snapped_slices = startLesson(kLesson, {"cascades.fit=slice", "shimmer.path=turn"}, 640, 480);
  snapped_slices->renderFrame();
  EXPECT_GT(reportNumber(*snapped_slices, "shimmer_pct"), 5.0 * snapped);
}

// In a window the shimmer of the user's own drag is measured frame to frame: each frame the
// eye moves, its points in the maps as they were and as they are. Free slices flip; snapped
// spheres do not.
TEST(Lesson12, WhileTheEyeIsDraggedTheShimmerIsMeasuredFrameToFrame) {
  const auto drag = [](const std::vector<std::string>& sets) {
    auto runner = startLesson(kLesson, sets, 640, 480);
    runner->renderFrame();
    EXPECT_EQ(reportNumber(*runner, "shimmer_live_frames"), 0);
    runner->setInputMoving(true);
    double sum = 0.0;
    for (int i = 1; i <= 4; ++i) {
      const float x = 0.013f * static_cast<float>(i), z = 8.0f - 0.027f * static_cast<float>(i);
      EXPECT_EQ(
          runner->params().assign("camera.pos=" + std::to_string(x) + ",1.7," + std::to_string(z)),
          "");
      runner->renderFrame();
      sum += reportNumber(*runner, "shimmer_live_pct");
    }
    EXPECT_EQ(reportNumber(*runner, "shimmer_live_frames"), 4);
    EXPECT_EQ(runner->glErrors(), 0);
    return sum / 4.0;
  };
  const double free_slices = drag({"cascades.fit=slice", "cascades.snap=false"});
  const double snapped = drag({});
  EXPECT_GT(free_slices, 0.01);
  EXPECT_LE(snapped, free_slices / 10.0) << snapped << " against " << free_slices;
}

TEST(Lesson12, ErrorStaysWithinTheBoundAtTheDefaultsAndForSunsNoOtherTestUses) {
  for (const std::vector<std::string>& sets : {std::vector<std::string>{},
                                               {"scene=street_low_sun"},
                                               {"light.pos=-30,50,-20"},
                                               {"light.pos=10,30,40"}}) {
    const ErrorMetrics e = testing::measureOnce(kLesson, sets, 640, 480);
    EXPECT_LE(e.false_shadow_pct, 0.2) << testing::label(sets);
    EXPECT_LE(e.false_lit_pct, 0.2) << testing::label(sets);
    EXPECT_GT(e.counted_pixels, 100000);
  }
}

TEST(Lesson12, EachCascadeIsRenderedOnceCulledOnItsOwnAndKeptWhileNothingMoves) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "cascade_renders"), 4);
  EXPECT_EQ(counter(*runner, "shadow_map_renders"), 1);
  // Each cascade draws only the casters in its box: most posts are outside the near ones.
  EXPECT_GT(counter(*runner, "culled_objects"), 100);
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "cascade_renders"), 0);
  EXPECT_EQ(counter(*runner, "shadow_map_renders"), 0);
  // The eye moves: the slices move with it.
  ASSERT_EQ(runner->params().assign("camera.pos=0.5,1.7,7"), "");
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "cascade_renders"), 4);
  ASSERT_EQ(runner->params().assign("cascades.count=2"), "");
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "cascade_renders"), 2);
  // cascades.update=3: while only the eye moves, the first cascade every frame and the far
  // one every third.
  ASSERT_EQ(runner->params().assign("cascades.update=3"), "");
  runner->renderFrame();
  std::vector<long long> renders;
  for (int i = 1; i <= 6; ++i) {
    ASSERT_EQ(runner->params().assign("camera.pos=" + std::to_string(0.1 * i) + ",1.7,7"), "");
    runner->renderFrame();
    renders.push_back(counter(*runner, "cascade_renders"));
  }
  const std::vector<long long> expected = {1, 1, 2, 1, 1, 2};
  EXPECT_EQ(renders, expected);
  EXPECT_EQ(runner->glErrors(), 0);
}

// A kept far cascade keeps the box it was fitted for; a step of the eye later the frame is
// still nearly right: the points its box no longer holds ask the next cascade.
TEST(Lesson12, KeptFarCascadesCostLittleErrorWhileTheEyeTakesAStep) {
  const std::string step = "camera.pos=1.5,1.7,5";
  auto kept = startLesson(kLesson, {"cascades.update=8"}, 640, 480);
  kept->renderFrame();
  ASSERT_EQ(kept->params().assign(step), "");
  kept->renderFrame();
  ASSERT_EQ(counter(*kept, "cascade_renders"), 1);
  const ErrorMetrics with_kept = kept->measureError().metrics;
  EXPECT_EQ(kept->glErrors(), 0);
  kept.reset();
  const ErrorMetrics fresh = testing::measureOnce(kLesson, {step}, 640, 480);
  EXPECT_LE(with_kept.false_lit_pct, fresh.false_lit_pct + 0.05);
  EXPECT_LE(with_kept.false_shadow_pct, fresh.false_shadow_pct + 0.05);
}

// The next cascade's lookup (a point outside a kept cascade's box) is compiled only into the
// frames that keep a cascade (issue 56): not while nothing has moved since every cascade was
// fitted, whatever cascades.update says.
TEST(Lesson12, TheNextCascadesLookupRunsOnlyWhileACascadeIsKept) {
  auto runner = startLesson(kLesson, {"cascades.update=3"}, 160, 120);
  std::vector<int> kept;
  for (int i = 0; i <= 4; ++i) {
    if (i > 0 && i < 4) {
      ASSERT_EQ(runner->params().assign("camera.pos=" + std::to_string(0.1 * i) + ",1.7,7"), "");
    }
    runner->renderFrame();
    // The frame's own eye pass (the first frame also measures the shimmer's steps).
    int shown = -1;
    for (const std::string& v : runner->measure().lastFrameVariants()) {
      if (v.find("VIEW=VIEW_SHADED") != std::string::npos) {
        shown = v.find("KEPT_CASCADES=1") != std::string::npos ? 1 : 0;
      }
    }
    kept.push_back(shown);
  }
  // Every cascade fitted; the eye moves: the far ones kept, twice, then fitted again; it rests.
  const std::vector<int> expected = {0, 1, 1, 0, 0};
  EXPECT_EQ(kept, expected);
  EXPECT_EQ(runner->glErrors(), 0);
}

// Texels per pixel, cascade by cascade: the practical split gives every slice that shades the
// road more than one; one map for the whole view gives it a fifth; an even split starves the
// nearest slice and spends ten times as many on the next.
TEST(Lesson12, ThePracticalSplitGivesEverySliceATexelAPixelAndOneMapDoesNot) {
  const auto texels = [](const std::vector<std::string>& sets) {
    auto runner = startLesson(kLesson, sets, 640, 480);
    runner->renderFrame();
    return reportValue(*runner, "cascade_texels_per_pixel").get<std::vector<double>>();
  };
  for (const double t : texels({})) EXPECT_GT(t, 1.0);
  const std::vector<double> one = texels({"cascades.count=1"});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_LT(one[0], 0.3);
  const std::vector<double> uniform = texels({"cascades.split=uniform"});
  ASSERT_EQ(uniform.size(), 4u);
  EXPECT_LT(uniform[0], 1.0);
  EXPECT_GT(uniform[1], 10.0 * uniform[0]);
}

// Issue 60, 3: cascades.range=visible fits the slices to the depths the eye sees, reduced on
// the GPU (visible_depths.hpp). On torus_pyramid, whose surfaces lie 5 to 16 units away, the
// fixed range (0.1 to 120) leaves two cascades shading nothing; fitted, all four do, and every
// counted pixel lies in a slice. The reduction's far is tight: a fixed range that stops half a
// percent short of it leaves pixels out.
TEST(Lesson12, AVisibleRangeFitsEverySliceToTheDepthsInView) {
  auto run = [](const std::vector<std::string>& sets) {
    return testing::measuredReport(kLesson, sets);
  };
  const auto inSlices = [](const nlohmann::ordered_json& r) {
    long long sum = 0;
    for (int i = 1; i <= 4; ++i) {
      sum += r["error"]["cascade_" + std::to_string(i)]["counted_pixels"].get<long long>();
    }
    return sum;
  };
  const auto fixed = run({"scene=torus_pyramid"});
  EXPECT_TRUE(fixed["cascade_texels_per_pixel"][3].is_null());
  EXPECT_TRUE(fixed["visible_depth_far"].is_null());
  EXPECT_EQ(fixed["visible_depth_far_not_counted"], "cascades.range=fixed: not measured");
  const auto fitted = run({"scene=torus_pyramid", "cascades.range=visible"});
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(fitted["cascade_texels_per_pixel"][i].is_null()) << i;
  const double near = fitted["visible_depth_near"], far = fitted["visible_depth_far"];
  EXPECT_GT(near, 3.0);
  EXPECT_LT(far, 30.0);
  EXPECT_NEAR(fitted["cascade_splits"][0].get<double>(), 0.999 * near, 1e-4);
  EXPECT_NEAR(fitted["cascade_splits"][4].get<double>(), 1.001 * far, 1e-3);
  EXPECT_EQ(inSlices(fitted), fitted["error"]["counted_pixels"].get<long long>());
  const auto onlyThere =
      run({"scene=torus_pyramid", "cascades.far=" + std::to_string(0.995 * far)});
  EXPECT_LT(inSlices(onlyThere), onlyThere["error"]["counted_pixels"].get<long long>());
  // Every surface beyond cascades.far (5, the slider's least): the fixed range, still clean.
  const auto beyond = run({"scene=torus_pyramid", "cascades.range=visible", "cascades.far=5"});
  EXPECT_NEAR(beyond["cascade_splits"][4].get<double>(), 5.0, 1e-6);
  EXPECT_GT(beyond["cascade_splits"][1].get<double>(), beyond["cascade_splits"][0].get<double>());
}

// The reduction costs a depth pass and its steps each time the cascades are fitted, and with a
// visible range every step of the eye fits them all: the slices move with what it sees.
TEST(Lesson12, TheVisibleRangeIsMeasuredWhenTheCascadesAreFitted) {
  auto runner = startLesson(kLesson, {"cascades.range=visible", "cascades.update=3"}, 320, 240);
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "depth_range_passes"), 5);  // 320x240: 80x60, 20x15, 5x4, 2x1
  EXPECT_EQ(counter(*runner, "cascade_renders"), 4);
  runner->renderFrame();  // nothing moved: neither
  EXPECT_EQ(runner->measure().lastFrameCounts().count("depth_range_passes"), 0u);
  ASSERT_EQ(runner->params().assign("camera.pos=0.5,1.7,7"), "");
  runner->renderFrame();
  EXPECT_EQ(counter(*runner, "cascade_renders"), 4) << "not only the first: the range moved";
  EXPECT_EQ(runner->glErrors(), 0);
}

// A 2048 map on a 320x240 frame gives the far slices more than 16 texels a pixel (about 29
// and 28): their true figures, not the ceiling of 16 an 8-bit level stored (issue 53, 7).
TEST(Lesson12, TexelsPerPixelAreNotClampedAtSixteen) {
  auto runner = startLesson(kLesson, {"cascades.size=2048"}, 320, 240);
  runner->renderFrame();
  const auto t = reportValue(*runner, "cascade_texels_per_pixel").get<std::vector<double>>();
  ASSERT_EQ(t.size(), 4u);
  EXPECT_GT(t[2], 20.0);
  EXPECT_GT(t[3], 20.0);
  EXPECT_NE(t[2], t[3]);
  // 2048 against the default 1024: twice the texels a pixel, slice by slice.
  auto base = startLesson(kLesson, {}, 320, 240);
  base->renderFrame();
  const auto b = reportValue(*base, "cascade_texels_per_pixel").get<std::vector<double>>();
  ASSERT_EQ(b.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(t[i] / b[i], 2.0, 0.05) << i;
}

// Figures over nothing are null with a reason, never a zero that reads "steady" (issue 53, 6):
// the shimmer with the camera at the sky, with shadow.off, and the live shimmer before any frame
// moved the eye.
TEST(Lesson12, AShimmerOverNothingIsNullWithAReason) {
  for (const std::vector<std::string>& sets :
       {std::vector<std::string>{"camera.target=0,60,-5"}, {"shadow.off=true"}}) {
    auto runner = startLesson(kLesson, sets, 160, 120);
    runner->renderFrame();
    const nlohmann::ordered_json r = testing::report(*runner);
    EXPECT_TRUE(r["shimmer_pct"].is_null()) << sets[0] << ": " << r["shimmer_pct"];
    EXPECT_TRUE(r["shimmer_pct_not_counted"].is_string()) << sets[0];
    EXPECT_TRUE(r["shimmer_live_pct"].is_null()) << sets[0];
    EXPECT_TRUE(r["shimmer_live_pct_not_counted"].is_string()) << sets[0];
    for (const auto& t : r["cascade_texels_per_pixel"]) EXPECT_TRUE(t.is_null()) << sets[0];
    EXPECT_TRUE(r["cascade_texels_per_pixel_not_counted"].is_string()) << sets[0];
  }
  auto seen = startLesson(kLesson, {}, 160, 120);
  seen->renderFrame();
  const nlohmann::ordered_json r = testing::report(*seen);
  EXPECT_TRUE(r["shimmer_pct"].is_number());
  EXPECT_FALSE(r.contains("shimmer_pct_not_counted"));
  EXPECT_TRUE(r["shimmer_live_pct"].is_null());  // headless: no frame moved the eye
}

TEST(Lesson12, EveryMapInputRendersTheMapsAgain) {
  testing::expectEveryMapInputRendersTheMapAgain(
      kLesson,
      {"cascades.count=3", "cascades.split=uniform", "cascades.fit=slice", "cascades.snap=false",
       "cascades.size=512", "cascades.far=60", "light.pos=-20,40,10", "scene=street_low_sun"},
      {});
  testing::expectACasterMoveRendersTheMapAgain(kLesson, {});
}

TEST(Lesson12, EveryViewIsCleanAndDistinct) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
}

}  // namespace
}  // namespace shadows
