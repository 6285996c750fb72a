// The garden's run (see garden_run.h).
#include "compose/garden_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "image/png.h"
#include "io/gltf_writer.h"
#include "math/det_math.h"
#include "render/tree_lod.h"
#include "tree/presets.h"
#include "tree/tree_budget.h"
#include "tree/tree_state.h"

namespace niwa::compose {
namespace {

using Clock = std::chrono::steady_clock;
double MsSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Bytes and seconds of one distinct tree's .glb part per triangle of its budget (the LOD mesh,
// its atlas share and the writer's copies), generous as docs/budgets.md's constants.
constexpr double kGardenGlbBytesPerTriangle = 400;
constexpr double kGardenGlbSecondsPerTriangle = 2e-6;
// The cards' atlas of a distinct tree in the garden's .glb (texels a side; render/tree_lod).
constexpr int kGardenAtlasSize = 512;

gltf::Material PlainMaterial(const std::string& name, double r, double g, double b,
                             double roughness) {
  gltf::Material m;
  m.name = name;
  m.base_color_factor = {r, g, b, 1};
  m.metallic_factor = 0;
  m.roughness_factor = roughness;
  return m;
}

// Appends `from`'s meshes, materials and textures to `into` (indices remapped); returns the
// offset of its meshes in `into`.
int AppendGardenDocument(gltf::Document* into, const gltf::Document& from) {
  const int mesh_base = static_cast<int>(into->meshes.size());
  const int material_base = static_cast<int>(into->materials.size());
  // A texture already in `into` with the same bytes and sampler (a species' bark and leaf
  // textures, the same for every tree of it) is shared, not written again.
  std::vector<int> texture_at;
  for (const gltf::Texture& t : from.textures) {
    int found = -1;
    for (std::size_t k = 0; k < into->textures.size() && found < 0; ++k) {
      const gltf::Texture& u = into->textures[k];
      if (u.png == t.png && u.wrap_s == t.wrap_s && u.wrap_t == t.wrap_t &&
          u.mag_filter == t.mag_filter && u.min_filter == t.min_filter)
        found = static_cast<int>(k);
    }
    if (found < 0) {
      found = static_cast<int>(into->textures.size());
      into->textures.push_back(t);
    }
    texture_at.push_back(found);
  }
  for (gltf::Material m : from.materials) {
    for (int* tex : {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture,
                     &m.occlusion_texture})
      if (*tex >= 0) *tex = texture_at[static_cast<std::size_t>(*tex)];
    into->materials.push_back(std::move(m));
  }
  for (gltf::Mesh mesh : from.meshes) {
    for (gltf::Primitive& p : mesh.primitives)
      if (p.material >= 0) p.material += material_base;
    into->meshes.push_back(std::move(mesh));
  }
  return mesh_base;
}

std::array<double, 4> YawQuaternion(double rot_deg) {
  const double half = rot_deg * det::kPi / 360.0;
  return {0, det::Sin(half), 0, det::Cos(half)};
}

std::string SpeciesColour(const std::string& species) {
  static const std::map<std::string, std::string> colours = {
      {"keyaki", "#5d8f3a"},          {"keyaki-thesis", "#5d8f3a"}, {"sakura", "#d98fa8"},
      {"sakura-thesis", "#d98fa8"},   {"maple", "#c4502c"},         {"pine", "#2f5d3a"},
      {"ginkgo", "#d8c03a"},          {"weeping", "#7fa65a"},       {"tsutsuji", "#c0457a"},
      {"tsutsuji-thesis", "#c0457a"}, {"binary", "#808080"}};
  const auto it = colours.find(species);
  return it == colours.end() ? "#4c7a3c" : it->second;
}

}  // namespace

Result<GardenRun> GardenRun::Start(const GardenState& state, const Budget& budget) {
  NIWA_RETURN_IF_ERROR(CheckGardenState(state));
  GardenRun run;
  run.state_ = state;
  run.budget_ = budget;
  auto t0 = Clock::now();
  Result<GardenScene> scene = BuildGardenScene(state, budget);
  if (!scene.ok()) return scene.status();
  run.scene_ = std::move(*scene);
  run.truncated_by_ = run.scene_.truncated_by;
  run.ms_ground_ = MsSince(t0);
  t0 = Clock::now();
  Result<Planting> planting = PlantGarden(state, run.scene_);
  if (!planting.ok()) return planting.status();
  run.planting_ = std::move(*planting);
  run.ms_plant_ = MsSince(t0);

  // Groups: a tree with a neighbour within shade_reach (shade 1) is grown on its own; the rest
  // share one growth per (species, seed, age).
  const std::vector<PlacedTree>& trees = run.planting_.trees;
  const bool shade = state.params.GetBool(GardenParam::kShade);
  const double reach = state.params.Get(GardenParam::kShadeReach);
  std::vector<bool> near(trees.size(), false);
  if (shade) {
    for (std::size_t a = 0; a < trees.size(); ++a)
      for (std::size_t b = a + 1; b < trees.size(); ++b) {
        const double dx = trees[a].x - trees[b].x, dz = trees[a].z - trees[b].z;
        if (dx * dx + dz * dz < reach * reach) near[a] = near[b] = true;
      }
  }
  std::map<std::tuple<std::string, uint64_t, int>, int> shared;
  run.tree_group_.assign(trees.size(), -1);
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const PlacedTree& p = trees[t];
    const auto key = std::make_tuple(p.species, p.seed, p.age);
    const auto it = near[t] ? shared.end() : shared.find(key);
    int g = it != shared.end() ? it->second : -1;
    if (g < 0) {
      g = static_cast<int>(run.groups_.size());
      if (!near[t]) shared[key] = g;
      GardenTreeGroup group;
      group.species = p.species;
      group.seed = p.seed;
      group.age = p.age;
      group.shaded = near[t];
      group.name = near[t]
                       ? p.species + "_t" + std::to_string(t)
                       : p.species + "_s" + std::to_string(p.seed) + "_a" + std::to_string(p.age);
      run.groups_.push_back(std::move(group));
    }
    run.groups_[g].trees.push_back(static_cast<int>(t));
    run.tree_group_[t] = g;
  }
  // Each group's growth within an equal share of the budget above the process's own base (the
  // tree's limits count that base once per tree; its limits stop a tree with a line).
  const double groups = std::max<double>(1, static_cast<double>(run.groups_.size()));
  const int years = state.params.GetInt(GardenParam::kYears);
  for (GardenTreeGroup& g : run.groups_) {
    TreeState ts;
    NIWA_RETURN_IF_ERROR(SetStatePreset(g.species, &ts));
    NIWA_RETURN_IF_ERROR(SetStateSeed(static_cast<double>(g.seed), &ts));
    NIWA_RETURN_IF_ERROR(SetStateYears(std::min(kMaxYears, g.age + years), &ts).Within("years"));
    ts.limits = TreeGrowLimits(ts.params, budget, "years");
    ts.limits.max_bytes =
        ts.limits.base_bytes + std::max(0.0, ts.limits.max_bytes - ts.limits.base_bytes) / groups;
    ts.limits.max_seconds /= groups;
    g.grower = std::make_unique<Grower>(ts);
  }
  return run;
}

Status GardenRun::Advance(const run::Observer& observer) {
  const auto t0 = Clock::now();
  const int years = target();
  if (!nursery_done_) {
    // The nursery: a tree planted at age a grows its first a years alone, before the clock.
    for (GardenTreeGroup& g : groups_)
      while (g.grower->year() < g.age && !g.grower->stopped()) g.grower->GrowYear();
    nursery_done_ = true;
  }
  while (year_ < years) {
    if (observer && !observer({"grow", static_cast<double>(year_), static_cast<double>(years)}))
      return run::CancelledStatus();
    for (GardenTreeGroup& g : groups_)
      if (g.grower->year() < g.age + year_ + 1 && !g.grower->stopped()) g.grower->GrowYear();
    ++year_;
  }
  if (observer) observer({"grow", static_cast<double>(year_), static_cast<double>(years)});
  for (const GardenTreeGroup& g : groups_)
    if (truncated_by_.empty() && g.grower->tree().truncated)
      truncated_by_ = g.name + ": " + g.grower->tree().truncated_by;
  ms_trees_ += MsSince(t0);
  return Status::Ok();
}

double GardenRun::CrownRadius(int group) const {
  double r2 = 0;
  for (const Branch& b : groups_[group].grower->tree().branches) {
    if (!b.alive) continue;
    for (const glm::vec3& p : b.nodes)
      r2 = std::max(r2, static_cast<double>(p.x) * p.x + static_cast<double>(p.z) * p.z);
  }
  return std::sqrt(r2) / 100.0;  // nodes are in cm
}

glm::dvec3 GardenRun::CrownCentroid(int t) const {
  const PlacedTree& p = planting_.trees[t];
  const Tree& tree = groups_[tree_group_[t]].grower->tree();
  glm::dvec3 sum(0.0);
  double n = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const Leaf& leaf : b.leaves) {
      sum += glm::dvec3(b.nodes[leaf.node]);
      n += 1;
    }
  }
  glm::dvec3 local = n > 0 ? sum / n / 100.0 : glm::dvec3(0.0);
  const double a = p.rot * det::kPi / 180.0;
  const double c = det::Cos(a), s = det::Sin(a);
  return {p.x + c * local.x + s * local.z, p.y + local.y, p.z - s * local.x + c * local.z};
}

std::vector<run::Part> GardenRun::Parts() const {
  std::vector<run::Part> parts;
  run::Part ground;
  ground.name = "ground";
  ground.mesh = scene_.ground.Mesh();
  ground.material = PlainMaterial("ground", 0.36, 0.42, 0.24, 0.95);
  parts.push_back(std::move(ground));
  for (std::size_t k = 0; k < scene_.objects.size(); ++k) {
    run::Part o;
    o.name = "object_" + std::to_string(k) + "_" + scene_.objects[k].kind;
    o.mesh = scene_.objects[k].mesh;
    o.material = scene_.objects[k].kind == "wall" ? PlainMaterial("plaster", 0.86, 0.82, 0.74, 0.9)
                                                  : PlainMaterial("stone", 0.52, 0.52, 0.5, 0.85);
    parts.push_back(std::move(o));
  }
  return parts;
}

Result<gltf::Document> GardenRun::Document() const {
  gltf::Document doc;
  doc.scene_name = "garden";
  nlohmann::ordered_json extras;
  extras["niwa"] = {{"study", "garden"}, {"url", "#" + Hash("")}};
  doc.asset_extras_json = extras.dump();
  for (const run::Part& part : Parts()) {
    gltf::Mesh mesh;
    mesh.name = part.name;
    gltf::Primitive prim;
    prim.mesh = part.mesh;
    prim.material = static_cast<int>(doc.materials.size());
    doc.materials.push_back(part.material);
    mesh.primitives.push_back(std::move(prim));
    gltf::Node node;
    node.name = part.name;
    node.mesh = static_cast<int>(doc.meshes.size());
    doc.meshes.push_back(std::move(mesh));
    doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
    doc.nodes.push_back(std::move(node));
  }
  const long max_triangles = state_.params.GetInt(GardenParam::kMaxTriangles);
  const bool lod = state_.params.GetBool(GardenParam::kLod);
  const bool instancing = state_.params.GetBool(GardenParam::kInstancing);
  LodOptions options;
  options.atlas_size = kGardenAtlasSize;
  for (const GardenTreeGroup& g : groups_) {
    std::vector<LodMesh> levels;
    if (lod) {
      Result<std::vector<LodMesh>> made =
          BuildLodLevels(g.grower->tree(), max_triangles, options, "max_triangles");
      if (!made.ok()) return made.status();
      levels = std::move(*made);
    } else {
      Result<LodMesh> made =
          BuildLodMesh(g.grower->tree(), max_triangles, options, "max_triangles");
      if (!made.ok()) return made.status();
      levels.push_back(std::move(*made));
    }
    Result<gltf::Document> tree_doc = LodGltfDocument(levels, g.name);
    if (!tree_doc.ok()) return tree_doc.status();
    const int mesh_base = AppendGardenDocument(&doc, *tree_doc);
    // The tree document's nodes, one a level, each name its level's mesh.
    for (const gltf::Node& level : tree_doc->nodes) {
      if (level.mesh < 0) continue;
      const int mesh = mesh_base + level.mesh;
      if (instancing) {
        gltf::Node node;
        node.name = level.name;
        node.mesh = mesh;
        for (int t : g.trees) {
          const PlacedTree& p = planting_.trees[t];
          node.instance_translations.insert(
              node.instance_translations.end(),
              {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
          const std::array<double, 4> q = YawQuaternion(p.rot);
          for (double v : q) node.instance_rotations.push_back(static_cast<float>(v));
        }
        doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
        doc.nodes.push_back(std::move(node));
      } else {
        for (int t : g.trees) {
          const PlacedTree& p = planting_.trees[t];
          gltf::Node node;
          node.name = g.name + "_" + std::to_string(t) +
                      (levels.size() > 1 ? level.name.substr(level.name.rfind('_')) : "");
          node.mesh = mesh;
          node.translation = {p.x, p.y, p.z};
          node.rotation = YawQuaternion(p.rot);
          doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
          doc.nodes.push_back(std::move(node));
        }
      }
    }
  }
  return doc;
}

std::string GardenRun::StatsJson() const {
  nlohmann::ordered_json j;
  j["study"] = "garden";
  j["years"] = year_;
  j["size"] = state_.params.Get(GardenParam::kSize);
  j["ground"] = {
      {"source", scene_.ground.source}, {"res", scene_.ground.n}, {"relief", scene_.ground.relief}};
  j["objects"] = scene_.objects.size();
  std::map<std::string, long> by_species;
  for (const PlacedTree& t : planting_.trees) ++by_species[t.species];
  double internodes = 0, leaves = 0;
  long shaded = 0;
  for (std::size_t t = 0; t < planting_.trees.size(); ++t) {
    const TreeCounts c = CountTree(groups_[tree_group_[t]].grower->tree());
    internodes += c.internodes;
    leaves += c.leaves;
  }
  for (const GardenTreeGroup& g : groups_) shaded += g.shaded ? 1 : 0;
  nlohmann::ordered_json species = nlohmann::ordered_json::object();
  for (const auto& [name, count] : by_species) species[name] = count;
  j["trees"] = {{"count", planting_.trees.size()}, {"distinct", groups_.size()},
                {"grown_with_neighbours", shaded}, {"by_species", species},
                {"internodes", internodes},        {"leaves", leaves}};
  j["planting"] = nlohmann::ordered_json::parse(PlantingJson(planting_))["report"];
  if (!truncated_by_.empty()) j["truncated_by"] = truncated_by_;
  return j.dump();
}

std::string GardenRun::Hash(const std::string& prefix) const {
  return EncodeGardenHash(state_, prefix);
}

Result<Estimate> GardenRun::ExportEstimate(const std::string& format) const {
  const double groups = static_cast<double>(groups_.size());
  const double ground_vertices = static_cast<double>(scene_.ground.n + 1) * (scene_.ground.n + 1);
  if (format == "glb") {
    const double tri = static_cast<double>(state_.params.GetInt(GardenParam::kMaxTriangles)) *
                       (state_.params.GetBool(GardenParam::kLod) ? 1.3 : 1.0);
    return Estimate{groups * tri * kGardenGlbBytesPerTriangle + ground_vertices * 120 +
                        groups * 4.0 * kGardenAtlasSize * kGardenAtlasSize,
                    groups * tri * kGardenGlbSecondsPerTriangle + ground_vertices * 1e-6,
                    "writing the garden's .glb (" + FormatCount(groups) + " distinct trees)"};
  }
  if (format == "heightmap" || format == "svg" || format == "json")
    return Estimate{ground_vertices * 16 + static_cast<double>(planting_.trees.size()) * 200.0,
                    ground_vertices * 1e-7, "writing the garden's " + format};
  return Status::Error("format", "'" + format +
                                     "' is not an export; must be glb, heightmap, svg "
                                     "or json");
}

Result<std::string> GardenRun::Export(const std::string& format) const {
  if (format == "glb") {
    Result<gltf::Document> doc = Document();
    if (!doc.ok()) return doc.status();
    Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
    if (!glb.ok()) return glb.status();
    return std::string(glb->begin(), glb->end());
  }
  if (format == "json") return PlantingJson(planting_);
  if (format == "heightmap") {
    const GardenGround& g = scene_.ground;
    image::Gray16Image img;
    img.width = img.height = g.n + 1;
    img.pixels.resize(static_cast<std::size_t>(img.width) * img.height);
    for (std::size_t k = 0; k < g.h.size(); ++k)
      img.pixels[k] = static_cast<uint16_t>(
          g.relief > 0 ? std::lround(std::clamp(g.h[k] / g.relief, 0.0, 1.0) * 65535.0) : 0);
    image::PngWriteOptions options;
    options.text = {{"niwa:size_m", FormatNumber(g.size)},
                    {"niwa:relief_m", FormatNumber(g.relief)},
                    {"niwa:rows", "row 0 is the north edge (z = -size/2), column 0 the west"}};
    Result<std::vector<unsigned char>> png = image::EncodeGray16Png(img, options);
    if (!png.ok()) return png.status();
    return std::string(png->begin(), png->end());
  }
  if (format == "svg") {
    // The plan, north up: the ground shaded by height, objects as their footprints, each tree a
    // circle of its crown's reach in its species' colour.
    const GardenGround& g = scene_.ground;
    const double px = 800.0 / g.size;
    std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"800\" "
        "viewBox=\"0 0 800 800\">\n";
    const int cells = std::min(g.n, 64);
    const double step = g.size / cells;
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) {
        const double h = g.HeightAt(-g.size / 2 + (i + 0.5) * step, -g.size / 2 + (j + 0.5) * step);
        const int shade = static_cast<int>(150 + 80 * (g.relief > 0 ? h / g.relief : 0));
        svg += "<rect x=\"" + FormatNumber(i * step * px) + "\" y=\"" +
               FormatNumber(j * step * px) + "\" width=\"" + FormatNumber(step * px + 0.5) +
               "\" height=\"" + FormatNumber(step * px + 0.5) + "\" fill=\"rgb(" +
               std::to_string(shade - 40) + "," + std::to_string(shade) + "," +
               std::to_string(shade - 70) + ")\"/>\n";
      }
    for (const PlacedObject& o : scene_.objects) {
      svg += "<rect class=\"object\" x=\"" + FormatNumber((o.x - o.hx + g.size / 2) * px) +
             "\" y=\"" + FormatNumber((o.z - o.hz + g.size / 2) * px) + "\" width=\"" +
             FormatNumber(2 * o.hx * px) + "\" height=\"" + FormatNumber(2 * o.hz * px) +
             "\" transform=\"rotate(" + FormatNumber(-o.rot) + " " +
             FormatNumber((o.x + g.size / 2) * px) + " " + FormatNumber((o.z + g.size / 2) * px) +
             ")\" fill=\"#8a8478\" stroke=\"#333\"><title>" + o.kind + "</title></rect>\n";
    }
    for (std::size_t t = 0; t < planting_.trees.size(); ++t) {
      const PlacedTree& p = planting_.trees[t];
      const double r = std::max(0.3, CrownRadius(tree_group_[t]));
      svg += "<circle class=\"tree\" cx=\"" + FormatNumber((p.x + g.size / 2) * px) + "\" cy=\"" +
             FormatNumber((p.z + g.size / 2) * px) + "\" r=\"" + FormatNumber(r * px) +
             "\" fill=\"" + SpeciesColour(p.species) +
             "\" fill-opacity=\"0.55\" stroke=\"#222\"><title>" + p.species + " seed " +
             std::to_string(p.seed) + (p.hand >= 0 ? " (by hand)" : "") + "</title></circle>\n";
    }
    svg += "</svg>\n";
    return svg;
  }
  return Status::Error("format", "'" + format +
                                     "' is not an export; must be glb, heightmap, svg "
                                     "or json");
}

}  // namespace niwa::compose
