// The JSON input guard (see json_guard.h): a byte scan for depth, then nlohmann's SAX parser for
// repeated keys, keeping one key set per open object.
#include "params/json_guard.h"

#include <cstddef>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "base/echo.h"

namespace niwa {
namespace {

using nlohmann::json;

// Receives nlohmann's SAX events and stops at the first key an open object already holds.
class DuplicateKeys {
 public:
  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(json::number_integer_t) { return true; }
  bool number_unsigned(json::number_unsigned_t) { return true; }
  bool number_float(json::number_float_t, const json::string_t&) { return true; }
  bool string(json::string_t&) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool start_object(std::size_t) {
    open_.emplace_back();
    is_object_.push_back(true);
    return true;
  }
  bool key(json::string_t& key) {
    if (open_.empty() || !is_object_.back()) return true;
    if (open_.back().insert(key).second) return true;
    status_ = Status::Error(Echo(key), "given twice in one object");
    return false;
  }
  bool end_object() { return Close(); }
  bool start_array(std::size_t) {
    open_.emplace_back();
    is_object_.push_back(false);
    return true;
  }
  bool end_array() { return Close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) {
    return false;  // malformed: the caller's own parse says so
  }
  const Status& status() const { return status_; }

 private:
  bool Close() {
    if (!open_.empty()) {
      open_.pop_back();
      is_object_.pop_back();
    }
    return true;
  }
  std::vector<std::set<std::string>> open_;  // one key set per open container (arrays: empty)
  std::vector<bool> is_object_;
  Status status_;
};

}  // namespace

Status CheckJsonDepth(std::string_view text, std::string_view field) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;  // the escaped character, whatever it is, does not end the string
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        return Status::Error(std::string(field),
                             "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return Status::Ok();
}

Status CheckJsonKeys(std::string_view text, std::string_view field) {
  NIWA_RETURN_IF_ERROR(CheckJsonDepth(text, field));
  DuplicateKeys keys;
  (void)json::sax_parse(text.begin(), text.end(), &keys);  // false on a duplicate or malformed
  return keys.status();
}

}  // namespace niwa
