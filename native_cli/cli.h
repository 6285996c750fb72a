// The niwa command line as a library: parses arguments, runs commands, reports one-line errors.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace niwa {

// Exit codes: 0 success, 2 bad input (one line on err naming the field and its allowed range),
// 1 an internal failure.
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace niwa
