// Values computed twice, once in a shader and once on the CPU for the truth, compared on the
// same input: a spotlight image's colour weighs the same in spot.glsl and SpotTexture, so the
// rendered air and the ray-marched air agree for a coloured image as for a grey one.
#include <unistd.h>

#include <array>
#include <filesystem>

#include "core/spotlight.hpp"
#include "harness.hpp"

namespace shadows {
namespace {

namespace fs = std::filesystem;

// A spotlight image of one colour inside the inscribed circle, black outside.
Image disc(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  constexpr int kSide = 64;
  Image image{kSide, kSide, std::vector<std::uint8_t>(kSide * kSide * 4, 0)};
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const float dx = (static_cast<float>(x) + 0.5f) / kSide * 2.0f - 1.0f;
      const float dy = (static_cast<float>(y) + 0.5f) / kSide * 2.0f - 1.0f;
      if (dx * dx + dy * dy >= 0.8f) continue;
      std::uint8_t* px = &image.rgba[static_cast<size_t>(y * kSide + x) * 4];
      px[0] = r, px[1] = g, px[2] = b, px[3] = 255;
    }
  }
  return image;
}

TEST(Twins, AColouredSpotWeighsTheSameOnTheGpuAndInTheTruth) {
  const fs::path dir = fs::temp_directory_path() / ("shadows_twins_" + std::to_string(getpid()));
  fs::create_directories(dir);
  double grey_error = 0.0;
  // Grey first: its error is what the slices cost; each pure primary must do as well.
  for (const auto& [name, colour] :
       std::vector<std::pair<std::string, std::array<std::uint8_t, 3>>>{{"grey", {200, 200, 200}},
                                                                        {"red", {255, 0, 0}},
                                                                        {"green", {0, 255, 0}},
                                                                        {"blue", {0, 0, 255}}}) {
    const std::string path = (dir / (name + ".png")).string();
    ASSERT_TRUE(writePng(path, disc(colour[0], colour[1], colour[2])));
    // The CPU twin of the GPU's luminance, read back from the file.
    const SpotTexture spot = SpotTexture::fromPng(path);
    EXPECT_NEAR(spot.value({0.5f, 0.5f}),
                (0.2126 * colour[0] + 0.7152 * colour[1] + 0.0722 * colour[2]) / 255.0, 1e-5)
        << name;
    auto runner = testing::startLesson("08_atmospherics", {"spot.image=" + path}, 160, 120);
    runner->renderFrame();
    const AirMetrics air = runner->measureError().metrics.air;
    ASSERT_TRUE(air.valid) << name;
    if (name == "grey") grey_error = air.rel_rmse;
    EXPECT_LT(air.rel_rmse, 1.5 * grey_error + 0.02) << name << ": the shader and the truth "
                                                     << "weigh this colour differently";
    EXPECT_EQ(runner->glErrors(), 0);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace shadows
