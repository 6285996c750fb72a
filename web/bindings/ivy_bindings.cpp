// The ivy study's bindings (paper 004): IvyLab, one support (a built-in scene or a dropped mesh,
// with its BVH) and the last ivy grown on it, for the worker (web/worker/ivy_handler.js); and the
// ivy table, presets, scenes and hash codec as JSON.
//
// Design (as the tree's "JS BINDINGS DESIGN" note in tree_bindings.cpp): everything from
// JavaScript arrives as text or bytes and is checked by the core (core/ivy/ivy_state,
// io/gltf_reader, ivy::Grow); nothing throws, errors come back as one line ("" = success).
// Buffers leave through buffers(group) (buffers.h), copied once by the worker. Groups:
//   "support"                    positions, normals (Float32 xyz), indices (Uint32); a dropped
//                                glTF's look: uvs (Float32 uv: where its material's
//                                baseColorTexture is sampled, io kBaseColorUvAttribute), colors
//                                (Float32 RGBA: COLOR_0) and material (Float32: the index in
//                                supportJson's materials, -1 none), each when the file has them
//   "stems" | "leaves" | "suckers"  positions, normals, indices, birth (Float32 per vertex: the
//                                birth_step of core/ivy/ivy_mesh.h, the .glb's _BIRTH_STEP);
//                                "leaves" also uvs (Float32 uv per vertex: the .glb's TEXCOORD_0)
//   "buds"                       positions (Float32 xyz), kind (Float32: 0 A, 1 D, 2 Z, as at the
//                                last step), birth (Float32: the step the bud was made)
//   "glb"                        bytes (Uint8, after buildGlb)
// ivyLeafTexture() -> {width, height, pixels: Uint8Array RGBA (row 0 = v 0)}: the leaf
// texture's pixels, the ones the .glb's PNG holds (core/ivy/ivy_leaf_texture.h).
// Calls (each a thin adapter over core/ivy/ivy_run's IvySupport and IvyRun, which the CLI also
// drives): loadScene(name), loadTree(preset, years) (a Niwa tree's bark, core/compose/ivy_on_tree,
// as the CLI's --tree-preset) or loadMesh(bytes, name) -> ""/error, supportJson(); grow(stateJson)
// ->
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
#include <optional>
#include <string>
#include <vector>

#include "buffers.h"
#include "compose/ivy_on_tree.h"
#include "error_record.h"
#include "geom/mesh_metrics.h"
#include "geom/ray_cast.h"
#include "image_val.h"
#include "io/mesh_reader.h"
#include "ivy/ivy_budget.h"
#include "ivy/ivy_leaf_texture.h"
#include "ivy/ivy_params.h"
#include "ivy/ivy_run.h"
#include "ivy/ivy_state.h"
#include "ivy/scenes.h"
#include "page_budget.h"
#include "params/param_json.h"
#include "run/field_names.h"

namespace niwa {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

json Vec(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

// Flat float views of a TriMesh's vectors (glm::vec3 is three packed floats).
struct FlatMesh {
  std::vector<float> positions, normals, birth, uvs;
  std::vector<uint32_t> indices;
  std::vector<float> colors, material;  // the support's look (a dropped glTF's), else empty
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

}  // namespace

// The leaf texture (ivy_leaf_texture.h), the pixels the .glb's PNG encodes, copied out of the heap.
emscripten::val IvyLeafTexture() {
  const image::Rgba8Image image = ivy::PaintLeafTexture(ivy::kLeafTextureSize);
  return ImageToJs(image);
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

// The page's support: no subdivision, BVH queries, a dropped mesh's default "front" seed, its
// estimate entering the growth's limits (not refused up front).
ivy::IvySupportOptions PageSupportOptions() {
  ivy::IvySupportOptions options;
  options.front_seed = true;
  options.check_budget = false;
  options.mesh_attach_always_counted = false;
  return options;
}

// The page's run: the page's budget (docs/budgets.md), its meshes held per bud, its fields in the
// lines, and every grow measured (statsJson) with room kept for the brute-force re-checks.
ivy::IvyRunOptions PageRunOptions() {
  ivy::IvyRunOptions options;
  options.reserve_stats = true;
  options.extra_bytes_per_bud = ivy::IvyPageMeshBytesPerBud();
  options.change = "lower Steps, or raise t1 and t2";  // the page's fields, not the CLI's flags
  options.build_meshes = true;
  options.export_change = "grow fewer steps";
  options.stats_change = "grow fewer steps (the page leaves the overlap pairs out)";
  options.export_with_stats_room = true;
  return options;
}

class IvyLab {
 public:
  // A built-in scene: "" or an error record ("scene: 'x' is unknown; must be one of ...").
  std::string loadScene(const std::string& name) {
    const auto t0 = Clock::now();
    Result<std::shared_ptr<const ivy::IvySupport>> s = ivy::IvySupport::Prepare(
        ivy::IvySupportInput::Scene(name), PageSupportOptions(), PageBudget());
    if (!s.ok()) return ErrorText(Status::Error("scene", s.status().message()));
    SetSupport(std::move(s).value());
    ms_bvh_ = Ms(t0, Clock::now());
    return "";
  }

  // The bark of tree preset `preset` grown `years` years (metres), seeded at the trunk foot as
  // `niwa ivy grow --tree-preset` does (core/compose/ivy_on_tree): "" or an error record naming
  // tree or tree_years. The tree stops where its bark fits the page's budget, or is refused.
  std::string loadTree(const std::string& preset, double years) {
    Progress("tree", 0, years);
    Result<ivy::IvySupportInput> tree = compose::IvyTreeSupport(
        preset, years, PageBudget(), "tree_years",
        [this](const char* stage, double done, double total) { Progress(stage, done, total); });
    if (!tree.ok()) return ErrorText(tree.status());
    Progress("bvh", 0, static_cast<double>(tree->prepared.mesh.triangle_count()));
    const auto t0 = Clock::now();  // ms_bvh: the support's BVH, not the tree's growth
    Result<std::shared_ptr<const ivy::IvySupport>> s =
        ivy::IvySupport::Prepare(std::move(tree).value(), PageSupportOptions(), PageBudget());
    if (!s.ok()) return ErrorText(s.status());
    SetSupport(std::move(s).value());
    ms_bvh_ = Ms(t0, Clock::now());
    return "";
  }

  void setProgress(emscripten::val fn) { progress_ = fn; }

  // A dropped .glb/.gltf/.obj (bytes; Draco already decoded): "" or an error record naming it.
  std::string loadMesh(const std::string& bytes, const std::string& name) {
    Progress("read", 0, static_cast<double>(bytes.size()));
    io::MeshReadStats read;
    Result<geom::TriMesh> mesh = io::ReadMeshBytes(bytes, name, &read);
    if (!mesh.ok()) return ErrorText(mesh.status());
    Status valid = geom::ValidateMesh(*mesh, name);
    if (!valid.ok()) return ErrorText(valid);
    Progress("bvh", 0, static_cast<double>(mesh->triangle_count()));
    const auto t0 = Clock::now();
    std::vector<io::MeshMaterial> materials = read.materials;  // the page draws with them
    Result<std::shared_ptr<const ivy::IvySupport>> s = ivy::IvySupport::Prepare(
        ivy::IvySupportInput::Mesh(std::move(mesh).value(), name, std::move(read.materials),
                                   read.metres_per_unit),
        PageSupportOptions(), PageBudget());
    if (!s.ok()) return ErrorText(run::RenameField(s.status(), {{"mesh", name}}));
    SetSupport(std::move(s).value());
    materials_ = std::move(materials);
    ms_bvh_ = Ms(t0, Clock::now());
    return "";
  }

  // {name, dropped, free, triangles, obstacles, bounds: {min, max}, px_per_unit (its own scale:
  // the paper pixels per unit of the row "scale" at 0, auto), look_px_per_unit (its tubes' and
  // leaves' own: 1000 on a glTF, in metres, whatever its size), seeds: [{name, pos}], ms_bvh,
  // materials: [{name, base_color: linear RGBA, image: the glTF image index of its
  // baseColorTexture or -1 (WebP too: the page decodes it), wrap_s, wrap_t}] (a dropped glTF's)}.
  std::string supportJson() const {
    ordered_json j;
    if (!support_) return JsonText(j);
    const ivy::IvyScene& scene = support_->scene();
    j["name"] = scene.name;
    j["dropped"] = support_->is_mesh();
    j["free"] = scene.free;
    j["triangles"] = scene.mesh.triangle_count();
    j["obstacles"] = support_->obstacles();
    const geom::Bounds3 b = geom::MeshBounds(scene.mesh);
    if (scene.mesh.triangle_count() > 0) {
      j["bounds"] = {{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}};
    } else {
      j["bounds"] = nullptr;
    }
    j["px_per_unit"] = support_->px_per_unit();
    j["look_px_per_unit"] = support_->look_px_per_unit();  // a glTF's metres (issue 31 item 7)
    ordered_json seeds = ordered_json::array();
    for (const ivy::NamedSeed& seed : scene.seeds)
      seeds.push_back({{"name", seed.name}, {"pos", Vec(seed.pos)}});
    j["seeds"] = seeds;
    j["ms_bvh"] = ms_bvh_;
    ordered_json materials = ordered_json::array();
    for (const io::MeshMaterial& m : materials_) {
      materials.push_back(
          {{"name", m.name},
           {"base_color", {m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a}},
           {"image", m.base_color_source},
           {"wrap_s", m.wrap_s},
           {"wrap_t", m.wrap_t}});
    }
    j["materials"] = materials;
    return JsonText(j);
  }

  // Grows the state (JSON, as ApplyIvyStateJson reads it) on the support loaded through the ivy
  // run (core/ivy/ivy_run): "" or an error record. Seed points: the state's, else the scene's first
  // named seed (a dropped mesh with no front seed needs one).
  std::string grow(const std::string& state_json) {
    const auto t0 = Clock::now();
    // The last ivy on this support, kept for a state that changes only mesh-stage rows (the run
    // re-meshes it, IvyRun::Update); any other change grows afresh.
    std::optional<ivy::IvyRun> last = std::move(run_);
    run_.reset();
    ivy::IvyState state;
    Status s = ivy::ApplyIvyStateJson(state_json, &state);
    if (s.ok()) s = ValidateIvyParams(state.params);
    if (!s.ok()) return ErrorText(s);
    if (!support_) return ErrorText(Status::Error("scene", "no support loaded"));
    if (state.seed_points.empty() && support_->scene().seeds.empty()) {
      return ErrorText(
          Status::Error("at", "a dropped mesh needs a seed point; click its surface to place one"));
    }
    std::optional<ivy::IvyRun> run;
    if (last && last->Update(state).ok()) {
      run = std::move(last);
    } else {
      Result<ivy::IvyRun> started =
          ivy::IvyRun::Start(state, support_, PageBudget(), PageRunOptions());
      if (!started.ok()) return ErrorText(started.status());
      run = std::move(started).value();
    }
    s = run->Advance([this](const run::Progress& p) {
      Progress(p.phase.c_str(), p.done, p.total);
      return true;
    });
    // Core errors name state fields, the page's keys (seed_points and steps sit beside their
    // fields); a dropped mesh's own error names the file, as its loadMesh errors do.
    if (!s.ok()) return ErrorText(run::RenameField(s, {{"mesh", support_->scene().name}}));
    const ivy::IvyMeshes& meshes = run->meshes();
    stems_ = Flatten(meshes.stems);
    leaves_ = Flatten(meshes.leaves);
    suckers_ = Flatten(meshes.suckers);
    buds_ = FlatMesh{};
    for (const ivy::Bud& b : run->model().buds) {
      buds_.positions.insert(
          buds_.positions.end(),
          {static_cast<float>(b.pos.x), static_cast<float>(b.pos.y), static_cast<float>(b.pos.z)});
      buds_.normals.push_back(static_cast<float>(static_cast<int>(b.kind)));
      buds_.birth.push_back(static_cast<float>(b.born_step));
    }
    ivy::IvyTimings& t = run->timings();
    t.ms_bvh = ms_bvh_;
    t.ms = Ms(t0, Clock::now()) + ms_bvh_;
    glb_.clear();
    run_ = std::move(run);
    return "";
  }

  // The --stats object of the last grow (as `niwa ivy grow --stats`), or "{}": the measurement
  // within the page's budget, its overlap sweep left out (overlap_skipped_by) when it does not fit.
  std::string statsJson() const { return run_ ? run_->StatsJson() : "{}"; }

  std::string hash() const { return run_ ? run_->Hash("") : ""; }
  int steps() const { return run_ ? run_->state().steps : 0; }
  std::string modelJson() const { return Text("json"); }
  std::string lstring() const { return Text("lsys"); }

  // Whether a download (glb, json, lsys) of the last grow fits the page's budget: "" or the line
  // naming it ("page memory budget: writing the .glb (...) needs about ...").
  std::string exportCheck(const std::string& format, bool with_support) const {
    if (!run_) return "";
    const std::string kind = format == "json" || format == "lsys" ? format : "glb";
    return ErrorText(run_->CheckExport(kind, with_support));
  }

  // The .glb of the last grow (with the support when asked): "" or an error record.
  std::string buildGlb(bool with_support) {
    if (!run_) return ErrorText(Status::Error("glb", "nothing grown yet"));
    ivy::IvyExportOptions options;
    options.with_support = with_support;
    Result<std::string> glb = run_->Export("glb", options);
    if (!glb.ok()) return ErrorText(glb.status());
    glb_.assign(glb->begin(), glb->end());
    return "";
  }

  // The first support face hit by the ray: {hit, point, normal, distance, triangle}.
  std::string rayCast(double ox, double oy, double oz, double dx, double dy, double dz) const {
    ordered_json j;
    j["hit"] = false;
    if (support_ && !support_->free() && support_->scene().mesh.triangle_count() > 0 &&
        std::isfinite(ox + oy + oz + dx + dy + dz)) {
      geom::RayHit h =
          geom::FirstHit(support_->scene().mesh, support_->bvh(), glm::vec3(ox, oy, oz),
                         glm::vec3(dx, dy, dz), std::numeric_limits<float>::infinity());
      if (h.hit) {
        j["hit"] = true;
        j["point"] = {h.point.x, h.point.y, h.point.z};
        j["normal"] = {h.normal.x, h.normal.y, h.normal.z};
        j["distance"] = h.distance;
        j["triangle"] = h.triangle;
      }
    }
    return JsonText(j);
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
      out.Add("positions", support_buffers_.positions)
          .Add("normals", support_buffers_.normals)
          .Add("indices", support_buffers_.indices);
      if (!support_buffers_.uvs.empty()) out.Add("uvs", support_buffers_.uvs);
      if (!support_buffers_.colors.empty()) out.Add("colors", support_buffers_.colors);
      if (!support_buffers_.material.empty()) out.Add("material", support_buffers_.material);
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

  std::string Text(const std::string& format) const {
    if (!run_) return "";
    Result<std::string> text = run_->ExportUnchecked(format, {});
    return text.ok() ? *text : "";
  }

  // The support just prepared and its flat buffers; forgets the last ivy.
  void SetSupport(std::shared_ptr<const ivy::IvySupport> support) {
    support_ = std::move(support);
    const geom::TriMesh& mesh = support_->scene().mesh;
    support_buffers_ = Flatten(mesh);
    // Its look: the base colour's uvs (not TEXCOORD_0 as read), COLOR_0 and the material index.
    support_buffers_.uvs.clear();
    const std::size_t n = mesh.positions.size();
    const auto look = [&mesh, n](const char* name, int width, std::vector<float>* to) {
      const geom::VertexAttribute* a = mesh.FindAttribute(name);
      if (a != nullptr && a->components == width &&
          a->values.size() == n * static_cast<std::size_t>(width))
        *to = a->values;
    };
    look(io::kBaseColorUvAttribute, 2, &support_buffers_.uvs);
    look(io::kColorAttribute, 4, &support_buffers_.colors);
    look(io::kMaterialAttribute, 1, &support_buffers_.material);
    materials_.clear();
    if (support_buffers_.normals.size() != support_buffers_.positions.size()) {
      support_buffers_.normals.clear();
      for (const glm::vec3& n : geom::FaceNormals(mesh))
        support_buffers_.normals.insert(support_buffers_.normals.end(), {n.x, n.y, n.z});
    }
    run_.reset();
    stems_ = leaves_ = suckers_ = buds_ = FlatMesh{};
    glb_.clear();
  }

  std::shared_ptr<const ivy::IvySupport> support_;
  std::vector<io::MeshMaterial> materials_;  // a dropped glTF's, for the page's drawing
  double ms_bvh_ = 0;
  FlatMesh support_buffers_;
  std::optional<ivy::IvyRun> run_;  // the last grow, empty before one (or after a failed one)
  FlatMesh stems_, leaves_, suckers_;
  FlatMesh buds_;  // positions, kind (in normals), birth
  std::vector<unsigned char> glb_;
  emscripten::val progress_ = emscripten::val::null();
};

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_ivy) {
  using namespace emscripten;
  function("ivyScenesJson", &niwa::IvyScenesJson);
  function("ivyLeafTexture", &niwa::IvyLeafTexture);
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
