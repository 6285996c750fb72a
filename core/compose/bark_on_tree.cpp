// The bark study on a grown tree's trunk, and the tree's .glb wearing its maps (see
// bark_on_tree.h).
#include "compose/bark_on_tree.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "bark/bark_maps.h"
#include "bark/bark_params.h"
#include "bark/bark_run.h"
#include "bark/lattice.h"
#include "geom/tri_mesh.h"
#include "params/param_text.h"
#include "tree/tree_gltf.h"
#include "tree/tree_params.h"

namespace niwa::compose {
namespace {

using bark::BarkParam;

constexpr double kPi = 3.14159265358979323846;
constexpr double kCmPerMetre = 100;
// The trunk shoot's continuation from its tip: the thickest living child starting there.
const Branch* Continuation(const Tree& tree, const Branch& branch) {
  const int tip = static_cast<int>(branch.nodes.size()) - 1;
  const Branch* best = nullptr;
  float radius = -1;
  for (int id : branch.children) {
    if (id < 0 || id >= static_cast<int>(tree.branches.size())) continue;
    const Branch& child = tree.branches[static_cast<std::size_t>(id)];
    if (!child.alive || child.parent_node != tip || child.nodes.size() < 2) continue;
    const float r = BranchRadius(child);
    if (r > radius) {
      radius = r;
      best = &child;
    }
  }
  return best;
}

// PNG bytes of one map of a finished run.
Result<std::string> Map(const bark::BarkRun& run, const char* name) {
  Result<std::string> png = run.MapPng(name);
  if (!png.ok()) return Status::Error("bark", png.status().Line());
  return png;
}

// with_height: the 16-bit height map's PNG too (the garden's frames go without: nothing of the
// garden reads it).
Result<BarkFrame> Frame(const bark::BarkRun& run, bool with_height = true) {
  BarkFrame frame;
  Result<std::string> png = Map(run, "base_colour");
  if (!png.ok()) return png.status();
  frame.base_colour = std::move(png).value();
  png = Map(run, "normal");
  if (!png.ok()) return png.status();
  frame.normal = std::move(png).value();
  png = Map(run, "orm");
  if (!png.ok()) return png.status();
  frame.orm = std::move(png).value();
  if (with_height) {
    png = Map(run, "height");
    if (!png.ok()) return png.status();
    frame.height = std::move(png).value();
  }
  const bark::Growth g = run.growth();
  frame.tile_width_m = run.lattice().circumference() * g.s_theta / kCmPerMetre;
  frame.tile_height_m = run.lattice().height() * g.s_z / kCmPerMetre;
  frame.hash = run.Hash("");
  frame.colour_pixels = run.maps().base_colour;
  frame.mean_colour = image::MeanLinearRgb(frame.colour_pixels);
  frame.normal_pixels = run.maps().normal;
  return frame;
}

// The maps' width for a tile of circumference cf and height hf (cm) whose longer side is `size`
// px: `size` when the tile is at least as wide as it is tall, else the power of two nearest
// size·cf/hf, in [32, size] (MapHeightPx then gives about `size` rows).
int FitMapWidth(int size, double cf, double hf) {
  if (!(cf > 0) || !(hf > cf)) return size;
  return bark::NearestPowerOfTwo(size * cf / hf, 32, size);
}

// Runs the state and frames it; fit: the maps' longer side is the state's map_size (FitMapWidth),
// else their width is.
Result<BarkFrame> RunFrame(const bark::BarkState& state, const Budget& budget,
                           const run::Observer& observer, bool fit = false) {
  Result<bark::BarkRun> started = bark::BarkRun::Start(state, budget);
  if (!started.ok()) return Status::Error("bark", started.status().Line());
  bark::BarkRun& run = *started;
  NIWA_RETURN_IF_ERROR(run.Advance(observer));
  if (fit) {
    const bark::Growth g = run.growth();
    const int width =
        FitMapWidth(state.params.GetInt(bark::BarkParam::kMapSize),
                    run.lattice().circumference() * g.s_theta, run.lattice().height() * g.s_z);
    NIWA_RETURN_IF_ERROR(run.SetMapWidth(width));
  }
  return Frame(run, /*with_height=*/!fit);
}

// The bark buffers' vertex range of each drawn branch: BuildTreeMesh writes one branch's tube
// (rings of sides + 1 vertices, then a cap of 1 + sides) contiguously.
struct TubeRun {
  uint32_t branch = 0;
  std::size_t first = 0, count = 0;
};
std::vector<TubeRun> TubeRuns(const TreeMesh& mesh) {
  std::vector<TubeRun> runs;
  const std::vector<uint32_t>& ids = mesh.bark_branch_id;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (runs.empty() || runs.back().branch != ids[i] ||
        runs.back().first + runs.back().count != i) {
      runs.push_back({ids[i], i, 0});
    }
    ++runs.back().count;
  }
  return runs;
}

gltf::Texture PngTexture(const std::string& name, const std::string& png) {
  gltf::Texture texture;
  texture.name = name;
  texture.png.assign(png.begin(), png.end());
  texture.wrap_s = texture.wrap_t = gltf::Wrap::kRepeat;
  return texture;
}

geom::TriMesh ToTriMesh(const MeshBuffers& b) {
  geom::TriMesh m;
  const std::size_t n = b.vertex_count();
  m.positions.reserve(n);
  m.normals.reserve(n);
  m.uvs.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    m.positions.emplace_back(b.positions[3 * i], b.positions[3 * i + 1], b.positions[3 * i + 2]);
    m.normals.emplace_back(b.normals[3 * i], b.normals[3 * i + 1], b.normals[3 * i + 2]);
    m.uvs.emplace_back(b.uvs[2 * i], b.uvs[2 * i + 1]);
  }
  m.indices = b.indices;
  return m;
}

}  // namespace

TrunkYear MeasureTrunk(const Tree& tree, double height_m) {
  TrunkYear out;
  out.year = tree.years;
  const Branch* shoot = nullptr;
  for (const Branch& b : tree.branches) {
    if (b.parent < 0) {
      shoot = &b;
      break;
    }
  }
  if (shoot == nullptr || !shoot->alive || shoot->nodes.size() < 2) return out;
  const double h = height_m * kCmPerMetre;
  bool found = false;
  while (shoot != nullptr) {
    const Branch* next = Continuation(tree, *shoot);
    out.top_m = std::max(out.top_m, static_cast<double>(shoot->nodes.back().y) / kCmPerMetre);
    if (!found) {
      // Where the shoot first climbs through h, as a share of its arc length (the mesh's taper:
      // from the shoot's radius at its base to its continuation's, never wider).
      double length = 0, at = -1;
      for (std::size_t i = 1; i < shoot->nodes.size(); ++i) {
        const glm::vec3 a = shoot->nodes[i - 1], b = shoot->nodes[i];
        const double segment =
            std::sqrt(double(b.x - a.x) * (b.x - a.x) + double(b.y - a.y) * (b.y - a.y) +
                      double(b.z - a.z) * (b.z - a.z));
        if (at < 0 && ((a.y <= h && b.y >= h) || (i == 1 && a.y >= h))) {
          const double t = b.y > a.y ? std::clamp((h - a.y) / (double(b.y) - a.y), 0.0, 1.0) : 0.0;
          at = length + t * segment;
        }
        length += segment;
      }
      if (at >= 0) {
        const double base = BranchRadius(*shoot);
        const double tip = next != nullptr ? std::min<double>(BranchRadius(*next), base) : base;
        const double t = length > 0 ? at / length : 0;
        out.radius_cm = base + (tip - base) * t;
        found = true;
      }
    }
    shoot = next;
  }
  return out;
}

void RecordTrunkYear(const Tree& tree, TrunkHistory* history) {
  if (!history->years.empty() && history->years.back().year >= tree.years) return;
  history->years.push_back(MeasureTrunk(tree, history->height_m));
}

BarkHeightRange BarkHeights(const TrunkHistory& history) {
  BarkHeightRange range;
  // Whole millimetres, so the range prints short and its bound is itself valid.
  if (history.years.size() >= 2) {
    range.max = std::floor(history.years[history.years.size() - 2].top_m * 1000) / 1000;
  }
  return range;
}

Status CheckBarkOnTreeOptions(const BarkOnTreeOptions& options) {
  bark::BarkState s;
  const Status species = bark::SetBarkSpecies(options.species, &s);
  if (!species.ok()) return Status::Error("bark_species", species.message());
  const Status model = bark::SetBarkModel(options.model, &s);
  if (!model.ok()) return Status::Error("bark_model", model.message());
  NIWA_RETURN_IF_ERROR(CheckValue("bark_map_size", options.map_size, 256, 4096, true));
  if ((options.map_size & (options.map_size - 1)) != 0) {
    return Status::Error("bark_map_size", FormatNumber(options.map_size) +
                                              " is not a power of two; must be 256, 512, 1024, "
                                              "2048 or 4096");
  }
  return Status::Ok();
}

double SurfaceStrain(double hoop_strain, double turnover_strain) {
  if (!(hoop_strain > 0) || !(turnover_strain > 0)) return 0;
  return hoop_strain * turnover_strain / (hoop_strain + turnover_strain);
}

Result<BarkOnTreePlan> PlanBarkOnTree(const TrunkHistory& history,
                                      const BarkOnTreeOptions& options) {
  const BarkHeightRange range = BarkHeights(history);
  if (range.max < 0) {
    return Status::Error("bark", "the tree grew " + std::to_string(history.years.size()) +
                                     " year(s); bark needs at least 2 years of growth");
  }
  const double h = history.height_m;
  if (!std::isfinite(h) || h < range.min || h > range.max) {
    return Status::Error("bark_height",
                         (std::isfinite(h) ? FormatNumber(h) : std::string("not a number")) +
                             " m is out of range; must be a number in [" + FormatNumber(range.min) +
                             ", " + FormatNumber(range.max) +
                             "] (m: the trunk's height a year before the last)");
  }
  BarkOnTreePlan plan;
  plan.last_year = history.years.back().year;
  for (const TrunkYear& y : history.years) {
    if (y.year < plan.last_year - kBarkWindow || y.radius_cm <= 0) continue;
    if (plan.radii_cm.empty()) plan.first_year = y.year;
    plan.radii_cm.push_back(y.radius_cm);
  }
  if (plan.radii_cm.size() < 2) {  // the trunk reached h only in the last year (range.max says no)
    return Status::Error("bark_height", "the trunk reaches " + FormatNumber(h) +
                                            " m only in its last year; must be within [" +
                                            FormatNumber(range.min) + ", " +
                                            FormatNumber(range.max) + "] m");
  }
  const double r0 = plan.radii_cm.front(), r1 = plan.radii_cm.back();
  plan.hoop_strain = r1 / r0 - 1;

  bark::BarkState& s = plan.state;
  Status st = CheckBarkOnTreeOptions(options);
  if (!st.ok()) return st;
  st = bark::SetBarkSpecies(options.species, &s);
  if (!st.ok()) return Status::Error("bark_species", st.message());
  st = bark::SetBarkModel(options.model, &s);
  if (!st.ok()) return Status::Error("bark_model", st.message());
  st = bark::SetBarkSeed(static_cast<double>(options.seed), &s);
  if (!st.ok()) return Status::Error("bark", st.message());
  // The visible surface has seen only the strain since it formed (docs/bark-model.md, "On Niwa's
  // trees", item 4): the window's and the turnover's limits on its age, as rates that add.
  const double lo = s.params.Get(BarkParam::kLo);
  const double r_o = bark::LatticeRadius(s.params.GetInt(BarkParam::kNR), lo);
  plan.surface_growth_cm = kSurfaceCycles * s.params.Get(BarkParam::kDeltaR) * r_o;
  plan.turnover_strain = plan.surface_growth_cm / std::max(r_o, r1 - plan.surface_growth_cm);
  plan.surface_strain = SurfaceStrain(plan.hoop_strain, plan.turnover_strain);
  plan.surface_years = plan.last_year - plan.first_year;
  // Back from the last year (radii linear between the recorded years) to where the trunk was
  // r1 / (1 + ε_s) thick: the surface formed there (within the window: ε_s < ε_window).
  const double birth = r1 / (1 + plan.surface_strain);
  for (std::size_t i = plan.radii_cm.size() - 1; i > 0; --i) {
    const double a = plan.radii_cm[i - 1], b = plan.radii_cm[i];
    if (a > birth) continue;
    const double t = b > a ? (b - birth) / (b - a) : 0;
    plan.surface_years = static_cast<double>(plan.radii_cm.size() - 1 - i) + t;
    break;
  }
  // The 4-layer model: kFourLayerCycles cycles of ε_s / kSurfaceCycles, the last kSurfaceCycles
  // the shown surface's life.
  const bool four = options.model == "4layer";
  const int cycles = four ? kFourLayerCycles : 1;
  const double cycle_dr = four ? plan.surface_strain / kSurfaceCycles : plan.surface_strain;
  // The even column count nearest the circumference where the run starts, 2π·r1/(1 + growth),
  // over the column pitch (√3/2)·L_o: the run ends at the trunk's real circumference 2π·r1 (the
  // 2-layer run starts at the surface's birth).
  // The 4-layer surface S lies outside the inner layer: its middle d_c·τ + 1.5·d_c beyond r_I,
  // 2.5·d_c at the last cycle's end (four_layer.cpp LayoutAt; d_c = cork·D), so r_I starts where
  // S ends at r1.
  const double d_c = s.params.Get(BarkParam::kCork) * s.params.Get(BarkParam::kD);
  const double start = four ? std::max(0.0, r1 - 2.5 * d_c) / (1 + cycles * cycle_dr) : birth;
  const double columns = 2 * kPi * start / bark::LatticePitch(lo);
  const auto& nr_spec = bark::BarkTable().row(static_cast<std::size_t>(BarkParam::kNR));
  const double n_r = std::clamp(2 * std::round(columns / 2), nr_spec.min_value, nr_spec.max_value);
  // One cycle, as the paper's Table 3 runs (its dH per cycle cuts the plates across once).
  for (const auto& [row, value] : {std::pair<BarkParam, double>{BarkParam::kNR, n_r},
                                   {BarkParam::kCycles, cycles},
                                   {BarkParam::kDeltaR, cycle_dr},
                                   {BarkParam::kMapSize, options.map_size}}) {
    st = s.params.Set(row, value);
    if (!st.ok()) return Status::Error("bark", st.Line());
  }
  st = bark::CheckBarkState(s);
  if (!st.ok()) return Status::Error("bark", st.Line());
  // The young shoots' surface: half as old (half the strain), one 2-layer cycle (a young shoot's
  // one periderm: nothing to peel yet).
  plan.young_state = s;
  st = bark::SetBarkModel("2layer", &plan.young_state);
  if (st.ok()) st = plan.young_state.params.Set(BarkParam::kCycles, 1);
  if (st.ok()) st = plan.young_state.params.Set(BarkParam::kDeltaR, plan.surface_strain / 2);
  if (!st.ok()) return Status::Error("bark", st.Line());
  plan.estimate = bark::EstimateBarkRun(s) + bark::EstimateBarkRun(plan.young_state);
  const std::string nodes = FormatCount(n_r * s.params.GetInt(BarkParam::kNH));
  plan.estimate.what = four ? "the bark (the 4-layer model over " + std::to_string(cycles) +
                                  " cycles of " + nodes +
                                  " nodes a layer and a 2-layer cycle, maps " +
                                  std::to_string(options.map_size) + " px wide)"
                            : "the bark (two runs of " + nodes + " nodes, 1 cycle each, maps " +
                                  std::to_string(options.map_size) + " px wide)";
  return plan;
}

Result<BarkOnTree> GrowBarkOnTree(const BarkOnTreePlan& plan, const Budget& budget,
                                  const run::Observer& observer) {
  const Status fits = CheckEstimate(plan.estimate, budget, "lower the bark's map size");
  if (!fits.ok()) return Status::Error("bark", fits.message());
  BarkOnTree out;
  out.plan = plan;
  Result<BarkFrame> old_bark = RunFrame(plan.state, budget, observer);
  if (!old_bark.ok()) return old_bark.status();
  out.old_bark = std::move(old_bark).value();
  Result<BarkFrame> young = RunFrame(plan.young_state, budget, observer);
  if (!young.ok()) return young.status();
  out.young_bark = std::move(young).value();
  return out;
}

bool TreeBarkSimulated(const ParamSet& tree_params) {
  return tree_params.GetBool(TreeParam::kBark);
}

Result<std::string> TreeBarkModel(const ParamSet& tree_params) {
  const int layers = tree_params.GetInt(TreeParam::kBarkModel);
  if (layers == 2) return std::string("2layer");
  if (layers == 4) return std::string("4layer");
  return Status::Error("bark_model", FormatNumber(tree_params.Get(TreeParam::kBarkModel)) +
                                         " must be 2 (the 2-layer model) or 4 (the 4-layer model)");
}

Result<BarkOnTree> GrowTreeBark(const std::vector<TrunkHistory>& trunks,
                                const BarkOnTreeOptions& options, const Estimate& held,
                                const Budget& budget, const std::string& hint,
                                const run::Observer& observer) {
  Result<BarkOnTreePlan> plan = Status::Error("bark", "no trunk recorded");
  double height_m = 0;
  for (const TrunkHistory& trunk : trunks) {
    plan = PlanBarkOnTree(trunk, options);
    if (plan.ok()) {
      height_m = trunk.height_m;
      break;
    }
  }
  if (!plan.ok()) return plan.status();
  const Status fits = CheckEstimate(held + plan->estimate, budget, hint);
  if (!fits.ok()) return Status::Error("bark", fits.message());
  Result<BarkOnTree> bark = GrowBarkOnTree(*plan, budget, observer);
  if (!bark.ok()) return bark.status();
  bark->height_m = height_m;
  return bark;
}

Estimate OldBarkEstimate(const BarkOnTreePlan& plan) {
  Estimate e = bark::EstimateBarkRun(plan.state);
  e.what = "the bark (" +
           FormatCount(plan.state.params.GetInt(BarkParam::kNR) *
                       static_cast<double>(plan.state.params.GetInt(BarkParam::kNH))) +
           " nodes, " + std::to_string(plan.state.params.GetInt(BarkParam::kCycles)) +
           " cycles, maps " + std::to_string(plan.state.params.GetInt(BarkParam::kMapSize)) +
           " px wide)";
  return e;
}

Result<BarkFrame> GrowOldBark(const BarkOnTreePlan& plan, const Budget& budget,
                              const run::Observer& observer) {
  const Status fits = CheckEstimate(OldBarkEstimate(plan), budget, "lower the bark's map size");
  if (!fits.ok()) return Status::Error("bark", fits.message());
  return RunFrame(plan.state, budget, observer, /*fit=*/true);
}

void DressBarkMaterial(const BarkFrame& frame, const std::string& name, gltf::Material* material,
                       gltf::Document* doc) {
  const auto put = [doc](gltf::Texture texture, int* index) {
    if (*index >= 0) {
      doc->textures[static_cast<std::size_t>(*index)] = std::move(texture);
    } else {
      doc->textures.push_back(std::move(texture));
      *index = static_cast<int>(doc->textures.size()) - 1;
    }
  };
  put(PngTexture(name, frame.base_colour), &material->base_color_texture);
  put(PngTexture(name + "_normal", frame.normal), &material->normal_texture);
  doc->textures.push_back(PngTexture(name + "_orm", frame.orm));
  const int orm = static_cast<int>(doc->textures.size()) - 1;
  material->occlusion_texture = orm;           // R: occlusion
  material->metallic_roughness_texture = orm;  // G: roughness, B: metallic
  material->metallic_factor = 1.0;             // the ORM's B (0) is the metalness
  material->roughness_factor = 1.0;            // the ORM's G is the roughness
}

int WrapsAround(double radius_m, double tile_width_m) {
  if (!(tile_width_m > 0)) return 1;
  return std::max(1, static_cast<int>(std::lround(2 * kPi * radius_m / tile_width_m)));
}

bool YoungShoot(int branch_year, int tree_year) {
  return tree_year - branch_year + 1 <= kYoungBarkYears;
}

namespace {

// Calls wrap(vertex, frame, young, ring) for every bark vertex of every tube, in order.
template <typename Wrap>
void ForEachBarkVertex(const Tree& tree, const TreeMesh& mesh, const BarkFrame& old_frame,
                       const BarkFrame& young_frame, Wrap wrap) {
  for (const TubeRun& run : TubeRuns(mesh)) {
    const Branch& branch = tree.branches[run.branch];
    const bool young = YoungShoot(branch.year, tree.years);
    const BarkFrame& frame = young ? young_frame : old_frame;
    const int n_u = WrapsAround(BranchRadius(branch) / kCmPerMetre, frame.tile_width_m);
    // rings·(sides + 1) ring vertices, then the cap's 1 + sides: count = (rings + 1)(sides + 1).
    const std::size_t rings = branch.nodes.size();
    const std::size_t stride = run.count / (rings + 1);
    const std::size_t ring_vertices = rings * stride;
    for (std::size_t k = 0; k < run.count; ++k) {
      const std::size_t i = run.first + k;
      float u = mesh.bark.uvs[2 * i], v = mesh.bark.uvs[2 * i + 1];
      if (k < ring_vertices) {
        u = static_cast<float>(static_cast<double>(u) * n_u);
        v = static_cast<float>(static_cast<double>(v) / frame.tile_height_m);
      }
      wrap(i, young, u, v);
    }
  }
}

}  // namespace

std::vector<float> WrapBarkUvs(const Tree& tree, const TreeMesh& mesh, const BarkFrame& frame) {
  std::vector<float> uvs(mesh.bark.uvs.size(), 0.0f);
  ForEachBarkVertex(tree, mesh, frame, frame, [&](std::size_t i, bool, float u, float v) {
    uvs[2 * i] = u;
    uvs[2 * i + 1] = v;
  });
  return uvs;
}

BarkParts WrapBark(const Tree& tree, const TreeMesh& mesh, const BarkOnTree& bark) {
  BarkParts parts;
  const MeshBuffers& in = mesh.bark;
  // Each vertex's place in its part, for the indices.
  std::vector<uint32_t> moved(in.vertex_count(), 0);
  std::vector<uint8_t> young_vertex(in.vertex_count(), 0);
  ForEachBarkVertex(tree, mesh, bark.old_bark, bark.young_bark,
                    [&](std::size_t i, bool young, float u, float v) {
                      MeshBuffers& out = young ? parts.young_bark : parts.old_bark;
                      moved[i] = static_cast<uint32_t>(out.vertex_count());
                      young_vertex[i] = young ? 1 : 0;
                      for (int c = 0; c < 3; ++c) {
                        out.positions.push_back(in.positions[3 * i + c]);
                        out.normals.push_back(in.normals[3 * i + c]);
                      }
                      out.uvs.push_back(u);
                      out.uvs.push_back(v);
                    });
  for (std::size_t t = 0; t + 2 < in.indices.size(); t += 3) {
    MeshBuffers& out = young_vertex[in.indices[t]] ? parts.young_bark : parts.old_bark;
    for (int c = 0; c < 3; ++c) out.indices.push_back(moved[in.indices[t + c]]);
  }
  return parts;
}

Result<gltf::Document> BarkTreeDocument(const Tree& tree, const TreeMesh& mesh,
                                        const BarkOnTree& bark) {
  BarkParts parts = WrapBark(tree, mesh, bark);
  TreeMesh dressed;
  dressed.bark = std::move(parts.old_bark);
  dressed.leaves = mesh.leaves;
  dressed.flowers = mesh.flowers;
  dressed.look = mesh.look;
  Result<gltf::Document> made = TreeGltfDocument(dressed);
  if (!made.ok()) return made.status();
  gltf::Document doc = std::move(made).value();
  // The procedural bark textures (the first two when the old bark is drawn) give way to the maps.
  gltf::Material* old_material = nullptr;
  for (gltf::Material& m : doc.materials) {
    if (m.name == "bark") old_material = &m;
  }
  if (old_material != nullptr) DressBarkMaterial(bark.old_bark, "bark", old_material, &doc);
  if (!parts.young_bark.indices.empty()) {
    gltf::Material young;
    young.name = "bark_young";
    DressBarkMaterial(bark.young_bark, "bark_young", &young, &doc);
    doc.materials.push_back(std::move(young));
    gltf::Primitive primitive;
    primitive.mesh = ToTriMesh(parts.young_bark);
    primitive.material = static_cast<int>(doc.materials.size()) - 1;
    primitive.index_type = gltf::IndexType::kUint32;
    if (doc.meshes.empty()) {
      gltf::Mesh m;
      m.name = "tree";
      doc.meshes.push_back(std::move(m));
      doc.nodes[0].mesh = 0;
    }
    doc.meshes[0].primitives.push_back(std::move(primitive));
  }
  return doc;
}

Result<std::string> BarkTreeGlb(const Tree& tree, const TreeMesh& mesh, const BarkOnTree& bark) {
  Result<gltf::Document> doc = BarkTreeDocument(tree, mesh, bark);
  if (!doc.ok()) return doc.status();
  Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
  if (!glb.ok()) return glb.status();
  return std::string(glb->begin(), glb->end());
}

std::string BarkOnTreeJson(const BarkOnTree& bark) {
  const BarkOnTreePlan& p = bark.plan;
  std::string radii;
  for (double r : p.radii_cm) radii += (radii.empty() ? "" : ",") + FormatNumber(r);
  const auto& params = p.state.params;
  return "{\"species\":\"" + p.state.species + "\",\"model\":\"" + p.state.model +
         "\",\"height_m\":" + FormatNumber(bark.height_m) + ",\"years\":[" +
         std::to_string(p.first_year) + "," + std::to_string(p.last_year) + "],\"radii_cm\":[" +
         radii + "],\"hoop_strain\":" + FormatNumber(p.hoop_strain) +
         ",\"surface_growth_cm\":" + FormatNumber(p.surface_growth_cm) +
         ",\"turnover_strain\":" + FormatNumber(p.turnover_strain) +
         ",\"surface_years\":" + FormatNumber(p.surface_years) +
         ",\"N_R\":" + std::to_string(params.GetInt(BarkParam::kNR)) +
         ",\"N_H\":" + std::to_string(params.GetInt(BarkParam::kNH)) +
         ",\"cycles\":" + std::to_string(params.GetInt(BarkParam::kCycles)) +
         ",\"dR\":" + FormatNumber(params.Get(BarkParam::kDeltaR)) +
         ",\"young_dR\":" + FormatNumber(p.young_state.params.Get(BarkParam::kDeltaR)) +
         ",\"tile_cm\":[" + FormatNumber(bark.old_bark.tile_width_m * kCmPerMetre) + "," +
         FormatNumber(bark.old_bark.tile_height_m * kCmPerMetre) +
         "],\"young_years\":" + std::to_string(kYoungBarkYears) + ",\"hash\":\"" +
         bark.old_bark.hash + "\"}";
}

}  // namespace niwa::compose
