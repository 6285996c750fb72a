// Shared parts of the niwa CLI: subcommand lookup, flag ranges, strict numeric flags, size-capped
// file reading and all-or-none atomic writing.
#include "cli_common.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>

#include "base/echo.h"
#include "params/param_text.h"
#include "params/strict_number.h"

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
  return Status::Error(flag, (std::isfinite(value) ? FormatNumber(value) : std::string("value")) +
                                 " is out of range; must be " +
                                 (range.integer ? "a whole number" : "a number") + " in [" +
                                 Bound(range.min, range) + ", " + Bound(range.max, range) + "]" +
                                 range.note);
}

FlagRange RowFlagRange(const ParamSpec& spec) {
  return {spec.min_value, spec.max_value, spec.integer};
}

double FlagNumber(const std::string& flag, const std::string& text, const FlagRange& range) {
  const std::string allowed = std::string(range.integer ? "a whole number" : "a number") + " in [" +
                              Bound(range.min, range) + ", " + Bound(range.max, range) + "]" +
                              range.note;
  if (text.empty()) Fail(Status::Error(flag, "empty; must be " + allowed));
  std::optional<double> value = ParseDecimal(text);
  if (!value) {
    Fail(Status::Error(flag, "'" + Echo(text) + "' is not a decimal number; must be " + allowed));
  }
  // A float flag (range.single) is checked as the float it becomes: "--distance 0.2" is the
  // float 0.2f, the bound itself.
  double checked = *value;
  if (range.single &&
      std::fabs(checked) <= static_cast<double>(std::numeric_limits<float>::max())) {
    checked = static_cast<double>(static_cast<float>(checked));
  }
  Check(CheckFlag(flag, checked, range));
  return checked;
}

std::string Extension(const std::string& path) {
  std::size_t dot = path.find_last_of('.');
  std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return path.substr(dot);
}

namespace {

std::string SizeText(std::size_t bytes) {
  if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0) {
    return std::to_string(bytes >> 20) + " MiB";
  }
  return std::to_string(bytes) + " bytes";
}

// The folder part of path ("." when none) and the name part.
std::string Folder(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

bool WriteAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// A temporary name unique to this process and call: ".niwa-<pid>-<n>-<clock>.partial" (short, so a
// 255-character target name still works); O_EXCL makes a clash fail and the caller try again.
std::string TempName(const std::string& folder, unsigned attempt) {
  static std::atomic<unsigned> counter{0};
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  return folder + "/.niwa-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" +
         std::to_string(static_cast<unsigned long long>(now) % 1000000007ULL) + "-" +
         std::to_string(attempt) + ".partial";
}

}  // namespace

Result<std::string> ReadFile(const std::string& path, const std::string& field,
                             std::size_t max_bytes) {
  const std::string name = "'" + Echo(path) + "'";
  if (path.empty()) return Status::Error(field, "empty; must be a file name");
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return Status::Error(field, "cannot read " + name);
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    return Status::Error(field, "cannot read " + name + ": not a regular file");
  }
  const auto size = static_cast<std::size_t>(info.st_size);
  if (size > max_bytes) {
    ::close(fd);
    return Status::Error(field, name + " has " + std::to_string(size) + " bytes; the limit is " +
                                    SizeText(max_bytes));
  }
  std::string bytes;
  bytes.reserve(size);
  char buffer[65536];
  while (true) {
    ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      ::close(fd);
      return Status::Error(field, "cannot read " + name);
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > max_bytes) {  // the file grew while being read
      ::close(fd);
      return Status::Error(field, name + " has more than " + std::to_string(max_bytes) +
                                      " bytes; the limit is " + SizeText(max_bytes));
    }
  }
  ::close(fd);
  return bytes;
}

StagedOutputs::~StagedOutputs() { RemoveTemps(); }

void StagedOutputs::RemoveTemps() {
  for (const Staged& s : staged_) ::unlink(s.temp.c_str());
  staged_.clear();
}

Status StagedOutputs::Stage(const std::string& field, const std::string& path,
                            const std::string& bytes) {
  const Status cannot = Status::Error(field, "cannot write '" + Echo(path) + "'");
  if (path.empty()) return Status::Error(field, "empty; must be a file name");
  if (path.back() == '/') return cannot;
  const std::string folder = Folder(path);
  for (const Staged& s : staged_) {
    if (s.path == path) return Status::Error(field, "'" + Echo(path) + "' is also " + s.field);
  }
  std::string temp;
  int fd = -1;
  for (unsigned attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp = TempName(folder, attempt);
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0 && errno != EEXIST) return cannot;
  }
  if (fd < 0) return cannot;
  const bool written = WriteAll(fd, bytes) && ::fsync(fd) == 0;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    ::unlink(temp.c_str());
    return cannot;
  }
  staged_.push_back({field, path, temp});
  return Status::Ok();
}

Status StagedOutputs::Commit() {
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    if (::rename(staged_[i].temp.c_str(), staged_[i].path.c_str()) != 0) {
      const Status cannot =
          Status::Error(staged_[i].field, "cannot write '" + Echo(staged_[i].path) + "'");
      for (std::size_t k = 0; k < i; ++k) ::unlink(staged_[k].path.c_str());  // all or none
      staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(i));
      RemoveTemps();
      return cannot;
    }
  }
  // Make the renames durable where the platform allows a folder fsync (best effort).
  for (const Staged& s : staged_) {
    int dir = ::open(Folder(s.path).c_str(), O_RDONLY | O_CLOEXEC);
    if (dir >= 0) {
      (void)::fsync(dir);
      ::close(dir);
    }
  }
  staged_.clear();
  return Status::Ok();
}

Status WriteFileAtomically(const std::string& path, const std::string& bytes) {
  StagedOutputs outputs;
  NIWA_RETURN_IF_ERROR(outputs.Stage("", path, bytes));
  return outputs.Commit();
}

namespace {
const FlagRange kMaxSeconds = {1, 86400, false};
constexpr uint64_t kMinMemory = uint64_t{128} << 20, kMaxMemory = uint64_t{1} << 40;
}  // namespace

void AddBudgetOptions(CLI::App* cmd, BudgetOptions* o) {
  cmd->add_option("--max-memory", o->max_memory,
                  "Memory budget: the work is estimated first and refused or stopped early "
                  "(truncated) above it; bytes with K, M, G or T, 128M..1T (default 2G)");
  AddNumberFlag(
      cmd, "--max-seconds", &o->max_seconds, kMaxSeconds,
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
