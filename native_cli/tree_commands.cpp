// niwa CLI commands of the tree study: its table and presets, 'tree grow', 'tree state' and
// 'tree mappings'.
// cli-order: 10
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "base/echo.h"
#include "cli_common.h"
#include "compose/bark_on_tree.h"
#include "render/tree_lod.h"
#include "render/tree_run.h"
#include "run/field_names.h"
#include "tree/presets.h"
#include "tree/tree_simple.h"
#include "tree/tree_state.h"
#include "tree/tree_svg.h"
#include "tree_cli.h"

namespace niwa::cli {
namespace {

const FlagRange kSvgSize = {100, 10000, true};
const FlagRange kZeroOne = {0, 1, true};
const FlagRange kMaxTriangles = {static_cast<double>(kMinLodTriangles), 100000000, true};
const FlagRange kBarkHeight = {0, compose::kMaxBarkHeight, false, " (metres above the ground)"};
const FlagRange kBarkMapSize = {256, 4096, true};

// The bark-on-tree fields (core/compose/bark_on_tree) as the flags that set them.
const run::FieldNames& BarkFlagNames() {
  static const run::FieldNames names = {{"bark", "--bark"},
                                        {"bark_height", "--bark-height"},
                                        {"bark_species", "--bark-species"},
                                        {"bark_model", "--bark-model"},
                                        {"bark_map_size", "--bark-map-size"}};
  return names;
}

struct TreeGrowOptions {
  StateOptions state;
  std::string out_path;
  bool stats = false;
  SvgOptions svg;
  long max_triangles = -1;          // --max-triangles (render/tree_lod); -1: the full mesh
  bool lod = false;                 // --lod: <name>_LOD0.._LOD2 sibling nodes
  std::string lod_layout;           // --lod-layout siblings|msft (with --lod)
  std::string bark = "procedural";  // --bark procedural|sim
  double bark_height = compose::kDefaultBarkHeight;
  // --bark-species, --bark-model, --bark-map-size (seed: the tree's)
  compose::BarkOnTreeOptions bark_options;
};

// --bark and its flags, and the tree table's bark rows (`bark`, `bark_model`: from --set, --url or
// --state), checked before any growth. The flags set the rows (--bark sim: bark 1, --bark-model
// 4layer: bark_model 4), so the rows and the flags are one setting; what a flag cannot be made
// with (a .glb only, the full mesh) is refused, while rows from a link simply leave the other
// outputs (.json, .svg, the LOD .glb) procedural. True when the full .glb is dressed.
bool CheckBarkFlags(TreeGrowOptions* o, const CLI::App& cmd, const std::string& ext,
                    TreeState* state) {
  if (o->bark != "procedural" && o->bark != "sim") {
    throw BadInput{"--bark: '" + Echo(o->bark) + "' must be procedural or sim"};
  }
  const bool flag = o->bark == "sim";
  const bool rows = compose::TreeBarkSimulated(state->params);
  for (const char* name : {"--bark-height", "--bark-species", "--bark-model", "--bark-map-size"}) {
    if (!flag && !rows && cmd.count(name))
      throw BadInput{std::string(name) + ": only applies with --bark sim"};
  }
  if (flag) {
    if (ext != ".glb") throw BadInput{"--bark: sim only applies with --out FILE.glb"};
    if (o->lod || o->max_triangles >= 0) {
      throw BadInput{
          "--bark: sim dresses the full .glb; give it without --lod and --max-triangles"};
    }
    Check(state->params.Set(TreeParam::kBark, 1));
  }
  if (cmd.count("--bark-model")) {
    Check(run::RenameField(compose::CheckBarkOnTreeOptions(o->bark_options), BarkFlagNames()));
    Check(state->params.Set(TreeParam::kBarkModel, o->bark_options.model == "4layer" ? 4 : 2));
  }
  if (!flag && !rows) return false;
  Result<std::string> model = compose::TreeBarkModel(state->params);
  Check(run::RenameField(model.status(), TreeFlagNames()));
  o->bark_options.model = *model;
  Check(run::RenameField(compose::CheckBarkOnTreeOptions(o->bark_options), BarkFlagNames()));
  return ext == ".glb" && !o->lod && o->max_triangles < 0;
}

// SVG-only drawing options of 'tree grow' (used by scripts/figures).
void AddSvgOptions(CLI::App* cmd, SvgOptions* o) {
  const std::vector<std::string> svg = {".svg"};
  OnlyWith(AddNumberFlag(cmd, "--svg-width", &o->width, kSvgSize,
                         "SVG width in pixels, " + RangeHelp(kSvgSize) + " (default 600)"),
           "--out", svg);
  OnlyWith(AddNumberFlag(cmd, "--svg-height", &o->height, kSvgSize,
                         "SVG height in pixels, " + RangeHelp(kSvgSize) + " (default 600)"),
           "--out", svg);
  OnlyWith(AddNumberFlag(cmd, "--svg-leaves", &o->leaves, kZeroOne,
                         "SVG: draw leaves, 0 or 1 (default 1)"),
           "--out", svg);
  OnlyWith(AddNumberFlag(cmd, "--svg-flowers", &o->flowers, kZeroOne,
                         "SVG: draw flowers, 0 or 1 (default 1)"),
           "--out", svg);
  // Escaped into the SVG by the core (base/markup_escape.h); control characters refused.
  OnlyWith(AddCaptionFlag(cmd, "--caption", &o->caption, "SVG: text under the tree"), "--out", svg);
}

// --bark sim: the bark study on the trunk's radius history (core/compose/bark_on_tree's
// GrowTreeBark, the page's TreeSession's run too), its estimate added to the tree's and its
// export's and refused up front naming --bark, then the tree's .glb dressed in its maps. Errors
// are BadInput lines naming the --bark flags.
Result<std::string> BarkGlb(const TreeGrowOptions& o, const Budget& budget,
                            const TreeExportRequest& request, compose::TrunkHistory* trunk,
                            TreeRun* run, std::string* bark_json) {
  compose::RecordTrunkYear(run->tree(), trunk);
  compose::BarkOnTreeOptions options = o.bark_options;
  options.seed = run->state().seed;
  Result<compose::BarkOnTree> bark = compose::GrowTreeBark(
      {*trunk}, options, run->Held() + run->ExportWork(request), budget,
      options.model == "4layer"
          ? "use --bark-model 2layer, or lower --bark-map-size or --bark-height"
          : "lower --bark-map-size or --bark-height");
  Check(run::RenameField(bark.status(), BarkFlagNames()));
  run->BuildBareMesh();
  *bark_json = compose::BarkOnTreeJson(*bark);
  return compose::BarkTreeGlb(run->tree(), run->mesh(), *bark);  // the page's download too
}

int RunGrow(TreeGrowOptions o, const CLI::App& cmd, std::ostream& out) {
  // --out's ending and the flags that apply only to one output were checked by the shared flags.
  const std::string ext = Extension(o.out_path);
  LodLayout layout = LodLayout::kSiblings;
  if (cmd.count("--lod-layout")) {
    if (!o.lod) throw BadInput{"--lod-layout: only applies with --lod"};
    if (o.lod_layout == "msft") {
      layout = LodLayout::kMsftLod;
    } else if (o.lod_layout != "siblings") {
      throw BadInput{"--lod-layout: '" + Echo(o.lod_layout) + "' must be siblings or msft"};
    }
  }
  TreeState state = ResolveTreeState(o.state, cmd);
  const bool bark_sim = CheckBarkFlags(&o, cmd, ext, &state);
  const Budget budget = ResolveBudget(o.state.budget);
  compose::TrunkHistory trunk;  // --bark sim: the trunk's radius at --bark-height, year by year
  trunk.height_m = o.bark_height;
  Result<TreeRun> started = TreeRun::Start(state, budget);  // core/render/tree_run
  Check(run::RenameField(started.status(), TreeFlagNames()));
  TreeRun& run = *started;
  TreeExportRequest request;
  // The game-ready .glb (--max-triangles, --lod) builds its levels from the full mesh: its own
  // estimate (core/render/lod_budget), the page's buildLodGlb the same.
  request.kind = ext == ".json"                    ? TreeExportRequest::Kind::kJson
                 : ext == ".svg"                   ? TreeExportRequest::Kind::kSvg
                 : (o.lod || o.max_triangles >= 0) ? TreeExportRequest::Kind::kLodGlb
                                                   : TreeExportRequest::Kind::kGlb;
  request.svg = o.svg;
  request.max_triangles = o.max_triangles;
  request.lod = o.lod;
  request.layout = layout;
  // The export is checked after every year of growth: without prunes the tree only grows, so an
  // export that does not fit the tree of year k cannot fit the last year's either, and is refused
  // then (issue 34: a 100-year tree's LOD export was refused only once grown, after 1.5 GB).
  Status early;
  const bool check_early = !o.out_path.empty() && state.prunes.empty();
  Status advanced = run.Advance([&](const run::Progress& progress) {
    if (bark_sim && progress.done >= 1) compose::RecordTrunkYear(run.tree(), &trunk);
    if (!check_early || progress.done == 0 || progress.done >= progress.total) return true;
    const Status fits = run.CheckExport(request);
    if (fits.ok()) return true;
    early = Status::Error(fits.field(), "in year " + FormatNumber(progress.done) + " of " +
                                            FormatNumber(progress.total) +
                                            " already: " + fits.message());
    return false;
  });
  if (!early.ok()) Fail(run::RenameField(early, TreeFlagNames()));
  std::string bark_json;  // --bark sim: the bark's part of --stats
  Check(advanced);        // stops early (truncated) at the budget's growth limits
  ReportTruncated(run.tree().truncated_by);
  Check(run::RenameField(run.CheckPrunes(), TreeFlagNames()));
  if (!o.out_path.empty()) {
    if (std::getenv("NIWA_BUDGET_TRACE")) {  // calibration (docs/budgets.md)
      const Estimate grown = run.grown(), export_estimate = run.ExportWork(request);
      std::fprintf(stderr, "budget: grown %.0f MB %.2f s; export %.0f MB %.2f s\n",
                   grown.memory_bytes / 1048576, grown.seconds,
                   export_estimate.memory_bytes / 1048576, export_estimate.seconds);
    }
    // The export's estimate on top of the grown tree's, refused before it starts.
    Check(run.CheckExport(request));
    Result<std::string> bytes =
        bark_sim ? BarkGlb(o, budget, request, &trunk, &run, &bark_json) : run.Export(request);
    if (!bytes.ok()) {
      if (request.kind == TreeExportRequest::Kind::kGlb) {
        throw BadInput{"--out: " + bytes.status().Line()};
      }
      Fail(run::RenameField(bytes.status(), TreeFlagNames()));
    }
    StagedOutputs outputs;
    Check(outputs.Stage("--out", o.out_path, *bytes));
    Check(outputs.Commit());
  }
  // Without an output file the statistics are the output (a bare 'niwa tree grow' prints them).
  if (o.stats || o.out_path.empty()) {
    std::string stats = run.StatsJson();
    if (!bark_json.empty() && !stats.empty() && stats.back() == '}') {
      stats.insert(stats.size() - 1, ",\"bark\":" + bark_json);
    }
    out << stats << "\n";
  }
  // The process ends soon and takes the tree's memory with it: freeing it one branch at a time
  // cost 4.3 M of a fresh sakura-thesis 15-year run's 149 M instructions (issue 17 item 7). The
  // last run is kept, still reachable (RunCli may run many commands in one process, as the unit
  // tests do; the one before is freed then).
  static TreeRun* last_run = nullptr;
  delete last_run;
  last_run = new TreeRun(std::move(run));
  return 0;
}

struct StateCommandOptions {
  StateOptions state;
  std::string out_path;
};

// 'niwa tree state': the state the flags give (e.g. a page's link) as a state file, for
// 'tree grow --state' and the page's Open. Nothing is grown.
int RunState(const StateCommandOptions& o, const CLI::App& cmd, std::ostream& out) {
  const std::string text = TreeStateFileJson(ResolveTreeState(o.state, cmd));
  if (o.out_path.empty()) {
    out << text;
    return 0;
  }
  StagedOutputs outputs;
  Check(outputs.Stage("--out", o.out_path, text));
  Check(outputs.Commit());
  return 0;
}

}  // namespace

void AddTreeCommands(CLI::App& app, CommandList& commands) {
  commands.studies.push_back({"tree",
                              &TreeParamTable(),
                              [](std::ostream& out) {
                                for (const Preset& p : Presets()) {
                                  out << p.name << "\t" << p.title << "\t" << p.years << " years\t"
                                      << p.source << "\n";
                                }
                              },
                              // with the Getting started group (tree/tree_simple.h), as the page
                              &TreeParamTableJsonWithSimple,
                              {"tree", "grow", "--preset", "binary", "--years", "2"}});
  CLI::App* tree = Subcommand(app, "tree", "Grow and export trees");

  CLI::App* grow = tree->add_subcommand("grow", "Grow a tree and write it or its statistics");
  auto grow_options = std::make_shared<TreeGrowOptions>();
  AddStateOptions(grow, TreeParamTable(), &grow_options->state);
  AddOutputFlag(grow, "--out", &grow_options->out_path, {".glb", ".json", ".svg"},
                "Write the tree: .glb (binary glTF), .json or .svg (side view)");
  grow->add_flag("--stats", grow_options->stats,
                 "Print one JSON object of statistics on stdout (also the output when no --out)");
  OnlyWith(AddNumberFlag(grow, "--max-triangles", &grow_options->max_triangles, kMaxTriangles,
                         ".glb within N triangles, " + RangeHelp(kMaxTriangles) +
                             ": thin twigs become cards or lines, leaves leaf-cluster cards"),
           "--out", {".glb"});
  OnlyWith(grow->add_flag("--lod", grow_options->lod,
                          ".glb with nodes tree_LOD0, tree_LOD1 (<= 25 % of LOD0's triangles) and "
                          "tree_LOD2 (<= 5 %)"),
           "--out", {".glb"});
  OnlyWith(grow->add_option(
               "--lod-layout", grow_options->lod_layout,
               "With --lod: siblings (three scene nodes, the default) or msft (LOD0 in the "
               "scene with the MSFT_lod extension naming LOD1 and LOD2: Babylon.js, UnityGLTF)"),
           "--out", {".glb"});
  OnlyWith(
      grow->add_option("--bark", grow_options->bark,
                       "Bark of the .glb: procedural (the default, today's textures) or sim "
                       "(the bark study run on the trunk's radius history; docs/bark-model.md)"),
      "--out", {".glb"});
  OnlyWith(AddNumberFlag(grow, "--bark-height", &grow_options->bark_height, kBarkHeight,
                         "With --bark sim: metres above the ground where the trunk's radius "
                         "history is read, " +
                             RangeHelp(kBarkHeight) +
                             " and within the trunk's height a year before the last (default 1.3)"),
           "--out", {".glb"});
  OnlyWith(grow->add_option("--bark-species", grow_options->bark_options.species,
                            "With --bark sim: the bark preset (camphor, tallow or pine; default "
                            "camphor)"),
           "--out", {".glb"});
  OnlyWith(grow->add_option("--bark-model", grow_options->bark_options.model,
                            "With --bark sim: the trunk's bark model, 2layer (the default: one "
                            "cycle) or 4layer (3 cycles with layer birth, peeling and shedding; "
                            "several times the cost, estimated and refused up front)"),
           "--out", {".glb"});
  OnlyWith(
      AddNumberFlag(grow, "--bark-map-size", &grow_options->bark_options.map_size, kBarkMapSize,
                    "With --bark sim: width of the bark maps, a power of two, " +
                        RangeHelp(kBarkMapSize) + " (default 1024)"),
      "--out", {".glb"});
  commands.push_back(
      {grow,
       [grow, grow_options](std::ostream& out) { return RunGrow(*grow_options, *grow, out); },
       {"--preset", "binary", "--years", "2"}});

  CLI::App* state_cmd = tree->add_subcommand(
      "state", "Write the state the flags give (e.g. --url LINK) as a state file for --state");
  auto state_options = std::make_shared<StateCommandOptions>();
  AddStateOptions(state_cmd, TreeParamTable(), &state_options->state);
  AddOutputFlag(state_cmd, "--out", &state_options->out_path, {".json"},
                "Write the state file here (.json); without it, print it on stdout");
  commands.push_back({state_cmd,
                      [state_cmd, state_options](std::ostream& out) {
                        return RunState(*state_options, *state_cmd, out);
                      },
                      {"--preset", "binary"}});

  CLI::App* mappings = tree->add_subcommand(
      "mappings",
      "Print the hormone- and age-dependent ranges (N, D, b_L, b_g, break chances) as CSV");
  auto mapping_options = std::make_shared<StateOptions>();
  AddStateOptions(mappings, TreeParamTable(), mapping_options.get());
  // Added after 'mappings' so that 'tree grow --help' lists its options as before.
  AddSvgOptions(grow, &grow_options->svg);
  commands.push_back({mappings,
                      [mappings, mapping_options](std::ostream& out) {
                        // core/render/tree_run: a prune checked against the tree it cuts.
                        Result<std::string> csv =
                            TreeRun::MappingsCsv(ResolveTreeState(*mapping_options, *mappings),
                                                 ResolveBudget(mapping_options->budget));
                        Check(run::RenameField(csv.status(), TreeFlagNames()));
                        out << *csv;
                        return 0;
                      },
                      {"--preset", "binary", "--years", "2"}});
}

}  // namespace niwa::cli
