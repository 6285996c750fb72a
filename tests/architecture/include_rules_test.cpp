// Enforces docs/ARCHITECTURE.md's include rules on the sources: studies never include each other,
// shared parts include no study, and nothing in core/ includes Emscripten, GL or JS.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Shared parts and what each may include (besides itself). Order: base < math, random < params,
// geom, image < io, light.
const std::map<std::string, std::set<std::string>> kSharedParts = {
    {"base", {}},
    {"math", {"base"}},
    {"random", {"base"}},
    {"params", {"base", "math"}},
    {"geom", {"base", "math", "random"}},
    {"image", {"base", "math"}},
    {"io", {"base", "math", "params", "geom", "image"}},
    {"light", {"base", "math", "random", "geom"}},
};

// The tree thesis is one study over three folders: chapter 3 (sway) and chapter 4 (render) stand on
// chapter 2's tree; the tree knows neither.
const std::map<std::string, std::set<std::string>> kStudyFamilies = {
    {"sway", {"tree"}},
    {"render", {"tree", "sway"}},
};

struct Include {
  std::string file;  // relative to core/
  int line;
  std::string target;
};

std::vector<Include> CoreIncludes(const fs::path& core) {
  std::vector<Include> out;
  const std::regex include_re(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  for (const auto& entry : fs::recursive_directory_iterator(core)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".h" && ext != ".cpp" && ext != ".hpp" && ext != ".inc") continue;
    std::ifstream in(entry.path());
    std::string text;
    int line_number = 0;
    while (std::getline(in, text)) {
      ++line_number;
      std::smatch m;
      if (std::regex_search(text, m, include_re)) {
        out.push_back({fs::relative(entry.path(), core).generic_string(), line_number, m[1]});
      }
    }
  }
  return out;
}

std::string FirstSegment(const std::string& path) {
  std::size_t slash = path.find('/');
  return slash == std::string::npos ? "" : path.substr(0, slash);
}

std::vector<std::string> CoreFolders(const fs::path& core) {
  std::vector<std::string> folders;
  for (const auto& entry : fs::directory_iterator(core)) {
    if (entry.is_directory()) folders.push_back(entry.path().filename().string());
  }
  return folders;
}

const fs::path kCore = fs::path(NIWA_SOURCE_DIR) / "core";

TEST(IncludeRules, CoreHasNoEmscriptenGlOrJs) {
  const std::regex banned(R"(^(emscripten|GL/|GLES|GLFW|EGL/|webgl|SDL))");
  int checked = 0;
  for (const Include& inc : CoreIncludes(kCore)) {
    ++checked;
    EXPECT_FALSE(std::regex_search(inc.target, banned))
        << "core/" << inc.file << ":" << inc.line << " includes <" << inc.target << ">";
  }
  EXPECT_GT(checked, 50);  // the scan saw the core's includes
}

TEST(IncludeRules, StudiesNeverIncludeEachOtherAndSharedPartsIncludeNoStudy) {
  std::set<std::string> folders;
  for (const std::string& f : CoreFolders(kCore)) folders.insert(f);
  ASSERT_TRUE(folders.count("tree") && folders.count("params"));
  int project_includes = 0;
  for (const Include& inc : CoreIncludes(kCore)) {
    const std::string from = FirstSegment(inc.file);
    const std::string to = FirstSegment(inc.target);
    if (to.empty() || !folders.count(to) || to == from) continue;  // system or own folder
    ++project_includes;
    auto shared = kSharedParts.find(from);
    bool allowed;
    if (shared != kSharedParts.end()) {
      allowed = shared->second.count(to) > 0;  // a shared part: only lower shared parts
    } else {
      auto family = kStudyFamilies.find(from);
      allowed = kSharedParts.count(to) > 0 ||
                (family != kStudyFamilies.end() && family->second.count(to) > 0);
    }
    EXPECT_TRUE(allowed) << "core/" << inc.file << ":" << inc.line << " (" << from
                         << ") may not include \"" << inc.target << "\" (" << to << ")";
  }
  EXPECT_GT(project_includes, 20);
}

TEST(IncludeRules, EveryCoreFolderIsASharedPartOrAStudy) {
  // A new folder must be added to this test's rules (and docs/ARCHITECTURE.md) on purpose.
  const std::set<std::string> studies = {"tree",    "sway", "render", "ivy",
                                         "terrain", "moss", "bark"};
  for (const std::string& f : CoreFolders(kCore)) {
    EXPECT_TRUE(kSharedParts.count(f) || studies.count(f))
        << "core/" << f << " is not in the rules";
  }
}

}  // namespace
