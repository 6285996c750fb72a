// The ivy study's bindings (paper 004): IvyLab, one support (a built-in scene or a dropped mesh,
// with its BVH) and the last ivy grown on it, for the worker (web/worker/ivy_handler.js); and the
// ivy table, presets, scenes and hash codec as JSON.
//
// Design (as the tree's "JS BINDINGS DESIGN" note in tree_bindings.cpp): everything from
// JavaScript arrives as text or bytes and is checked by the core (core/ivy/ivy_state,
// io/gltf_reader, ivy::Grow); nothing throws, errors come back as one line ("" = success).
// Buffers leave through buffers(group) (buffers.h), copied once by the worker. Groups:
//   "support"                    positions, normals (Float32 xyz), indices (Uint32)
//   "stems" | "leaves" | "suckers"  positions, normals, indices, birth (Float32 per vertex: the
//                                birth_step of core/ivy/ivy_mesh.h, the .glb's _BIRTH_STEP);
//                                "leaves" also uvs (Float32 uv per vertex: the .glb's TEXCOORD_0)
//   "buds"                       positions (Float32 xyz), kind (Float32: 0 A, 1 D, 2 Z, as at the
//                                last step), birth (Float32: the step the bud was made)
//   "glb"                        bytes (Uint8, after buildGlb)
// ivyLeafTexture() -> {width, height, pixels: Uint8Array RGBA (row 0 = v 0)}: the leaf
// texture's pixels, the ones the .glb's PNG holds (core/ivy/ivy_leaf_texture.h).
// Calls: loadScene(name), loadTree(preset, years) (a Niwa tree's bark, core/tree/bark_support, as
// the CLI's --tree-preset) or loadMesh(bytes, name) -> ""/error, supportJson(); grow(stateJson) ->
// ""/error, then statsJson(), buffers(..), modelJson(), lstring(), buildGlb(withSupport),
// exportCheck(format, withSupport) -> "" or the page budget's line (docs/budgets.md);
// rayCast(ox, oy, oz, dx, dy, dz) -> {hit, point, normal, distance} on the support;
// setProgress(fn): fn(stage, done, total) is called during loadMesh ("read", then "bvh" with the
// triangle count), loadTree ("tree", "bvh") and grow ("grow" after every step), so the worker can
// post progress while the call runs (a big mesh); null stops it.
// Does not: decode Draco (web/mesh/mesh_import.js does before the bytes arrive), or keep more than
// one ivy.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "buffers.h"
#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/mesh_metrics.h"
#include "geom/ray_cast.h"
#include "io/gltf_reader.h"
#include "io/mesh_reader.h"
#include "io/obj_reader.h"
#include "ivy/growth.h"
#include "ivy/ivy_budget.h"
#include "ivy/ivy_leaf_texture.h"
#include "ivy/ivy_mesh.h"
#include "ivy/ivy_params.h"
#include "ivy/ivy_report.h"
#include "ivy/ivy_state.h"
#include "ivy/lstring.h"
#include "ivy/scenes.h"
#include "page_budget.h"
#include "params/param_json.h"
#include "tree/bark_support.h"

namespace niwa {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

json Vec(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

std::string Dump(const ordered_json& j) {
  // Errors and notices may echo hostile text: replace bytes that are not UTF-8.
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

// Flat float views of a TriMesh's vectors (glm::vec3 is three packed floats).
struct FlatMesh {
  std::vector<float> positions, normals, birth, uvs;
  std::vector<uint32_t> indices;
};

FlatMesh Flatten(const geom::TriMesh& mesh) {
  FlatMesh out;
  out.positions.reserve(mesh.positions.size() * 3);
  for (const glm::vec3& p : mesh.positions)
    out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
  out.normals.reserve(mesh.normals.size() * 3);
  for (const glm::vec3& n : mesh.normals) out.normals.insert(out.normals.end(), {n.x, n.y, n.z});
  out.uvs.reserve(mesh.uvs.size() * 2);
  for (const glm::vec2& t : mesh.uvs) out.uvs.insert(out.uvs.end(), {t.x, t.y});
  out.indices = mesh.indices;
  if (const geom::VertexAttribute* birth = mesh.FindAttribute("birth_step"))
    out.birth = birth->values;
  return out;
}

// Per-vertex normals of a support without them: each vertex gets its triangles' face normal
// (the readers never share vertices across primitives; shared vertices get the area-weighted sum).
std::vector<float> FaceNormals(const geom::TriMesh& mesh) {
  std::vector<glm::vec3> sum(mesh.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1],
                   c = mesh.indices[3 * t + 2];
    const glm::vec3 n =
        glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    sum[a] += n;
    sum[b] += n;
    sum[c] += n;
  }
  std::vector<float> out;
  out.reserve(sum.size() * 3);
  for (const glm::vec3& n : sum) {
    const float l = std::sqrt(glm::dot(n, n));
    const glm::vec3 u = l > 0 ? n / l : glm::vec3(0, 1, 0);
    out.insert(out.end(), {u.x, u.y, u.z});
  }
  return out;
}

}  // namespace

std::string IvyParamTableJson() { return ParamTableJson(IvyTable()); }

// The leaf texture (ivy_leaf_texture.h), the pixels the .glb's PNG encodes, copied out of the heap.
emscripten::val IvyLeafTexture() {
  const image::Rgba8Image image = ivy::PaintLeafTexture(ivy::kLeafTextureSize);
  emscripten::val view(emscripten::typed_memory_view(image.pixels.size(), image.pixels.data()));
  emscripten::val out = emscripten::val::object();
  out.set("width", image.width);
  out.set("height", image.height);
  out.set("pixels", emscripten::val::global("Uint8Array").new_(view));  // a copy
  return out;
}

std::string IvyPresetsJson() {
  ordered_json out = ordered_json::array();
  for (const std::string& name : IvyPresetNames()) {
    ordered_json j;
    j["name"] = name;
    ordered_json overrides = ordered_json::object();
    for (const auto& [key, value] : IvyPresetOverrides(name)) overrides[key] = value;
    j["overrides"] = overrides;
    j["params"] = ordered_json::parse(ParamsToJson(*IvyPreset(name), -1));
    out.push_back(std::move(j));
  }
  return out.dump();
}

std::string IvyScenesJson() {
  ordered_json out = ordered_json::array();
  for (const std::string& name : ivy::IvySceneNames()) {
    Result<ivy::IvyScene> s = ivy::MakeIvyScene(name);
    if (!s.ok()) continue;
    ordered_json seeds = ordered_json::array();
    for (const ivy::NamedSeed& seed : s->seeds)
      seeds.push_back({{"name", seed.name}, {"pos", Vec(seed.pos)}});
    out.push_back({{"name", name},
                   {"description", s->description},
                   {"free", s->free},
                   {"triangles", s->mesh.triangle_count()},
                   {"seeds", seeds}});
  }
  return out.dump();
}

// {preset, seed, steps, scene, seed_points, tree, tree_years, params} of a state.
ordered_json IvyStateObject(const ivy::IvyState& state) {
  ordered_json j;
  j["preset"] = state.preset;
  j["seed"] = state.seed;
  j["steps"] = state.steps;
  j["scene"] = state.scene;
  j["seed_points"] = ivy::FormatSeedPoints(state.seed_points);
  j["tree"] = state.tree;
  j["tree_years"] = state.tree_years;
  j["params"] = ordered_json::parse(ParamsToJson(state.params, -1));
  return j;
}

// {state, notices}: the hash read as the CLI's --url reads it (bad values clamped or dropped, each
// with a notice).
std::string IvyDecodeHash(const std::string& hash) {
  ivy::IvyState state;
  std::vector<std::string> notices;
  ivy::ApplyIvyHash(hash, "", &state, &notices);
  ordered_json out;
  out["state"] = IvyStateObject(state);
  out["notices"] = notices;
  return Dump(out);
}

// {hash} or {error} of a state JSON.
std::string IvyEncodeHash(const std::string& state_json) {
  ivy::IvyState state;
  ordered_json out;
  std::string error = ivy::ApplyIvyStateJson(state_json, &state).Line();
  if (error.empty()) {
    out["hash"] = ivy::EncodeIvyHash(state);
  } else {
    out["error"] = error;
  }
  return Dump(out);
}

class IvyLab {
 public:
  // A built-in scene: "" or one error line ("scene: 'x' is unknown; must be one of ...").
  std::string loadScene(const std::string& name) {
    Result<ivy::IvyScene> s = ivy::MakeIvyScene(name);
    if (!s.ok()) return Status::Error("scene", s.status().message()).Line();
    const auto t0 = Clock::now();
    scene_ = std::move(s).value();
    tree_seconds_ = 0;
    tree_truncated_by_.clear();
    mesh_name_.clear();
    attach_ = geom::TriMesh{};
    obstacles_ = 0;
    Prepare();
    ms_bvh_ = Ms(t0, Clock::now());
    return "";
  }

  // The bark of tree preset `preset` grown `years` years (metres), seeded at the trunk foot as
  // `niwa ivy grow --tree-preset` does: "" or one error line naming tree or tree_years.
  std::string loadTree(const std::string& preset, double years) {
    Progress("tree", 0, years);
    BarkBudget budget;  // the tree page's limits: the tree stops where its bark fits, or is refused
    budget.budget = PageBudget();
    budget.years_name = "tree_years";
    Result<BarkSupport> bark = GrowBarkSupport(preset, years, &budget);
    if (!bark.ok()) return bark.status().Line();
    tree_seconds_ = bark->estimate.seconds;
    tree_truncated_by_ = bark->truncated_by;
    Progress("bvh", 0, static_cast<double>(bark->mesh.triangle_count()));
    const auto t0 = Clock::now();  // ms_bvh: the support's BVH, not the tree's growth
    scene_ = ivy::IvyScene{};
    scene_.name = "tree:" + preset;
    scene_.description = bark->description;
    scene_.mesh = std::move(bark->mesh);
    scene_.seeds.push_back({"trunk", bark->trunk_seed});
    mesh_name_.clear();
    attach_ = geom::TriMesh{};
    obstacles_ = 0;
    Prepare();
    ms_bvh_ = Ms(t0, Clock::now());
    return "";
  }

  void setProgress(emscripten::val fn) { progress_ = fn; }

  // A dropped .glb/.gltf/.obj (bytes; Draco already decoded): "" or one error line naming it.
  std::string loadMesh(const std::string& bytes, const std::string& name) {
    Progress("read", 0, static_cast<double>(bytes.size()));
    io::MeshReadStats read;
    const bool obj = name.size() >= 4 && (name.compare(name.size() - 4, 4, ".obj") == 0 ||
                                          name.compare(name.size() - 4, 4, ".OBJ") == 0);
    Result<geom::TriMesh> mesh =
        obj ? io::ReadObjMesh(bytes, name, &read) : io::ReadGltfMesh(bytes, name, "", &read);
    if (!mesh.ok()) return mesh.status().Line();
    Status valid = geom::ValidateMesh(*mesh, name);
    if (!valid.ok()) return valid.Line();
    Progress("bvh", 0, static_cast<double>(mesh->triangle_count()));
    const auto t0 = Clock::now();
    scene_ = ivy::IvyScene{};
    tree_seconds_ = 0;
    tree_truncated_by_.clear();
    scene_.name = name;
    scene_.mesh = std::move(mesh).value();
    mesh_name_ = name;
    attach_ = ivy::IvyAttachTriangles(scene_.mesh, read.materials, &obstacles_);
    Prepare();
    // A default seed, so a dropped mesh grows at once: the surface point nearest to a point in
    // front of the mesh (+z) at a tenth of its height (Grow lifts it to d/2 off that face).
    const geom::TriMesh& seedable = obstacles_ > 0 ? attach_ : scene_.mesh;
    const geom::Bvh& seed_bvh = obstacles_ > 0 ? attach_bvh_ : bvh_;
    if (seedable.triangle_count() > 0) {
      const geom::Bounds3 b = geom::MeshBounds(seedable);
      const glm::vec3 size = b.max - b.min;
      const glm::vec3 probe(0.5f * (b.min.x + b.max.x), b.min.y + 0.1f * size.y,
                            b.max.z + std::max({size.x, size.y, size.z}));
      geom::ClosestHit hit =
          geom::ClosestPoint(seedable, seed_bvh, probe, std::numeric_limits<float>::infinity());
      if (hit.found) scene_.seeds.push_back({"front", glm::dvec3(hit.point)});
    }
    ms_bvh_ = Ms(t0, Clock::now());
    return "";
  }

  // {name, dropped, free, triangles, obstacles, bounds: {min, max}, seeds: [{name, pos}], ms_bvh}.
  std::string supportJson() const {
    ordered_json j;
    j["name"] = scene_.name;
    j["dropped"] = !mesh_name_.empty();
    j["free"] = scene_.free;
    j["triangles"] = scene_.mesh.triangle_count();
    j["obstacles"] = obstacles_;
    const geom::Bounds3 b = geom::MeshBounds(scene_.mesh);
    if (scene_.mesh.triangle_count() > 0) {
      j["bounds"] = {{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}};
    } else {
      j["bounds"] = nullptr;
    }
    ordered_json seeds = ordered_json::array();
    for (const ivy::NamedSeed& seed : scene_.seeds)
      seeds.push_back({{"name", seed.name}, {"pos", Vec(seed.pos)}});
    j["seeds"] = seeds;
    j["ms_bvh"] = ms_bvh_;
    return Dump(j);
  }

  // Grows the state (JSON, as ApplyIvyStateJson reads it) on the support loaded: "" or one error
  // line. Seed points: the state's, else the scene's first named seed (a dropped mesh needs one).
  std::string grow(const std::string& state_json) {
    const auto t0 = Clock::now();
    grown_ = false;
    ivy::IvyState state;
    Status s = ivy::ApplyIvyStateJson(state_json, &state);
    if (s.ok()) s = ValidateIvyParams(state.params);
    if (!s.ok()) return s.Line();
    std::vector<glm::dvec3> seeds = state.seed_points;
    if (seeds.empty() && !scene_.seeds.empty()) seeds.push_back(scene_.seeds[0].pos);
    if (seeds.empty()) {
      return Status::Error("at",
                           "a dropped mesh needs a seed point; click its surface to place one")
          .Line();
    }
    ivy::Support support;
    if (!scene_.free) {
      support = {&scene_.mesh, &bvh_, ivy::Accel::kBvh};
      if (obstacles_ > 0) {
        support.attach_mesh = &attach_;
        support.attach_bvh = &attach_bvh_;
      }
    }
    log_ = ivy::GrowLog{};
    // The page's budget (docs/budgets.md): the support, the model and its meshes within what a
    // tab's WASM heap holds; a bigger ivy stops at a step with the line in its stats.
    ivy::IvySupportSize size;
    size.triangles = scene_.free ? 0 : static_cast<double>(scene_.mesh.triangle_count());
    size.obstacles = obstacles_ > 0;
    Estimate support_estimate = ivy::EstimateIvySupport(size);
    support_estimate.seconds += tree_seconds_;  // a tree support's growth and bark
    limits_ = ivy::IvyLimits(state.params, PageBudget(), support_estimate, !scene_.free);
    limits_.bytes_per_bud += ivy::IvyPageMeshBytesPerBud();
    limits_.change = "lower Steps, or raise t1 and t2";  // the page's fields, not the CLI's flags
    stats_limits_ = limits_;  // the statistics' own check replaces the room kept for them
    // The page measures every grow (statsJson): keep room for its brute-force re-checks.
    ivy::ReserveIvyStats(size.triangles, &limits_);
    const ivy::StepObserver on_step = [this](int step, int steps) {
      Progress("grow", step, steps);
    };
    Result<ivy::IvyModel> model =
        ivy::Grow(support, seeds, state.params, state.steps, state.seed, &log_, &limits_, on_step);
    if (!model.ok()) return model.status().Line();
    state_ = state;
    model_ = std::move(model).value();
    const auto t1 = Clock::now();
    meshes_ = ivy::BuildIvyMeshes(model_, state_.params);
    stems_ = Flatten(meshes_.stems);
    leaves_ = Flatten(meshes_.leaves);
    suckers_ = Flatten(meshes_.suckers);
    buds_ = FlatMesh{};
    for (const ivy::Bud& b : model_.buds) {
      buds_.positions.insert(
          buds_.positions.end(),
          {static_cast<float>(b.pos.x), static_cast<float>(b.pos.y), static_cast<float>(b.pos.z)});
      buds_.normals.push_back(static_cast<float>(static_cast<int>(b.kind)));
      buds_.birth.push_back(static_cast<float>(b.born_step));
    }
    timings_ = {};
    timings_.ms_mesh = Ms(t1, Clock::now());
    timings_.ms_bvh = ms_bvh_;
    timings_.ms_rules = log_.ms_rules;
    timings_.ms_search = log_.ms_search;
    timings_.ms = Ms(t0, Clock::now()) + ms_bvh_;
    glb_.clear();
    grown_ = true;
    return "";
  }

  // The --stats object of the last grow (as `niwa ivy grow --stats`), or "{}".
  std::string statsJson() const {
    if (!grown_) return "{}";
    // As `niwa ivy grow --stats`: the measurement's exact estimate (the overlap sweep's pairs,
    // counted before any is tested) with the grown ivy's, against the page's budget. The growth
    // kept room for the rest (ReserveIvyStats); when the pairs do not fit, the sweep is left out
    // and its line is a notice (overlap_skipped_by), the other statistics are still measured.
    const double tris = scene_.free ? 0 : static_cast<double>(scene_.mesh.triangle_count());
    const Status fits = CheckEstimate(
        ivy::EstimateIvyGrown(model_, log_, stats_limits_) +
            ivy::EstimateIvyStats(ivy::CountIvyStatsWork(model_, state_.params, tris)),
        PageBudget(), "grow fewer steps (the page leaves the overlap pairs out)");
    ivy::IvyStats stats =
        ivy::MeasureIvy(model_, log_, scene_.free ? nullptr : &scene_.mesh, state_.params,
                        obstacles_ > 0 ? &attach_ : nullptr, fits.ok());
    stats.overlap_skipped_by = fits.Line();
    stats.tree_truncated_by = tree_truncated_by_;
    return ivy::IvyStatsJson(stats, log_, model_, timings_);
  }

  std::string hash() const { return grown_ ? ivy::EncodeIvyHash(state_) : ""; }
  int steps() const { return grown_ ? state_.steps : 0; }
  std::string modelJson() const {
    return grown_ ? ivy::IvyModelJson(model_, state_.params, state_.seed, state_.steps) + "\n" : "";
  }
  std::string lstring() const { return grown_ ? ivy::PrintLString(model_) : ""; }

  // Whether a download (glb, json, lsys) of the last grow fits the page's budget: "" or the line
  // naming it ("page memory budget: writing the .glb (...) needs about ...").
  std::string exportCheck(const std::string& format, bool with_support) const {
    if (!grown_) return "";
    const ivy::IvyExport kind = format == "json"   ? ivy::IvyExport::kJson
                                : format == "lsys" ? ivy::IvyExport::kLsys
                                                   : ivy::IvyExport::kGlb;
    const double tris = with_support && kind == ivy::IvyExport::kGlb
                            ? static_cast<double>(scene_.mesh.triangle_count())
                            : 0;
    return CheckEstimate(ivy::EstimateIvyGrown(model_, log_, limits_) +
                             ivy::EstimateIvyExport(model_, kind, tris),
                         PageBudget(), "grow fewer steps")
        .Line();
  }

  // The .glb of the last grow (with the support when asked): "" or one error line.
  std::string buildGlb(bool with_support) {
    if (!grown_) return "glb: nothing grown yet";
    if (std::string line = exportCheck("glb", with_support); !line.empty()) return line;
    Result<std::vector<unsigned char>> glb =
        ivy::WriteIvyGlb(model_, state_.params, state_.seed, state_.steps,
                         with_support && !scene_.free ? &scene_.mesh : nullptr);
    if (!glb.ok()) return glb.status().Line();
    glb_ = std::move(glb).value();
    return "";
  }

  // The first support face hit by the ray: {hit, point, normal, distance, triangle}.
  std::string rayCast(double ox, double oy, double oz, double dx, double dy, double dz) const {
    ordered_json j;
    j["hit"] = false;
    if (!scene_.free && scene_.mesh.triangle_count() > 0 &&
        std::isfinite(ox + oy + oz + dx + dy + dz)) {
      geom::RayHit h =
          geom::FirstHit(scene_.mesh, bvh_, glm::vec3(ox, oy, oz), glm::vec3(dx, dy, dz),
                         std::numeric_limits<float>::infinity());
      if (h.hit) {
        j["hit"] = true;
        j["point"] = {h.point.x, h.point.y, h.point.z};
        j["normal"] = {h.normal.x, h.normal.y, h.normal.z};
        j["distance"] = h.distance;
        j["triangle"] = h.triangle;
      }
    }
    return Dump(j);
  }

  emscripten::val buffers(const std::string& group) const {
    NamedBuffers out;
    const auto part = [&out](const FlatMesh& m) {
      out.Add("positions", m.positions)
          .Add("normals", m.normals)
          .Add("indices", m.indices)
          .Add("birth", m.birth);
      if (!m.uvs.empty()) out.Add("uvs", m.uvs);
    };
    if (group == "support") {
      out.Add("positions", support_.positions)
          .Add("normals", support_.normals)
          .Add("indices", support_.indices);
    } else if (group == "stems") {
      part(stems_);
    } else if (group == "leaves") {
      part(leaves_);
    } else if (group == "suckers") {
      part(suckers_);
    } else if (group == "buds") {
      out.Add("positions", buds_.positions).Add("kind", buds_.normals).Add("birth", buds_.birth);
    } else if (group == "glb") {
      out.Add("bytes", glb_);
    } else {
      return emscripten::val::null();
    }
    return out.ToJs();
  }

 private:
  void Progress(const char* stage, double done, double total) const {
    if (!progress_.isNull() && !progress_.isUndefined()) progress_(std::string(stage), done, total);
  }

  // The BVHs and the flat support buffers of the scene just loaded; forgets the last ivy.
  void Prepare() {
    bvh_ = scene_.free ? geom::Bvh{} : geom::Bvh::Build(scene_.mesh);
    attach_bvh_ = obstacles_ > 0 ? geom::Bvh::Build(attach_) : geom::Bvh{};
    support_ = Flatten(scene_.mesh);
    if (support_.normals.size() != support_.positions.size())
      support_.normals = FaceNormals(scene_.mesh);
    grown_ = false;
    model_ = ivy::IvyModel{};
    stems_ = leaves_ = suckers_ = buds_ = FlatMesh{};
    glb_.clear();
  }

  ivy::IvyScene scene_;
  std::string mesh_name_;
  geom::TriMesh attach_;
  std::size_t obstacles_ = 0;
  geom::Bvh bvh_, attach_bvh_;
  double ms_bvh_ = 0;
  FlatMesh support_;
  bool grown_ = false;
  ivy::IvyState state_;
  ivy::IvyModel model_;
  ivy::GrowLog log_;
  ivy::IvyGrowLimits limits_;
  double tree_seconds_ = 0;  // a tree support: its growth and bark's estimated seconds
  ivy::IvyGrowLimits
      stats_limits_;  // limits_ without ReserveIvyStats (as the CLI's EstimateIvyGrown)
  std::string tree_truncated_by_;  // a tree support that stopped at the page budget: its line
  ivy::IvyTimings timings_;
  ivy::IvyMeshes meshes_;
  FlatMesh stems_, leaves_, suckers_;
  FlatMesh buds_;  // positions, kind (in normals), birth
  std::vector<unsigned char> glb_;
  emscripten::val progress_ = emscripten::val::null();
};

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_ivy) {
  using namespace emscripten;
  function("ivyParamTableJson", &niwa::IvyParamTableJson);
  function("ivyPresetsJson", &niwa::IvyPresetsJson);
  function("ivyScenesJson", &niwa::IvyScenesJson);
  function("ivyLeafTexture", &niwa::IvyLeafTexture);
  function("ivyDecodeHash", &niwa::IvyDecodeHash);
  function("ivyEncodeHash", &niwa::IvyEncodeHash);
  class_<niwa::IvyLab>("IvyLab")
      .constructor<>()
      .function("loadScene", &niwa::IvyLab::loadScene)
      .function("loadTree", &niwa::IvyLab::loadTree)
      .function("loadMesh", &niwa::IvyLab::loadMesh)
      .function("supportJson", &niwa::IvyLab::supportJson)
      .function("grow", &niwa::IvyLab::grow)
      .function("statsJson", &niwa::IvyLab::statsJson)
      .function("hash", &niwa::IvyLab::hash)
      .function("steps", &niwa::IvyLab::steps)
      .function("modelJson", &niwa::IvyLab::modelJson)
      .function("lstring", &niwa::IvyLab::lstring)
      .function("buildGlb", &niwa::IvyLab::buildGlb)
      .function("exportCheck", &niwa::IvyLab::exportCheck)
      .function("rayCast", &niwa::IvyLab::rayCast)
      .function("setProgress", &niwa::IvyLab::setProgress)
      .function("buffers", &niwa::IvyLab::buffers);
}
