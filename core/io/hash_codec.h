// The generic share-link hash codec: "k=v&k=v" split with percent-decoding, printable notices, and
// clamp-with-notice of table rows, for any parameter table and an optional key prefix ("ivy." on a
// composed page). Does not: know any study's state fields (preset, seed, prunes, camera): those
// are read by core/<study>/<study>_state over these functions.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "params/param_table.h"

namespace niwa {

using HashPairs = std::vector<std::pair<std::string, std::string>>;

// Longest hash read, in characters (the '#' included). A longer hash is refused whole, never cut.
constexpr std::size_t kMaxHashLength = 16384;

// Splits "#k=v&k2=v2" (the '#' optional) into decoded (key, value) pairs in order; empty items are
// skipped, a missing '=' gives an empty value. '+' is a space and %XX a byte. A hash longer than
// kMaxHashLength gives no pairs and the notice "hash: N characters; the limit is 16384, nothing
// was read"; a key given more than once (other than those in `repeatable`) gives no pairs either
// and the notice "KEY: given N times; must be given once, nothing was read" (the link is refused
// whole, by the CLI and every page alike).
HashPairs SplitHash(std::string_view hash, std::vector<std::string>* notices = nullptr,
                    const std::vector<std::string_view>& repeatable = {});
// A --url value split into the page it names and its hash. A whole link ("http://host/#k=v",
// "https://host/dir/index.html?q#k=v": an http or https scheme) gives is_link, the last segment of
// its path ("" for a folder, e.g. "index.html") and the text after its first '#' ("" when it has
// none); any other text is a bare hash (is_link false, page "", hash the text). `error` is set for
// a link of another scheme ("ftp://..."): "must be an http(s):// link or a bare hash".
struct ShareLink {
  bool is_link = false;
  std::string page;
  std::string hash;
  std::string error;
};
ShareLink SplitShareLink(std::string_view text);
// Percent-encodes a value or key for a hash: every byte outside [A-Za-z0-9._~:,-] as %XX, so a
// decoded value written back cannot add keys ('&', '=', '#', '%' are encoded).
std::string PercentEncode(std::string_view text);
std::string PercentDecode(std::string_view text);
// Text safe to show in a notice: base/echo.h's EchoNoMarkup (control, non-ASCII and markup bytes as
// "\xNN", cut at 60 characters + "..."); the page shows notices as text, the CLI as one line.
std::string Printable(std::string_view text);

// If key is prefix + a row key of params' table, sets that row from the text, clamped into its
// range (and rounded when whole numbers only) with a notice, or dropped with a notice when the
// text is not a number; returns true. False when the key is not a row of the table.
bool ApplyHashParam(std::string_view key, std::string_view value, std::string_view prefix,
                    ParamSet* params, std::vector<std::string>* notices);
// "&k=v" for every row whose value differs from base (same table), in row order, keys prefixed.
std::string EncodeChangedParams(const ParamSet& params, const ParamSet& base,
                                std::string_view prefix = "");

}  // namespace niwa
