// Budgets of one job (a CLI command, a page's grow or export): the memory and time a job may use,
// and the estimate a study makes from its inputs before the work starts. Does not: measure memory
// or wall-clock time (estimates are counts times calibrated constants, so the native and WASM
// builds refuse at the same point), know any study, or print.
#pragma once

#include <cstdint>
#include <string>

#include "base/status.h"

namespace niwa {

// What a job may use, and the names of the settings that change it (in the error lines): the
// state fields "max_memory" and "max_seconds" unless the front end names them in its own words
// ("--max-memory" on the CLI: cli::ResolveBudget; "page memory budget" on the page).
struct Budget {
  uint64_t memory_bytes = uint64_t{2} << 30;  // 2 GB: the CLI's default
  double seconds = 60;                        // estimated seconds of work (not wall clock)
  std::string memory_limit = "max_memory";
  std::string seconds_limit = "max_seconds";
};

// What a piece of work is estimated to need (upper bounds, by calibrated constants).
struct Estimate {
  double memory_bytes = 0;
  double seconds = 0;
  std::string what;  // "writing the .glb (1,234 internodes, 56 leaves)"
};

inline Estimate operator+(const Estimate& a, const Estimate& b) {
  return {a.memory_bytes + b.memory_bytes, a.seconds + b.seconds,
          a.what.empty() ? b.what : (b.what.empty() ? a.what : a.what + " and " + b.what)};
}

// "2 GB", "512 MB", "12 kB", "100 B" (binary multiples, at most one decimal).
std::string FormatBytes(double bytes);
// "60 s", "1.5 s".
std::string FormatSeconds(double seconds);
// "194,948": a count rounded to a whole number, with thousands separators (the budget lines).
std::string FormatCount(double n);
// "4G", "4GB", "512M", "64k", "1000000": bytes (K, M, G, T are powers of 1024); false for anything
// else (signs, decimals, spaces, more than 15 digits) or above 2^62 bytes.
bool ParseBytes(const std::string& text, uint64_t* bytes);

// Ok when the estimate fits, else one line naming the limit:
// {"--max-memory", "<what> needs about 3.1 GB, more than the 2 GB allowed; <change>"}.
// `change` says what to lower ("lower --years or --duration"); the limit's own raise is added.
Status CheckEstimate(const Estimate& estimate, const Budget& budget, const std::string& change);

// " (or raise --max-memory)" when the limit is a flag the user can raise, else "" (the page's).
std::string RaiseHint(const std::string& limit);

// The line of a job stopped early at a limit: "<limit>: stopped <where>: <why>; <change>".
std::string TruncatedLine(const std::string& limit, const std::string& where,
                          const std::string& why, const std::string& change);

}  // namespace niwa
