// Tests of the echo and markup rules (base/echo.h, base/markup_escape.h): control characters and
// ANSI escapes never reach a message raw, echoed values are short, and escaped text is XML-safe.
#include "base/echo.h"

#include <gtest/gtest.h>

#include <string>

#include "base/markup_escape.h"
#include "base/status.h"

namespace niwa {
namespace {

TEST(Echo, EscapesControlAndAnsiAndCuts) {
  EXPECT_EQ(Echo("plain"), "plain");
  EXPECT_EQ(Echo("a\x1b[31mred\x07\n"), "a\\x1b[31mred\\x07\\x0a");
  EXPECT_EQ(Echo("caf\xc3\xa9"), "caf\\xc3\\xa9");  // non-ASCII bytes too (C1 controls are UTF-8)
  EXPECT_EQ(Echo(std::string(200, 'x')), std::string(kMaxEchoLength, 'x') + "...");
  // The cut never splits an escape.
  std::string cut = Echo(std::string(58, 'x') + "\x1b\x1b");
  EXPECT_EQ(cut, std::string(58, 'x') + "...");
}

TEST(Echo, StatusLineIsOneEscapedShortLine) {
  Status s = Status::Error("--out", "cannot write 'a\nb\x1b[2J'" + std::string(5000, 'z'));
  std::string line = s.Line();
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_EQ(line.find('\x1b'), std::string::npos);
  EXPECT_LE(line.size(), kMaxMessageLength + 3);
  EXPECT_EQ(line.rfind("--out: cannot write 'a\\x0ab\\x1b[2J'", 0), 0u);
}

// The whole line keeps the core's own UTF-8 ("§3.1") but not C0/C1 control characters.
TEST(Echo, LineKeepsUtf8ButNotControls) {
  EXPECT_EQ(Status::Error("t1",
                          "must be in [0, t2) (\xc2\xa7"
                          "3.1)")
                .Line(),
            "t1: must be in [0, t2) (\xc2\xa7"
            "3.1)");
  EXPECT_EQ(EscapeLine("a\x1b\xc2\x9b"
                       "b",
                       100),
            "a\\x1b\\xc2\\x9bb");
}

TEST(MarkupEscape, EntitiesControlAndBadUtf8) {
  EXPECT_EQ(XmlEscape("P<1 & \"q\" 'r' >"), "P&lt;1 &amp; &quot;q&quot; &apos;r&apos; &gt;");
  EXPECT_EQ(XmlEscape("a\x01\x1b[0m\x7f"
                      "b"),
            "a[0mb");
  EXPECT_EQ(XmlEscape("caf\xc3\xa9 \xe6\x9c\xa8"), "caf\xc3\xa9 \xe6\x9c\xa8");  // kept
  EXPECT_EQ(XmlEscape("\xff\xc3(\xed\xa0\x80\xc2\x85"), "?\?(???");  // bad, surrogate, C1
  EXPECT_EQ(XmlEscape("\xef\xbf\xbf"), "???");                      // U+FFFF
}

}  // namespace
}  // namespace niwa
