// Lesson 15's atlas (math/light_map_atlas.hpp), no GL: charts where the meshes are cut, every
// vertex on a texel of its own chart, charts apart by their padding, texel points on the
// surfaces at the density asked for, the refusal past the memory limit, and the dilation.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "math/light_map_atlas.hpp"

namespace shadows {
namespace {

std::vector<SceneObject> objects() {
  std::vector<SceneObject> o;
  o.push_back({"floor", makePlane(2.0f, 1.0f), glm::mat4(1.0f), glm::vec3(0.8f), false, true});
  o.push_back({"box", makeBox({0.5f, 0.25f, 0.5f}),
               glm::translate(glm::mat4(1.0f), {0.0f, 0.25f, 0.0f}), glm::vec3(0.8f)});
  o.push_back({"sphere", makeSphere(0.4f, 16, 8),
               glm::translate(glm::mat4(1.0f), {1.0f, 0.4f, 0.0f}), glm::vec3(0.8f)});
  o.push_back({"pyramid", makePyramid(0.5f, 1.0f), glm::scale(glm::mat4(1.0f), {2.0f, 1.0f, 1.0f}),
               glm::vec3(0.8f)});
  return o;
}

TEST(LightMapAtlas, ChartsFollowTheMeshesCuts) {
  const LightMapAtlas a = planLightMap(objects(), 8.0f, 2);
  std::vector<int> per_object(4, 0);
  for (const auto& c : a.charts) ++per_object[c.object];
  // A plane one; a box a chart a face; a sphere's grid one; a pyramid four sides and its base.
  EXPECT_EQ(per_object, (std::vector<int>{1, 6, 1, 5}));
  EXPECT_EQ(a.width % 4, 0);  // R16F rows of any width, RG32F too; kept tidy
}

TEST(LightMapAtlas, ChartsDoNotOverlapAndKeepTheirPadding) {
  const LightMapAtlas a = planLightMap(objects(), 8.0f, 3);
  for (size_t i = 0; i < a.charts.size(); ++i) {
    const auto& c = a.charts[i];
    EXPECT_GE(c.origin.x, 3);
    EXPECT_GE(c.origin.y, 3);
    EXPECT_LE(c.origin.x + c.size.x + 3, a.width);
    EXPECT_LE(c.origin.y + c.size.y + 3, a.height);
    for (size_t j = i + 1; j < a.charts.size(); ++j) {
      const auto& d = a.charts[j];
      const bool apart =
          c.origin.x + c.size.x + 6 <= d.origin.x || d.origin.x + d.size.x + 6 <= c.origin.x ||
          c.origin.y + c.size.y + 6 <= d.origin.y || d.origin.y + d.size.y + 6 <= c.origin.y;
      EXPECT_TRUE(apart) << "charts " << i << " and " << j;
    }
  }
}

TEST(LightMapAtlas, EveryVertexSitsInsideItsChart) {
  const auto o = objects();
  const LightMapAtlas a = planLightMap(o, 8.0f, 2);
  for (const auto& c : a.charts) {
    for (const std::uint32_t t : c.triangles) {
      for (int j = 0; j < 3; ++j) {
        const glm::vec2 uv = a.uv[c.object][o[c.object].mesh.indices[3 * t + j]];
        const glm::vec2 texel = uv * glm::vec2(a.width, a.height) - 0.5f;
        // On or between the chart's first and last texel centres (float rounding aside).
        EXPECT_GE(texel.x, static_cast<float>(c.origin.x) - 1e-3f);
        EXPECT_GE(texel.y, static_cast<float>(c.origin.y) - 1e-3f);
        EXPECT_LE(texel.x, static_cast<float>(c.origin.x + c.size.x - 1) + 1e-3f);
        EXPECT_LE(texel.y, static_cast<float>(c.origin.y + c.size.y - 1) + 1e-3f);
      }
    }
  }
}

TEST(LightMapAtlas, TexelsLieOnTheSurfacesAtTheDensityAsked) {
  const auto o = objects();
  LightMapAtlas a = planLightMap(o, 10.0f, 2);
  fillLightMap(o, a);
  // The floor (4 x 2 units) at 10 texels a unit: 41 x 21 texel centres, every one covered.
  const auto& floor = a.charts[0].object == 0 ? a.charts[0] : a.charts.back();
  ASSERT_EQ(floor.object, 0u);
  EXPECT_EQ(floor.size, glm::ivec2(41, 21));
  long long on_floor = 0;
  for (size_t i = 0; i < a.position.size(); ++i) {
    if (a.position[i].w == 0.0f) {
      ++on_floor;
      EXPECT_NEAR(a.position[i].y, 0.0f, 1e-6f);
      EXPECT_NEAR(a.normal[i].y, 1.0f, 1e-6f);
    }
  }
  EXPECT_EQ(on_floor, 41 * 21);
  // Neighbouring floor texels are a tenth of a unit apart.
  const size_t first = static_cast<size_t>(floor.origin.y) * a.width + floor.origin.x;
  EXPECT_NEAR(glm::distance(glm::vec3(a.position[first]), glm::vec3(a.position[first + 1])), 0.1f,
              1e-5f);
  // The stretched pyramid (x scaled 2) gets its charts sized in world units, not its own.
  for (size_t i = 0; i < a.position.size(); ++i) {
    if (a.position[i].w != 3.0f) continue;
    EXPECT_LE(std::abs(a.position[i].x), 1.0f + 1e-5f);
  }
  // A point on the sphere is at its radius from its centre; its normal points out.
  for (size_t i = 0; i < a.position.size(); ++i) {
    if (a.position[i].w != 2.0f) continue;
    const glm::vec3 out = glm::vec3(a.position[i]) - glm::vec3(1.0f, 0.4f, 0.0f);
    EXPECT_NEAR(glm::length(out), 0.4f, 0.02f);  // a 16 x 8 grid's flat facets
    EXPECT_GT(glm::dot(out, glm::vec3(a.normal[i])), 0.0f);
  }
  // A pyramid side is a triangle in its rectangle: some of its texels cover nothing.
  EXPECT_LT(a.coveredTexels(), a.texels());
}

TEST(LightMapAtlas, ChartsEndingOnTexelEdgesCoverWholeTexels) {
  const auto o = objects();
  LightMapAtlas a = planLightMap(o, 10.0f, 2, /*texelEdges=*/true);
  fillLightMap(o, a);
  // The floor at 10 texels a unit: 40 x 20 texels, their centres half a texel in from its
  // edges, and its corners on the outer edges of its corner texels.
  const auto& floor = a.charts[0].object == 0 ? a.charts[0] : a.charts.back();
  ASSERT_EQ(floor.object, 0u);
  EXPECT_EQ(floor.size, glm::ivec2(40, 20));
  float lo_x = 1e9f, hi_x = -1e9f;
  for (const glm::vec2 uv : a.uv[0]) {
    lo_x = std::min(lo_x, uv.x * static_cast<float>(a.width));
    hi_x = std::max(hi_x, uv.x * static_cast<float>(a.width));
  }
  EXPECT_NEAR(lo_x, static_cast<float>(floor.origin.x), 1e-3f);
  EXPECT_NEAR(hi_x, static_cast<float>(floor.origin.x + floor.size.x), 1e-3f);
  long long on_floor = 0;
  float min_x = 1e9f;
  for (size_t i = 0; i < a.position.size(); ++i) {
    if (a.position[i].w != 0.0f) continue;
    ++on_floor;
    min_x = std::min(min_x, a.position[i].x);
  }
  EXPECT_EQ(on_floor, 40 * 20);
  EXPECT_NEAR(min_x, -2.0f + 0.05f, 1e-5f);  // the first centre, half a texel in
}

TEST(LightMapAtlas, PastTheLimitARefusalNamesIt) {
  const auto o = objects();
  EXPECT_EQ(lightMapRefusal(planLightMap(o, 16.0f, 2)), "");
  const LightMapAtlas big = planLightMap(o, 3000.0f, 2);
  ASSERT_GT(big.texels(), kLightMapTexelLimit);
  const std::string why = lightMapRefusal(big);
  EXPECT_NE(why.find("4096 texels a side and 4096 x 4096 in all"), std::string::npos) << why;
  EXPECT_NE(why.find("lightmap.texels_per_unit"), std::string::npos) << why;
  // The limit's bytes rounded, as the README prints them: 754,974,720 is 755 MB, not 754.
  EXPECT_NE(why.find("755 MB"), std::string::npos) << why;
  // A long strip: few texels, but a side past what a texture may be.
  const std::vector<SceneObject> strip = {
      {"strip", makePlane(300.0f, 0.5f), glm::mat4(1.0f), glm::vec3(0.8f), false, true}};
  const LightMapAtlas thin = planLightMap(strip, 8.0f, 2);
  EXPECT_LT(thin.texels(), kLightMapTexelLimit);
  EXPECT_GT(thin.width, kLightMapSideLimit);
  EXPECT_NE(lightMapRefusal(thin), "");
}

TEST(LightMapAtlas, DilationFillsTheGapsFromTheirOwnChart) {
  const auto o = objects();
  LightMapAtlas a = planLightMap(o, 8.0f, 2);
  fillLightMap(o, a);
  // Every covered texel of chart k holds k + 1; the rest hold -5 (nothing).
  std::vector<float> v(a.position.size(), -5.0f);
  for (size_t i = 0; i < v.size(); ++i) {
    if (a.position[i].w >= 0.0f) v[i] = static_cast<float>(a.chart[i] + 1);
  }
  const std::vector<float> before = v;
  dilateLightMap(a, v, 1);
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const size_t i = static_cast<size_t>(y) * a.width + x;
      if (a.chart[i] < 0 || before[i] != -5.0f) continue;
      // A gap in a chart next to a covered texel of its own takes that chart's value, never
      // a neighbouring chart's (across the padding).
      bool beside_own = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= a.width || ny >= a.height) continue;
          const size_t j = static_cast<size_t>(ny) * a.width + nx;
          beside_own |= before[j] != -5.0f && a.chart[j] == a.chart[i];
        }
      }
      if (beside_own) {
        EXPECT_EQ(v[i], static_cast<float>(a.chart[i] + 1)) << "texel " << i;
      } else {
        EXPECT_EQ(v[i], -5.0f) << "texel " << i << ": one ring only";
      }
    }
  }
}

TEST(LightMapAtlas, BordersAreTheEdgesOfOneTriangle) {
  const auto borders = chartBorders(objects());
  EXPECT_EQ(borders[0].size(), 4u);       // a plane's outline
  EXPECT_EQ(borders[1].size(), 6u * 4u);  // each face's
  EXPECT_NEAR(distanceToSegment({0.5f, 1.0f, 0.0f}, {{0, 0, 0}, {1, 0, 0}}), 1.0f, 1e-6f);
  EXPECT_NEAR(distanceToSegment({2.0f, 0.0f, 0.0f}, {{0, 0, 0}, {1, 0, 0}}), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace shadows
