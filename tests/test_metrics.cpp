// compareVisibility and errorImage on small synthetic images whose answers are known by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "truth/truth.hpp"

namespace shadows {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(Metrics, IdenticalImagesGiveZeros) {
  const std::vector<float> truth = {1.0f, 0.0f, 0.25f, kNotCounted, 0.75f, 1.0f};
  const std::vector<float> weight = {1.0f, 0.5f, 0.3f, 0.0f, 0.9f, 0.1f};
  const ErrorMetrics m = compareVisibility(truth, truth, weight);
  EXPECT_EQ(m.false_shadow_pct, 0.0);
  EXPECT_EQ(m.false_lit_pct, 0.0);
  EXPECT_EQ(m.vis_mae, 0.0);
  EXPECT_EQ(m.shade_mae, 0.0);
  EXPECT_EQ(m.nonfinite_pixels, 0);
  EXPECT_EQ(m.counted_pixels, 5);
  EXPECT_TRUE(m.truth.empty());
}

// N counted pixels of value `from` plus uncounted ones; the first k counted are set to `to`.
struct Flip {
  std::vector<float> rendered, truth, weight;
};
Flip flipK(int n, int k, float from, float to) {
  Flip f;
  for (int i = 0; i < n; ++i) {
    f.truth.push_back(from);
    f.rendered.push_back(i < k ? to : from);
    f.weight.push_back(0.5f + 0.5f * static_cast<float>(i % 3) / 2.0f);
    // Interleaved uncounted pixels, rendered wrong on purpose.
    f.truth.push_back(kNotCounted);
    f.rendered.push_back(to);
    f.weight.push_back(0.0f);
  }
  return f;
}

TEST(Metrics, FlippingKLitPixelsGivesExactFalseShadowPct) {
  for (const auto& [n, k] : {std::pair{1000, 37}, std::pair{7, 3}, std::pair{3, 3}}) {
    const Flip f = flipK(n, k, 1.0f, 0.0f);
    const ErrorMetrics m = compareVisibility(f.rendered, f.truth, f.weight);
    EXPECT_EQ(m.counted_pixels, n);
    EXPECT_EQ(m.false_shadow_pct, 100.0 * k / n);
    EXPECT_EQ(m.false_lit_pct, 0.0);
    EXPECT_DOUBLE_EQ(m.vis_mae, static_cast<double>(k) / n);
  }
}

TEST(Metrics, FlippingKShadowedPixelsGivesExactFalseLitPct) {
  for (const auto& [n, k] : {std::pair{1000, 37}, std::pair{7, 3}, std::pair{3, 3}}) {
    const Flip f = flipK(n, k, 0.0f, 1.0f);
    const ErrorMetrics m = compareVisibility(f.rendered, f.truth, f.weight);
    EXPECT_EQ(m.counted_pixels, n);
    EXPECT_EQ(m.false_lit_pct, 100.0 * k / n);
    EXPECT_EQ(m.false_shadow_pct, 0.0);
    EXPECT_DOUBLE_EQ(m.vis_mae, static_cast<double>(k) / n);
  }
}

TEST(Metrics, ThresholdIsOneHalfInclusiveForLit) {
  // truth 0.5 is lit; rendered 0.5 is lit: no misclassification, only |diff|.
  const ErrorMetrics m =
      compareVisibility({0.5f, 0.5f, 0.49f}, {0.5f, 1.0f, 0.5f}, {1.0f, 1.0f, 1.0f});
  EXPECT_EQ(m.false_lit_pct, 0.0);
  EXPECT_DOUBLE_EQ(m.false_shadow_pct, 100.0 / 3.0);  // 0.49 under a lit 0.5
}

TEST(Metrics, TruthBetweenPointFourAndOneHalfIsShadowed) {
  // Area-light truths take every value in between: the lit threshold must be 0.5 for the
  // truth as for the picture, or penumbra pixels drift from one class to the other.
  // Counted pixels: truth 0.45 rendered 0.5 (false lit), truth 0.41 rendered 0.55 (false
  // lit), truth 0.49 rendered 0.3 (right), truth 0.5 rendered 0.45 (false shadow), and four
  // right ones. Two false lit against one false shadow, so swapped classes show.
  const std::vector<float> rendered = {0.5f, 0.55f, 0.3f, 0.45f, 1.0f, 0.0f, 0.6f, 0.4f};
  const std::vector<float> truth = {0.45f, 0.41f, 0.49f, 0.5f, 1.0f, 0.0f, 0.5f, 0.4999f};
  const ErrorMetrics m = compareVisibility(rendered, truth, std::vector<float>(8, 1.0f));
  EXPECT_EQ(m.counted_pixels, 8);
  EXPECT_DOUBLE_EQ(m.false_lit_pct, 25.0);
  EXPECT_DOUBLE_EQ(m.false_shadow_pct, 12.5);
  // The error picture classifies the same way: cyan, cyan, dim, magenta, then dim.
  const std::vector<std::uint8_t> shaded(4 * truth.size(), 100);
  const std::vector<std::uint8_t> img = errorImage(shaded, rendered, truth);
  const std::vector<int> red = {0, 0, 35, 255, 35, 35, 35, 35};  // cyan 0, magenta 255
  const std::vector<int> green = {255, 255, 35, 0, 35, 35, 35, 35};
  for (size_t i = 0; i < truth.size(); ++i) {
    EXPECT_EQ(img[4 * i], red[i]) << "pixel " << i;
    EXPECT_EQ(img[4 * i + 1], green[i]) << "pixel " << i;
  }
}

TEST(Metrics, NonFinitePixelsAreCountedEverywhereAndAreWrong) {
  // Asymmetric on purpose: two non-finite pixels on lit truth (false shadow), one on shadowed
  // truth (false lit), so a swap of the two classes changes the numbers.
  const std::vector<float> rendered = {kNaN, kInf, -kInf, kNaN, kInf, 1.0f, 0.0f, -kInf};
  const std::vector<float> truth = {1.0f, 0.0f, kNotCounted, kNotCounted, 1.0f, 1.0f, 0.0f, 0.75f};
  const std::vector<float> weight = {1.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f};
  const ErrorMetrics m = compareVisibility(rendered, truth, weight);
  EXPECT_EQ(m.nonfinite_pixels, 6);  // index 4 has weight 0: uncounted, still non-finite
  EXPECT_EQ(m.counted_pixels, 5);
  EXPECT_EQ(m.false_shadow_pct, 40.0);  // NaN and -Inf where the truth is lit
  EXPECT_EQ(m.false_lit_pct, 20.0);     // Inf where the truth is shadowed
  EXPECT_DOUBLE_EQ(m.vis_mae, 0.6);     // each non-finite pixel is an error of 1
  EXPECT_DOUBLE_EQ(m.shade_mae, 0.6);
  EXPECT_TRUE(std::isfinite(m.vis_mae) && std::isfinite(m.shade_mae));
}

TEST(Metrics, UncountedPixelsNeverAffectResults) {
  const std::vector<float> rendered = {1.0f, 0.0f, 0.7f, 0.2f};
  const std::vector<float> truth = {0.0f, 0.0f, 1.0f, 0.4f};
  const std::vector<float> weight = {0.5f, 1.0f, 0.25f, 0.75f};
  const ErrorMetrics base = compareVisibility(rendered, truth, weight);

  std::vector<float> r2 = rendered, t2 = truth, w2 = weight;
  // No surface (truth kNotCounted) with any rendered value and even a stray weight.
  for (float v : {0.0f, 1.0f, 0.3f, -5.0f, 42.0f}) {
    r2.push_back(v);
    t2.push_back(kNotCounted);
    w2.push_back(1.0f);
  }
  // A surface with zero weight (facing away) is not counted either.
  r2.push_back(1.0f);
  t2.push_back(0.0f);
  w2.push_back(0.0f);
  const ErrorMetrics m = compareVisibility(r2, t2, w2);
  EXPECT_EQ(m.counted_pixels, base.counted_pixels);
  EXPECT_EQ(m.false_shadow_pct, base.false_shadow_pct);
  EXPECT_EQ(m.false_lit_pct, base.false_lit_pct);
  EXPECT_EQ(m.vis_mae, base.vis_mae);
  EXPECT_EQ(m.shade_mae, base.shade_mae);
  EXPECT_EQ(base.false_lit_pct, 25.0);
  EXPECT_EQ(base.counted_pixels, 4);
}

TEST(Metrics, ShadeMaeIsWeightedByNDotL) {
  // |errors| 0.5 and 0.25 with weights 0.25 and 0.75 (all exact in binary):
  // vis_mae = (0.5 + 0.25) / 2; shade_mae = (0.25*0.5 + 0.75*0.25) / (0.25 + 0.75).
  const ErrorMetrics m = compareVisibility({0.5f, 0.25f}, {1.0f, 0.0f}, {0.25f, 0.75f});
  EXPECT_EQ(m.vis_mae, 0.375);
  EXPECT_EQ(m.shade_mae, 0.3125);
  // The same errors with the weights swapped weigh the other pixel.
  const ErrorMetrics s = compareVisibility({0.5f, 0.25f}, {1.0f, 0.0f}, {0.75f, 0.25f});
  EXPECT_EQ(s.vis_mae, 0.375);
  EXPECT_EQ(s.shade_mae, 0.4375);
}

TEST(Metrics, EmptyAndAllUncountedGiveZeros) {
  const ErrorMetrics e = compareVisibility({}, {}, {});
  EXPECT_EQ(e.counted_pixels, 0);
  EXPECT_EQ(e.false_shadow_pct, 0.0);
  const ErrorMetrics u = compareVisibility({0.0f, kNaN}, {kNotCounted, kNotCounted}, {1.0f, 1.0f});
  EXPECT_EQ(u.counted_pixels, 0);
  EXPECT_EQ(u.nonfinite_pixels, 1);
  EXPECT_EQ(u.false_shadow_pct, 0.0);
  EXPECT_EQ(u.false_lit_pct, 0.0);
  EXPECT_EQ(u.vis_mae, 0.0);
  EXPECT_EQ(u.shade_mae, 0.0);
}

TEST(Metrics, SizeMismatchThrows) {
  EXPECT_THROW(compareVisibility({1.0f}, {1.0f, 1.0f}, {1.0f, 1.0f}), std::invalid_argument);
  EXPECT_THROW(compareVisibility({1.0f}, {1.0f}, {}), std::invalid_argument);
  EXPECT_THROW(errorImage(std::vector<std::uint8_t>(7), {1.0f, 1.0f}, {1.0f, 1.0f}),
               std::invalid_argument);
}

// A lesson's region (lesson 10's plane, region II): the frame's definitions over the pixels
// inside it; pixels with no surface (w = -1) and uncounted ones are in no region.
TEST(Metrics, RegionCountsOnlyItsOwnCountedPixels) {
  ErrorPixels p;
  // Object 2: correct lit, false shadow, NaN on shadowed truth (false lit, as the frame says),
  // uncounted; object 1: false lit; no surface: a false shadow that no region may count.
  p.rendered = {1.0f, 0.1f, kNaN, 0.0f, 0.9f, 0.0f};
  p.truth = {1.0f, 1.0f, 0.0f, kNotCounted, 0.0f, 1.0f};
  p.weight = {1.0f, 1.0f, 1.0f, 0.0f, 1.0f, 1.0f};
  p.position = {{0, 0, 0, 2}, {1, 0, 0, 2}, {2, 0, 0, 2},
                {3, 0, 0, 2}, {0, 0, 0, 1}, {0, 0, 0, -1}};
  const ErrorMetrics two = compareVisibilityIn(p, [](glm::vec4 q) { return q.w == 2.0f; });
  EXPECT_EQ(two.counted_pixels, 3);
  EXPECT_DOUBLE_EQ(two.false_shadow_pct, 100.0 / 3.0);
  EXPECT_DOUBLE_EQ(two.false_lit_pct, 100.0 / 3.0);
  const ErrorMetrics all = compareVisibilityIn(p, [](glm::vec4) { return true; });
  EXPECT_EQ(all.counted_pixels, 4);  // not the surfaceless pixel
  EXPECT_DOUBLE_EQ(all.false_lit_pct, 50.0);
  const ErrorMetrics by_position = compareVisibilityIn(p, [](glm::vec4 q) { return q.x > 0.5f; });
  EXPECT_EQ(by_position.counted_pixels, 2);
  EXPECT_DOUBLE_EQ(by_position.false_shadow_pct, 50.0);
  const ErrorMetrics none = compareVisibilityIn(p, [](glm::vec4) { return false; });
  EXPECT_EQ(none.counted_pixels, 0);
  EXPECT_EQ(none.false_shadow_pct + none.false_lit_pct, 0.0);
  p.position.pop_back();
  EXPECT_THROW(compareVisibilityIn(p, [](glm::vec4) { return true; }), std::invalid_argument);
}

TEST(Metrics, ErrorImagePaintsFalseShadowMagentaAndFalseLitCyan) {
  // Pixels: uncounted, correct lit, correct shadow, false shadow, false lit,
  // NaN on lit truth, Inf on shadowed truth, uncounted with NaN.
  const std::vector<float> rendered = {0.0f, 1.0f, 0.0f, 0.2f, 0.5f, kNaN, kInf, kNaN};
  const std::vector<float> truth = {kNotCounted, 0.9f, 0.1f, 1.0f, 0.0f, 1.0f, 0.0f, kNotCounted};
  std::vector<std::uint8_t> shaded;
  for (std::size_t i = 0; i < truth.size(); ++i) shaded.insert(shaded.end(), {200, 100, 255, 7});
  const std::vector<std::uint8_t> img = errorImage(shaded, rendered, truth);
  ASSERT_EQ(img.size(), shaded.size());
  using Px = std::vector<std::uint8_t>;
  const Px dim = {70, 35, 89, 255};  // 35% of (200, 100, 255), opaque
  const Px magenta = {255, 0, 255, 255};
  const Px cyan = {0, 255, 255, 255};
  const std::vector<Px> expected = {dim, dim, dim, magenta, cyan, magenta, cyan, dim};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(Px(img.begin() + 4 * i, img.begin() + 4 * i + 4), expected[i]) << "pixel " << i;
  }
}

}  // namespace
}  // namespace shadows
