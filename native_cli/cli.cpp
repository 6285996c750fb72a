// The niwa CLI app: builds CLI11's app from every study's registered commands (generated from
// native_cli/*_commands.cpp), lists a study's table and presets, runs the command given and maps
// errors to exit codes. Does not: hold any study's commands.
#include "cli.h"

#include <CLI/CLI.hpp>
#include <new>

#include "base/echo.h"
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
  throw cli::BadInput{"unknown command '" + Echo(word) + "', must be one of " + names};
}

// Every option of app and its subcommands, for the checks CLI11 does not make.
void CollectOptions(const CLI::App& app, std::vector<const CLI::Option*>* options) {
  for (const CLI::Option* opt : app.get_options()) options->push_back(opt);
  for (const CLI::App* sub : app.get_subcommands({})) CollectOptions(*sub, options);
}

// Booleans are flags: "--stats=yes" (any value given to a flag) is refused naming the flag.
void CheckFlagValues(const CLI::App& app, const std::vector<std::string>& args) {
  std::vector<const CLI::Option*> options;
  CollectOptions(app, &options);
  for (const std::string& arg : args) {
    if (arg == "--") return;  // what follows is positional
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    const std::size_t eq = arg.find('=');
    if (eq == std::string::npos) continue;
    const std::string name = arg.substr(0, eq);
    for (const CLI::Option* opt : options) {
      if (opt->get_expected_max() == 0 && opt->check_lname(name.substr(2))) {
        throw cli::BadInput{name + ": is a flag and takes no value; give " + name + " alone"};
      }
    }
  }
}

// A given option with an empty value ("--out ''") is refused naming it; numeric flags already
// refuse it through their parser. Free text (a caption) may be empty.
void CheckEmptyValues(const CLI::App& app) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0 || opt->get_expected_max() == 0) continue;
    if (opt->check_lname("caption")) continue;
    for (const std::string& value : opt->results()) {
      if (value.empty()) throw cli::BadInput{opt->get_name() + ": empty; give a value"};
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) CheckEmptyValues(*sub);
}

const cli::Study& FindStudy(const cli::CommandList& commands, const std::string& name) {
  std::string names;
  for (const cli::Study& study : commands.studies) {
    if (name.empty() || study.name == name) return study;
    names += (names.empty() ? "" : ", ") + study.name;
  }
  throw cli::BadInput{"study: unknown '" + Echo(name) + "', must be one of " + names};
}

void PrintTable(const cli::Study& study, bool json, std::ostream& out) {
  const ParamTable& table = *study.table;
  if (json) {
    out << (study.table_json ? study.table_json() : ParamTableJson(table)) << "\n";
    return;
  }
  for (const ParamSpec& s : table) {
    out << s.key << "\t" << s.symbol << "\t" << (*s.unit ? s.unit : "-") << "\tdefault "
        << FormatNumber(s.default_value) << "\t" << RangeText(s) << "\t" << s.help << "\n";
  }
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  cli::ClearDeclarations();  // the flags' declarations belong to this call's app
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
                        PrintTable(FindStudy(commands, study), params_json, o);
                        return 0;
                      }});
  cli::AddRegisteredCommands(app, commands);
  // 'niwa flags': every command's flags with their kinds, for tests/cli/hostile.test.mjs. Hidden
  // from the help (an empty group).
  CLI::App* flags = app.add_subcommand("flags", "Every command's flags as JSON (for tests)");
  flags->group("");
  commands.push_back({flags, [&](std::ostream& o) {
                        o << cli::FlagsJson(commands) << "\n";
                        return 0;
                      }});

  if (args.empty()) {  // 'niwa' alone: the usage, and exit code 2 (no command given)
    err << app.help() << "niwa: error: give a command, e.g. 'niwa tree grow'\n";
    return 2;
  }
  try {
    if (!args.empty()) CheckCommand(app, args[0]);
    for (const CLI::App* group : app.get_subcommands({})) {
      if (args.size() > 1 && args[0] == group->get_name() && group->get_require_subcommand_min())
        CheckCommand(*group, args[1]);
    }
    CheckFlagValues(app, args);
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
    CheckEmptyValues(app);
    for (const cli::Command& command : commands) {
      if (*command.app) {
        cli::CheckApplicable(*command.app);  // flags that apply only to another output
        cli::PreflightOutputs(*command.app);  // outputs that could not be written, before the work
        return command.run(out);
      }
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
    err << "niwa: error: " << EscapeLine(message, kMaxMessageLength) << " (see --help)\n";
    return 2;
  } catch (const cli::BadInput& e) {
    err << "niwa: error: " << EscapeLine(e.message, kMaxMessageLength) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // The budgets (docs/budgets.md) are estimates meant to refuse first; should an allocation
    // still fail (a machine with less memory than --max-memory), it is still the input's size.
    err << "niwa: error: --max-memory: out of memory within the budget (this machine or build "
           "has less free memory); lower --max-memory or the work asked for\n";
    return 2;
  } catch (const std::exception& e) {
    err << "niwa: internal error: " << EscapeLine(e.what(), kMaxMessageLength) << "\n";
    return 1;
  }
  return 0;
}

}  // namespace niwa
