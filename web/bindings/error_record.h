// The one shape an error crosses the JS boundary in: {ok: false, field, message} from a core
// Status (field: the state key it names, "" when none; message: its one line, Status::Line()),
// after Draco's web decoder Status (ok(), error_msg()). Pages show `message` and put it beside
// `field`; no page parses error text. Also JsonText, the bindings' one JSON writer. Does not:
// rename fields (a composed page prefixes them in JS).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "base/status.h"

namespace niwa {

// JSON text for the worker: bytes that are not UTF-8 (echoed from hostile input in errors and
// notices) are replaced, never thrown on. The one writer of the bindings' JSON answers.
template <typename J>
std::string JsonText(const J& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

inline nlohmann::ordered_json ErrorRecord(const Status& status) {
  nlohmann::ordered_json j;
  j["ok"] = status.ok();
  if (!status.ok()) {
    j["field"] = status.field();
    j["message"] = status.Line();
  }
  return j;
}

// A record as JSON text (bytes that are not UTF-8, echoed from hostile input, replaced).
inline std::string ErrorRecordJson(const Status& status) { return JsonText(ErrorRecord(status)); }

// What a session method that can fail returns: "" when it worked, else the record as JSON text.
inline std::string ErrorText(const Status& status) {
  return status.ok() ? std::string() : ErrorRecordJson(status);
}

}  // namespace niwa
