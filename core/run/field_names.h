// How a front end names a core error's field: one table per study and front end maps a state
// field ("steps", "seed_points", "max_memory") to the front end's word ("--steps", "Steps",
// "ivy.steps"). Does not: know any study's fields (the tables live in the front ends), or change
// the message.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "base/status.h"

namespace niwa::run {

using FieldNames = std::vector<std::pair<std::string, std::string>>;  // state field -> front end's

// The status with its field renamed through `names` (unchanged when not listed), then prefixed
// ("ivy." on a composed page) when `prefix` is not empty.
inline Status RenameField(const Status& status, const FieldNames& names,
                          const std::string& prefix = "") {
  if (status.ok()) return status;
  std::string field = status.field();
  for (const auto& [from, to] : names) {
    if (from == field) {
      field = to;
      break;
    }
  }
  if (!prefix.empty() && !field.empty()) field = prefix + field;
  return Status::Error(field, status.message());
}

}  // namespace niwa::run
