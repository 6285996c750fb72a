// Echo: the one way a user's text is shown back in a message (CLI stderr, page notice, Status
// line). Control characters, ANSI escapes and non-ASCII bytes become "\xNN" and the text is cut
// short, so a hostile value can neither drive a terminal nor flood a log. Does not: escape for XML,
// JSON or HTML (core/base/markup_escape.h does), or know where the message goes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace niwa {

// Longest echoed value, in output characters, before "..." is appended.
constexpr std::size_t kMaxEchoLength = 60;
// Longest whole message line (Status::Line()), in output characters, before "...".
constexpr std::size_t kMaxMessageLength = 400;

// Text with every byte outside printable ASCII (0x20..0x7e) written as "\xNN" (ESC is "\x1b"), cut
// after max_length output characters (never inside an escape) with "..." appended. With markup,
// the characters < > & " ' are written as "\xNN" too (notices that a page shows).
inline std::string EscapeControl(std::string_view text, std::size_t max_length,
                                 bool markup = false) {
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const bool is_markup = byte == '<' || byte == '>' || byte == '&' || byte == '"' || byte == '\'';
    const bool printable = byte >= 0x20 && byte < 0x7f && !(markup && is_markup);
    const std::size_t width = printable ? 1 : 4;
    if (out.size() + width > max_length) return out + "...";
    if (printable) {
      out += static_cast<char>(byte);
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

// A whole message line (Status::Line(), the CLI's last line of defence): C0 control characters,
// DEL and the C1 controls (UTF-8 C2 80..C2 9F) as "\xNN", other UTF-8 kept (the core's own text
// says "§3.1"), cut after max_length characters with "...". Values inside were cut by Echo().
inline std::string EscapeLine(std::string_view text, std::size_t max_length) {
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const bool c1 = byte == 0xc2 && i + 1 < text.size() &&
                    static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(text[i + 1]) <= 0x9f;
    const bool control = byte < 0x20 || byte == 0x7f;
    const std::size_t width = c1 ? 8 : control ? 4 : 1;
    if (out.size() + width > max_length) return out + "...";
    if (!control && !c1) {
      out += static_cast<char>(byte);
      continue;
    }
    for (std::size_t k = 0; k < (c1 ? 2u : 1u); ++k) {
      const auto b = static_cast<unsigned char>(text[i + k]);
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 15];
    }
    if (c1) ++i;
  }
  return out;
}

// A user's value as it may appear in a message: escaped and at most kMaxEchoLength characters.
inline std::string Echo(std::string_view text) { return EscapeControl(text, kMaxEchoLength); }
// The same for a notice a page may show: markup characters escaped as well.
inline std::string EchoNoMarkup(std::string_view text) {
  return EscapeControl(text, kMaxEchoLength, true);
}

}  // namespace niwa
