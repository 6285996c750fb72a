// Shared parts of the niwa CLI's per-study command files: the bad-input error and the command list.
// Does not: hold any study's commands (those live in native_cli/<study>_commands.cpp).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "base/status.h"

namespace niwa::cli {

// Thrown from a command; RunCli prints "niwa: error: <message>" and exits with code 2.
struct BadInput {
  std::string message;
};

[[noreturn]] inline void Fail(const Status& status) { throw BadInput{status.Line()}; }
inline void Check(const Status& status) {
  if (!status.ok()) Fail(status);
}

// What a study's Add<Study>Commands(CLI::App& app, CommandList& commands) registers: a subcommand
// and what runs (returning the exit code) when it was the one given.
struct Command {
  CLI::App* app;
  std::function<int(std::ostream& out)> run;
};
using CommandList = std::vector<Command>;

}  // namespace niwa::cli
