// Test helpers shared by the CLI tests: a failed run is exit code 2, nothing on stdout and exactly
// one line on stderr that contains the expected text; a failed Status names its field.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "base/status.h"
#include "support/cli_runner.h"

namespace niwa {

inline void ExpectOneLineError(const CliResult& r, const std::string& must_contain) {
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // exactly one line
  EXPECT_NE(r.err.find(must_contain), std::string::npos) << r.err;
}

// A Status that names field and says must_contain.
inline void ExpectError(const Status& s, const std::string& field,
                        const std::string& must_contain) {
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.field(), field) << s.Line();
  EXPECT_NE(s.message().find(must_contain), std::string::npos) << s.Line();
}

}  // namespace niwa
