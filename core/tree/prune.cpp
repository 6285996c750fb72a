// Prune text and the check that a prune cut something.
#include "tree/prune.h"

#include <cctype>
#include <cmath>
#include <optional>

#include "io/hash_codec.h"
#include "params/param_text.h"

namespace niwa {
namespace {

std::optional<int> WholeIn(std::string_view text, double min, double max) {
  std::optional<double> value = ParseNumber(text);
  if (!value || *value < min || *value > max || std::floor(*value) != *value) return std::nullopt;
  return static_cast<int>(*value);
}

}  // namespace

Result<Prune> ParsePrune(std::string_view text) {
  const Status bad = Status::Error("prune", "'" + Printable(text) +
                                                "' must be YEAR:bID or YEAR:sinceY with YEAR in "
                                                "[1, " +
                                                std::to_string(kMaxYears) + "]");
  std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) return bad;
  std::optional<int> year = WholeIn(text.substr(0, colon), 1, kMaxYears);
  std::string_view selector = text.substr(colon + 1);
  if (!year) return bad;
  Prune prune;
  prune.year = *year;
  if (selector.substr(0, 5) == "since") {
    std::optional<int> since = WholeIn(selector.substr(5), 1, kMaxYears);
    if (!since) return bad;
    prune.since_year = *since;
  } else if (!selector.empty() &&
             (selector[0] == 'b' || std::isdigit(static_cast<unsigned char>(selector[0])))) {
    std::optional<int> id = WholeIn(selector[0] == 'b' ? selector.substr(1) : selector, 0, 1e8);
    if (!id) return bad;
    prune.branch = *id;
  } else {
    return bad;
  }
  return prune;
}

std::string FormatPrune(const Prune& prune) {
  return std::to_string(prune.year) + ":" +
         (prune.since_year >= 0 ? "since" + std::to_string(prune.since_year)
                                : "b" + std::to_string(prune.branch));
}

Status IdlePruneReason(const Prune& prune, const Tree& grown) {
  const std::string year = std::to_string(prune.year);
  const std::string field = FormatPrune(prune);
  if (prune.year > grown.years) {
    return Status::Error(field, "year " + year + " is after the last year grown (" +
                                    std::to_string(grown.years) + ")");
  }
  if (prune.branch >= 0) {
    // The branches grown by that year are the first ones: ids follow the order of growth.
    std::size_t count = 0;
    while (count < grown.branches.size() && grown.branches[count].year <= prune.year) ++count;
    if (static_cast<std::size_t>(prune.branch) >= count) {
      return Status::Error(
          field, "the tree had no branch b" + std::to_string(prune.branch) + " by year " + year +
                     (count > 0 ? " (ids 0 to " + std::to_string(count - 1) + ")" : ""));
    }
  }
  if (prune.since_year > prune.year) {
    return Status::Error(field, "nothing had grown since year " + std::to_string(prune.since_year) +
                                    " by year " + year);
  }
  return Status::Ok();
}

}  // namespace niwa
