// The moss study's bindings (Nomura 2010; spec §1): MossLab, one moss run (core/moss/moss_run.h)
// grown to its days for the worker (web/worker/moss_handler.js), with every moss that was ever
// alive kept with its birth and death day, so the page's day scrubber replays day 0..N without
// growing again; and the moss table, presets, scenes and hash codec as JSON (the compose registry,
// core/compose/studies.cpp, has no moss row yet, so the generic tableJson('moss') cannot answer).
//
// Design (as the tree's "JS BINDINGS DESIGN" note in tree_bindings.cpp): everything from
// JavaScript arrives as text and is checked by the core (SetMossPreset, the table's ranges,
// CheckMossParams, SetMossScene/Days/Seed, MossRun::Start's estimate against the page budget);
// nothing throws, errors come back as the {ok, field, message} record (error_record.h) naming a
// state field: preset, scene, days, seed, a row key, or the budget's line. Buffers leave through
// buffers(group) (buffers.h), copied once by the worker. Groups:
//   "land"    positions, normals (Float32 xyz: three vertices per soil cell, the cell's flat
//             normal), coverage (Float32 per vertex: the cell's min(1, n·s²/A) of the last day,
//             as the stats' coverage), irradiance (Float32 per vertex: the cell's S of the last
//             day, W/m²), geology (Float32 per vertex: 0 humus, 1 sandy, 2 asphalt), and the
//             last day's soil state per vertex (Float32, the cell's; MossWorld): T_s (K), rh_s,
//             theta (soil water), fitness (the best species' G of eq 3.17 from the cell's T_s,
//             rh_s and the soil's S; a moss itself is scored with the S it gathers)
//   "mosses"  positions, normals (Float32 xyz: a moss's centre and the normal of what it grows
//             on), species (Float32: 0 gingoke, 1 haigoke, 2 sugigoke), birth (Float32: its birth
//             day), death (Float32: the first day it was gone, -1 while alive), cell (Uint32:
//             its soil cell, the land's triangle), on_moss (Float32: 1 when it rests on other
//             mosses); one entry per moss ever alive at the end of a day, in order of first
//             appearance (the page replays any day's coverage from them)
//   "photons" positions (Float32 xyz) and depth (Float32: 0 straight from the sun or sky, n
//             after n bounces) of every photon the last day stored (MossRun::photon_map()), on
//             the land and on mosses (figs 4.1/4.2's photon points)
// Calls: setProgress(fn) (fn(stage, done, total) after every day), grow(stateJson) -> ""/error
// record (on the state's land: a built-in scene, or scene "tree" / "terrain" with its land fields,
// grown through core/compose/moss_land.h), or loadMesh(bytes, name) -> ""/error record (a dropped
// .glb/.gltf/.obj, Draco already decoded by the page, read as `niwa moss grow --mesh` reads a
// file: soil_cells.h SceneFromMesh, geology from its materials, textures and colours) then
// growOnMesh(stateJson) (MossRun::StartOnScene: the stats say scene "mesh" and the file's name;
// errors about the mesh name the field "mesh"), shareMesh(otherLab) (the other lab's mesh, shared:
// the A/B view), meshJson() ({name, triangles} or {}); then
// statsJson() (the CLI's `niwa moss grow --stats`, ms* timing fields included), hash(),
// stateJson(), boundsJson(), buffers(group); build("glb"|"json") then buffers("download"): the
// bytes of `--out moss.glb` / `--out moss.json`. The state JSON: {preset, scene, days, seed,
// [tree, tree_years | terrain, terrain_seed], params: {row: value}} (params over the preset's).
// Does not: keep more than one run or mesh, or tell a moss that
// died and one with the same place, species and birth day apart (the run never makes two).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "buffers.h"
#include "compose/moss_land.h"
#include "error_record.h"
#include "geom/mesh_metrics.h"
#include "io/gltf_writer.h"
#include "io/mesh_reader.h"
#include "moss/fitness.h"
#include "moss/moss_params.h"
#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "page_budget.h"
#include "params/json_guard.h"
#include "params/param_json.h"

namespace niwa {
namespace {

using moss::MossParam;
using nlohmann::json;
using nlohmann::ordered_json;

ordered_json MossStateObject(const moss::MossState& state) {
  ordered_json j;
  j["preset"] = state.preset;
  j["scene"] = state.scene;
  j["days"] = state.days;
  j["seed"] = state.seed;
  if (state.scene == moss::kTreeLand) {
    j["tree"] = state.tree;
    j["tree_years"] = state.tree_years;
  } else if (state.scene == moss::kTerrainLand) {
    j["terrain"] = state.terrain;
    j["terrain_seed"] = state.terrain_seed;
  } else if (state.scene == "rocks" && state.rock_triangles != moss::kRockTrianglesDefault) {
    j["rock_triangles"] = state.rock_triangles;
  }
  j["params"] = ordered_json::parse(ParamsToJson(state.params, -1));
  return j;
}

void PushVec(std::vector<float>* out, const glm::dvec3& v) {
  out->insert(out->end(),
              {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)});
}

}  // namespace

// The built-in scenes as `niwa moss scenes` lists them.
std::string MossScenes() { return moss::MossScenesJson(); }

// An adapter over core/moss/moss_run.h: one run grown to its days, its land and its mosses'
// lives flattened for the page.
class MossLab {
 public:
  void setProgress(emscripten::val fn) { progress_ = fn; }

  // Starts the run of the state (JSON, above) and grows it to its days, recording every moss's
  // life: "" or the error record (the last run is kept on error).
  std::string grow(const std::string& state_json) { return Grow(state_json, false); }
  // The same on the mesh loadMesh read (the state's scene is not read).
  std::string growOnMesh(const std::string& state_json) { return Grow(state_json, true); }

  // A dropped mesh file's bytes: "" with the mesh kept for growOnMesh, or the error record
  // (field "mesh"; the mesh loaded before is kept).
  std::string loadMesh(const std::string& bytes, const std::string& name) {
    io::MeshReadStats read;
    Result<geom::TriMesh> mesh = io::ReadMeshBytes(bytes, name, &read);
    if (!mesh.ok()) return ErrorText(mesh.status().Within("mesh"));
    Status valid = geom::ValidateMesh(*mesh, name);
    if (!valid.ok()) return ErrorText(valid.Within("mesh"));
    Result<moss::MossScene> scene = moss::SceneFromMesh(*mesh, read.materials, name, read.images);
    if (!scene.ok()) return ErrorText(scene.status().Within("mesh"));
    mesh_scene_ = std::make_shared<const moss::MossScene>(std::move(scene).value());
    mesh_name_ = name;
    mesh_triangles_ = mesh->triangle_count();
    return "";
  }

  // Takes the mesh `other` read (the A/B view's second lab grows on run A's dropped mesh): the
  // same scene, shared, not read or copied again; other without a mesh leaves this lab without one.
  void shareMesh(const MossLab& other) {
    mesh_scene_ = other.mesh_scene_;
    mesh_name_ = other.mesh_name_;
    mesh_triangles_ = other.mesh_triangles_;
  }

  std::string meshJson() const {
    ordered_json j = ordered_json::object();
    if (mesh_scene_) {
      j["name"] = mesh_name_;
      j["triangles"] = mesh_triangles_;
    }
    return JsonText(j);
  }

 private:
  std::string Grow(const std::string& state_json, bool on_mesh) {
    moss::MossState state;
    Status s = moss::ApplyMossStateJson(state_json, &state);
    if (!s.ok()) return ErrorText(s);
    if (on_mesh && !mesh_scene_) return ErrorText(Status::Error("mesh", "no mesh is loaded"));
    // A built-in scene, or the state's Niwa tree or terrain grown through the composition tier
    // (as `niwa moss grow --url` grows it).
    Result<moss::MossRun> started =
        on_mesh ? moss::MossRun::StartOnScene(state, *mesh_scene_, PageBudget(), mesh_name_)
                : compose::StartMossOnLand(state, PageBudget(), {}, nullptr);
    if (!started.ok()) return ErrorText(started.status());
    moss::MossRun run = std::move(started).value();
    Lives lives;
    s = run.Advance([&](const run::Progress& p) {
      lives.Observe(run.world());
      if (!progress_.isNull() && !progress_.isUndefined())
        progress_(std::string(p.phase), p.done, p.total);
      return true;
    });
    if (!s.ok()) return ErrorText(s);
    state_ = state;
    run_.emplace(std::move(run));
    FillLand();
    FillMosses(lives);
    FillPhotons();
    return "";
  }

 public:
  std::string statsJson() const { return run_ ? run_->StatsJson() : "{}"; }
  std::string hash() const { return run_ ? run_->Hash("") : ""; }
  std::string stateJson() const { return run_ ? JsonText(MossStateObject(state_)) : "{}"; }

  // One download of the last run into the "download" group: "" or an error record. glb: the bytes
  // of `niwa moss grow ... --out moss.glb` (the coverage map, tufts merged: the run's Document());
  // json: those of --out moss.json. Refused (field "download") over the page's memory budget.
  std::string build(const std::string& format) {
    download_.clear();
    if (!run_) return ErrorText(Status::Error("download", "nothing grown yet"));
    if (format != "glb" && format != "json") {
      return ErrorText(Status::Error("download", "format '" + format.substr(0, 20) +
                                                     "' is unknown; must be glb or json"));
    }
    Result<Estimate> needs = run_->ExportEstimate(format);
    if (!needs.ok()) return ErrorText(needs.status().Within("download"));
    const Status fits = CheckEstimate(*needs, PageBudget(), "lower days or max_mosses");
    if (!fits.ok()) return ErrorText(fits);
    if (format == "json") {
      const std::string text = run_->MossesJson() + "\n";
      download_.assign(text.begin(), text.end());
      return "";
    }
    Result<gltf::Document> doc = run_->Document();
    if (!doc.ok()) return ErrorText(doc.status().Within("download"));
    Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
    if (!glb.ok()) return ErrorText(glb.status().Within("download"));
    download_ = std::move(glb).value();
    return "";
  }

  // {min, max (the land's box, m), cells, days, mosses_ever, mosses_alive, irradiance_max (W/m²)}.
  std::string boundsJson() const {
    if (!run_) return "{}";
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::vec3& p : run_->cells().mesh.positions) {
      lo = glm::min(lo, glm::dvec3(p));
      hi = glm::max(hi, glm::dvec3(p));
    }
    ordered_json j;
    j["min"] = {lo.x, lo.y, lo.z};
    j["max"] = {hi.x, hi.y, hi.z};
    j["cells"] = run_->cells().size();
    j["days"] = run_->done();
    j["mosses_ever"] = moss_species_.size();
    j["mosses_alive"] = run_->world().mosses.size();
    double s_max = 0;
    for (double S : run_->world().S) s_max = std::max(s_max, S);
    j["irradiance_max"] = s_max;
    return JsonText(j);
  }

  emscripten::val buffers(const std::string& group) const {
    NamedBuffers out;
    if (group == "land") {
      out.Add("positions", land_positions_)
          .Add("normals", land_normals_)
          .Add("coverage", land_coverage_)
          .Add("irradiance", land_irradiance_)
          .Add("geology", land_geology_)
          .Add("T_s", land_T_s_)
          .Add("rh_s", land_rh_s_)
          .Add("theta", land_theta_)
          .Add("fitness", land_fitness_);
    } else if (group == "mosses") {
      out.Add("positions", moss_positions_)
          .Add("normals", moss_normals_)
          .Add("species", moss_species_)
          .Add("birth", moss_birth_)
          .Add("death", moss_death_)
          .Add("cell", moss_cell_)
          .Add("on_moss", moss_on_moss_);
    } else if (group == "photons") {
      out.Add("positions", photon_positions_).Add("depth", photon_depth_);
    } else if (group == "download") {
      out.Add("bytes", download_);
    } else {
      return emscripten::val::null();
    }
    return out.ToJs();
  }

 private:
  // Every moss seen at the end of a day, matched from day to day: the run keeps its living
  // mosses in order, drops the dead and appends the newborn, and never moves one.
  struct Life {
    moss::MossPlant plant;
    int death = -1;
  };
  struct Lives {
    std::vector<Life> ever;
    std::vector<uint32_t> alive;  // indexes into ever, in the run's order
    void Observe(const moss::MossWorld& w) {
      std::vector<uint32_t> next;
      next.reserve(w.mosses.size());
      std::size_t i = 0;
      for (const moss::MossPlant& m : w.mosses) {
        while (i < alive.size() && !Same(ever[alive[i]].plant, m)) ever[alive[i++]].death = w.day;
        if (i < alive.size()) {
          next.push_back(alive[i++]);
        } else {
          next.push_back(static_cast<uint32_t>(ever.size()));
          ever.push_back({m, -1});
        }
      }
      for (; i < alive.size(); ++i) ever[alive[i]].death = w.day;
      alive.swap(next);
    }
    static bool Same(const moss::MossPlant& a, const moss::MossPlant& b) {
      return a.pos == b.pos && a.birth_day == b.birth_day && a.species == b.species;
    }
  };

  void FillLand() {
    const moss::SoilCells& cells = run_->cells();
    const moss::MossWorld& w = run_->world();
    const double s = state_.params.Get(MossParam::kMossSize);
    std::vector<int> on_cell(cells.size(), 0);
    for (const moss::MossPlant& m : w.mosses)
      if (!m.on_moss && m.cell < on_cell.size()) ++on_cell[m.cell];
    land_positions_.clear();
    land_normals_.clear();
    land_coverage_.clear();
    land_irradiance_.clear();
    land_geology_.clear();
    land_T_s_.clear();
    land_rh_s_.clear();
    land_theta_.clear();
    land_fitness_.clear();
    const moss::MossParams& p = state_.params;
    const auto g_form = static_cast<moss::GForm>(p.GetInt(MossParam::kGForm));
    std::vector<moss::SpeciesRanges> species;
    for (int k = 0; k < moss::kSpeciesCount; ++k)
      species.push_back(moss::SpeciesOf(p, static_cast<moss::Species>(k)));
    const auto at = [](const std::vector<double>& v, std::size_t c) {
      return c < v.size() ? v[c] : 0.0;
    };
    const geom::TriMesh& mesh = cells.mesh;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const float coverage =
          cells.area[c] > 0 ? static_cast<float>(std::min(1.0, on_cell[c] * s * s / cells.area[c]))
                            : 0.f;
      const float S = c < w.S.size() ? static_cast<float>(w.S[c]) : 0.f;
      const double T_s = at(w.T_s, c), rh_s = at(w.rh_s, c);
      double G_best = 0;
      if (c < w.T_s.size() && c < w.rh_s.size() && c < w.S.size())
        for (const moss::SpeciesRanges& r : species)
          G_best = std::max(G_best, moss::FitnessOf(r, T_s, rh_s, w.S[c], g_form).G);
      for (int k = 0; k < 3; ++k) {
        PushVec(&land_positions_, glm::dvec3(mesh.positions[mesh.indices[3 * c + k]]));
        PushVec(&land_normals_, cells.normal[c]);
        land_coverage_.push_back(coverage);
        land_irradiance_.push_back(S);
        land_geology_.push_back(static_cast<float>(static_cast<int>(cells.geology[c])));
        land_T_s_.push_back(static_cast<float>(T_s));
        land_rh_s_.push_back(static_cast<float>(rh_s));
        land_theta_.push_back(static_cast<float>(at(w.theta, c)));
        land_fitness_.push_back(static_cast<float>(G_best));
      }
    }
  }

  void FillMosses(const Lives& lives) {
    moss_positions_.clear();
    moss_normals_.clear();
    moss_species_.clear();
    moss_birth_.clear();
    moss_death_.clear();
    moss_cell_.clear();
    moss_on_moss_.clear();
    for (const Life& life : lives.ever) {
      PushVec(&moss_positions_, life.plant.pos);
      PushVec(&moss_normals_, life.plant.normal);
      moss_species_.push_back(static_cast<float>(static_cast<int>(life.plant.species)));
      moss_birth_.push_back(static_cast<float>(life.plant.birth_day));
      moss_death_.push_back(static_cast<float>(life.death));
      moss_cell_.push_back(life.plant.cell);
      moss_on_moss_.push_back(life.plant.on_moss ? 1.f : 0.f);
    }
  }

  void FillPhotons() {
    photon_positions_.clear();
    photon_depth_.clear();
    for (const moss::Photon& ph : run_->photon_map().photons) {
      PushVec(&photon_positions_, ph.position);
      photon_depth_.push_back(static_cast<float>(ph.depth));
    }
  }

  std::optional<moss::MossRun> run_;
  moss::MossState state_;
  std::shared_ptr<const moss::MossScene> mesh_scene_;  // shared with another lab by shareMesh
  std::string mesh_name_;
  std::size_t mesh_triangles_ = 0;
  std::vector<float> land_positions_, land_normals_, land_coverage_, land_irradiance_,
      land_geology_, land_T_s_, land_rh_s_, land_theta_, land_fitness_;
  std::vector<float> photon_positions_, photon_depth_;
  std::vector<float> moss_positions_, moss_normals_, moss_species_, moss_birth_, moss_death_,
      moss_on_moss_;
  std::vector<uint32_t> moss_cell_;
  std::vector<unsigned char> download_;  // the last build's bytes (group "download")
  emscripten::val progress_ = emscripten::val::null();
};

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_moss) {
  using namespace emscripten;
  function("mossScenesJson", &niwa::MossScenes);
  class_<niwa::MossLab>("MossLab")
      .constructor<>()
      .function("setProgress", &niwa::MossLab::setProgress)
      .function("grow", &niwa::MossLab::grow)
      .function("loadMesh", &niwa::MossLab::loadMesh)
      .function("growOnMesh", &niwa::MossLab::growOnMesh)
      .function("meshJson", &niwa::MossLab::meshJson)
      .function("shareMesh", &niwa::MossLab::shareMesh)
      .function("statsJson", &niwa::MossLab::statsJson)
      .function("hash", &niwa::MossLab::hash)
      .function("stateJson", &niwa::MossLab::stateJson)
      .function("boundsJson", &niwa::MossLab::boundsJson)
      .function("buffers", &niwa::MossLab::buffers)
      .function("build", &niwa::MossLab::build);
}
