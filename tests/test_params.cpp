// Parameters: declared once, set from text with one-line errors that say what is allowed.
#include "core/params.hpp"

#include "core/json.hpp"

#include <gtest/gtest.h>

namespace shadows {
namespace {

class ParamsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    params.addInt("shadow.size", 1024, 64, 4096, "map size", kDirtyShadowMap);
    params.addFloat("dimming", 0.4f, 0, 1, "dimming");
    params.addBool("inset", true, "inset");
    params.addVec3("light.pos", {1, 2, 3}, -50, 50, "light", kDirtyShadowMap);
    params.addChoice("shadow.format", {"16", "24", "32f"}, "24", "bits", kDirtyResources);
    params.consume(kDirtyAll);
  }
  Params params;
};

TEST_F(ParamsTest, GoodValuesAreApplied) {
  EXPECT_EQ(params.set("shadow.size", "2048"), "");
  EXPECT_EQ(params.at("shadow.size").i(), 2048);
  EXPECT_EQ(params.set("dimming", "0.25"), "");
  EXPECT_FLOAT_EQ(params.at("dimming").f(), 0.25f);
  EXPECT_EQ(params.set("inset", "false"), "");
  EXPECT_FALSE(params.at("inset").b());
  EXPECT_EQ(params.assign("light.pos=-1.5,0,2e1"), "");
  EXPECT_EQ(params.at("light.pos").v(), glm::vec3(-1.5f, 0, 20));
  EXPECT_EQ(params.set("shadow.format", "32f"), "");
  EXPECT_TRUE(params.at("shadow.format").is("32f"));
}

TEST_F(ParamsTest, BadValuesNameTheParameterAndWhatIsAllowedAndChangeNothing) {
  struct Case {
    const char* name;
    const char* value;
    const char* must_mention;
  };
  const Case cases[] = {
      {"shadow.size", "99999", "[64, 4096]"}, {"shadow.size", "63", "[64, 4096]"},
      {"shadow.size", "1024.5", "integer"},   {"shadow.size", "abc", "integer"},
      {"shadow.size", "", "integer"},         {"dimming", "nan", "[0, 1]"},
      {"dimming", "inf", "[0, 1]"},           {"dimming", "1.5", "[0, 1]"},
      {"dimming", "0.5x", "[0, 1]"},          {"dimming", "0x1", "[0, 1]"},
      {"dimming", " 0.5", "[0, 1]"},          {"inset", "maybe", "true or false"},
      {"light.pos", "1,2", "x,y,z"},          {"light.pos", "1,2,3,4", "x,y,z"},
      {"light.pos", "1,2,", "x,y,z"},         {"light.pos", "1,,3", "x,y,z"},
      {"light.pos", "1,2,99", "[-50, 50]"},   {"shadow.format", "8", "16, 24, 32f"},
      {"shadow.format", "24 ", "16, 24, 32f"}};
  for (const Case& c : cases) {
    const std::string error = params.set(c.name, c.value);
    EXPECT_NE(error.find(c.name), std::string::npos) << c.name << "=" << c.value;
    EXPECT_NE(error.find(c.must_mention), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  }
  EXPECT_EQ(params.at("shadow.size").i(), 1024);
  EXPECT_FLOAT_EQ(params.at("dimming").f(), 0.4f);
  EXPECT_EQ(params.at("light.pos").v(), glm::vec3(1, 2, 3));
  EXPECT_EQ(params.dirty(), 0u) << "a failed set must not mark anything dirty";
}

TEST_F(ParamsTest, UnknownNamesAndMalformedAssignmentsAreRejected) {
  const std::string error = params.set("shadow.sise", "1");
  EXPECT_NE(error.find("unknown parameter 'shadow.sise'"), std::string::npos);
  EXPECT_NE(error.find("did you mean 'shadow.size'?"), std::string::npos) << error;
  EXPECT_EQ(params.set("zzzzzzzzzz", "1").find("did you mean"), std::string::npos)
      << "no guess when nothing is close";
  EXPECT_NE(error.find("inset"), std::string::npos) << "lists what exists";
  EXPECT_NE(params.assign("novalue"), "");
  EXPECT_NE(params.assign("=3"), "");
}

TEST_F(ParamsTest, TheGuessIsTheNearestNameWithinThreeEditsAndNamesItExactly) {
  // CONTRACTS.md: "did you mean" names the nearest parameter (Levenshtein distance, the
  // first declared on a tie) when it is at most 3 edits away, and nothing beyond.
  const auto guess = [&](const std::string& name) {
    const std::string error = params.set(name, "1");
    const auto at = error.find("did you mean '");
    if (at == std::string::npos) return std::string("-");
    const auto from = at + std::string("did you mean '").size();
    return error.substr(from, error.find('\'', from) - from);
  };
  EXPECT_EQ(guess("dimmimg"), "dimming");        // 1 edit
  EXPECT_EQ(guess("dimxing"), "dimming");        // 1
  EXPECT_EQ(guess("dimmxxx"), "dimming");        // 3: still a typo
  EXPECT_EQ(guess("dimxxxx"), "-");              // 4: not a typo
  EXPECT_EQ(guess("inse"), "inset");             // a letter short
  EXPECT_EQ(guess("light.pos.x"), "light.pos");  // 2 more
  EXPECT_EQ(guess("shadow.sizes"), "shadow.size");
  EXPECT_EQ(guess("shadow.formt"), "shadow.format");
  // Nearest, not first: 'shadow.form' is 2 from shadow.format, 4 from shadow.size.
  EXPECT_EQ(guess("shadow.form"), "shadow.format");
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("flaw", "lawn"), 2u);
}

TEST_F(ParamsTest, ChangesMarkOnlyWhatDependsOnThem) {
  EXPECT_EQ(params.set("dimming", "0.1"), "");
  EXPECT_FALSE(params.consume(kDirtyShadowMap)) << "dimming does not touch the shadow map";
  EXPECT_EQ(params.set("light.pos", "0,5,0"), "");
  EXPECT_TRUE(params.consume(kDirtyShadowMap));
  EXPECT_FALSE(params.consume(kDirtyShadowMap)) << "consumed once";
  EXPECT_EQ(params.set("light.pos", "0,5,0"), "");
  EXPECT_FALSE(params.consume(kDirtyShadowMap)) << "setting the same value is not a change";
  EXPECT_EQ(params.set("shadow.format", "16"), "");
  EXPECT_TRUE(params.consume(kDirtyResources));
}

TEST_F(ParamsTest, ProgrammaticSetsClampToTheRange) {
  params.setFloat(params.at("shadow.size"), 1e9);
  EXPECT_EQ(params.at("shadow.size").i(), 4096);
  params.setVec3(params.at("light.pos"), {-100, 0, 100});
  EXPECT_EQ(params.at("light.pos").v(), glm::vec3(-50, 0, 50));
}

TEST_F(ParamsTest, ListAndReportCarryEveryParameter) {
  const std::string list = params.listText();
  JsonWriter json;
  json.beginObject();
  params.writeJson(json);
  json.endObject();
  for (const auto& p : params.all()) {
    EXPECT_NE(list.find(p.name), std::string::npos) << p.name;
    EXPECT_NE(json.str().find("\"" + p.name + "\""), std::string::npos) << p.name;
  }
  EXPECT_NE(list.find("[64, 4096]"), std::string::npos);
  EXPECT_NE(list.find("16, 24, 32f"), std::string::npos);
  EXPECT_NE(list.find("map size"), std::string::npos) << "help text is listed";
}

TEST_F(ParamsTest, ResetToDefaultsRestoresEveryValueAndMarksOnlyWhatChanged) {
  ASSERT_EQ(params.set("dimming", "0.9"), "");
  ASSERT_EQ(params.set("shadow.format", "16"), "");
  params.consume(kDirtyAll);
  params.resetToDefaults();
  EXPECT_FLOAT_EQ(params.at("dimming").f(), 0.4f);
  EXPECT_TRUE(params.at("shadow.format").is("24"));
  EXPECT_TRUE(params.consume(kDirtyResources)) << "the format changed back";
  EXPECT_FALSE(params.consume(kDirtyShadowMap)) << "nothing that affects the map moved";
  params.setDefaultFloat(params.at("dimming"), 0.7);  // a preset's default
  params.setFloat(params.at("dimming"), 0.1);
  params.resetToDefaults();
  EXPECT_FLOAT_EQ(params.at("dimming").f(), 0.7f);
}

TEST_F(ParamsTest, DeclaringTwiceIsAProgrammingError) {
  EXPECT_THROW(params.addBool("inset", false, "again"), std::logic_error);
}

// ---------------------------------------------------------------- free text (file paths)

TEST(StringParam, TakesAnyTextListsReportsAndMarksDirtyOnlyOnAChange) {
  Params params;
  Param& image = params.addString("projector.image", "builtin", "slide", kDirtyResources);
  params.consume(kDirtyAll);
  EXPECT_EQ(image.kind, ParamKind::String);
  EXPECT_EQ(image.s(), "builtin");
  EXPECT_EQ(params.assign("projector.image=/tmp/a b,c=d.png"), "") << "spaces, commas, '='";
  EXPECT_EQ(image.s(), "/tmp/a b,c=d.png");
  EXPECT_EQ(image.text(), "/tmp/a b,c=d.png") << "text() is what --set takes back";
  EXPECT_TRUE(params.consume(kDirtyResources));
  EXPECT_EQ(params.set("projector.image", "/tmp/a b,c=d.png"), "");
  EXPECT_FALSE(params.consume(kDirtyResources)) << "the same text is not a change";
  EXPECT_EQ(params.set("projector.image", ""), "") << "empty is text too";
  EXPECT_NE(params.set("projector.image", "two\nlines"), "") << "a report line stays one line";
  EXPECT_EQ(image.s(), "");

  const std::string list = params.listText();
  EXPECT_NE(list.find("projector.image"), std::string::npos);
  EXPECT_NE(list.find("string"), std::string::npos);
  EXPECT_NE(list.find("default builtin"), std::string::npos) << list;
  JsonWriter json;
  json.beginObject();
  ASSERT_EQ(params.set("projector.image", "say \"hi\".png"), "");
  params.writeJson(json);
  json.endObject();
  EXPECT_NE(json.str().find(R"("projector.image": "say \"hi\".png")"), std::string::npos)
      << json.str();
}

TEST(StringParam, ACheckRefusesWithOneLineAndChangesNothing) {
  Params params;
  Param& image = params.addString("projector.image", "builtin", "slide", kDirtyResources);
  image.check = [](const std::string& text) -> std::string {
    return text == "builtin" || text.ends_with(".png") ? "" : "cannot read '" + text + "'";
  };
  params.consume(kDirtyAll);
  const std::string error = params.set("projector.image", "missing.jpg");
  EXPECT_EQ(error, "projector.image: cannot read 'missing.jpg'");
  EXPECT_EQ(image.s(), "builtin");
  EXPECT_EQ(params.dirty(), 0u);
  EXPECT_EQ(params.set("projector.image", "slide.png"), "");
  EXPECT_EQ(image.s(), "slide.png");
  // A check works on the other kinds too, after their own parsing.
  Param& size = params.addInt("shadow.size", 1024, 64, 4096, "size");
  size.check = [](const std::string& text) -> std::string {
    return std::stoi(text) % 2 == 0 ? "" : "must be even";
  };
  EXPECT_EQ(params.set("shadow.size", "513"), "shadow.size: must be even");
  EXPECT_EQ(size.i(), 1024);
  EXPECT_NE(params.set("shadow.size", "abc").find("integer"), std::string::npos)
      << "the kind's own parsing comes first";
}

// Handles: what a lesson keeps from declare() reads the value in force, with its type.
TEST_F(ParamsTest, HandlesReadTheValueInForceAndRefuseTheWrongKind) {
  const IntParam size = params.at("shadow.size");
  const FloatParam dimming = params.at("dimming");
  const BoolParam inset = params.at("inset");
  const Vec3Param light = params.at("light.pos");
  enum class Format { D16, D24, D32F };
  const ChoiceParam<Format> format = params.at("shadow.format");
  ASSERT_EQ(params.set("shadow.size", "512"), "");
  ASSERT_EQ(params.set("dimming", "0.25"), "");
  ASSERT_EQ(params.set("inset", "false"), "");
  ASSERT_EQ(params.set("light.pos", "4,5,6"), "");
  ASSERT_EQ(params.set("shadow.format", "32f"), "");
  EXPECT_EQ(size(), 512);
  EXPECT_FLOAT_EQ(dimming(), 0.25f);
  EXPECT_FALSE(inset());
  EXPECT_EQ(light(), glm::vec3(4, 5, 6));
  EXPECT_EQ(format(), Format::D32F);
  EXPECT_EQ(format.name(), "32f");
  EXPECT_THROW(FloatParam{params.at("shadow.size")}, std::logic_error);
  EXPECT_THROW(ChoiceParam<>{params.at("inset")}, std::logic_error);
  EXPECT_THROW(BoolParam{params.at("dimming")}, std::logic_error);
}

// A choice reaches a shader as named #defines from its one declaration.
TEST_F(ParamsTest, ChoicesAndBoolsBecomeNamedDefines) {
  ASSERT_EQ(params.set("shadow.format", "32f"), "");
  EXPECT_EQ(params.at("shadow.format").defines(),
            (std::vector<std::string>{"SHADOW_FORMAT_16 0", "SHADOW_FORMAT_24 1",
                                      "SHADOW_FORMAT_32F 2", "SHADOW_FORMAT SHADOW_FORMAT_32F"}));
  EXPECT_EQ(params.at("inset").defines(), std::vector<std::string>{"INSET 1"});
  ASSERT_EQ(params.set("inset", "false"), "");
  EXPECT_EQ(params.at("inset").defines(), std::vector<std::string>{"INSET 0"});
  EXPECT_EQ(params.at("shadow.size").defines(), std::vector<std::string>{"SHADOW_SIZE 1024"});
  EXPECT_THROW(params.at("dimming").defines(), std::logic_error) << "a float is no variant";
  EXPECT_EQ(
      choiceDefines("view", {"shaded", "light_depth"}, "light_depth"),
      (std::vector<std::string>{"VIEW_SHADED 0", "VIEW_LIGHT_DEPTH 1", "VIEW VIEW_LIGHT_DEPTH"}));
}

}  // namespace
}  // namespace shadows
