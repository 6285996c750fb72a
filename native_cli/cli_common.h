// Shared parts of the niwa CLI's per-study command files: the bad-input error, the command list,
// flag ranges written once (help text and check), strict numeric flags, size-capped file reading
// and all-or-none atomic writing (docs/input-rules.md).
// Does not: hold any study's commands (those live in native_cli/<study>_commands.cpp).
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "params/param_table.h"

namespace niwa::cli {

// Thrown from a command; RunCli prints "niwa: error: <message>" and exits with code 2.
struct BadInput {
  std::string message;
};

[[noreturn]] inline void Fail(const Status& status) { throw BadInput{status.Line()}; }
inline void Check(const Status& status) {
  if (!status.ok()) Fail(status);
}
// The same error under the flag that gave the value: {"years", m} -> {"--years", m}.
inline Status AsFlag(const Status& status, const std::string& flag) {
  return status.ok() ? status : Status::Error(flag, status.message());
}

// What a study's Add<Study>Commands(CLI::App& app, CommandList& commands) registers: a subcommand
// and what runs (returning the exit code) when it was the one given.
struct Command {
  CLI::App* app;
  std::function<int(std::ostream& out)> run;
  // A quick valid run's arguments after the command's words ("--steps", "3"), on which the shared
  // hostile-input suite (tests/cli/hostile.test.mjs, through 'niwa flags') varies one flag at a
  // time; empty: the suite gives the hostile flag alone.
  std::vector<std::string> example = {};
};
// A study's parameter table and presets, for 'niwa params [STUDY]' and 'niwa presets [STUDY]'.
struct Study {
  std::string name;  // "tree"
  const ParamTable* table;
  std::function<void(std::ostream& out)> print_presets;
  // The table as JSON for 'niwa params STUDY --json' when it carries more than ParamTableJson
  // (the tree's Getting started group); empty: ParamTableJson(*table).
  std::function<std::string()> table_json = {};
  // A quick valid run of the command that takes this study's --set KEY=VALUE and --url (full
  // words, "ivy", "grow", "--steps", "3"), on which the hostile-input suite varies every table row.
  std::vector<std::string> example = {};
};
struct CommandList : std::vector<Command> {
  std::vector<Study> studies;  // the first registered is the default of 'params' and 'presets'
};

// The subcommand `name` of parent, made (with its description) by the first study that needs it.
CLI::App* Subcommand(CLI::App& parent, const std::string& name, const std::string& description);

// A flag's allowed range, written once: its help text says RangeHelp and CheckFlag checks it.
struct FlagRange {
  double min, max;
  bool integer = false;
  const char* note = "";  // appended to the error, e.g. " (radians)"
  bool single = false;    // min and max are floats: shown as their shortest float text
};
std::string RangeHelp(double min, double max);  // "0..100"
std::string RangeHelp(const FlagRange& range);
std::string RangeHelp(const ParamSpec& spec);
// Ok when value is in range (params' CheckValue), else {flag, "must be a number in [a, b]"}.
Status CheckFlag(const std::string& flag, double value, const FlagRange& range);

// The FlagRange of a table row: a flag that overrides the row takes its range.
FlagRange RowFlagRange(const ParamSpec& spec);

// The value of a numeric flag's text through the one strict parser (params/strict_number.h):
// decimal only, never empty, then CheckFlag. Throws BadInput naming the flag and its range.
double FlagNumber(const std::string& flag, const std::string& text, const FlagRange& range);

// What a flag takes, declared where the flag is added, for the checks every command shares
// (RunCli's CheckApplicable) and for the hostile-input suite ('niwa flags' lists every command's
// flags with their kinds, ranges and output extensions). A flag added without a declaration is a
// switch (no value) or free text.
enum class FlagKind { kSwitch, kNumber, kText, kInput, kOutput };
struct FlagInfo {
  explicit FlagInfo(FlagKind k = FlagKind::kText, FlagRange r = {0, 0}) : kind(k), range(r) {}
  FlagKind kind;
  FlagRange range;                           // kNumber
  std::vector<std::string> extensions;       // kOutput: the endings it accepts (".glb")
  std::string only_with;                     // applies only with this output flag ("--out") ...
  std::vector<std::string> only_endings;     // ... ending in one of these (".svg")
  std::vector<const CLI::Option*> excludes;  // flags it cannot be given with
};
// Declares what an added flag takes (the flags above call it; a command file calls it for a flag
// that CLI11 adds directly).
CLI::Option* Declare(CLI::Option* option, FlagInfo info);
const FlagInfo* Declared(const CLI::Option* option);
// Forgets every declaration (RunCli builds a new app for each call).
void ClearDeclarations();
// An input file flag (kInput): read later with ReadFile or a core reader.
CLI::Option* AddInputFlag(CLI::App* cmd, const std::string& flag, std::string* path,
                          const std::string& help);
// Ok when path ("" too) ends in one of endings, else {flag, "'a.txt' must end in .glb, .json or
// .svg"}: the one check of a file's ending (output flags, and an input read by its ending: --dem).
Status CheckEnding(const std::string& flag, const std::string& path,
                   const std::vector<std::string>& endings);
// An output file flag (kOutput) taking one of extensions; the ending is checked when the flag is
// given ("--out: 'a.txt' must end in .glb, .json or .svg"), before any work.
CLI::Option* AddOutputFlag(CLI::App* cmd, const std::string& flag, std::string* path,
                           std::vector<std::string> extensions, const std::string& help);
// The flag applies only when output_flag is given and ends in one of endings; given otherwise,
// CheckApplicable refuses it ("--caption: only applies with --out FILE.svg").
CLI::Option* OnlyWith(CLI::Option* option, const std::string& output_flag,
                      std::vector<std::string> endings);
// Flags that cannot be given together (--mesh FILE and --scene NAME): given both, CheckApplicable
// refuses the one declared first ("--mesh: give only one of --mesh and --scene").
void Excludes(CLI::Option* a, CLI::Option* b);
// Refuses every given flag of the chosen command whose OnlyWith does not hold, and
// flags given together that exclude each other.
void CheckApplicable(const CLI::App& cmd);
// Refuses, before any work, a given output flag (kOutput) that StagedOutputs would refuse after the
// work: an empty name, one ending in '/' or one over 255 bytes, a folder that does not exist or
// cannot be written, an existing target that is not a regular file, two outputs naming one file.
// Same lines as Stage's.
void PreflightOutputs(const CLI::App& cmd);
// A caption flag: printable text of at most kMaxCaptionBytes bytes (control characters refused,
// not silently dropped), written into markup escaped (base/markup_escape.h) by the core.
constexpr std::size_t kMaxCaptionBytes = 200;
CLI::Option* AddCaptionFlag(CLI::App* cmd, const std::string& flag, std::string* caption,
                            const std::string& help);
// Every command's flags as JSON, for 'niwa flags' (the hostile-input suite's list):
// [{"command": ["ivy","grow"], "example": [...], "flags": [{"flag", "kind", "repeatable",
// "min", "max", "integer", "extensions", "only_with", "only_endings"}]}] and the studies
// {"studies": [{"name", "example"}]}.
std::string FlagsJson(const CommandList& commands);

// Adds a numeric flag read as text and parsed by FlagNumber into *value when CLI11 stores it, so
// CLI11's own conversions (hex, octal, wrapping) never see it. T: int, uint64_t, float or double.
template <typename T>
CLI::Option* AddNumberFlag(CLI::App* cmd, const std::string& flag, T* value, const FlagRange& range,
                           const std::string& help) {
  static_assert(std::is_arithmetic_v<T>);
  CLI::Option* option = cmd->add_option_function<std::string>(
      flag,
      [flag, value, range](const std::string& text) {
        *value = static_cast<T>(FlagNumber(flag, text, range));
      },
      help);
  return Declare(option, FlagInfo(FlagKind::kNumber, range));
}

// Largest file read by --params (1 MiB) and --contour (16 MiB); --mesh uses io::kMaxMeshFileBytes.
constexpr std::size_t kMaxParamsFileBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxContourFileBytes = std::size_t{16} << 20;
// Largest elevation model read by terrain compare --dem (a 16-bit PNG; 64 MiB holds 4096^2 cells).
constexpr std::size_t kMaxDemFileBytes = std::size_t{64} << 20;

// ".glb" of "out/tree.glb" ("" when none).
std::string Extension(const std::string& path);
// The whole file, refused before reading when it is not a regular file or larger than max_bytes:
// {field, "'path' has N bytes; the limit is M (1 MiB)"}, {field, "cannot read 'path'"}.
Result<std::string> ReadFile(const std::string& path, const std::string& field,
                             std::size_t max_bytes);

// The outputs of one run, written all or none: Stage writes each to a unique temporary file in its
// target's folder (created with O_CREAT|O_EXCL|O_NOFOLLOW, mode 0644 under the umask, fsynced);
// Commit renames them all into place. A failure (or destruction before Commit) removes every
// temporary; a rename failing after others succeeded puts back the files they replaced (kept as
// hard links until the commit ends) and removes the outputs that were new. The same file named
// twice ("a.json" and "./a.json") is refused at Stage; SIGINT, SIGTERM and SIGHUP remove the
// temporaries before the process ends.
class StagedOutputs {
 public:
  StagedOutputs() = default;
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs();
  // The error is {field, "cannot write 'path'"} (field: the flag, e.g. "--out").
  Status Stage(const std::string& field, const std::string& path, const std::string& bytes);
  Status Commit();

 private:
  struct Staged {
    std::string field, path, temp;
    std::string identity;  // the file it names, however spelled (a second name is refused)
    std::string backup;    // a hard link to the file it replaces, until Commit ends
    int slot = -1, backup_slot = -1;  // the signal handler's slots (removed on SIGINT/SIGTERM)
  };
  void RemoveTemps();
  std::vector<Staged> staged_;
};

// One output through StagedOutputs; the error is {"", "cannot write 'path'"}.
Status WriteFileAtomically(const std::string& path, const std::string& bytes);

// The budget flags every command that does heavy work takes (issue 16, docs/budgets.md):
// --max-memory (default 2G) and --max-seconds (default 60), the one definition of both.
struct BudgetOptions {
  std::string max_memory = "2G";
  double max_seconds = 60;
};
void AddBudgetOptions(CLI::App* cmd, BudgetOptions* options);
// The Budget the flags give; BadInput naming the flag and its range when out of range.
Budget ResolveBudget(const BudgetOptions& options);
// The line a command prints on stderr when a limit stopped its work early ("" prints nothing).
void ReportTruncated(const std::string& line);

// Milliseconds from a to b (the `ms` fields of --stats).
inline double Ms(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace niwa::cli
