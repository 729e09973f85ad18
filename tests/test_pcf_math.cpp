// Lesson 05's arithmetic without GL (common/math/pcf_math.hpp): seed 000's "Depth
// Values are not Blend-able" example, the kernels' tap offsets (the very ones pcf.glsl takes
// as uTaps), and the area light a kernel imitates.
#include "../common/math/pcf_math.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace shadows::pcf {
namespace {

TEST(PcfMath, AveragingDepthsSaysShadowedWherePercentageCloserSaysHalf) {
  // Seed 000: texels 0.25, 0.25, 0.63, 0.63; the fragment's depth is 0.57.
  const std::vector<float> depths = {0.25f, 0.25f, 0.63f, 0.63f};
  // Average(0.25, 0.25, 0.63, 0.63) = 0.44 and 0.57 > 0.44: "wrongly in shadow", at a depth
  // where nothing is.
  EXPECT_EQ(compareAveragedDepth(depths, 0.57f), 0.0f);
  // Compare first: two texels occlude (0.25 < 0.57), two do not (0.63): 50% lit.
  EXPECT_FLOAT_EQ(percentageCloser(depths, 0.57f), 0.5f);
  // The hardware's bilinear weights between the texel centres give the same at the middle.
  EXPECT_FLOAT_EQ(bilinearPercentageCloser({0.25f, 0.63f, 0.25f, 0.63f}, 0.57f, 0.5f, 0.5f), 0.5f);
  // ... and move smoothly with the position, where the averaged depth flips all at once.
  EXPECT_FLOAT_EQ(bilinearPercentageCloser({0.25f, 0.63f, 0.25f, 0.63f}, 0.57f, 0.75f, 0.5f),
                  0.75f);
}

TEST(PcfMath, PercentageCloserStaysBetweenAllLitAndAllShadowed) {
  const std::vector<float> depths = {0.2f, 0.4f, 0.6f, 0.8f};
  EXPECT_EQ(percentageCloser(depths, 0.1f), 1.0f);  // in front of everything: lit
  EXPECT_EQ(percentageCloser(depths, 0.9f), 0.0f);  // behind everything: shadowed
  EXPECT_FLOAT_EQ(percentageCloser(depths, 0.5f), 0.5f);
}

TEST(PcfMath, GridTapsAreTheMidpointsOfTheKernelBox) {
  const auto taps = gridOffsets(8, 2.0f);
  ASSERT_EQ(taps.size(), 64u);
  float lo = 1e9f, hi = -1e9f;
  glm::vec2 sum(0.0f);
  for (const auto& t : taps) {
    lo = std::min({lo, t.x, t.y});
    hi = std::max({hi, t.x, t.y});
    sum += t;
  }
  EXPECT_FLOAT_EQ(lo, -1.75f);  // half a step (0.25 of 2 texels) inside the box edge
  EXPECT_FLOAT_EQ(hi, 1.75f);
  EXPECT_NEAR(sum.x, 0.0f, 1e-5f);  // centred: no shift of the shadow edge
  EXPECT_NEAR(sum.y, 0.0f, 1e-5f);
  EXPECT_EQ(gridOffsets(1, 5.0f)[0], glm::vec2(0.0f));
}

TEST(PcfMath, TheFourDitheredPatternsOfA2x2BlockAreThe16TapGrid) {
  // Seed 001: each pixel takes 4 taps chosen by gl_FragCoord mod 2; a 2x2 block of pixels
  // together covers the 4x4 grid of the same radius once each, which is why 4 dithered taps
  // look like 16 from a step back.
  std::vector<glm::vec2> dithered;
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) {
      for (const auto& t : ditheredOffsets(x, y, 3.0f)) dithered.push_back(t);
    }
  }
  std::vector<glm::vec2> grid = gridOffsets(4, 3.0f);
  auto order = [](const glm::vec2& a, const glm::vec2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  std::sort(dithered.begin(), dithered.end(), order);
  std::sort(grid.begin(), grid.end(), order);
  ASSERT_EQ(dithered.size(), grid.size());
  for (size_t i = 0; i < grid.size(); ++i) {
    EXPECT_FLOAT_EQ(dithered[i].x, grid[i].x) << i;
    EXPECT_FLOAT_EQ(dithered[i].y, grid[i].y) << i;
  }
  // The pattern depends on the pixel only through its parity.
  EXPECT_EQ(ditheredOffsets(3, 5, 3.0f), ditheredOffsets(1, 1, 3.0f));
}

TEST(PcfMath, TheShadersTapArrayHoldsEachKernelCentredInItsLayout) {
  // pcf.glsl indexes the compiled offsets: grid corners first, then row by row; dithered
  // pattern x + 2y; poisson in disk order.
  auto centre = [](const std::vector<glm::vec2>& taps) {
    glm::vec2 sum(0.0f);
    for (const auto& t : taps) sum += t;
    return sum / static_cast<float>(taps.size());
  };
  const auto grid = tapOffsets(Mode::Grid, 20, 3.0f);  // 4 x 4
  ASSERT_EQ(grid.size(), 16u);
  const auto rows = gridOffsets(4, 3.0f);
  EXPECT_EQ(grid, cornersFirst(rows, 4));
  EXPECT_EQ(grid[4], rows[1]) << "after the corners, row by row: x runs first";
  EXPECT_EQ(grid[5], rows[2]);
  EXPECT_EQ(grid[6], rows[4]);
  EXPECT_NEAR(glm::length(centre(grid)), 0.0f, 1e-5f);
  const auto dithered = tapOffsets(Mode::Dithered, 16, 3.0f);
  ASSERT_EQ(dithered.size(), 16u);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) {
      const auto pattern = ditheredOffsets(x, y, 3.0f);
      for (size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(dithered[static_cast<size_t>(4 * (x + 2 * y)) + k], pattern[k]) << x << y;
      }
    }
  }
  EXPECT_NEAR(glm::length(centre(dithered)), 0.0f, 1e-5f);
  const auto poisson = tapOffsets(Mode::Poisson, 10, 2.0f);
  ASSERT_EQ(poisson.size(), 10u);
  EXPECT_EQ(poisson[3], 2.0f * poissonDisk()[3]);
  EXPECT_EQ(tapOffsets(Mode::Poisson, 1, 2.0f).size(), 4u) << "never fewer than the 4 probes";
  EXPECT_EQ(tapOffsets(Mode::None, 64, 5.0f), std::vector<glm::vec2>{glm::vec2(0.0f)});
  EXPECT_EQ(tapOffsets(Mode::Hw2x2, 64, 5.0f), std::vector<glm::vec2>{glm::vec2(0.0f)});
}

TEST(PcfMath, TheGridsFirstFourTapsAreItsCornersTheEarlyOutsProbes) {
  // pcf.glsl probes with the first four compiled offsets (the grid's and the disk's alike):
  // for the grid they must be its four corners, and every tap must still come exactly once.
  for (int n = 3; n <= 8; ++n) {
    const auto rows = gridOffsets(n, 1.0f);
    const auto taps = unitTapOffsets(Mode::Grid, n * n);
    ASSERT_EQ(taps.size(), rows.size()) << n;
    // A corner: x and y each the smallest or the largest of the grid (the midpoints are not
    // symmetric to the last bit, so no sign flip); the four all different.
    const float low = rows.front().x, high = rows.back().x;
    for (size_t k = 0; k < 4; ++k) {
      EXPECT_TRUE(taps[k].x == low || taps[k].x == high) << n << " probe " << k;
      EXPECT_TRUE(taps[k].y == low || taps[k].y == high) << n << " probe " << k;
      for (size_t j = 0; j < k; ++j) EXPECT_NE(taps[j], taps[k]) << n << " probes " << j << k;
    }
    auto sorted = [](std::vector<glm::vec2> v) {
      std::sort(v.begin(), v.end(), [](const glm::vec2& a, const glm::vec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
      });
      return v;
    };
    EXPECT_EQ(sorted(taps), sorted(rows)) << n << ": the same taps, each once";
  }
  // 2 x 2 is all corners: its own order.
  EXPECT_EQ(unitTapOffsets(Mode::Grid, 4), gridOffsets(2, 1.0f));
}

TEST(PcfMath, TheShaderScalesTheCompiledUnitOffsetsByTheRadiusAsTheCppDoes) {
  // pcf.glsl takes unitTapOffsets() as constants and multiplies each by the radius (one
  // rounding): the offsets of tapOffsets(), float for float, for any radius.
  for (const Mode mode : {Mode::None, Mode::Grid, Mode::Dithered, Mode::Poisson}) {
    for (const int taps : {1, 9, 20, 64}) {
      for (const float radius : {0.0f, 1.5f, 2.3f, 16.0f}) {
        std::vector<glm::vec2> scaled = unitTapOffsets(mode, taps);
        for (glm::vec2& o : scaled) o *= radius;
        EXPECT_EQ(tapOffsets(mode, taps, radius), scaled);
      }
    }
  }
  // The grid's and the disk's as they were before they were compiled in (uTaps, issue 20),
  // the grid's corners first.
  EXPECT_EQ(tapOffsets(Mode::Grid, 9, 2.3f), cornersFirst(gridOffsets(3, 2.3f), 3));
  EXPECT_EQ(tapOffsets(Mode::Poisson, 64, 2.3f)[63], poissonDisk()[63] * 2.3f);
  // Seed 001's dithered taps, (-1.5, 1.5) swidth + (x, -y) swidth with swidth = radius / 2:
  // the unit pattern is exact, so for a radius whose quarters are exact the seed's sums agree.
  const float swidth = 0.5f * 3.0f;
  EXPECT_EQ(ditheredOffsets(1, 1, 3.0f)[0],
            glm::vec2(-1.5f * swidth + swidth, 1.5f * swidth - swidth));
}

TEST(PcfMath, ThePoissonDiskFillsTheUnitDiskAndProbesOnItsRim) {
  // The first four double as early-out probes: on the rim, one per quadrant, centred.
  glm::vec2 probes(0.0f);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_GT(glm::length(poissonDisk()[k]), 0.85f) << k;
    probes += poissonDisk()[k];
  }
  EXPECT_NEAR(glm::length(probes), 0.0f, 1e-4f);
  glm::vec2 all(0.0f);
  for (const auto& p : poissonDisk()) {
    EXPECT_LE(glm::length(p), 1.0f);
    all += p;
  }
  EXPECT_LT(glm::length(all / 64.0f), 0.05f) << "no sideways shift of the shadow";
}

TEST(PcfMath, GridSideIsTheLargestSquareInTheTapBudget) {
  EXPECT_EQ(gridSide(1), 1);
  EXPECT_EQ(gridSide(3), 1);
  EXPECT_EQ(gridSide(4), 2);
  EXPECT_EQ(gridSide(16), 4);
  EXPECT_EQ(gridSide(63), 7);
  EXPECT_EQ(gridSide(64), 8);
  EXPECT_EQ(gridSide(1000), 8);  // 8 x 8 = 64 at most
  EXPECT_EQ(gridSide(0), 1);
}

TEST(PcfMath, GatherTakesAGridWhoseTapsAreAdjacentTexels) {
  // Midpoints 2 r / N apart: one texel when r = N / 2, the grid's offsets then whole or half
  // texels one apart (tapOffsets), so 2 x 2 blocks hold them.
  EXPECT_EQ(gatherGridSide(Mode::Grid, 3, 1.5f), 3);
  EXPECT_EQ(gatherGridSide(Mode::Grid, 8, 4.0f), 8);
  const auto offsets = tapOffsets(Mode::Grid, 9, 1.5f);
  // -1, 0, 1: adjacent texels, up to the rounding of (2/3) * 1.5 in floats. The shader's
  // s + offset / size rounds too (about size * 2^-24 texel): a tap that close to a texel's
  // edge may pick its neighbour where the gathered block does not.
  for (const glm::vec2& o : offsets) {
    EXPECT_NEAR(o.x, std::round(o.x), 1e-6);
    EXPECT_NEAR(o.y, std::round(o.y), 1e-6);
  }
  EXPECT_EQ(gatherGridSide(Mode::Grid, 3, 1.0f), 0);  // 2/3 texel apart
  EXPECT_EQ(gatherGridSide(Mode::Grid, 3, 3.0f), 0);  // 2 texels apart: one tap a block
  EXPECT_EQ(gatherGridSide(Mode::Grid, 1, 0.5f), 0);  // one tap
  EXPECT_EQ(gatherGridSide(Mode::Poisson, 4, 2.0f), 0);
  EXPECT_EQ(gatherGridSide(Mode::Dithered, 4, 2.0f), 0);
}

TEST(PcfMath, AreaLightRadiusMatchesThePenumbraWidth) {
  // Occluder edge at 6, receiver at 8 from the light, texel 0.01 wide at the receiver, kernel
  // half-width 2 texels: the kernel blurs +-0.02. A disk of radius a gives a penumbra of
  // half-width a (8 - 6) / 6, so a = 0.06.
  const float a = areaLightRadius(2.0f, 0.01f, 6.0f, 8.0f);
  EXPECT_FLOAT_EQ(a, 0.06f);
  EXPECT_FLOAT_EQ(a * (8.0f - 6.0f) / 6.0f, 2.0f * 0.01f);
  // Linear in the kernel; a wider gap needs a smaller light for the same blur.
  EXPECT_FLOAT_EQ(areaLightRadius(4.0f, 0.01f, 6.0f, 8.0f), 2.0f * a);
  EXPECT_LT(areaLightRadius(2.0f, 0.01f, 6.0f, 12.0f), a);
  // No kernel, no gap, or nonsense: a point light.
  EXPECT_EQ(areaLightRadius(0.0f, 0.01f, 6.0f, 8.0f), 0.0f);
  EXPECT_EQ(areaLightRadius(2.0f, 0.01f, 6.0f, 6.0f), 0.0f);
  EXPECT_EQ(areaLightRadius(2.0f, 0.01f, 0.0f, 6.0f), 0.0f);
  EXPECT_EQ(areaLightRadius(2.0f, -0.01f, 6.0f, 8.0f), 0.0f);  // receiver behind the light
  // Directional: the truth's cone is set at the receiver, so the radius scales with dR, not dO.
  EXPECT_FLOAT_EQ(areaLightRadius(2.0f, 0.01f, 6.0f, 8.0f, /*directional=*/true), a * 8.0f / 6.0f);
}

}  // namespace
}  // namespace shadows::pcf
