// The settings table: one name per setting, checked values, messages that say what is expected.
#include <gtest/gtest.h>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/settings_schema.h"

namespace reflect {
namespace {

using nlohmann::json;

TEST(SettingsSchema, PlannerSettingsRoundTripThroughJson) {
  PlannerSettings s;
  s.policy = UpdatePolicy::TimeSliced;
  s.facesPerFrame = 3;
  s.everyN = 7;
  s.captureLod = 0.5f;
  s.viewLod = 0.25f;
  const json j = settingsJson(s, plannerFields());
  EXPECT_EQ(j, json::parse(R"({"policy": "time-sliced", "facesPerFrame": 3, "everyN": 7,
                               "captureLod": 0.5, "viewLod": 0.25})"));
  PlannerSettings back;
  EXPECT_EQ(applySettingsJson(j, plannerFields(), back), "");
  EXPECT_EQ(settingsJson(back, plannerFields()), j);
}

TEST(SettingsSchema, AccuracySettingsRoundTripThroughJson) {
  AccuracySettings a;
  a.captureAtOrigin = true;
  a.search = Search::Linear;
  a.layers = 1;
  a.depthBits = 16;
  a.halfFloat = true;
  AccuracySettings back;
  EXPECT_EQ(applySettingsJson(settingsJson(a, accuracyFields()), accuracyFields(), back), "");
  EXPECT_TRUE(back == a);
}

TEST(SettingsSchema, BadValuesSayWhatIsExpectedAndChangeNothing) {
  PlannerSettings s;
  const PlannerSettings before = s;
  const auto apply = [&](const char* text) {
    return applySettingsJson(json::parse(text), plannerFields(), s);
  };
  EXPECT_EQ(apply(R"({"facesPerFrame": 7})"), "facesPerFrame: 7 is not in 1..6");
  EXPECT_EQ(apply(R"({"facesPerFrame": 2.5})"), "facesPerFrame: 2.5 is not a whole number");
  EXPECT_EQ(apply(R"({"policy": "sometimes"})"),
            "policy: \"sometimes\" is not one of every-frame, when-changed, time-sliced, every-n");
  EXPECT_EQ(apply(R"({"captureLod": "high"})"),
            "captureLod: \"high\" is not a number from 0 to 1000");
  EXPECT_EQ(apply(R"({"slice": 2})"),
            "unknown setting 'slice' (known: policy, facesPerFrame, everyN, captureLod, viewLod)");
  // One bad key among good ones: nothing is applied.
  EXPECT_NE(apply(R"({"policy": "every-n", "everyN": 0})"), "");
  EXPECT_EQ(settingsJson(s, plannerFields()), settingsJson(before, plannerFields()));
  EXPECT_EQ(apply("[1, 2]"), "expected an object of settings");

  AccuracySettings a;
  EXPECT_EQ(applySettingsJson(json::parse(R"({"depthBits": 20})"), accuracyFields(), a),
            "depthBits: 20 is not one of 16, 24");
  EXPECT_EQ(applySettingsJson(json::parse(R"({"mipmaps": 1})"), accuracyFields(), a),
            "mipmaps: 1 is not true or false");
}

TEST(SettingsSchema, OptionNamesAreTheNamesInKebabCase) {
  EXPECT_EQ(plannerFields()[1].info.optionName(), "--faces-per-frame");
  EXPECT_EQ(accuracyFields()[0].info.optionName(), "--capture-at-origin");
  EXPECT_EQ(plannerFields()[0].info.optionName(), "--policy");
}

TEST(SettingsSchema, TheTableForThePageListsEveryNameOnceWithItsDefault) {
  const json schema = settingsSchemaJson();
  for (const char* group : {"planner", "accuracy", "material"}) {
    ASSERT_TRUE(schema[group].is_array()) << group;
    std::set<std::string> names;
    for (const json& entry : schema[group]) {
      EXPECT_TRUE(names.insert(entry["name"].get<std::string>()).second) << entry.dump();
      EXPECT_TRUE(entry.contains("label") && entry.contains("help") && entry.contains("kind") &&
                  entry.contains("default"))
          << entry.dump();
    }
  }
  EXPECT_EQ(schema["planner"][0]["default"], "when-changed");
  EXPECT_EQ(schema["planner"][0]["choices"].size(), 4u);
  EXPECT_EQ(schema["material"][0]["choices"],
            json::parse(R"(["phong", "mirror", "glass", "cube-textured"])"));
  EXPECT_EQ(schema["accuracy"][1]["name"], "search");
  EXPECT_EQ(schema["accuracy"][1]["default"], "planned");
  EXPECT_EQ(schema["accuracy"][2]["max"], 2);
}

TEST(SettingsSchema, TheInsideViewsAreViewSettingsInTheirOwnFolder) {
  ViewSettings view;
  EXPECT_EQ(applySettingsJson(json::parse(R"({"inside": "faces", "facesChannel": "distance"})"),
                              viewFields(), view),
            "");
  EXPECT_EQ(view.inside, InsideView::Faces);
  EXPECT_EQ(view.facesChannel, FacesChannel::Distance);
  EXPECT_EQ(applySettingsJson(json::parse(R"({"facesChannel": "depth"})"), viewFields(), view),
            "facesChannel: \"depth\" is not one of colour, distance, layer2, irradiance");
  EXPECT_EQ(view.facesChannel, FacesChannel::Distance);
  EXPECT_EQ(settingsJson(view, viewFields())["facesChannel"], "distance");
  EXPECT_EQ(applySettingsJson(json::parse(R"({"inside": "faceuse", "facesProbe": 2})"),
                              viewFields(), view),
            "");
  EXPECT_EQ(view.inside, InsideView::FaceUse);
  EXPECT_EQ(view.facesProbe, 2);
  EXPECT_EQ(applySettingsJson(json::parse(R"({"facesProbe": 0})"), viewFields(), view),
            "facesProbe: 0 is not in 1..64");
  EXPECT_EQ(view.facesProbe, 2);
  const json schema = settingsSchemaJson();
  for (const json& entry : schema["view"]) {
    const std::string name = entry["name"].get<std::string>();
    const bool inside = name == "inside" || name == "facesChannel" || name == "facesProbe";
    EXPECT_EQ(entry.value("folder", ""), inside ? "Inside the frame" : "") << name;
  }
}

TEST(SettingsSchema, EnumerationNamesRoundTrip) {
  for (Material m : {Material::Phong, Material::Mirror, Material::Glass, Material::CubeTextured}) {
    Material back = Material::Phong;
    EXPECT_TRUE(parseMaterial(materialName(m), &back));
    EXPECT_EQ(back, m);
  }
  Environment e = Environment::LiveProbe;
  EXPECT_TRUE(parseEnvironment("skybox", &e));
  EXPECT_EQ(e, Environment::Skybox);
  EXPECT_FALSE(parseEnvironment("sky", &e));
  Material m = Material::Phong;
  EXPECT_FALSE(parseMaterial("chrome", &m));
}

// Every value's name parses back to it, and a name no value has is refused (core/enum_names.h).
TEST(EnumNames, EveryValueRoundTripsAndUnknownNamesAreRefused) {
  for (Search search : kSearches) {
    Search parsed = Search::Plain;
    EXPECT_TRUE(parseSearch(searchName(search), &parsed)) << searchName(search);
    EXPECT_EQ(parsed, search);
  }
  for (Material material :
       {Material::Phong, Material::Mirror, Material::Glass, Material::CubeTextured}) {
    Material parsed = Material::Phong;
    EXPECT_TRUE(parseMaterial(materialName(material), &parsed)) << materialName(material);
    EXPECT_EQ(parsed, material);
  }
  for (Environment environment : {Environment::LiveProbe, Environment::Skybox}) {
    Environment parsed = Environment::LiveProbe;
    EXPECT_TRUE(parseEnvironment(environmentName(environment), &parsed));
    EXPECT_EQ(parsed, environment);
  }
  for (UpdatePolicy policy : {UpdatePolicy::EveryFrame, UpdatePolicy::WhenChanged,
                              UpdatePolicy::TimeSliced, UpdatePolicy::EveryNFrames}) {
    UpdatePolicy parsed = UpdatePolicy::EveryFrame;
    EXPECT_TRUE(parsePolicy(policyName(policy), &parsed)) << policyName(policy);
    EXPECT_EQ(parsed, policy);
  }
  Search unchanged = Search::Linear;
  EXPECT_FALSE(parseSearch("Exact", &unchanged));  // names are case-sensitive
  EXPECT_EQ(unchanged, Search::Linear);
  Material material = Material::Glass;
  EXPECT_FALSE(parseMaterial("?", &material));
  EXPECT_EQ(material, Material::Glass);
}

}  // namespace
}  // namespace reflect
