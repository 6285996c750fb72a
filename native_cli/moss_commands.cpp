// niwa CLI commands of the moss study (Nomura 2010, paper 001; core/moss, docs/moss-model.md):
// its table and presets for 'niwa params moss' and 'niwa presets moss'.
// cli-order: 50
#include <CLI/CLI.hpp>
#include <ostream>
#include <string>

#include "cli_common.h"
#include "moss/moss_params.h"
#include "params/param_text.h"

namespace niwa::cli {

void AddMossCommands(CLI::App& /*app*/, CommandList& commands) {
  commands.studies.push_back({"moss", &moss::MossTable(), [](std::ostream& out) {
                                for (const std::string& name : moss::MossPresetNames()) {
                                  out << name;
                                  for (const auto& [key, value] : moss::MossPresetValues(name))
                                    out << "\t" << key << "=" << FormatNumber(value);
                                  out << "\t" << moss::MossPresetSource(name) << "\n";
                                }
                              }});
}

}  // namespace niwa::cli
