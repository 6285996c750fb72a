// Enforces docs/ARCHITECTURE.md's include rules on the sources: studies never include each other,
// shared parts include no study, nothing in a study or a shared part includes the composition tier
// (core/compose, which may include studies), nothing in core/ includes Emscripten, GL or JS, and
// the two front ends (native_cli/, web/bindings/) never include each other.
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
    {"run", {"base", "math", "params", "geom", "image", "io"}},
};

// The composition tier: may include every shared part and study; nothing in core/ includes it.
const char* const kComposeTier = "compose";

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

// Every #include of the sources below `dir` (file relative to `dir`).
std::vector<Include> IncludesUnder(const fs::path& dir) {
  std::vector<Include> out;
  const std::regex include_re(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
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
        out.push_back({fs::relative(entry.path(), dir).generic_string(), line_number, m[1]});
      }
    }
  }
  return out;
}

std::vector<Include> CoreIncludes(const fs::path& core) { return IncludesUnder(core); }

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
    if (from == kComposeTier) {
      allowed = true;
    } else if (to == kComposeTier) {
      allowed = false;  // no study or shared part includes the composition tier
    } else if (shared != kSharedParts.end()) {
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
    EXPECT_TRUE(kSharedParts.count(f) || studies.count(f) || f == kComposeTier)
        << "core/" << f << " is not in the rules";
  }
}

// The front ends are adapters over core runs: the CLI never includes the web bindings and the
// bindings never include the CLI, and a study's front-end file (native_cli/<study>_*.{h,cpp},
// web/bindings/<study>_*.cpp) reaches core/ through shared parts, its own study (family) and the
// composition tier only, so a composition (ivy on a tree) is written once, in core/compose.
TEST(IncludeRules, FrontEndsAreAdaptersOverTheCore) {
  const fs::path root(NIWA_SOURCE_DIR);
  const std::map<std::string, std::set<std::string>> kFamily = {
      {"tree", {"tree", "sway", "render"}},
      {"sway", {"tree", "sway", "render"}},
      {"render", {"tree", "sway", "render"}},
      {"texture", {"tree"}},
      {"ivy", {"ivy"}},
      {"terrain", {"terrain"}},
      {"moss", {"moss"}},
      {"bark", {"bark"}},
      {"mesh", {}},
      {"light", {}}};
  std::set<std::string> core_folders;
  for (const std::string& f : CoreFolders(kCore)) core_folders.insert(f);
  int checked = 0, study_checked = 0;
  for (const std::string folder : {"native_cli", "web/bindings"}) {
    const bool cli = folder == std::string("native_cli");
    for (const Include& inc : IncludesUnder(root / folder)) {
      const std::string name = fs::path(inc.file).filename().string();
      const auto family = kFamily.find(name.substr(0, name.find('_')));
      ++checked;
      const std::string& target = inc.target;
      const std::string where = folder + "/" + inc.file + ":" + std::to_string(inc.line);
      if (cli) {
        EXPECT_EQ(target.find("bindings/"), std::string::npos) << where << " includes " << target;
      } else {
        EXPECT_EQ(target.find("native_cli/"), std::string::npos) << where << " includes " << target;
        EXPECT_NE(target, "cli_common.h") << where;
      }
      const std::string to = FirstSegment(target);
      if (family == kFamily.end() || !core_folders.count(to)) continue;
      ++study_checked;
      EXPECT_TRUE(kSharedParts.count(to) || family->second.count(to) || to == kComposeTier)
          << where << " (a " << family->first << " front end) may not include \"" << target
          << "\": a composition of studies belongs in core/compose";
    }
  }
  EXPECT_GT(checked, 40);        // the scan saw both front ends' includes
  EXPECT_GT(study_checked, 30);  // and the study files' core includes
}

}  // namespace

// Issue 28 item 1: core errors name state fields, never a front end's words; the command line's
// flags ("--max-memory", "--years") are the CLI's (run::FieldNames, cli::ResolveBudget). A string
// literal in core holding a flag ("--word") fails here (comments and tinygltf aside).
TEST(FlagWords, CoreStringsNameNoCommandLineFlag) {
  const std::regex flag_in_string(R"re("(?:[^"\n]*[^-\w"\n])?--[a-z][a-z-]*[^"\n]*")re");
  int files = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(kCore)) {
    const std::string name = e.path().filename().string();
    if (!e.is_regular_file() || name.rfind("tinygltf", 0) == 0) continue;
    if (e.path().extension() != ".h" && e.path().extension() != ".cpp") continue;
    ++files;
    std::ifstream in(e.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      const std::size_t comment = line.find("//");
      const std::string code = comment == std::string::npos ? line : line.substr(0, comment);
      EXPECT_FALSE(std::regex_search(code, flag_in_string))
          << e.path().string() << ":" << n << ": " << line;
    }
  }
  EXPECT_GT(files, 100);
}
