// The list of every study's CLI commands, generated at configure time from
// native_cli/*_commands.cpp (native_cli/CMakeLists.txt): adding a study's command file adds its
// commands, with no edit here.
#pragma once

#include <CLI/CLI.hpp>

#include "cli_common.h"

namespace niwa::cli {

// Calls Add<Study>Commands(app, commands) of every native_cli/<study>_commands.cpp, in the order of
// their "// cli-order: N" lines (100 when a file has none), then by file name.
void AddRegisteredCommands(CLI::App& app, CommandList& commands);

}  // namespace niwa::cli
