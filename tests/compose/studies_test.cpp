// The registry of studies: every study (and the garden) answers the same calls (table, presets,
// hash codec with a key prefix), and a state round-trips through its hash under a foreign prefix.
#include "compose/studies.h"

#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>

#include "compose/garden_params.h"
#include "compose/garden_state.h"

namespace niwa::compose {
namespace {

using nlohmann::json;

TEST(Studies, TheFiveStudiesThenTheGarden) {
  ASSERT_EQ(Studies().size(), 6u);
  EXPECT_EQ(Studies()[0].name, "tree");
  EXPECT_EQ(Studies()[1].name, "ivy");
  EXPECT_EQ(Studies()[2].name, "terrain");
  EXPECT_EQ(Studies()[3].name, "bark");
  EXPECT_EQ(FindStudy("ivy")->unit, "steps");
  EXPECT_EQ(FindStudy("bark")->unit, "cycles");
  EXPECT_EQ(Studies()[4].name, "moss");
  EXPECT_EQ(FindStudy("moss")->unit, "days");
  EXPECT_EQ(Studies()[5].name, "garden");
  ASSERT_NE(FindStudy("garden"), nullptr);
  EXPECT_EQ(FindStudy("garden")->unit, "years");
  EXPECT_EQ(&FindStudy("garden")->table(), &GardenTable());
  EXPECT_EQ(FindStudy("forest"), nullptr);
  EXPECT_EQ(StudyNames(), "tree, ivy, terrain, bark, moss or garden");
}

TEST(Studies, EachTableAndPresetListIsJsonOfItsTable) {
  for (const StudyInfo& s : Studies()) {
    const json table = json::parse(s.table_json());
    ASSERT_TRUE(table.is_array()) << s.name;
    EXPECT_EQ(table.size(), s.table().size()) << s.name;
    EXPECT_EQ(table[0]["key"], s.table().row(0).key) << s.name;
    const json presets = json::parse(s.presets_json());
    ASSERT_TRUE(presets.is_array()) << s.name;
    // Table 2's three species; moss's two physics presets (nomura2010, nomura2010-sky); the
    // garden's one, its default garden
    EXPECT_GE(presets.size(), s.name == "bark"     ? 3u
                              : s.name == "moss"   ? 2u
                              : s.name == "garden" ? 1u
                                                   : 4u)
        << s.name;
    for (const json& p : presets) EXPECT_TRUE(p.contains("name")) << s.name;
  }
}

TEST(Studies, AStateRoundTripsThroughItsPrefixedHash) {
  const std::map<std::string, std::string> edits = {
      {"tree", "preset=maple&seed=4&years=7"},
      {"ivy", "preset=improved&seed=3&steps=40&scene=wall"},
      {"terrain", "preset=fig13b&builtin=dumbbell"},
      {"bark", "species=pine&seed=3&N_R=64&sigma=0.2"},
      {"moss", "preset=nomura2010-sky&scene=walls&days=40&seed=2&photons=2048"},
      {"garden", "years=5&size=30&plants=sakura:2:3:5:-6:90&terrain.preset=fig13b"},
  };
  for (const StudyInfo& s : Studies()) {
    const std::string prefix = s.name + ".";
    // The study's keys among another study's (a composed page's hash).
    std::string hash = "other.x=1";
    for (std::size_t at = 0; at < edits.at(s.name).size();) {
      std::size_t amp = edits.at(s.name).find('&', at);
      if (amp == std::string::npos) amp = edits.at(s.name).size();
      hash += "&" + prefix + edits.at(s.name).substr(at, amp - at);
      at = amp + 1;
    }
    const json decoded = json::parse(s.decode_hash(hash, prefix));
    EXPECT_TRUE(decoded["notices"].empty()) << s.name << ": " << decoded["notices"].dump();
    // The prefixed keys were read (not skipped as another study's).
    if (s.name == "garden") {
      const json& g = decoded["state"];
      EXPECT_EQ(g["params"]["years"], 5);
      EXPECT_EQ(g["params"]["size"], 30);
      ASSERT_EQ(g["plants"].size(), 1u);
      EXPECT_EQ(g["plants"][0]["species"], "sakura");
      EXPECT_EQ(g["plants"][0]["pos"], json::array({5, -6}));
      EXPECT_EQ(g["ground"]["terrain"]["preset"], "fig13b");  // its terrain's keys nested
    } else {
      const std::string preset = decoded["state"][s.name == "bark" ? "species" : "preset"];
      EXPECT_EQ(preset, s.name == "tree"      ? "maple"
                        : s.name == "ivy"     ? "improved"
                        : s.name == "terrain" ? "fig13b"
                        : s.name == "moss"    ? "nomura2010-sky"
                                              : "pine")
          << s.name;
    }
    Result<std::string> again = s.encode_hash(decoded["state"].dump(), prefix);
    ASSERT_TRUE(again.ok()) << s.name << ": " << again.status().Line();
    const json twice = json::parse(s.decode_hash(*again, prefix));
    EXPECT_EQ(twice["state"], decoded["state"]) << s.name << ": " << *again;
    EXPECT_NE(again->find(prefix), std::string::npos) << s.name;
  }
}

// The garden's ivy as a link or a state JSON gives it, whatever the order of the keys: "ivy="
// alone is no ivy on the default wall, and a state JSON's ivy.on (read before its objects, keys
// sorted) is not replaced by the default layout's.
TEST(Studies, TheGardensIvyAsGiven) {
  const StudyInfo& garden = *FindStudy("garden");
  const json plain = json::parse(garden.decode_hash("years=3", ""));
  EXPECT_EQ(plain["state"]["ivy"]["on"], json::array({"objects[0]"}));  // the default wall's
  const json none = json::parse(garden.decode_hash("years=3&ivy=", ""));
  EXPECT_TRUE(none["notices"].empty()) << none["notices"].dump();
  EXPECT_EQ(none["state"]["ivy"]["on"], json::array());
  EXPECT_EQ(none["state"]["objects"].size(), 4u);  // the default layout
  // A smaller garden's default objects are laid out for its size (the wall 12 m north at 40 m: 6
  // at 20), so the decoded state is one the garden grows (CheckGardenState: inside the square).
  const json small = json::parse(garden.decode_hash("size=20", ""));
  EXPECT_EQ(small["state"]["objects"][0]["pos"], json::array({0.0, -6.0}));
  GardenState check = DefaultGardenState();
  ASSERT_TRUE(ApplyGardenStateJson(small["state"].dump(), &check).ok());
  EXPECT_TRUE(CheckGardenState(check).ok()) << CheckGardenState(check).Line();
  Result<std::string> hash = garden.encode_hash(
      R"({"ivy": {"on": ["objects[1]"]}, "objects": [{"kind": "wall", "pos": [0, -12]},
          {"kind": "rock", "pos": [6, 4]}]})",
      "");
  ASSERT_TRUE(hash.ok()) << hash.status().Line();
  EXPECT_NE(hash->find("ivy=objects%5B1%5D"), std::string::npos) << *hash;
}

TEST(Studies, ABadStateNamesItsField) {
  for (const StudyInfo& s : Studies()) {
    // The garden's seed is its planting rules' (its state JSON's rows are under params).
    Result<std::string> bad = s.encode_hash(
        s.name == "garden" ? R"({"params": {"plant_seed": -5}})" : R"({"seed": -5})", "");
    ASSERT_FALSE(bad.ok()) << s.name;
    EXPECT_NE(bad.status().field().find("seed"), std::string::npos)
        << s.name << ": " << bad.status().Line();
  }
}

}  // namespace
}  // namespace niwa::compose
