// Shared parts of the niwa CLI: subcommand lookup, flag ranges, strict numeric flags, size-capped
// file reading and all-or-none atomic writing.
#include "cli_common.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
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
    Fail(Status::Error(flag, NotDecimalWhy(text) + "; must be " + allowed));
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

namespace {

std::map<const CLI::Option*, FlagInfo>& Declarations() {
  static std::map<const CLI::Option*, FlagInfo> declarations;
  return declarations;
}

// ".glb, .json or .svg"
std::string Either(const std::vector<std::string>& words, const std::string& prefix = "") {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + prefix + words[i];
  }
  return text;
}

const char* KindName(FlagKind kind) {
  switch (kind) {
    case FlagKind::kSwitch:
      return "switch";
    case FlagKind::kNumber:
      return "number";
    case FlagKind::kText:
      return "text";
    case FlagKind::kInput:
      return "input";
    case FlagKind::kOutput:
      return "output";
  }
  return "text";
}

}  // namespace

CLI::Option* Declare(CLI::Option* option, FlagInfo info) {
  Declarations()[option] = std::move(info);
  return option;
}

const FlagInfo* Declared(const CLI::Option* option) {
  auto it = Declarations().find(option);
  return it == Declarations().end() ? nullptr : &it->second;
}

void ClearDeclarations() { Declarations().clear(); }

namespace {
// The declaration of option, made as a switch or free text when it had none.
FlagInfo& DeclaredOrNew(CLI::Option* option) {
  if (Declared(option) == nullptr) {
    Declare(option,
            FlagInfo(option->get_expected_max() == 0 ? FlagKind::kSwitch : FlagKind::kText));
  }
  return Declarations()[option];
}
}  // namespace

CLI::Option* AddInputFlag(CLI::App* cmd, const std::string& flag, std::string* path,
                          const std::string& help) {
  return Declare(cmd->add_option(flag, *path, help), FlagInfo(FlagKind::kInput));
}

Status CheckEnding(const std::string& flag, const std::string& path,
                   const std::vector<std::string>& endings) {
  if (path.empty()) return Status::Ok();
  const std::string ext = Extension(path);
  for (const std::string& e : endings)
    if (e == ext) return Status::Ok();
  return Status::Error(flag, "'" + Echo(path) + "' must end in " + Either(endings));
}

CLI::Option* AddOutputFlag(CLI::App* cmd, const std::string& flag, std::string* path,
                           std::vector<std::string> extensions, const std::string& help) {
  CLI::Option* option = cmd->add_option_function<std::string>(
      flag,
      [flag, path, extensions](const std::string& text) {
        Check(CheckEnding(flag, text, extensions));
        *path = text;
      },
      help);
  FlagInfo info(FlagKind::kOutput);
  info.extensions = std::move(extensions);
  return Declare(option, std::move(info));
}

CLI::Option* OnlyWith(CLI::Option* option, const std::string& output_flag,
                      std::vector<std::string> endings) {
  FlagInfo& info = DeclaredOrNew(option);
  info.only_with = output_flag;
  info.only_endings = std::move(endings);
  return option;
}

void Excludes(CLI::Option* a, CLI::Option* b) {
  DeclaredOrNew(a).excludes.push_back(b);
  DeclaredOrNew(b).excludes.push_back(a);
}

void CheckApplicable(const CLI::App& cmd) {
  for (const CLI::Option* option : cmd.get_options()) {  // in the order they were added
    const FlagInfo* info = Declared(option);
    if (option->count() == 0 || info == nullptr) continue;
    for (const CLI::Option* other : info->excludes) {
      if (other->count() > 0) {
        Fail(Status::Error(option->get_name(),
                           "give only one of " + option->get_name() + " and " + other->get_name()));
      }
    }
  }
  for (const CLI::Option* option : cmd.get_options()) {
    const FlagInfo* info = Declared(option);
    if (option->count() == 0 || info == nullptr || info->only_with.empty()) continue;
    const CLI::Option* output = cmd.get_option_no_throw(info->only_with);
    bool applies = false;
    if (output != nullptr && output->count() > 0 && !output->results().empty()) {
      const std::string ext = Extension(output->results().back());
      for (const std::string& e : info->only_endings) applies = applies || e == ext;
    }
    if (!applies) {
      Fail(Status::Error(option->get_name(), "only applies with " + info->only_with + " " +
                                                 Either(info->only_endings, "FILE")));
    }
  }
}

CLI::Option* AddCaptionFlag(CLI::App* cmd, const std::string& flag, std::string* caption,
                            const std::string& help) {
  return Declare(
      cmd->add_option_function<std::string>(
          flag,
          [flag, caption](const std::string& text) {
            for (char c : text) {
              const auto byte = static_cast<unsigned char>(c);
              if (byte < 0x20 || byte == 0x7f) {
                Fail(Status::Error(flag, "'" + Echo(text) +
                                             "' holds a control character; must be "
                                             "printable text"));
              }
            }
            if (text.size() > kMaxCaptionBytes) {
              Fail(Status::Error(flag, std::to_string(text.size()) + " bytes; must be at most " +
                                           std::to_string(kMaxCaptionBytes)));
            }
            *caption = text;
          },
          help),
      FlagInfo(FlagKind::kText));
}

std::string FlagsJson(const CommandList& commands) {
  nlohmann::json list = nlohmann::json::array();
  for (const Command& command : commands) {
    std::vector<std::string> words;
    for (const CLI::App* a = command.app; a != nullptr && a->get_parent() != nullptr;
         a = a->get_parent()) {
      words.insert(words.begin(), a->get_name());
    }
    nlohmann::json flags = nlohmann::json::array();
    for (const CLI::Option* option : command.app->get_options()) {
      if (option->get_lnames().empty()) continue;  // positional
      const std::string name = "--" + option->get_lnames().front();
      if (name == "--help" || name == "--help-all") continue;
      const FlagInfo* info = Declared(option);
      const FlagKind kind = info != nullptr                   ? info->kind
                            : option->get_expected_max() == 0 ? FlagKind::kSwitch
                                                              : FlagKind::kText;
      nlohmann::json flag = {{"flag", name},
                             {"kind", KindName(kind)},
                             {"repeatable", option->get_items_expected_max() > 1}};
      if (kind == FlagKind::kNumber) {
        flag["min"] = info->range.min;
        flag["max"] = info->range.max;
        flag["integer"] = info->range.integer;
      }
      if (info != nullptr && !info->extensions.empty()) flag["extensions"] = info->extensions;
      std::vector<std::string> excludes;
      for (const CLI::Option* other :
           info != nullptr ? info->excludes : std::vector<const CLI::Option*>{}) {
        if (!other->get_lnames().empty()) excludes.push_back("--" + other->get_lnames().front());
      }
      if (!excludes.empty()) flag["excludes"] = excludes;
      if (info != nullptr && !info->only_with.empty()) {
        flag["only_with"] = info->only_with;
        flag["only_endings"] = info->only_endings;
      }
      flags.push_back(std::move(flag));
    }
    list.push_back({{"command", words}, {"example", command.example}, {"flags", flags}});
  }
  nlohmann::json studies = nlohmann::json::array();
  for (const Study& study : commands.studies) {
    studies.push_back({{"name", study.name}, {"example", study.example}});
  }
  return nlohmann::json{{"commands", list}, {"studies", studies}}.dump(1);
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
  // Checked before opening too: under node (the WASM build) opening a FIFO blocks whatever the
  // flags, until a writer comes.
  struct stat before {};
  if (::stat(path.c_str(), &before) == 0 && !S_ISREG(before.st_mode)) {
    return Status::Error(field, "cannot read " + name + ": not a regular file");
  }
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

namespace {

// The temporaries of the running process, for the signal handler: fixed slots of fixed size, so
// that SIGINT/SIGTERM/SIGHUP can unlink them with async-signal-safe calls only (no allocation).
constexpr int kTempSlots = 64;
constexpr std::size_t kTempPathBytes = 4096;
char g_temp_paths[kTempSlots][kTempPathBytes];
volatile std::sig_atomic_t g_temp_used[kTempSlots];

extern "C" void RemoveTempsAndDie(int signal_number) {
  for (int i = 0; i < kTempSlots; ++i) {
    if (g_temp_used[i]) ::unlink(g_temp_paths[i]);
  }
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

void InstallTempCleanup() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction action {};
    action.sa_handler = RemoveTempsAndDie;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal_number, &action, nullptr);
  }
}

// A slot holding path until ReleaseTemp (-1 when every slot is taken: the file is then only
// removed by the normal paths, not by a signal).
int HoldTemp(const std::string& path) {
  if (path.size() >= kTempPathBytes) return -1;
  InstallTempCleanup();
  for (int i = 0; i < kTempSlots; ++i) {
    if (g_temp_used[i]) continue;
    std::memcpy(g_temp_paths[i], path.c_str(), path.size() + 1);
    g_temp_used[i] = 1;
    return i;
  }
  return -1;
}
void ReleaseTemp(int slot) {
  if (slot >= 0) g_temp_used[slot] = 0;
}

// Which file path names, whatever the spelling ("a.json", "./a.json", "dir/../a.json", a symlink
// to it): the real path of its folder and its name, or "" when the folder does not resolve.
std::string FileIdentity(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  char* real = ::realpath(Folder(path).c_str(), nullptr);
  if (real == nullptr) return "";
  std::string identity = std::string(real) + "/" + name;
  std::free(real);
  struct stat info {};
  if (::stat(identity.c_str(), &info) == 0) {  // an existing file: its device and inode
    return "inode:" + std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
  }
  return identity;
}

}  // namespace

// A file name's longest length on the file systems Niwa writes to (Linux NAME_MAX; node's under the
// WASM CLI).
constexpr std::size_t kNameMaxBytes = 255;

void PreflightOutputs(const CLI::App& cmd) {
  struct Given {
    std::string field, path, identity;
  };
  std::vector<Given> given;
  // --out first, then the others in the order they were added: the order the commands stage them,
  // so a clash names the same flag as Stage did.
  std::vector<const CLI::Option*> options = cmd.get_options();
  std::stable_partition(options.begin(), options.end(),
                        [](const CLI::Option* o) { return o->get_name() == "--out"; });
  for (const CLI::Option* option : options) {
    const FlagInfo* info = Declared(option);
    if (option->count() == 0 || info == nullptr || info->kind != FlagKind::kOutput) continue;
    if (option->results().empty()) continue;
    const std::string field = option->get_name();
    const std::string& path = option->results().back();
    const Status cannot = Status::Error(field, "cannot write '" + Echo(path) + "'");
    if (path.empty() || path.back() == '/') Fail(cannot);
    const std::size_t slash = path.find_last_of('/');
    const std::size_t name_bytes = slash == std::string::npos ? path.size() : path.size() - slash - 1;
    if (name_bytes > kNameMaxBytes) Fail(cannot);  // the rename at Commit would fail (ENAMETOOLONG)
    struct stat folder {};
    if (::stat(Folder(path).c_str(), &folder) != 0 || !S_ISDIR(folder.st_mode) ||
        ::access(Folder(path).c_str(), W_OK) != 0) {
      Fail(cannot);
    }
    struct stat target {};
    if (::stat(path.c_str(), &target) == 0 && !S_ISREG(target.st_mode)) {
      Fail(Status::Error(field, "cannot write '" + Echo(path) + "': not a regular file"));
    }
    const std::string identity = FileIdentity(path);
    for (const Given& g : given) {
      if (g.path == path || (!identity.empty() && g.identity == identity)) {
        Fail(Status::Error(field, "'" + Echo(path) + "' is the same file as " + g.field + " '" +
                                      Echo(g.path) + "'; give each output its own file"));
      }
    }
    given.push_back({field, path, identity});
  }
}

StagedOutputs::~StagedOutputs() { RemoveTemps(); }

void StagedOutputs::RemoveTemps() {
  for (const Staged& s : staged_) {
    ::unlink(s.temp.c_str());
    ReleaseTemp(s.slot);
    if (!s.backup.empty()) {
      ::unlink(s.backup.c_str());
      ReleaseTemp(s.backup_slot);
    }
  }
  staged_.clear();
}

Status StagedOutputs::Stage(const std::string& field, const std::string& path,
                            const std::string& bytes) {
  const Status cannot = Status::Error(field, "cannot write '" + Echo(path) + "'");
  if (path.empty()) return Status::Error(field, "empty; must be a file name");
  if (path.back() == '/') return cannot;
  const std::string folder = Folder(path);
  const std::string identity = FileIdentity(path);
  for (const Staged& s : staged_) {
    if (s.path == path || (!identity.empty() && s.identity == identity)) {
      return Status::Error(field, "'" + Echo(path) + "' is the same file as " + s.field + " '" +
                                      Echo(s.path) + "'; give each output its own file");
    }
  }
  struct stat target {};
  if (::stat(path.c_str(), &target) == 0 && !S_ISREG(target.st_mode)) {
    return Status::Error(field, "cannot write '" + Echo(path) + "': not a regular file");
  }
  std::string temp;
  int fd = -1;
  for (unsigned attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp = TempName(folder, attempt);
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0 && errno != EEXIST) return cannot;
  }
  if (fd < 0) return cannot;
  const int slot = HoldTemp(temp);  // removed should a signal end the process while writing
  const bool written = WriteAll(fd, bytes) && ::fsync(fd) == 0;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    ::unlink(temp.c_str());
    ReleaseTemp(slot);
    return cannot;
  }
  staged_.push_back({field, path, temp, identity, "", slot, -1});
  return Status::Ok();
}

Status StagedOutputs::Commit() {
  // A file already at a target is kept as a hard link beside it until every rename has succeeded,
  // so that a failed commit puts it back instead of losing it.
  for (Staged& s : staged_) {
    struct stat info {};
    if (::lstat(s.path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) continue;
    for (unsigned attempt = 0; attempt < 100; ++attempt) {
      const std::string backup = TempName(Folder(s.path), attempt);
      if (::link(s.path.c_str(), backup.c_str()) == 0) {
        s.backup = backup;
        s.backup_slot = HoldTemp(backup);
        break;
      }
      if (errno != EEXIST) break;  // no hard links here: the old file cannot be kept
    }
  }
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    if (::rename(staged_[i].temp.c_str(), staged_[i].path.c_str()) != 0) {
      const Status cannot =
          Status::Error(staged_[i].field, "cannot write '" + Echo(staged_[i].path) + "'");
      for (std::size_t k = 0; k < i; ++k) {  // all or none: what was there before comes back
        Staged& done = staged_[k];
        if (!done.backup.empty() && ::rename(done.backup.c_str(), done.path.c_str()) == 0) {
          ReleaseTemp(done.backup_slot);
          done.backup.clear();
        } else {
          ::unlink(done.path.c_str());
        }
        done.temp.clear();  // renamed: no temporary of it left to remove
      }
      RemoveTemps();
      return cannot;
    }
    ReleaseTemp(staged_[i].slot);
    staged_[i].slot = -1;
  }
  // Make the renames durable where the platform allows a folder fsync (best effort).
  for (Staged& s : staged_) {
    if (!s.backup.empty()) {
      ::unlink(s.backup.c_str());
      ReleaseTemp(s.backup_slot);
      s.backup.clear();
    }
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
  budget.memory_limit = "--max-memory";  // the budget's fields under this front end's flags
  budget.seconds_limit = "--max-seconds";
  Check(CheckFlag("--max-seconds", o.max_seconds, kMaxSeconds));
  budget.seconds = o.max_seconds;
  return budget;
}

void ReportTruncated(const std::string& line) {
  if (!line.empty()) std::cerr << "niwa: truncated: " << line << "\n";
}

}  // namespace niwa::cli
