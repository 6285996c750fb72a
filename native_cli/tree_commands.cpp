// niwa CLI commands of the tree study: its table and presets, 'tree grow' and 'tree mappings'.
// cli-order: 10
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "cli_common.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree_budget.h"
#include "tree/tree_gltf.h"
#include "tree/tree_json.h"
#include "tree/tree_report.h"
#include "tree/tree_svg.h"
#include "tree_cli.h"

namespace niwa::cli {
namespace {

const FlagRange kSvgSize = {100, 10000, true};

struct GrowOptions {
  StateOptions state;
  std::string out_path;
  bool stats = false;
  SvgOptions svg;
};

// SVG-only drawing options of 'tree grow' (used by scripts/figures).
void AddSvgOptions(CLI::App* cmd, SvgOptions* o) {
  cmd->add_option("--svg-width", o->width,
                  "SVG width in pixels, " + RangeHelp(kSvgSize) + " (default 600)");
  cmd->add_option("--svg-height", o->height,
                  "SVG height in pixels, " + RangeHelp(kSvgSize) + " (default 600)");
  cmd->add_option("--svg-leaves", o->leaves, "SVG: draw leaves, 0 or 1 (default 1)");
  cmd->add_option("--svg-flowers", o->flowers, "SVG: draw flowers, 0 or 1 (default 1)");
  cmd->add_option("--caption", o->caption, "SVG: text under the tree");
}

void CheckSvgOptions(const SvgOptions& o, const CLI::App& cmd, const std::string& ext) {
  for (const char* name :
       {"--svg-width", "--svg-height", "--svg-leaves", "--svg-flowers", "--caption"}) {
    if (cmd.count(name) && ext != ".svg") {
      throw BadInput{std::string(name) + ": only applies with --out FILE.svg"};
    }
  }
  Check(CheckFlag("--svg-width", o.width, kSvgSize));
  Check(CheckFlag("--svg-height", o.height, kSvgSize));
}

int RunGrow(const GrowOptions& o, const CLI::App& cmd, std::ostream& out) {
  std::string ext = Extension(o.out_path);
  if (!o.out_path.empty() && ext != ".glb" && ext != ".json" && ext != ".svg") {
    throw BadInput{"--out: '" + o.out_path + "' must end in .glb, .json or .svg"};
  }
  CheckSvgOptions(o.svg, cmd, ext);
  TreeState state = ResolveTreeState(o.state, cmd);
  Grower grower(state);  // stops early (truncated) at the budget's growth limits
  while (grower.year() < state.years && !grower.stopped()) grower.GrowYear();
  const GrowthTimings timings = grower.timings();
  const Estimate grown = grower.estimate();
  Tree tree = grower.TakeTree();
  ReportTruncated(tree.truncated_by);
  CheckPrunes(state, tree);
  if (!o.out_path.empty()) {
    // The export's estimate on top of the grown tree's, refused before it starts.
    const TreeExport kind = ext == ".json"  ? TreeExport::kJson
                            : ext == ".svg" ? TreeExport::kSvg
                                            : TreeExport::kGlb;
    if (std::getenv("NIWA_BUDGET_TRACE")) {  // calibration (docs/budgets.md)
      const Estimate e = EstimateTreeExport(CountTree(tree), kind);
      std::fprintf(stderr, "budget: grown %.0f MB %.2f s; export %.0f MB %.2f s\n",
                   grown.memory_bytes / 1048576, grown.seconds, e.memory_bytes / 1048576,
                   e.seconds);
    }
    Check(CheckEstimate(grown + EstimateTreeExport(CountTree(tree), kind),
                        ResolveBudget(o.state.budget), "lower --years, N_high or B_l"));
    std::string bytes;
    if (ext == ".json") {
      bytes = TreeToJson(tree);
    } else if (ext == ".svg") {
      bytes = TreeToSvg(tree, o.svg);
    } else {
      std::vector<unsigned char> glb;
      std::string error = WriteTreeGlb(BuildTreeMesh(tree), &glb).Line();
      if (!error.empty()) throw BadInput{"--out: " + error};
      bytes.assign(glb.begin(), glb.end());
    }
    Check(WriteFileAtomically(o.out_path, bytes).Within("--out"));
  }
  if (o.stats) out << TreeStatsJson(tree, timings) << "\n";
  return 0;
}

}  // namespace

void AddTreeCommands(CLI::App& app, CommandList& commands) {
  commands.studies.push_back({"tree", &TreeParamTable(), [](std::ostream& out) {
                                for (const Preset& p : Presets()) {
                                  out << p.name << "\t" << p.title << "\t" << p.years << " years\t"
                                      << p.source << "\n";
                                }
                              }});
  CLI::App* tree = Subcommand(app, "tree", "Grow and export trees");

  CLI::App* grow = tree->add_subcommand("grow", "Grow a tree and write it or its statistics");
  auto grow_options = std::make_shared<GrowOptions>();
  AddStateOptions(grow, TreeParamTable(), &grow_options->state);
  grow->add_option("--out", grow_options->out_path,
                   "Write the tree: .glb (binary glTF), .json or .svg (side view)");
  grow->add_flag("--stats", grow_options->stats, "Print one JSON object of statistics on stdout");
  commands.push_back({grow, [grow, grow_options](std::ostream& out) {
                        return RunGrow(*grow_options, *grow, out);
                      }});

  CLI::App* mappings = tree->add_subcommand(
      "mappings",
      "Print the hormone- and age-dependent ranges (N, D, b_L, b_g, break chances) as CSV");
  auto mapping_options = std::make_shared<StateOptions>();
  AddStateOptions(mappings, TreeParamTable(), mapping_options.get());
  // Added after 'mappings' so that 'tree grow --help' lists its options as before.
  AddSvgOptions(grow, &grow_options->svg);
  commands.push_back({mappings, [mappings, mapping_options](std::ostream& out) {
                        out << TreeMappingsCsv(
                            ResolveTreeState(*mapping_options, *mappings).params);
                        return 0;
                      }});
}

}  // namespace niwa::cli
