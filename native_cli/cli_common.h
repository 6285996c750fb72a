// Shared parts of the niwa CLI's per-study command files: the bad-input error, the command list,
// flag ranges written once (help text and check), file reading and atomic writing.
// Does not: hold any study's commands (those live in native_cli/<study>_commands.cpp).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>
#include <string>
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
};
// A study's parameter table and presets, for 'niwa params [STUDY]' and 'niwa presets [STUDY]'.
struct Study {
  std::string name;  // "tree"
  const ParamTable* table;
  std::function<void(std::ostream& out)> print_presets;
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

// ".glb" of "out/tree.glb" ("" when none).
std::string Extension(const std::string& path);
// The whole file; {field, "cannot read 'path'"} when it cannot be read.
Result<std::string> ReadFile(const std::string& path, const std::string& field);
// Writes bytes to path through a temporary file and a rename, so no half-written file remains;
// the error is {"", "cannot write 'path'"}.
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

}  // namespace niwa::cli
