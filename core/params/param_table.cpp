// The parameter mechanism: table checks, lookup and the checked setters of ParamSet.
#include "params/param_table.h"

#include <cstdio>
#include <cstdlib>
#include <set>

namespace niwa {
namespace {

[[noreturn]] void BadTable(const std::string& table, const char* key, const char* what) {
  std::fprintf(stderr, "niwa: parameter table %s, row %s: %s\n", table.c_str(), key, what);
  std::abort();  // a programming error in a table's rows, caught by every test binary
}

}  // namespace

const char* StageName(Stage stage) {
  switch (stage) {
    case Stage::kGrow:
      return "grow";
    case Stage::kMesh:
      return "mesh";
    case Stage::kSway:
      return "sway";
    case Stage::kView:
      return "view";
  }
  return "grow";
}

ParamTable::ParamTable(std::string name, std::vector<ParamSpec> rows,
                       std::vector<ParamGroup> groups)
    : name_(std::move(name)), rows_(std::move(rows)), groups_(std::move(groups)) {
  std::set<std::string_view> keys;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const ParamSpec& s = rows_[i];
    if (static_cast<std::size_t>(s.id) != i) BadTable(name_, s.key, "out of id order");
    if (!keys.insert(s.key).second) BadTable(name_, s.key, "key repeats");
    if (!CheckValue(s.key, s.default_value, s.min_value, s.max_value, s.integer).ok()) {
      BadTable(name_, s.key, "default out of range");
    }
    if (*GroupTitle(s.group) == '\0') BadTable(name_, s.key, "group not in the table's groups");
  }
}

std::optional<std::size_t> ParamTable::Find(std::string_view key) const {
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (key == rows_[i].key) return i;
  }
  return std::nullopt;
}

const char* ParamTable::GroupTitle(std::string_view group) const {
  for (const ParamGroup& g : groups_) {
    if (group == g.key) return g.title;
  }
  return "";
}

std::string RangeText(const ParamSpec& spec) {
  return RangeText(spec.min_value, spec.max_value, spec.integer);
}

ParamSet::ParamSet(const ParamTable& table) : table_(&table) {
  values_.reserve(table.size());
  for (const ParamSpec& spec : table) values_.push_back(spec.default_value);
}

Status ParamSet::Set(std::size_t row, double value) {
  const ParamSpec& spec = table_->row(row);
  Status status = CheckValue(spec.key, value, spec.min_value, spec.max_value, spec.integer);
  if (status.ok()) values_[row] = value;
  return status;
}

Status ParamSet::SetFromText(std::string_view key, std::string_view text) {
  std::optional<std::size_t> row = table_->Find(key);
  if (!row) {
    return Status::Error("", "unknown parameter '" + std::string(key.substr(0, 64)) + "'");
  }
  std::optional<double> value = ParseNumber(text);
  if (!value) {
    return Status::Error(std::string(key), "'" + std::string(text.substr(0, 32)) + "' is not " +
                                               RangeText(table_->row(*row)));
  }
  return Set(*row, *value);
}

Status ParamSet::SetFromAssignment(std::string_view assignment) {
  std::size_t eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    return Status::Error("", "'" + std::string(assignment) + "' must be key=value");
  }
  return SetFromText(assignment.substr(0, eq), assignment.substr(eq + 1));
}

}  // namespace niwa
