// Shared parts of the niwa CLI: subcommand lookup, flag ranges, file reading and atomic writing.
#include "cli_common.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "params/param_text.h"

namespace niwa::cli {

CLI::App* Subcommand(CLI::App& parent, const std::string& name, const std::string& description) {
  for (CLI::App* sub : parent.get_subcommands({})) {
    if (sub->get_name() == name) return sub;
  }
  CLI::App* sub = parent.add_subcommand(name, description);
  sub->require_subcommand(1);
  return sub;
}

namespace {

// Shortest text that reads back as the same float.
std::string FormatFloat(double value) {
  if (std::floor(value) == value) return FormatNumber(value);
  char buffer[32];
  for (int precision = 1; precision <= 9; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtof(buffer, nullptr) == static_cast<float>(value)) break;
  }
  return buffer;
}

std::string Bound(double value, const FlagRange& range) {
  return range.single ? FormatFloat(value) : FormatNumber(value);
}

}  // namespace

std::string RangeHelp(double min, double max) {
  return FormatNumber(min) + ".." + FormatNumber(max);
}
std::string RangeHelp(const FlagRange& range) {
  return Bound(range.min, range) + ".." + Bound(range.max, range);
}
std::string RangeHelp(const ParamSpec& spec) { return RangeHelp(spec.min_value, spec.max_value); }

Status CheckFlag(const std::string& flag, double value, const FlagRange& range) {
  if (CheckValue(flag, value, range.min, range.max, range.integer).ok()) return Status::Ok();
  return Status::Error(
      flag, std::string("must be ") + (range.integer ? "a whole number" : "a number") + " in [" +
                Bound(range.min, range) + ", " + Bound(range.max, range) + "]" + range.note);
}

std::string Extension(const std::string& path) {
  std::size_t dot = path.find_last_of('.');
  std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return path.substr(dot);
}

Result<std::string> ReadFile(const std::string& path, const std::string& field) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(field, "cannot read '" + path + "'");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

Status WriteFileAtomically(const std::string& path, const std::string& bytes) {
  const Status cannot = Status::Error("", "cannot write '" + path + "'");
  std::string temp = path + ".niwa-partial";
  {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    if (!file) return cannot;
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.flush();
    if (!file) {
      file.close();
      std::remove(temp.c_str());
      return cannot;
    }
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    return cannot;
  }
  return Status::Ok();
}

namespace {
const FlagRange kMaxSeconds = {1, 86400, false};
constexpr uint64_t kMinMemory = uint64_t{128} << 20, kMaxMemory = uint64_t{1} << 40;
}  // namespace

void AddBudgetOptions(CLI::App* cmd, BudgetOptions* o) {
  cmd->add_option("--max-memory", o->max_memory,
                  "Memory budget: the work is estimated first and refused or stopped early "
                  "(truncated) above it; bytes with K, M, G or T, 128M..1T (default 2G)");
  cmd->add_option(
      "--max-seconds", o->max_seconds,
      "Time budget in estimated seconds of work, " + RangeHelp(kMaxSeconds) + " (default 60)");
}

Budget ResolveBudget(const BudgetOptions& o) {
  Budget budget;
  uint64_t bytes = 0;
  if (!ParseBytes(o.max_memory, &bytes) || bytes < kMinMemory || bytes > kMaxMemory) {
    throw BadInput{
        "--max-memory: must be a size from 128M to 1T (a whole number with K, M, G or "
        "T, e.g. 4G)"};
  }
  budget.memory_bytes = bytes;
  Check(CheckFlag("--max-seconds", o.max_seconds, kMaxSeconds));
  budget.seconds = o.max_seconds;
  return budget;
}

void ReportTruncated(const std::string& line) {
  if (!line.empty()) std::cerr << "niwa: truncated: " << line << "\n";
}

}  // namespace niwa::cli
