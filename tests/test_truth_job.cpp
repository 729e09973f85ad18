// The truth job and its trace as bytes (what a browser's tracer receives and returns), and
// the native tracer of a job against Truth called directly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <stdexcept>
#include <vector>

#include "test_meshes.hpp"
#include "truth/truth_job.hpp"

namespace shadows {
namespace {

// A sphere over a quad, seen from above by a 24x16 grid of surface points, with a soft light
// and lesson 08's air (and a spot texture): every field of the job has something in it.
TruthJob sampleJob(bool air) {
  testing::Mesh m;
  testing::addSphere(m, {0.0f, 2.0f, 0.0f}, 1.0f, 32, 16);
  const auto base = static_cast<unsigned>(m.positions.size());
  m.positions.insert(m.positions.end(), {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}});
  m.triangles.emplace_back(base, base + 1, base + 2);
  m.triangles.emplace_back(base, base + 2, base + 3);
  TruthJob job;
  job.positions = m.positions;
  job.triangles = m.triangles;
  job.scene_radius = 7.0f;
  job.surface.width = 24;
  job.surface.height = 16;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 24; ++x) {
      // One pixel left out (w = -1), as the geometry pass leaves what is outside the frustum.
      const float object = x == 3 && y == 5 ? -1.0f : 1.0f;
      job.surface.position.emplace_back(-3.0f + 0.25f * static_cast<float>(x), 0.0f,
                                        -2.0f + 0.25f * static_cast<float>(y), object);
      job.surface.normal.emplace_back(0.0f, 1.0f, 0.0f, 0.0f);
    }
  }
  job.light.position = {0.5f, 6.0f, 0.2f};
  job.light.direction = {0.0f, -1.0f, 0.0f};
  job.light.radius = 0.4f;
  job.light.samples = 16;
  if (air) {
    TruthJob::Air a;
    a.eye = {0.0f, 8.0f, 6.0f};
    a.inverse_view_projection =
        glm::inverse(glm::perspective(glm::radians(50.0f), 1.5f, 0.1f, 30.0f) *
                     glm::lookAt(a.eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
    a.medium.density = 0.2f;
    a.medium.light_position = job.light.position;
    a.medium.light_view_projection =
        glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 12.0f) *
        glm::lookAt(job.light.position, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    a.medium.samples = 16;
    a.spot = SpotTexture::builtin(0.3f, 32);
    job.air = std::move(a);
  }
  return job;
}

TEST(TruthJob, BytesRoundTripWithEveryField) {
  for (const bool air : {false, true}) {
    const TruthJob job = sampleJob(air);
    const std::vector<std::uint8_t> bytes = serializeTruthJob(job);
    const TruthJob back = parseTruthJob(bytes);
    EXPECT_EQ(serializeTruthJob(back), bytes) << air;
    EXPECT_EQ(back.id(), job.id());
    EXPECT_EQ(back.sceneId(), job.sceneId());
    EXPECT_EQ(back.air.has_value(), air);
    if (air) {
      ASSERT_TRUE(back.air->spot.has_value());
      EXPECT_EQ(back.air->spot->image().rgba, job.air->spot->image().rgba);
    }
    // The job's first words: the magic "SHTJ", version 1, then its id.
    ASSERT_GE(bytes.size(), 16u);
    EXPECT_EQ(std::memcmp(bytes.data(), "SHTJ", 4), 0);
    std::uint64_t id = 0;
    std::memcpy(&id, bytes.data() + 8, 8);
    EXPECT_EQ(id, job.id());
  }
}

TEST(TruthJob, TheIdFollowsWhatTheTracerSees) {
  const TruthJob job = sampleJob(true);
  TruthJob other = job;
  other.light.samples = 25;
  EXPECT_NE(other.id(), job.id());
  EXPECT_EQ(other.sceneId(), job.sceneId());
  other = job;
  other.air->medium.density = 0.3f;
  EXPECT_NE(other.id(), job.id());
  other = job;
  other.positions[0].x += 0.001f;
  EXPECT_NE(other.sceneId(), job.sceneId());
}

TEST(TruthJob, MalformedBytesAreRefusedWithAReason) {
  const std::vector<std::uint8_t> bytes = serializeTruthJob(sampleJob(true));
  for (const std::size_t cut :
       {std::size_t{0}, std::size_t{10}, std::size_t{200}, bytes.size() - 1}) {
    EXPECT_THROW(parseTruthJob({bytes.begin(), bytes.begin() + static_cast<long>(cut)}),
                 std::invalid_argument)
        << cut;
  }
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_THROW(parseTruthJob(longer), std::invalid_argument);
  std::vector<std::uint8_t> changed = bytes;
  changed[changed.size() / 2] ^= 1;  // a surface point moved: the id no longer matches
  EXPECT_THROW(parseTruthJob(changed), std::invalid_argument);
  std::vector<std::uint8_t> version = bytes;
  version[4] = 2;
  try {
    parseTruthJob(version);
    ADD_FAILURE() << "version 2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("version 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseTruthTrace(bytes), std::invalid_argument);  // a job is not a trace
}

TEST(TruthJob, TheNativeTracerTracesTheJobAsTruthDoes) {
  const TruthJob job = sampleJob(true);
  const auto tracer = makeTruthTracer(job);
  EXPECT_EQ(tracer->sceneId(), job.sceneId());
  const TruthTrace trace = tracer->trace(job);
  const Truth truth(job.positions, job.triangles, job.scene_radius);
  EXPECT_EQ(trace.visibility, truth.visibility(job.surface, job.light));
  AirMedium medium = job.air->medium;
  medium.spot = &*job.air->spot;
  const Truth::AirResult air =
      truth.airLight(job.surface, job.air->eye, job.air->inverse_view_projection, medium);
  ASSERT_TRUE(trace.air.has_value());
  EXPECT_EQ(trace.air->light, air.light);
  EXPECT_EQ(trace.air->noise, air.noise);
  // Not a trivial scene: some counted pixels are shadowed, some lit, some partly; one is not
  // counted; the air has light.
  int shadowed = 0, lit = 0, partial = 0, not_counted = 0;
  for (float v : trace.visibility) {
    not_counted += v == kNotCounted;
    shadowed += v == 0.0f;
    lit += v == 1.0f;
    partial += v > 0.0f && v < 1.0f;
  }
  EXPECT_EQ(not_counted, 1);
  EXPECT_GT(shadowed, 0);
  EXPECT_GT(lit, 0);
  EXPECT_GT(partial, 0);
  EXPECT_GT(air.noise, 0.0);
  // A tracer is for its scene only.
  TruthJob moved = job;
  moved.positions[0].y += 1.0f;
  EXPECT_THROW(tracer->trace(moved), std::invalid_argument);
}

TEST(TruthJob, TraceBytesRoundTrip) {
  const TruthJob job = sampleJob(true);
  TruthTrace trace = makeTruthTracer(job)->trace(job);
  trace.job_id = job.id();
  const std::vector<std::uint8_t> bytes = serializeTruthTrace(trace);
  const TruthTrace back = parseTruthTrace(bytes);
  EXPECT_EQ(back.job_id, job.id());
  EXPECT_EQ(back.width, 24);
  EXPECT_EQ(back.height, 16);
  EXPECT_EQ(back.visibility, trace.visibility);
  ASSERT_TRUE(back.air.has_value());
  EXPECT_EQ(back.air->light, trace.air->light);
  EXPECT_EQ(back.air->noise, trace.air->noise);
  EXPECT_EQ(serializeTruthTrace(back), bytes);
  EXPECT_THROW(parseTruthTrace({bytes.begin(), bytes.end() - 4}), std::invalid_argument);
  TruthTrace wrong = trace;
  wrong.visibility.pop_back();
  EXPECT_THROW(serializeTruthTrace(wrong), std::invalid_argument);
}

// A trace holds what a tracer can answer: visibility in [0, 1] or -1 (not counted), air light
// finite and >= 0; anything else is refused with the pixel it was found at (issue 53, 4). A trace
// of 0x0 pixels is well formed (its vectors empty: nothing copied from their null data).
TEST(TruthJob, ATraceOfImpossibleValuesIsRefused) {
  const TruthJob job = sampleJob(true);
  const TruthTrace trace = makeTruthTracer(job)->trace(job);
  ASSERT_TRUE(trace.air.has_value());
  const std::vector<float> visibility = trace.visibility, air = trace.air->light;
  // The trace's bytes with its visibility and air light replaced.
  const auto bytesOf = [&](const std::vector<float>& v, const std::vector<float>& a, double noise) {
    TruthTrace t;
    t.job_id = trace.job_id;
    t.width = trace.width;
    t.height = trace.height;
    t.visibility = v;
    t.air = Truth::AirResult{a, noise};
    return serializeTruthTrace(t);
  };
  for (const float bad :
       {1e30f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
        std::numeric_limits<float>::quiet_NaN(), -7.0f, -0.001f, 1.001f}) {
    std::vector<float> v = visibility;
    v[24 * 2 + 5] = bad;
    try {
      parseTruthTrace(bytesOf(v, air, trace.air->noise));
      ADD_FAILURE() << "visibility " << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("pixel (5, 2)"), std::string::npos) << e.what();
    }
    std::vector<float> a = air;
    a[7] = bad < 0.0f || !std::isfinite(bad) ? bad : -bad;
    EXPECT_THROW(parseTruthTrace(bytesOf(visibility, a, trace.air->noise)), std::invalid_argument)
        << bad;
  }
  EXPECT_THROW(parseTruthTrace(bytesOf(visibility, air, std::numeric_limits<double>::quiet_NaN())),
               std::invalid_argument);
  // The edges themselves are answers: 0, 1, -1 (not counted).
  std::vector<float> edges = visibility, dark = air;
  edges[0] = 0.0f;
  edges[1] = 1.0f;
  edges[2] = kNotCounted;
  dark[0] = 0.0f;
  EXPECT_EQ(parseTruthTrace(bytesOf(edges, dark, trace.air->noise)).visibility, edges);

  TruthTrace empty;
  empty.job_id = 7;
  const TruthTrace back = parseTruthTrace(serializeTruthTrace(empty));
  EXPECT_EQ(back.width, 0);
  EXPECT_TRUE(back.visibility.empty());
}

}  // namespace
}  // namespace shadows
