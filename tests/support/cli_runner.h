// Test helper shared by the CLI tests: runs niwa's RunCli in-process and captures its output.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace niwa {

struct CliResult {
  int code;
  std::string out, err;
};

inline CliResult RunNiwa(std::vector<std::string> args) {
  std::ostringstream out, err;
  int code = RunCli(args, out, err);
  return {code, out.str(), err.str()};
}

}  // namespace niwa
