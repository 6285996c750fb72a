// Test helper shared by the CLI tests: a failed run is exit code 2, nothing on stdout and exactly
// one line on stderr that contains the expected text.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "support/cli_runner.h"

namespace niwa {

inline void ExpectOneLineError(const CliResult& r, const std::string& must_contain) {
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // exactly one line
  EXPECT_NE(r.err.find(must_contain), std::string::npos) << r.err;
}

}  // namespace niwa
