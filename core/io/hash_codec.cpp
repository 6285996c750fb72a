// Generic hash codec for shared links; hostile input is clamped or dropped with a notice.
#include "io/hash_codec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>

#include "base/echo.h"

namespace niwa {
namespace {

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return c - 'A' + 10;
}

}  // namespace

std::string PercentDecode(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '+') {
      out += ' ';
    } else if (c == '%' && i + 2 < text.size() &&
               std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
               std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(HexDigit(text[i + 1]) * 16 + HexDigit(text[i + 2]));
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

std::string Printable(std::string_view text) { return EchoNoMarkup(text); }

ShareLink SplitShareLink(std::string_view text) {
  ShareLink link;
  const std::size_t hash_at = text.find('#');
  const std::string_view before_hash = text.substr(0, hash_at);
  const std::size_t scheme_end = before_hash.find("://");
  if (scheme_end == std::string_view::npos) {  // a bare hash ('/' and "://" never occur in one)
    link.hash = std::string(text);
    return link;
  }
  link.is_link = true;
  std::string scheme(before_hash.substr(0, scheme_end));
  std::transform(scheme.begin(), scheme.end(), scheme.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (scheme != "http" && scheme != "https") {
    link.error = "'" + Printable(text) + "' must be an http(s):// link or a bare hash";
    return link;
  }
  // The path: after the authority, up to a query; its last segment names the page.
  std::string_view rest = before_hash.substr(scheme_end + 3);
  rest = rest.substr(0, rest.find('?'));
  const std::size_t path_at = rest.find('/');
  const std::string_view path =
      path_at == std::string_view::npos ? std::string_view() : rest.substr(path_at);
  link.page = std::string(path.substr(path.empty() ? 0 : path.rfind('/') + 1));
  if (hash_at != std::string_view::npos) link.hash = std::string(text.substr(hash_at + 1));
  return link;
}

HashPairs SplitHash(std::string_view hash, std::vector<std::string>* notices,
                    const std::vector<std::string_view>& repeatable) {
  HashPairs pairs;
  if (hash.size() > kMaxHashLength) {
    if (notices != nullptr) {
      notices->push_back("hash: " + std::to_string(hash.size()) + " characters; the limit is " +
                         std::to_string(kMaxHashLength) + ", nothing was read");
    }
    return pairs;
  }
  std::string_view text = hash;
  if (!text.empty() && text[0] == '#') text.remove_prefix(1);
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('&', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view item = text.substr(start, end - start);
    if (!item.empty()) {
      std::size_t eq = item.find('=');
      std::string key = PercentDecode(item.substr(0, eq));
      std::string value = eq == std::string_view::npos ? "" : PercentDecode(item.substr(eq + 1));
      pairs.emplace_back(std::move(key), std::move(value));
    }
    start = end + 1;
  }
  // A key given twice (other than those in `repeatable`) makes the link ambiguous: refused whole,
  // as the CLI refuses it, each such key named once, in order of first appearance.
  std::map<std::string, std::size_t> counts;
  for (const auto& pair : pairs) ++counts[pair.first];
  std::vector<std::string> repeated;
  for (const auto& pair : pairs) {
    auto it = counts.find(pair.first);
    if (it->second > 1 &&
        std::find(repeatable.begin(), repeatable.end(), pair.first) == repeatable.end()) {
      repeated.push_back(Printable(pair.first) + ": given " + std::to_string(it->second) +
                         " times; must be given once, nothing was read");
    }
    it->second = 0;  // named once
  }
  if (!repeated.empty()) {
    if (notices != nullptr) notices->insert(notices->end(), repeated.begin(), repeated.end());
    pairs.clear();
  }
  return pairs;
}

std::string PercentEncode(std::string_view text) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '_' || c == '~' || c == ':' || c == ',' || c == '-';
    if (plain) {
      out += c;
    } else {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

bool ApplyHashParam(std::string_view key, std::string_view value, std::string_view prefix,
                    ParamSet* params, std::vector<std::string>* notices) {
  if (key.substr(0, prefix.size()) != prefix) return false;
  std::optional<std::size_t> row = params->table().Find(key.substr(prefix.size()));
  if (!row) return false;
  const ParamSpec& spec = params->table().row(*row);
  const std::string name(key);
  std::optional<double> number = ParseNumber(value);
  if (!number) {
    notices->push_back(name + ": '" + Printable(value) + "' dropped, must be " + RangeText(spec));
    return true;
  }
  double clamped = std::min(spec.max_value, std::max(spec.min_value, *number));
  if (spec.integer) clamped = std::round(clamped);
  if (clamped != *number) {
    notices->push_back(name + ": clamped to " + FormatNumber(clamped) + ", must be " +
                       RangeText(spec));
  }
  // Clamped into the row's range (and whole when integer), so the check passes.
  if (!params->Set(*row, clamped).ok()) notices->push_back(name + ": dropped");
  return true;
}

std::string EncodeChangedParams(const ParamSet& params, const ParamSet& base,
                                std::string_view prefix) {
  std::string out;
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (params.Get(i) != base.Get(i)) {
      out +=
          "&" + std::string(prefix) + params.table().row(i).key + "=" + FormatNumber(params.Get(i));
    }
  }
  return out;
}

}  // namespace niwa
