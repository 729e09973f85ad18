// Lesson 16 end to end, headless: every technique is its own lesson's code run inside this one
// (common/lesson/hosted_lesson.hpp), so each draws exactly the picture its lesson draws with the
// same settings; the knobs reach it; what it holds on the GPU is counted; a technique that
// cannot serve the light says so and draws no shadow; a change made while another technique
// was drawn is seen when it comes back; and every technique is scored on the same pixels
// against the same light.
#include <glm/gtc/matrix_transform.hpp>

#include "../16_choose_your_shadow/bench_front.hpp"
#include "harness.hpp"

namespace shadows {
namespace {

using testing::startLesson;

const std::string kLesson = "16_choose_your_shadow";

TEST(Lesson16, SnapshotMatchesTheGolden) {
  auto runner = startLesson(kLesson, {});
  runner->renderFrame();
  testing::expectMatchesGolden(runner->readImage(), kLesson);
  EXPECT_EQ(runner->glErrors(), 0);
}

TEST(Lesson16, EveryViewIsCleanAndDistinct) {
  auto runner = startLesson(kLesson, {});
  testing::expectEveryViewCleanAndDistinct(*runner);
}

// One runner (one GL context) at a time: its picture, and no GL error on the way.
Image picture(const std::string& lesson, const std::vector<std::string>& sets) {
  auto runner = startLesson(lesson, sets);
  runner->renderFrame();
  EXPECT_EQ(runner->glErrors(), 0) << lesson << " " << testing::label(sets);
  return runner->readImage();
}

struct Hosted {
  std::string key, lesson;
  std::vector<std::string> host_sets;    // lesson 16's
  std::vector<std::string> lesson_sets;  // the same frame, asked of the lesson itself
};

// Each technique's picture is its lesson's: the settings lesson 16 gives it (no inset, no
// counting atomics), its knobs as the lesson's own parameters.
TEST(Lesson16, EachTechniqueDrawsItsLessonsPictureByteForByte) {
  const std::vector<Hosted> cases = {
      {"hard", "04_bias_offset", {"hard/shadow.size=512"}, {"inset=false", "shadow.size=512"}},
      {"pcf",
       "05_pcf_dithered",
       {"pcf/pcf.mode=poisson", "pcf/pcf.taps=12"},
       {"inset=false", "pcf.count=false", "pcf.mode=poisson", "pcf.taps=12"}},
      {"filtered",
       "13_filterable_maps",
       {"filtered/filter.method=esm"},
       {"inset=false", "filter.method=esm"}},
      {"pcss",
       "14_soft_shadows",
       {"light.radius=0.2"},
       {"inset=false", "pcss.count=false", "pcss.light_radius=0.2"}},
      {"cube", "11_omni_cube", {"cube/omni.method=tetrahedron"}, {"omni.method=tetrahedron"}},
      {"volumes", "09_shadow_volumes", {}, {}},
      {"warped",
       "10_plane_optimal",
       {"warped/light.projection=lispsm", "warped/shadow.size=512"},
       {"inset=false", "light.projection=lispsm", "shadow.size=512"}},
      {"lightmap",
       "15_light_maps",
       {"lightmap/lightmap.mode=hybrid", "light.radius=0.2", "move.x=0.8"},
       {"inset=false", "lightmap.mode=hybrid", "lightmap.light_radius=0.2", "move.x=0.8"}},
  };
  for (const Hosted& c : cases) {
    std::vector<std::string> host = {"scene=torus_pyramid", "technique=" + c.key};
    host.insert(host.end(), c.host_sets.begin(), c.host_sets.end());
    std::vector<std::string> own = {"scene=torus_pyramid"};
    own.insert(own.end(), c.lesson_sets.begin(), c.lesson_sets.end());
    EXPECT_EQ(testing::pixelsDiffering(picture(kLesson, host), picture(c.lesson, own), 0), 0u)
        << c.key;
  }
  // Cascades take a sun: the street's.
  EXPECT_EQ(
      testing::pixelsDiffering(
          picture(kLesson, {"scene=street", "technique=cascades", "cascades/cascades.count=3"}),
          picture("12_cascades", {"scene=street", "cascades.count=3"}), 0),
      0u);
  auto runner = startLesson(kLesson, {"technique=filtered"});
  runner->renderFrame();
  EXPECT_EQ(testing::reportString(*runner, "technique_lesson"), "13_filterable_maps");
}

// One caster moved for every technique (move.x): each dynamic technique draws its shadow where
// it is now, and lesson 15's light map, baked where the preset put it, does not follow.
TEST(Lesson16, AMovedCasterIsFollowedByEveryTechniqueButTheBake) {
  const auto vis = [](const std::string& key, const std::string& x) {
    return testing::measuredReport(kLesson, {"scene=yard", "technique=" + key, "move.x=" + x}, 160,
                                   120)["error"]["vis_mae"]
        .get<double>();
  };
  for (const char* key : {"hard", "volumes"}) {
    EXPECT_LT(vis(key, "1.2"), 1.5 * vis(key, "0")) << key << " follows the ball";
  }
  const double baked = vis("lightmap", "0"), moved = vis("lightmap", "1.2");
  EXPECT_GT(moved, 2.0 * baked) << "the bake keeps the ball's shadow where it was";
  // The picture differs where the ball was: a map technique's frame changes with the move.
  EXPECT_GT(
      testing::pixelsDiffering(picture(kLesson, {"scene=yard", "technique=hard"}),
                               picture(kLesson, {"scene=yard", "technique=hard", "move.x=1.2"}), 8),
      100u);
}

// A technique's texture storage, as the GL holds it: its map, or its atlas, or nothing.
TEST(Lesson16, TextureBytesAreTheTechniquesMaps) {
  auto runner = startLesson(kLesson, {"technique=hard", "hard/shadow.size=512"});
  runner->renderFrame();
  EXPECT_EQ(testing::reportNumber(*runner, "technique_texture_bytes"), 512.0 * 512.0 * 4.0);
  ASSERT_EQ(runner->params().assign("technique=volumes"), "");
  runner->renderFrame();
  EXPECT_EQ(testing::reportNumber(*runner, "technique_texture_bytes"), 0.0) << "the stencil's";
  ASSERT_EQ(runner->params().assign("technique=cube"), "");
  ASSERT_EQ(runner->params().assign("cube/cube.size=256"), "");
  runner->renderFrame();
  EXPECT_EQ(testing::reportNumber(*runner, "technique_texture_bytes"), 6.0 * 256 * 256 * 4);

  runner.reset();
  auto street = startLesson(kLesson, {"scene=street", "technique=cascades"});
  street->renderFrame();
  const auto json = testing::report(*street);
  EXPECT_EQ(json["technique_texture_bytes"], json["technique_report"]["atlas_bytes"]);
  // Lesson 12's shimmer measurement (run for the report) keeps an atlas and a frame of its own:
  // not the sun's, on the next frame either.
  street->renderFrame();
  const auto again = testing::report(*street);
  EXPECT_EQ(again["technique_texture_bytes"], again["technique_report"]["atlas_bytes"]);
  EXPECT_GT(again["technique_texture_bytes"].get<double>(), 0.0);
}

// Cascades split a sun's view; a cube surrounds a lamp. Asked of the other light, each says
// why, and the frame is the one without a shadow.
TEST(Lesson16, ATechniqueThatCannotServeTheLightSaysSoAndDrawsNoShadow) {
  for (const auto& [scene, key] : std::vector<std::pair<std::string, std::string>>{
           {"contact", "cascades"}, {"street", "cube"}, {"street", "warped"}}) {
    auto runner = startLesson(kLesson, {"scene=" + scene, "technique=" + key});
    runner->renderFrame();
    EXPECT_NE(testing::reportString(*runner, "technique_cannot"), "") << key;
    EXPECT_NE(runner->checkConsistency(), "") << key << ": the command line refuses it";
    EXPECT_EQ(runner->glErrors(), 0) << key;
    const Image drawn = runner->readImage();
    runner.reset();
    EXPECT_EQ(
        testing::pixelsDiffering(
            drawn, picture(kLesson, {"scene=" + scene, "technique=" + key, "shadow.off=true"}), 0),
        0u)
        << key;
  }
  // The street has no floor for plane-optimal; LiSPSM, the same lesson's warp, needs none.
  for (const char* fine_sets : {"technique=cascades", "warped/light.projection=lispsm"}) {
    auto fine = startLesson(kLesson, {"scene=street", "technique=warped", fine_sets});
    fine->renderFrame();
    EXPECT_EQ(testing::reportString(*fine, "technique_cannot"), "") << fine_sets;
    EXPECT_EQ(fine->checkConsistency(), "") << fine_sets;
  }
}

// A caster moves while the hard map is drawn (no parameter changes: the runner tells the host
// its map is dirty); PCF's map, kept from before, must be drawn again when PCF comes back: the
// host's dirty bits are every technique's. A moved light reaches it as a parameter.
TEST(Lesson16, AChangeMadeWhileAnotherTechniqueDrewIsSeenWhenItComesBack) {
  const glm::mat4 moved = glm::translate(glm::mat4(1.0f), glm::vec3(0.7f, 0.0f, -0.4f));
  const auto seen = [&](bool light) {
    auto runner = startLesson(kLesson, {"technique=pcf"});
    runner->renderFrame();
    ASSERT_EQ(runner->params().assign("technique=hard"), "");
    runner->renderFrame();
    if (light) {
      ASSERT_EQ(runner->params().assign("light.pos=-2,5,3"), "");
    } else {
      runner->host().setObjectModel(1, moved * runner->host().presetModel(1));
    }
    runner->renderFrame();
    ASSERT_EQ(runner->params().assign("technique=pcf"), "");
    runner->renderFrame();
    const Image back = runner->readImage();
    // The same frame drawn afresh (one runner, one GL context, at a time).
    runner.reset();
    runner = startLesson(kLesson, {"technique=pcf"});
    if (light) {
      ASSERT_EQ(runner->params().assign("light.pos=-2,5,3"), "");
    } else {
      runner->host().setObjectModel(1, moved * runner->host().presetModel(1));
    }
    runner->renderFrame();
    EXPECT_EQ(testing::pixelsDiffering(back, runner->readImage(), 0), 0u)
        << (light ? "the light moved: " : "a caster moved: ") << "a stale map";
  };
  seen(false);
  seen(true);
}

// A kept map stays kept: a switch to another technique and back, and the runner's frames
// without shadow (which turn shadow.off on and off), redraw no map while nothing moved; a moved
// caster redraws the returning technique's map once.
TEST(Lesson16, AKeptMapIsDrawnAgainOnlyWhenSomethingMoved) {
  auto runner = startLesson(kLesson, {"technique=pcf"});
  runner->renderFrame();
  runner->renderFrame();
  EXPECT_EQ(testing::counter(*runner, "shadow_map_renders"), 0);
  runner->baseline().render();
  runner->renderFrame();
  EXPECT_EQ(testing::counter(*runner, "shadow_map_renders"), 0) << "after a frame without shadow";
  ASSERT_EQ(runner->params().assign("technique=hard"), "");
  runner->renderFrame();
  ASSERT_EQ(runner->params().assign("technique=pcf"), "");
  runner->renderFrame();
  EXPECT_EQ(testing::counter(*runner, "shadow_map_renders"), 0) << "back from another technique";
  ASSERT_EQ(runner->params().assign("technique=hard"), "");
  runner->renderFrame();
  ASSERT_EQ(runner->params().assign("move.x=0.5"), "");
  runner->renderFrame();
  ASSERT_EQ(runner->params().assign("technique=pcf"), "");
  runner->renderFrame();
  EXPECT_EQ(testing::counter(*runner, "shadow_map_renders"), 1) << "a caster moved meanwhile";
}

// One light and one set of pixels for all: a spot map's frustum does not shrink what is
// counted (the bulb's 90° spot leaves the walls beside it out of its map), and PCF is scored
// against the scene's light, not the area light lesson 05 matches to its kernel.
TEST(Lesson16, EveryTechniqueIsScoredOnTheSamePixelsAgainstTheSameLight) {
  const auto measured = [](const std::string& key) {
    return testing::measuredReport(kLesson, {"scene=bulb", "technique=" + key}, 160, 120);
  };
  const auto hard = measured("hard"), cube = measured("cube"), pcf = measured("pcf");
  EXPECT_EQ(hard["error"]["counted_pixels"], cube["error"]["counted_pixels"]);
  EXPECT_EQ(pcf["error"]["counted_pixels"], cube["error"]["counted_pixels"]);
  EXPECT_EQ(pcf["truth_area_radius"], 0.0);
  EXPECT_GT(pcf["technique_report"]["truth_area_radius"].get<double>(), 0.0)
      << "lesson 05's own match, reported, not used";
  // The map covers a cone of the bulb's light: outside it, a map says lit where the truth has
  // shadow. The cube sees every direction.
  EXPECT_GT(hard["error"]["vis_mae"].get<double>(), 2.0 * cube["error"]["vis_mae"].get<double>());
}

}  // namespace
}  // namespace shadows

namespace shadows {
namespace {

// The panel's bench front: the sweep's points of the current preset and light, the current
// settings' point among them where the sweep measured them, a knob it did not set at its
// default, and none under a light it did not measure.
TEST(Lesson16, TheBenchsFrontIsThisPresetAndLightsWithTheseSettingsRinged) {
  auto runner = startLesson(kLesson, {"scene=street", "technique=hard", "hard/shadow.size=2048"});
  Params& p = runner->params();
  const BenchFront bench(p);
  const auto ringed = [&] {
    const BenchFront::Here here = bench.at(p);
    return here.current < 0 ? std::string() : here.points[static_cast<size_t>(here.current)].label;
  };
  BenchFront::Here here = bench.at(p);
  EXPECT_EQ(here.light, "point");
  ASSERT_FALSE(here.points.empty());
  for (const Tried::Point& q : here.points) EXPECT_EQ(q.where, "point");
  EXPECT_EQ(ringed(), "hard_2048");
  ASSERT_EQ(p.assign("hard/bias.mode=none"), "");  // a knob the sweep left: not its point
  EXPECT_EQ(ringed(), "");
  ASSERT_EQ(p.assign("hard/bias.mode=back_faces"), "");
  EXPECT_EQ(ringed(), "hard_2048") << "bias.mode's default";
  ASSERT_EQ(p.assign("technique=cascades"), "");
  ASSERT_EQ(p.assign("cascades/cascades.count=2"), "");
  EXPECT_EQ(ringed(), "cascades_2");
  ASSERT_EQ(p.assign("light.radius=0.1"), "");
  EXPECT_EQ(bench.at(p).light, "disk");
  EXPECT_EQ(ringed(), "cascades_2");
  ASSERT_EQ(p.assign("move.x=1.2"), "");
  EXPECT_EQ(bench.at(p).light, "disk_moved");
  ASSERT_EQ(p.assign("light.radius=0.3"), "");
  EXPECT_TRUE(bench.at(p).points.empty()) << "the sweep measured no disk of 0.3";
  ASSERT_EQ(p.assign("light.radius=0"), "");
  ASSERT_EQ(p.assign("move.x=0"), "");
  EXPECT_EQ(bench.at(p).light, "point");
  const std::string sun = p.at("light.pos").text();
  ASSERT_EQ(p.assign("light.pos=30,40,-16"), "");  // the sweep kept the preset's sun
  EXPECT_TRUE(bench.at(p).points.empty()) << "a moved light is another frame";
  ASSERT_EQ(p.assign("light.pos=" + sun), "");
  ASSERT_EQ(p.assign("scene=bulb"), "");
  const BenchFront::Here bulb = bench.at(p);
  ASSERT_FALSE(bulb.points.empty());
  EXPECT_EQ(ringed(), "") << "cascades under the bulb were refused, never measured";
  EXPECT_TRUE(std::none_of(bulb.points.begin(), bulb.points.end(),
                           [](const Tried::Point& q) { return q.label == "cascades_2"; }));
  // A point whose settings no longer read (a knob renamed since the sweep) is refused, not
  // taken to match whatever the knob is now.
  const BenchPoint renamed[] = {
      {"street", "point", "hard_2048", "technique=hard hard/map.size=2048 light.radius=0", 1, 1}};
  EXPECT_THROW(BenchFront(p, renamed), std::logic_error);
}

}  // namespace
}  // namespace shadows
