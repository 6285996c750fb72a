// XML/SVG/HTML text escaping: the one function that puts user text (an SVG --caption) into markup.
// Does not: echo values into messages (base/echo.h does) or write JSON (nlohmann escapes JSON).
#pragma once

#include <string>
#include <string_view>

namespace niwa {

// Text safe inside an XML element or a quoted attribute: & < > " ' as entities, control characters
// other than tab and newline removed (XML 1.0 cannot carry them), and each byte that is not part of
// well-formed UTF-8 replaced by '?', so every XML parser accepts the result.
inline std::string XmlEscape(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if (c == '&')
        out += "&amp;";
      else if (c == '<')
        out += "&lt;";
      else if (c == '>')
        out += "&gt;";
      else if (c == '"')
        out += "&quot;";
      else if (c == '\'')
        out += "&apos;";
      else if (c >= 0x20 && c != 0x7f)
        out += static_cast<char>(c);
      else if (c == '\t' || c == '\n')
        out += static_cast<char>(c);
      ++i;
      continue;
    }
    // Well-formed UTF-8 (RFC 3629: no overlongs, no surrogates, at most U+10FFFF), else '?'.
    std::size_t length = c >= 0xc2 && c <= 0xdf   ? 2
                         : c >= 0xe0 && c <= 0xef ? 3
                         : c >= 0xf0 && c <= 0xf4 ? 4
                                                  : 0;
    bool ok = length > 0 && i + length <= text.size();
    for (std::size_t k = 1; ok && k < length; ++k) {
      ok = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    }
    if (ok && length >= 3) {
      const auto c1 = static_cast<unsigned char>(text[i + 1]);
      if (c == 0xe0 && c1 < 0xa0) ok = false;   // overlong
      if (c == 0xed && c1 >= 0xa0) ok = false;  // surrogate
      if (c == 0xf0 && c1 < 0x90) ok = false;   // overlong
      if (c == 0xf4 && c1 >= 0x90) ok = false;  // past U+10FFFF
      if (c == 0xef && c1 == 0xbf && length == 3 &&
          static_cast<unsigned char>(text[i + 2]) >= 0xbe) {
        ok = false;  // U+FFFE, U+FFFF are not XML characters
      }
    }
    if (ok && length == 2 && c == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0) {
      i += 2;  // C1 control characters (U+0080..U+009F): removed like C0 ones
      continue;
    }
    if (ok) {
      out.append(text.substr(i, length));
      i += length;
    } else {
      out += '?';
      ++i;
    }
  }
  return out;
}

}  // namespace niwa
