// Lesson 09 end to end, headless: each choice the shadow-volume slides discuss, its failure
// measured against the ray-traced truth, and its fix.
#include "harness.hpp"

#include "../09_shadow_volumes/ray_count.hpp"
#include "math/shadow_volume.hpp"

namespace shadows {
namespace {

using testing::label;
using testing::reportNumber;
using testing::startLesson;

const std::string kLesson = "09_shadow_volumes";

// Renders once and measures against the truth.
ErrorMetrics measured(const std::vector<std::string>& sets, int w = 320, int h = 240) {
  const ErrorMetrics e = testing::measureOnce(kLesson, sets, w, h);
  EXPECT_GT(e.counted_pixels, 1000) << label(sets);
  return e;
}

double wrongPct(const ErrorMetrics& e) {
  return e.false_shadow_pct + e.false_lit_pct;
}

long long counter(Runner& runner, const std::string& name) {
  return runner.measure().lastFrameCounts().at(name);
}

TEST(Lesson09, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson09, WeldingClosesTheSeamsAndNamesAnOpenMesh) {
  // Every caster of the presets closes once welded by position; a plane does not: its rim is
  // open and it becomes a two-sided shell.
  for (const MeshData& closed : {makeTorus(1.0f, 0.35f, 96, 48), makeSphere(0.45f, 48, 24),
                                 makePyramid(0.8f, 1.6f), makeBox({1, 1, 1})}) {
    const EdgeMesh m = buildEdgeMesh(closed);
    EXPECT_EQ(m.open_edges, 0);
    EXPECT_FALSE(m.two_sided);
    EXPECT_EQ(m.edges.size() * 2, m.planes.size() * 3) << "each edge shared by two triangles";
  }
  const EdgeMesh plane = buildEdgeMesh(makePlane(1, 1));
  EXPECT_EQ(plane.open_edges, 4);
  EXPECT_TRUE(plane.two_sided);
  EXPECT_EQ(plane.edges.size(), 5u + 1u) << "two triangles and their reversed copies";
}

TEST(Lesson09, VolumeCountersAreWhatOneCountsByHandOnACubeAPyramidAndAnOpenQuad) {
  // volumeWork's silhouette edges and triangles (the report's counters) on meshes whose
  // answer a student counts on paper: sides are 2 triangles per silhouette edge; z-fail adds
  // the lit triangles (light cap) and the unlit ones (dark cap).
  struct Case {
    const char* what;
    MeshData mesh;
    glm::vec4 light;  // in the mesh's space: (position, 1) or (-direction, 0)
    long long silhouettes, lit, unlit;
  };
  const std::vector<Case> cases = {
      // The unit cube lit from straight above: the top's two triangles lit, its 4 rim edges.
      {"cube, light above", makeBox({1, 1, 1}), {0, 10, 0, 1}, 4, 2, 10},
      // From a corner's side (x, y, z > 1): three faces lit, the silhouette a hexagon.
      {"cube, light off a corner", makeBox({1, 1, 1}), {10, 9, 8, 1}, 6, 6, 6},
      // A directional light along -y: the same as from above.
      {"cube, sun overhead", makeBox({1, 1, 1}), {0, 1, 0, 0}, 4, 2, 10},
      // The square pyramid lit from above its apex: its 4 sides lit, the base's 4 edges.
      {"pyramid, light above", makePyramid(0.8f, 1.6f), {0, 10, 0, 1}, 4, 4, 2},
      // Lit from below: only the base (2 triangles); its rim again.
      {"pyramid, light below", makePyramid(0.8f, 1.6f), {0, -10, 0, 1}, 4, 2, 4},
      // An open quad, made a two-sided shell: the top copy lit, the reversed one not, and
      // the rim (4 edges, each between a lit and an unlit copy) is the silhouette.
      {"open quad", makePlane(1, 1), {0.2f, 5, 0.1f, 1}, 4, 2, 2},
  };
  for (const Case& c : cases) {
    const EdgeMesh m = buildEdgeMesh(c.mesh);
    const VolumeWork sides = volumeWork(m, VolumeGeometry::Silhouette, c.light, false, false);
    EXPECT_EQ(sides.silhouette_edges, c.silhouettes) << c.what;
    EXPECT_EQ(sides.triangles, 2 * c.silhouettes) << c.what;
    const VolumeWork capped = volumeWork(m, VolumeGeometry::Silhouette, c.light, true, true);
    EXPECT_EQ(capped.triangles, 2 * c.silhouettes + c.lit + c.unlit) << c.what;
    EXPECT_EQ(volumeWork(m, VolumeGeometry::Silhouette, c.light, true, false).triangles,
              2 * c.silhouettes + c.lit)
        << c.what;
    // One prism per lit triangle: 3 edges, 6 side triangles, and its own two caps.
    const VolumeWork prisms = volumeWork(m, VolumeGeometry::PerTriangle, c.light, true, true);
    EXPECT_EQ(prisms.silhouette_edges, 3 * c.lit) << c.what;
    EXPECT_EQ(prisms.triangles, 8 * c.lit) << c.what;
  }
}

TEST(Lesson09, TheReportsCountersAddUpAsTheClosedFormsSayOnTheCubesPreset) {
  // On `cubes` every caster is a box (12 triangles, none dropped by welding): z-pass draws 2
  // side triangles per silhouette edge; z-fail adds both caps, every triangle of every box.
  for (const std::string method : {"zpass", "zfail"}) {
    auto runner = startLesson(kLesson, {"scene=cubes", "volume.method=" + method}, 64, 48);
    runner->renderFrame();
    const long long volumes = counter(*runner, "volumes_drawn");
    const long long silhouettes = counter(*runner, "silhouette_edges");
    EXPECT_GE(volumes, 3) << method;
    EXPECT_GE(silhouettes, 4 * volumes) << method << ": a box's silhouette has 4 edges or more";
    EXPECT_EQ(counter(*runner, "volume_triangles"),
              2 * silhouettes + (method == "zfail" ? 12 * volumes : 0))
        << method;
  }
}

TEST(Lesson09, AutoAndZFailWithCapsMatchTheTruthOnEveryPreset) {
  // Exact up to rasterization at the shadow edges: bound 0.05 % of the counted pixels.
  auto probe = startLesson(kLesson, {}, 8, 8);
  const std::vector<std::string> scenes = probe->params().at("scene").choices;
  probe.reset();
  for (const std::string& scene : scenes) {
    for (const std::string method : {"auto", "zfail"}) {
      const std::vector<std::string> sets = {"scene=" + scene, "volume.method=" + method};
      EXPECT_LE(wrongPct(measured(sets)), 0.05) << label(sets);
    }
  }
}

TEST(Lesson09, ExactOnLightPositionsTheOtherTestsDoNotUse) {
  for (const std::string light :
       {"light.pos=-3,5,4", "light.pos=1,9,-2", "light.pos=6,2.5,1", "light.pos=0.3,4,0.2"}) {
    const std::vector<std::string> sets = {light};
    EXPECT_LE(wrongPct(measured(sets)), 0.05) << label(sets);
  }
  const std::vector<std::string> directional = {"light.type=directional"};
  EXPECT_LE(wrongPct(measured(directional)), 0.05);
}

TEST(Lesson09, EyeInsideAVolumeBreaksZPassNotZFail) {
  // Slide 38: the near plane clips the volume the eye sits in, so every z-pass count is one
  // short. Slide 45: auto sees the near plane in the pyramid's volume and takes z-fail there.
  const ErrorMetrics zpass = measured({"scene=eye_in_shadow", "volume.method=zpass"});
  EXPECT_GE(wrongPct(zpass), 10.0);
  EXPECT_LE(wrongPct(measured({"scene=eye_in_shadow", "volume.method=zfail"})), 0.05);
  auto runner = startLesson(kLesson, {"scene=eye_in_shadow"});
  runner->renderFrame();
  EXPECT_GE(counter(*runner, "volumes_zfail"), 1);
  EXPECT_LT(counter(*runner, "volumes_zfail"), counter(*runner, "volumes_drawn"));
  EXPECT_LE(wrongPct(runner->measureError().metrics), 0.05);
}

TEST(Lesson09, ARayCountsOneEnterAndOneLeaveThroughAVolumeAndStartsInsideOneItBegunIn) {
  // By hand: a unit cube centred at (0, 3, 0) under a light straight above it at (0, 10, 0);
  // its volume is the column |x|, |z| <= 1 (and wider below, from the point light) under it.
  std::vector<volumes::Triangle> triangles;
  const glm::vec3 c{0.0f, 3.0f, 0.0f};
  const MeshData box = makeBox(glm::vec3(1.0f));
  for (size_t i = 0; i + 2 < box.indices.size(); i += 3) {
    triangles.push_back({c + box.vertices[box.indices[i]].position,
                         c + box.vertices[box.indices[i + 1]].position,
                         c + box.vertices[box.indices[i + 2]].position});
  }
  const volumes::Caster cube(triangles);
  const glm::vec4 light{0.0f, 10.0f, 0.0f, 1.0f};
  EXPECT_TRUE(volumes::inVolume(cube, light, {0.0f, 0.5f, 0.0f}));   // under it
  EXPECT_FALSE(volumes::inVolume(cube, light, {3.0f, 0.5f, 0.0f}));  // beside it
  EXPECT_FALSE(volumes::inVolume(cube, light, {0.0f, 6.0f, 0.0f}));  // between it and the light
  // Slide 24: a ray at y = 0.5 from x = -5 to a wall at x = 5 crosses the column: +1, -1.
  const volumes::RayCount through =
      volumes::countAlongRay({cube}, light, {-5.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}, 10.0f);
  EXPECT_EQ(through.at_eye, 0);
  EXPECT_EQ(through.enters, 1);
  EXPECT_EQ(through.leaves, 1);
  EXPECT_EQ(through.zpassCount(), 0);
  EXPECT_EQ(through.at_surface, 0);
  ASSERT_EQ(through.crossings.size(), 2u);
  // The volume's walls run from the light at y = 10 through the cube's top edges at y = 4
  // (x = +-1), its silhouette: at y = 0.5, x = +-(10 - 0.5) / (10 - 4) = +-1.5833, that is
  // 3.4167 and 6.5833 along the ray (sampled every 0.005).
  EXPECT_NEAR(through.crossings[0].first, 3.4167f, 0.01f);
  EXPECT_NEAR(through.crossings[1].first, 6.5833f, 0.01f);
  // Slide 38: the eye inside the column looking out: it only leaves. z-pass, which starts at
  // 0, counts -1; the wall it sees is lit (0), and the eye was in 1.
  const volumes::RayCount out =
      volumes::countAlongRay({cube}, light, {0.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}, 5.0f);
  EXPECT_EQ(out.at_eye, 1);
  EXPECT_EQ(out.enters, 0);
  EXPECT_EQ(out.leaves, 1);
  EXPECT_EQ(out.zpassCount(), -1);
  EXPECT_EQ(out.at_surface, 0);
  EXPECT_EQ(out.at_surface, out.at_eye + out.zpassCount());
}

TEST(Lesson09, TheOverviewShowsTheEyeInTheTorussVolumeWhereZPassCountsOneShort) {
  // scene=eye_in_shadow's centre pixel: the eye sits in the torus's volume and its ray leaves
  // it on the way to a lit floor, so z-pass's count is one short (slide 38); from the default
  // eye nothing holds the eye and z-pass's count is the surface's.
  auto runner = startLesson(kLesson, {"scene=eye_in_shadow", "view=overview"}, 160, 120);
  runner->renderFrame();
  EXPECT_EQ(runner->glErrors(), 0);
  const auto ray = testing::reportValue(*runner, "center_ray");
  EXPECT_EQ(ray.at("at_eye"), 1);
  EXPECT_GE(ray.at("leaves").get<int>(), 1);
  EXPECT_EQ(ray.at("zpass_count").get<int>(), ray.at("at_surface").get<int>() - 1);
  runner.reset();
  auto outside = startLesson(kLesson, {"view=overview"}, 160, 120);
  outside->renderFrame();
  const auto plain = testing::reportValue(*outside, "center_ray");
  EXPECT_EQ(plain.at("at_eye"), 0);
  EXPECT_EQ(plain.at("zpass_count"), plain.at("at_surface"));
  outside.reset();
  // Any other view reports no ray.
  auto shaded = startLesson(kLesson, {"scene=eye_in_shadow"}, 160, 120);
  shaded->renderFrame();
  EXPECT_FALSE(testing::report(*shaded).contains("center_ray"));
}

TEST(Lesson09, DroppingACapBreaksZFail) {
  // Without the light cap every lit caster face counts one back face too many. Without the
  // dark cap a ray that leaves the volume at infinity, as the eye's rays do when it looks
  // along the light's, misses its exit: seen from behind the light.
  EXPECT_GE(wrongPct(measured({"volume.method=zfail", "volume.light_cap=false"})), 5.0);
  const std::vector<std::string> behind_light = {"volume.method=zfail", "camera.pos=4.5,7,5.5"};
  std::vector<std::string> no_dark_cap = behind_light;
  no_dark_cap.push_back("volume.dark_cap=false");
  EXPECT_GE(wrongPct(measured(no_dark_cap)), 5.0);
  EXPECT_LE(wrongPct(measured(behind_light)), 0.05);
}

TEST(Lesson09, AFiniteFarPlaneBreaksZFailInfinityOrDepthClampMendIt) {
  // Slide 44: "problem at far clip plane": the dark cap at infinity is clipped away.
  const std::vector<std::string> base = {"volume.method=zfail"};
  const auto with = [&](const std::string& far) {
    std::vector<std::string> s = base;
    s.push_back("volume.far=" + far);
    return wrongPct(measured(s));
  };
  EXPECT_GE(with("finite"), 5.0);
  EXPECT_LE(with("infinite"), 0.05);
  EXPECT_LE(with("depth_clamp"), 0.05);
}

TEST(Lesson09, SilhouettesRasterizeFiveTimesFewerStencilFragmentsForTheSameShadow) {
  const auto run = [](const std::string& geometry) {
    auto runner = startLesson(kLesson, {"scene=torus_pyramid", "volume.geometry=" + geometry});
    runner->renderFrame();
    // llvmpipe on desktop GL counts them (ES cannot: this test runs on gl45).
    const long long fragments =
        runner->measure().lastFrameWork().at("volumes").fragment_invocations.value_or(-1);
    const long long triangles = counter(*runner, "volume_triangles");
    return std::tuple{fragments, triangles, runner->renderVisibility()};
  };
  const auto [sil_fragments, sil_triangles, sil_vis] = run("silhouette");
  const auto [tri_fragments, tri_triangles, tri_vis] = run("per_triangle");
  EXPECT_GT(sil_fragments, 0);
  EXPECT_GE(tri_fragments, 5 * sil_fragments);
  EXPECT_GE(tri_triangles, 5 * sil_triangles);
  EXPECT_EQ(testing::valuesDiffering(sil_vis, tri_vis), 0u) << "a bit-identical shadow term";
}

TEST(Lesson09, MoreThan255VolumesBreakTheClampingOpsNotTheWrappingOnes) {
  const ErrorMetrics clamp = measured({"scene=fence", "stencil.op=clamp"});
  const ErrorMetrics wrap = measured({"scene=fence", "stencil.op=wrap"});
  EXPECT_GE(wrongPct(clamp), 1.0);
  EXPECT_LE(wrongPct(wrap), 0.05);
}

TEST(Lesson09, ClampingOpsCountWhatWrappingOnesCountBelow256Volumes) {
  // Slide 39's order (z-fail: back faces increment first) and slide 34's (z-pass: front faces
  // first): a clamped count never dips below 0, so below 255 overlapping volumes GL_INCR/DECR
  // give the wrapping ops' shadow exactly, for each method and in one two-sided pass too.
  for (const std::string scene : {"torus_pyramid", "cubes", "dueling", "grazing"}) {
    for (const std::string method : {"zpass", "zfail", "auto"}) {
      for (const std::string mode : {"two_pass", "two_sided"}) {
        const std::vector<std::string> sets = {"scene=" + scene, "volume.method=" + method,
                                               "stencil.mode=" + mode};
        std::vector<std::string> clamp = sets, wrap = sets;
        clamp.push_back("stencil.op=clamp");
        wrap.push_back("stencil.op=wrap");
        auto runner = startLesson(kLesson, clamp, 160, 120);
        const std::vector<float> clamped = runner->renderVisibility();
        EXPECT_EQ(reportNumber(*runner, "stencil_passes"), 2) << label(clamp);
        runner.reset();  // one GL context at a time
        runner = startLesson(kLesson, wrap, 160, 120);
        EXPECT_EQ(testing::valuesDiffering(clamped, runner->renderVisibility()), 0u)
            << label(clamp);
      }
    }
  }
  EXPECT_LE(wrongPct(measured({"volume.method=zfail", "stencil.op=clamp"})), 0.05);
}

TEST(Lesson09, TwoSidedStencilIsOnePassWithWrappingOps) {
  auto runner = startLesson(kLesson, {"stencil.mode=two_sided"}, 64, 48);
  runner->renderFrame();
  EXPECT_EQ(reportNumber(*runner, "stencil_passes"), 1);
  runner.reset();
  runner = startLesson(kLesson, {"stencil.mode=two_pass"}, 64, 48);
  runner->renderFrame();
  EXPECT_EQ(reportNumber(*runner, "stencil_passes"), 2);
}

// The picture and the shadow term of one setting (one GL context at a time).
std::pair<Image, std::vector<float>> pictureAndVisibility(const std::vector<std::string>& sets) {
  auto runner = startLesson(kLesson, sets);
  runner->renderFrame();
  Image image = runner->readImage();
  std::vector<float> visibility = runner->renderVisibility();
  EXPECT_EQ(runner->glErrors(), 0) << label(sets);
  return {std::move(image), std::move(visibility)};
}

TEST(Lesson09, TheVolumesViewShowsTheVolumesAlsoWithShadowOff) {
  // The volumes are never counted with shadow.off; the view builds them to show them anyway.
  const auto volumes_view = [](const std::string& off) {
    auto runner = startLesson(kLesson, {"view=volumes", "shadow.off=" + off}, 160, 120);
    runner->renderFrame();
    EXPECT_EQ(runner->glErrors(), 0) << off;
    return runner->readImage();
  };
  const Image off = volumes_view("true");
  const Image plain = pictureAndVisibility({"shadow.off=true"}).first;
  EXPECT_GT(testing::pixelsDiffering(off, plain, 8), 2000u) << "volumes drawn";
  EXPECT_GT(testing::pixelsDiffering(off, volumes_view("false"), 8), 0u) << "everything lit";
}

TEST(Lesson09, TwoSidedStencilCountsWhatTwoPassesCount) {
  const auto [a, two_pass] = pictureAndVisibility({"stencil.mode=two_pass"});
  const auto [b, two_sided] = pictureAndVisibility({"stencil.mode=two_sided"});
  EXPECT_EQ(testing::valuesDiffering(two_pass, two_sided), 0u);
  EXPECT_EQ(testing::pixelsDiffering(a, b, 0), 0u);
}

TEST(Lesson09, AnOpenCasterIsNamedAndStillShadowsCorrectly) {
  // The floor lit from below casts (castsFrom) over everything, the eye included: it is open,
  // closed as a two-sided shell, and auto takes z-fail for it.
  auto runner = startLesson(kLesson, {"light.pos=1,-4,1"});
  runner->renderFrame();
  EXPECT_EQ(reportNumber(*runner, "volume_open_edges"), 4);
  EXPECT_EQ(testing::reportString(*runner, "volume_open_casters"), "floor");
  EXPECT_LE(wrongPct(runner->measureError().metrics), 0.05);
}

TEST(Lesson09, VolumesOutsideTheViewAreCulledWithoutChangingTheShadow) {
  // Looking at the floor on the light's side: every volume runs away from the view.
  const std::vector<std::string> view = {"camera.pos=5,3,6", "camera.target=6,0,8"};
  auto culled = startLesson(kLesson, view);
  culled->renderFrame();
  EXPECT_EQ(counter(*culled, "culled_volumes"), 3);
  EXPECT_EQ(counter(*culled, "volumes_drawn"), 0);
  const Image kept = culled->readImage();
  culled.reset();
  std::vector<std::string> all = view;
  all.push_back("volume.cull=false");
  auto drawn = startLesson(kLesson, all);
  drawn->renderFrame();
  EXPECT_EQ(counter(*drawn, "culled_volumes"), 0);
  EXPECT_EQ(counter(*drawn, "volumes_drawn"), 3);
  EXPECT_EQ(testing::pixelsDiffering(kept, drawn->readImage(), 0), 0u);
}

TEST(Lesson09, ModulativeKeepsADimmedHighlightInShadowAdditiveDoesNot) {
  // Seed 002: "specular highlights in shadow will appear as darkened specular highlights".
  // The same shadow term; the pictures differ where shadowed, and only there (both read
  // bottom row first).
  const auto [additive, a] = pictureAndVisibility({"combine=additive"});
  const auto [modulative, m] = pictureAndVisibility({"combine=modulative"});
  EXPECT_EQ(testing::valuesDiffering(a, m), 0u);
  size_t lit_differing = 0, shadow_differing = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(additive.rgba[4 * i + c] - modulative.rgba[4 * i + c]));
    }
    (a[i] >= 0.5f ? lit_differing : shadow_differing) += worst > 2;
  }
  EXPECT_GT(shadow_differing, 1000u);
  EXPECT_LT(lit_differing, 50u) << "where lit both show the full light";
  // Where the floor mirrors the light into the torus's shadow, modulative keeps a highlight:
  // somewhere in the shadow it is brighter than additive, which it never is from the default
  // eye (its ambient is dimmed too, so elsewhere it is darker).
  const auto most_brighter_in_shadow = [](const std::vector<std::string>& view) {
    std::vector<std::string> modulative_view = view;
    modulative_view.push_back("combine=modulative");
    const auto [add_image, visibility] = pictureAndVisibility(view);
    const auto [mod_image, unused] = pictureAndVisibility(modulative_view);
    int most = -255;
    for (size_t i = 0; i < visibility.size(); ++i) {
      if (visibility[i] >= 0.5f || add_image.rgba[4 * i + 3] == 0) continue;
      most = std::max(most, mod_image.rgba[4 * i + 1] - add_image.rgba[4 * i + 1]);
    }
    return most;
  };
  const int mirror =
      most_brighter_in_shadow({"camera.pos=-5.05,3,-4.7", "camera.target=-2.2,0,-1.8"});
  EXPECT_GT(mirror, 12);
  EXPECT_LT(most_brighter_in_shadow({}), 3);
}

TEST(Lesson09, EveryViewRendersCleanAndDistinct) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
  auto fence = startLesson(kLesson, {"scene=fence", "stencil.op=clamp"});
  testing::expectEveryViewCleanAndDistinct(*fence, "fence");
}

TEST(Lesson09, SliderExtremesStayFiniteAndErrorFree) {
  testing::expectFiniteAndErrorFree(
      kLesson, {{"volume.method=zpass", "volume.geometry=per_triangle", "stencil.mode=two_sided"},
                {"volume.method=zfail", "volume.far=finite", "volume.far_distance=2"},
                {"volume.far=depth_clamp", "volume.far_distance=1000"},
                {"light.pos=0,0.5,0", "light.target=0,0.5,0"},
                {"light.pos=-50,0.01,0"},
                {"light.type=directional", "light.pos=0,5,0"},
                {"camera.pos=0.6,0.45,1.6", "light.pos=-3,7,2"},  // the eye inside the sphere
                {"shadow.off=true", "combine=modulative"},
                {"dimming=0"},
                {"dimming=1"}});
}

}  // namespace
}  // namespace shadows
