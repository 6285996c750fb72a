// The niwa CLI app: builds CLI11's app from every study's registered commands (generated from
// native_cli/*_commands.cpp), lists a study's table and presets, runs the command given and maps
// errors to exit codes. Does not: hold any study's commands.
#include "cli.h"

#include <CLI/CLI.hpp>
#include <new>

#include "cli_common.h"
#include "commands_registry.h"
#include "params/param_json.h"

namespace niwa {
namespace {

// Name unknown commands ourselves: CLI11 would only say that a subcommand is required.
void CheckCommand(const CLI::App& parent, const std::string& word) {
  if (word.empty() || word[0] == '-') return;
  std::string names;
  for (const CLI::App* sub : parent.get_subcommands({})) {
    if (sub->get_name() == word) return;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  throw cli::BadInput{"unknown command '" + word + "', must be one of " + names};
}

const cli::Study& FindStudy(const cli::CommandList& commands, const std::string& name) {
  std::string names;
  for (const cli::Study& study : commands.studies) {
    if (name.empty() || study.name == name) return study;
    names += (names.empty() ? "" : ", ") + study.name;
  }
  throw cli::BadInput{"study: unknown '" + name + "', must be one of " + names};
}

void PrintTable(const ParamTable& table, bool json, std::ostream& out) {
  if (json) {
    out << ParamTableJson(table) << "\n";
    return;
  }
  for (const ParamSpec& s : table) {
    out << s.key << "\t" << s.symbol << "\t" << (*s.unit ? s.unit : "-") << "\tdefault "
        << FormatNumber(s.default_value) << "\t" << RangeText(s) << "\t" << s.help << "\n";
  }
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"niwa: procedural nature lab (tree growth after Kanayama 1998)", "niwa"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");
  cli::CommandList commands;
  std::string study;
  bool params_json = false;
  CLI::App* presets = app.add_subcommand("presets", "List the species presets");
  presets->add_option("study", study, "Study whose presets to list (default: tree)");
  CLI::App* params = app.add_subcommand("params", "List every model parameter with its range");
  params->add_option("study", study, "Study whose table to list (default: tree)");
  params->add_flag("--json", params_json, "Print the table as JSON");
  commands.push_back({presets, [&](std::ostream& o) {
                        FindStudy(commands, study).print_presets(o);
                        return 0;
                      }});
  commands.push_back({params, [&](std::ostream& o) {
                        PrintTable(*FindStudy(commands, study).table, params_json, o);
                        return 0;
                      }});
  cli::AddRegisteredCommands(app, commands);

  try {
    if (!args.empty()) CheckCommand(app, args[0]);
    for (const CLI::App* group : app.get_subcommands({})) {
      if (args.size() > 1 && args[0] == group->get_name() && group->get_require_subcommand_min())
        CheckCommand(*group, args[1]);
    }
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
    for (const cli::Command& command : commands) {
      if (*command.app) return command.run(out);
    }
  } catch (const CLI::CallForHelp&) {
    out << app.help();  // CLI11 delegates to the innermost selected subcommand
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ParseError& e) {
    std::string message = e.what();
    for (char& c : message) {
      if (c == '\n') c = ' ';
    }
    err << "niwa: error: " << message << " (see --help)\n";
    return 2;
  } catch (const cli::BadInput& e) {
    err << "niwa: error: " << e.message << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // The budgets (docs/budgets.md) are estimates meant to refuse first; should an allocation
    // still fail (a machine with less memory than --max-memory), it is still the input's size.
    err << "niwa: error: --max-memory: out of memory within the budget (this machine or build "
           "has less free memory); lower --max-memory or the work asked for\n";
    return 2;
  } catch (const std::exception& e) {
    err << "niwa: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace niwa
