// The one guard every reader of an untrusted JSON text runs before parsing it: nesting depth by a
// byte scan (no recursion, so no input can overflow a stack) and keys given twice in one object at
// any depth (nlohmann's iterative SAX parser). Does not: parse into a document, check types or
// know any file's fields (each reader checks its own with find()/is_*).
#pragma once

#include <string>
#include <string_view>

#include "base/status.h"

namespace niwa {

// Deepest nesting of arrays and objects in any JSON input (params, state, contour, glTF and its
// extras): the one limit, stated here.
inline constexpr int kMaxJsonDepth = 32;

// Ok when text nests arrays and objects at most kMaxJsonDepth deep and no object names a key twice;
// else {field, "nested deeper than 32 levels"} (checked first, on the bytes, before any parser sees
// them) or {"KEY", "given twice in one object"}. Malformed JSON is left to the caller's parse (ok
// here, past the depth check).
Status CheckJsonKeys(std::string_view text, std::string_view field);

// The depth check alone (a byte scan outside strings), for callers that parse with another parser.
Status CheckJsonDepth(std::string_view text, std::string_view field);

}  // namespace niwa
