// The one error type of the core: Status {field, message} and Result<T>, after
// draco::Status/StatusOr. Does not: print, throw, or know about exit codes; the CLI maps a failed
// Status to exit 2 and the web bindings to an {error} reply. The one-line text is rendered in one
// place: Status::Line().
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "base/echo.h"

namespace niwa {

class [[nodiscard]] Status {
 public:
  Status() = default;  // ok
  static Status Ok() { return Status(); }
  // field: what the user gave ("--years", "alpha_t", "mesh.glb"); message: what is wrong and what
  // is allowed ("12.5 is out of range; must be a whole number in [0, 100]").
  static Status Error(std::string field, std::string message) {
    Status s;
    s.ok_ = false;
    s.field_ = std::move(field);
    s.message_ = std::move(message);
    return s;
  }
  bool ok() const { return ok_; }
  const std::string& field() const { return field_; }
  const std::string& message() const { return message_; }
  // The one-line error text: "field: message" (or the message alone when there is no field),
  // with control characters escaped and cut at kMaxMessageLength (base/echo.h EscapeLine); values
  // inside the message are cut shorter by their makers through Echo().
  std::string Line() const {
    if (ok_) return "";
    return EscapeLine(field_.empty() ? message_ : field_ + ": " + message_, kMaxMessageLength);
  }
  // The same error under an outer field, e.g. "--params: alpha_t: ...".
  Status Within(const std::string& outer) const {
    if (ok_ || outer.empty()) return *this;
    return Error(outer, field_.empty() ? message_ : field_ + ": " + message_);
  }

 private:
  bool ok_ = true;
  std::string field_;
  std::string message_;
};

// A value or the Status saying why there is none.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}         // NOLINT: implicit, as StatusOr
  Result(Status status) : status_(std::move(status)) {  // NOLINT
    if (status_.ok()) status_ = Status::Error("", "internal: Result made from an ok Status");
  }
  bool ok() const { return value_.has_value(); }
  const Status& status() const { return status_; }
  const T& value() const& { return *value_; }
  T& value() & { return *value_; }
  T&& value() && { return std::move(*value_); }
  const T& operator*() const& { return *value_; }
  T& operator*() & { return *value_; }
  const T* operator->() const { return &*value_; }
  T* operator->() { return &*value_; }

 private:
  std::optional<T> value_;
  Status status_;
};

}  // namespace niwa

// Returns the Status of expr from the enclosing function when it failed.
#define NIWA_RETURN_IF_ERROR(expr)               \
  do {                                           \
    ::niwa::Status niwa_status_ = (expr);        \
    if (!niwa_status_.ok()) return niwa_status_; \
  } while (0)
