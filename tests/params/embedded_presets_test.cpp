// The one embed step of every study's presets: each core/<study>/presets/*.json is in the build,
// by study then file name, and a list file is read against its table.
#include "params/embedded_presets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

namespace niwa {
namespace {

namespace fs = std::filesystem;

TEST(EmbeddedPresets, EveryPresetFileOfEveryStudyIsEmbedded) {
  std::set<std::string> on_disk, embedded;
  for (const auto& study : fs::directory_iterator(fs::path(NIWA_SOURCE_DIR) / "core")) {
    const fs::path dir = study.path() / "presets";
    if (!fs::is_directory(dir)) continue;
    for (const auto& f : fs::directory_iterator(dir))
      if (f.path().extension() == ".json")
        on_disk.insert(study.path().filename().string() + "/" + f.path().filename().string());
  }
  for (const EmbeddedPreset& f : EmbeddedPresetFiles())
    embedded.insert(std::string(f.study) + "/" + f.file);
  EXPECT_EQ(embedded, on_disk);
  // The three studies with presets today.
  EXPECT_GE(EmbeddedPresets("tree").size(), 8u);
  EXPECT_EQ(EmbeddedPresets("ivy").size(), 1u);
  EXPECT_EQ(EmbeddedPresets("terrain").size(), 1u);
  EXPECT_TRUE(EmbeddedPresets("nothing").empty());
}

TEST(EmbeddedPresets, FilesComeInStudyThenNameOrder) {
  const std::vector<EmbeddedPreset>& files = EmbeddedPresetFiles();
  for (std::size_t i = 1; i < files.size(); ++i) {
    const std::string a = std::string(files[i - 1].study) + "/" + files[i - 1].file;
    const std::string b = std::string(files[i].study) + "/" + files[i].file;
    EXPECT_LT(a, b);
  }
}

}  // namespace
}  // namespace niwa
