// The one parameter mechanism: ParamSpec rows, a named ParamTable of them with group titles, and a
// ParamSet of values bound to one table. Each study declares its own table
// (core/<study>/<study>_params.cpp; the tree's is core/tree/tree_params.cpp).
// Does not: hold any study's rows, read JSON or URL text (params/param_json, io/hash_codec), or
// print anything.
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "base/status.h"
#include "params/param_text.h"

namespace niwa {

// What an edit of a row invalidates, earliest first: a page reruns that stage and the ones after it
// (grow, then mesh, then sway, then view), as mapgen4 reruns its phases.
enum class Stage : uint8_t {
  kGrow,  // the model run itself (regrow)
  kMesh,  // only the geometry built from the model's result
  kSway,  // only the animation of the built geometry
  kView,  // only how it is drawn (no new geometry)
};
const char* StageName(Stage stage);  // "grow", "mesh", "sway", "view"

struct ParamSpec {
  int id;              // row index; equal to the study's enum value (checked by ParamTable)
  const char* key;     // stable name used in JSON, URL hash and CLI --set
  const char* symbol;  // the paper's symbol, e.g. "α_t"
  const char* unit;    // "" when dimensionless
  double default_value;
  double min_value;
  double max_value;
  bool integer;       // value must be a whole number
  const char* group;  // one of the table's group keys
  Stage stage;        // what an edit of this row invalidates
  const char* help;
};

// A panel section: the group key of the rows and its title.
struct ParamGroup {
  const char* key;    // "hormone"
  const char* title;  // "Hormone"
};

// One study's table: its name ("tree"), rows in id order and groups in panel order.
class ParamTable {
 public:
  // Aborts (a programming error, caught by every test) when a row's id is not its index, a key
  // repeats, a default is out of range or a row names a group the table does not have.
  ParamTable(std::string name, std::vector<ParamSpec> rows, std::vector<ParamGroup> groups);

  const std::string& name() const { return name_; }
  std::size_t size() const { return rows_.size(); }
  const ParamSpec& row(std::size_t index) const { return rows_[index]; }
  const ParamSpec& operator[](std::size_t index) const { return rows_[index]; }
  std::vector<ParamSpec>::const_iterator begin() const { return rows_.begin(); }
  std::vector<ParamSpec>::const_iterator end() const { return rows_.end(); }
  const std::vector<ParamGroup>& groups() const { return groups_; }
  // Index of the row with this key; nullopt when unknown.
  std::optional<std::size_t> Find(std::string_view key) const;
  // The title of a group key ("" when unknown).
  const char* GroupTitle(std::string_view group) const;

 private:
  std::string name_;
  std::vector<ParamSpec> rows_;
  std::vector<ParamGroup> groups_;
};

// "alpha_t must be a number in [0, 1]" style description of a row's allowed range.
std::string RangeText(const ParamSpec& spec);

// A full set of values of one table, indexed by row. A study's enum reads it typed:
// params.Get(TreeParam::kGamma), checked (in debug builds) to be the enum of the bound table.
// A study's enum E declares `const ParamTable& TableOf(E)` beside it (found by argument lookup).
class ParamSet {
 public:
  explicit ParamSet(const ParamTable& table);  // every value at its table default
  const ParamTable& table() const { return *table_; }
  std::size_t size() const { return values_.size(); }

  double Get(std::size_t row) const { return values_[row]; }
  template <typename E, typename = std::enable_if_t<std::is_enum_v<E>>>
  double Get(E id) const {
    assert(&TableOf(id) == table_);
    return values_[static_cast<std::size_t>(id)];
  }
  template <typename E, typename = std::enable_if_t<std::is_enum_v<E>>>
  int GetInt(E id) const {
    return static_cast<int>(Get(id));
  }
  template <typename E, typename = std::enable_if_t<std::is_enum_v<E>>>
  bool GetBool(E id) const {
    return Get(id) != 0.0;
  }

  // Sets a value after checking it against its row; the error names the key and the range.
  Status Set(std::size_t row, double value);
  template <typename E, typename = std::enable_if_t<std::is_enum_v<E>>>
  Status Set(E id, double value) {
    assert(&TableOf(id) == table_);
    return Set(static_cast<std::size_t>(id), value);
  }
  // Parses text (from --set key=value, a URL or JSON) and sets it.
  Status SetFromText(std::string_view key, std::string_view text);
  // "key=value" as given to --set.
  Status SetFromAssignment(std::string_view assignment);

  bool operator==(const ParamSet& other) const {
    return table_ == other.table_ && values_ == other.values_;
  }
  bool operator!=(const ParamSet& other) const { return !(*this == other); }

 private:
  const ParamTable* table_;
  std::vector<double> values_;
};

// A ParamSet whose default constructor binds it to the table of the study enum E: what a study
// stores (e.g. TreeParams = StudyParams<TreeParam>).
template <typename E>
class StudyParams : public ParamSet {
 public:
  StudyParams() : ParamSet(TableOf(E{})) {}
  explicit StudyParams(const ParamSet& values) : ParamSet(values) {
    assert(&values.table() == &TableOf(E{}));
  }
};

}  // namespace niwa
