// The garden's bindings (issue 33 item 6; docs/garden-model.md "The page"): GardenLab, one garden
// run (core/compose/garden_run.h) grown to its years for the worker (web/worker/garden_handler.js),
// flattened for the page from GardenRun's public API: the ground's triangles and heights, the
// objects' meshes, each distinct tree's full mesh once (bark, leaves, flowers: GardenGroupMesh of
// compose/garden_view, tubes of 3 to 6 sides; the page's view, not the .glb's LOD) and every
// planted tree's placement in its group; and the garden table and share-link codec as JSON (the
// compose registry, core/compose/studies.cpp, has no garden row).
//
// Design (as the moss lab's): everything from JavaScript arrives as text and is checked by the core
// (ApplyGardenStateJson, CheckGardenState, GardenRun::Start's estimate against the page budget);
// nothing throws, errors come back as the {ok, field, message} record (error_record.h) naming a
// state field ("plants[1].pos", "years", "density") or the budget's line. Buffers leave through
// buffers(group) (buffers.h), copied once by the worker. Groups:
//   "ground"  positions, normals (Float32 xyz, metres, y up), indices (Uint32): GardenGround::Mesh;
//             heights (Float32, (n + 1)² in GardenGround's order: vertex (i, j) at x = −L/2 +
//             i·cell, z = −L/2 + j·cell), for the page's ray against the ground (its clicks);
//             moss_S (Float32 per ground vertex, the same order: the moss's light of its last day,
//             compose/garden_moss GardenMossGroundLight; −1 where no cell is near; empty without
//             moss)
//   "objects" positions, normals, indices (every object's mesh, placed, in one list), kind (Float32
//             per vertex: 0 wall, 1 rock, 2 lantern, 3 ivy stem, 4 ivy leaf), birth (Float32 per
//             vertex: the garden year an ivy vertex grew in, ceil(birth_step / ivy_steps), 0 for
//             the objects; the ivy grows on the garden's clock, ivy_steps steps a year on that
//             year's trunks, so a year's ivy is exactly the part of it born by then)
//   "trees"   positions, normals, indices (each group's mesh at the origin, one after another;
//             the indices absolute), part (Float32 per vertex: 0 bark, 1 leaves, 2 flowers),
//             ranges (Uint32, 4 per group: first index, index count, first instance, instance
//             count), instances (Float32, 4 per planted tree in group order: x, y, z of its
//             foot, its turn about y in radians, counter-clockwise seen from above), uvs
//             (Float32, u, v per vertex, only when some group wears simulated bark (bark 1): its
//             bark's wrapping the tile of barkTexture(group, ...), 0 elsewhere; else empty)
//   "year"    the trees' seven buffers above for the year of the last showYear(y), and moss_S of
//             that year (the garden's year scrubber: nothing regrows)
//   "skin"    after blowStart: joints (Uint32 per vertex of "trees": its node point in its
//             group's sway model, compose/garden_wind Skin) and weights (Float32, eq. 3.15), and
//             blocks (Float32 per planted tree in the instances' order: its first pose block)
//   "wind"    poses (Float32, 16 per node point of every copy, core/sway/skin.h; copy k's node
//             point j at block blocks[k] + j), after blowStart and every blowStep
// Calls: loadMesh(bytes, name) -> ""/error record naming "mesh" (a dropped .glb/.gltf/.obj, Draco
// decoded by the page, kept by name for the state's mesh objects (kind "mesh", file name) and a
// mesh ground (ground.kind "mesh", file name)),
// meshTriangles(); loadImage(role, bytes, name) -> ""/error record naming "ground.file" (role
// "heightmap") or "mask" (role "mask"): an opened PNG decoded as the garden reads it
// (DecodeGardenHeightmap, DecodeGardenMask: 16-bit samples kept) and kept by its name for the
// state's heightmap ground (ground.kind "heightmap", file name) or mask (mask: name), at most 4 of
// each; imageJson() ({role, name, width, height, bit_depth, colour_type} of the last loaded);
// setProgress(fn) (fn(stage, done, total) after every year), start(stateJson) ->
// ""/error record (the state JSON of GardenStateJson over the default garden, LayOutDefaults,
// checked and started, recording every year), then step() -> "more" | "grown" | error (one garden
// year a call, the worker taking its messages between them; "grown": the run advanced and its
// buffers filled); statsJson() (the run's StatsJson, as `niwa garden grow --stats` without the
// CLI's timings), hash(), stateJson(), boundsJson() ({size, n, cell, relief, min, max, groups,
// trees}); build("glb"|"svg"|"json") then buffers("download"): the run's Export bytes (the bytes of
// `niwa garden grow --url HASH --out g.glb`); grows() (how many grows this lab started: a page's
// check that the scrubber grows nothing), runGrows() (grows() when the run kept was grown);
// yearsJson() ({years, recorded: [years], stopped_by, record_bytes, bytes: [per recorded year],
// mosses: [per recorded year], ivy: [the ivy's internodes per recorded year]}); showYear(y) ->
// ""/error record naming "year": the "year" group filled from the run's record of year y
// (GardenRun's record_years, on for every page grow: compose/garden_view GardenGroupMeshAt). Blow
// (compose/garden_wind, the last grown year's trees): blowStart(windJson) -> ""/error record (the
// wind rows over the state's wind (its "wind" rows, set by start or setWind), "{}" for none; errors
// name the row, "wind" or the page budget's limit; fills "skin" and "wind" at rest),
// setWind(windJson) -> ""/error record naming "wind.<key>" (the state's wind rows changed on the
// last run, nothing regrown: hash() and stateJson() carry them), blowStep(steps) -> the wind's time
// (s; at most 64 steps a call; fills "wind"), blowStop(), blowDt(), blowDuration(),
// blowStepsPerTick(), blowSpeed() (the share of real time the worker can keep), blowWindSpeed()
// (m/s at the garden's centre now), blowBlocks() (pose blocks of every copy; 0: not blowing); a new
// grow stops it. Free functions: gardenTableJson(), gardenWindTableJson() (the wind panel's rows),
// gardenDecodeJson(hash)
// ({state, notices}: the default garden with the link's keys). Does not: keep more than one run,
// keep more than one year's buffers, sway a recorded year's trees, or read files (the page hands
// their bytes in). phasesJson(): where the last grow's time went in the worker, ms (ground, plant,
// moss_start, growth (the trees' own years), moss (its days), records, ivy, bark, mesh (the page's
// buffers)).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "buffers.h"
#include "compose/garden_moss.h"
#include "compose/garden_params.h"
#include "compose/garden_run.h"
#include "compose/garden_state.h"
#include "compose/garden_view.h"
#include "compose/garden_wind.h"
#include "compose/studies.h"
#include "error_record.h"
#include "geom/mesh_metrics.h"
#include "image/png.h"
#include "image_val.h"
#include "io/mesh_reader.h"
#include "ivy/ivy_budget.h"
#include "ivy/ivy_run.h"
#include "page_budget.h"
#include "params/param_json.h"
#include "render/atlas_mesh.h"
#include "render/hybrid.h"
#include "view_camera.h"

namespace niwa {
namespace {

using nlohmann::ordered_json;

constexpr double kPi = 3.14159265358979323846;
// The page's hybrid card atlases (hybridBuild): their texels in all, the grove page's 10 atlases of
// 2048² (web/tree/grove_page.js), and the smallest side they are cut to.
constexpr double kGardenPageAtlasTexels = 10.0 * 2048 * 2048;
constexpr int kGardenPageAtlasMin = 512;

void AppendMesh(const geom::TriMesh& mesh, std::vector<float>* positions,
                std::vector<float>* normals, std::vector<uint32_t>* indices) {
  const auto base = static_cast<uint32_t>(positions->size() / 3);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3& p = mesh.positions[v];
    positions->insert(positions->end(), {p.x, p.y, p.z});
    const glm::vec3 n = v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0, 1, 0);
    normals->insert(normals->end(), {n.x, n.y, n.z});
  }
  for (uint32_t i : mesh.indices) indices->push_back(base + i);
}

// One part of a tree's mesh appended: its vertices tagged `part`, its indices absolute.
void AppendPart(const MeshBuffers& m, float part, std::vector<float>* positions,
                std::vector<float>* normals, std::vector<float>* parts,
                std::vector<uint32_t>* indices) {
  const auto base = static_cast<uint32_t>(positions->size() / 3);
  positions->insert(positions->end(), m.positions.begin(), m.positions.end());
  normals->insert(normals->end(), m.normals.begin(), m.normals.end());
  parts->insert(parts->end(), m.vertex_count(), part);
  for (uint32_t i : m.indices) indices->push_back(base + i);
}

}  // namespace

std::string GardenTableJson() { return ParamTableJson(compose::GardenTable()); }

// The garden's wind panel: the tree table's rows a garden state carries as its wind
// (compose::IsGardenWindKey: the "wind" group but gust_on), as ParamTableJson gives them, each
// default the garden's (GardenWindBase).
std::string GardenWindTableJson() {
  const TreeParams base = compose::GardenWindBase();
  nlohmann::json rows = nlohmann::json::parse(ParamTableJson(base.table()));
  nlohmann::json out = nlohmann::json::array();
  for (nlohmann::json& row : rows) {
    const std::string key = row.value("key", "");
    if (!compose::IsGardenWindKey(key)) continue;
    const std::optional<std::size_t> r = base.table().Find(key);
    if (r) row["default"] = base.Get(*r);
    out.push_back(row);
  }
  return out.dump();
}

// {state (GardenStateJson, parsed), notices} of the default garden with the link's keys: the
// compose registry's decode (the one every composer reads a garden link with), a leading '#' off.
// (Until 2026-12-07 this was a copy that laid the defaults out again after ApplyGardenHash, which
// put the default wall's ivy back on a link that said `ivy=`.)
std::string GardenDecodeJson(const std::string& hash) {
  std::string_view h = hash;
  if (!h.empty() && h[0] == '#') h.remove_prefix(1);
  return compose::FindStudy("garden")->decode_hash(h, "");
}

// An adapter over core/compose/garden_run.h: one garden grown to its years, flattened for the page.
class GardenLab {
 public:
  void setProgress(emscripten::val fn) { progress_ = fn; }

  // Starts a garden (checked and estimated, nothing grown yet): "" or an error record. The worker
  // then calls step() until it says "grown", yielding to its messages between calls, so a newer
  // update (an edit, a link) takes over within a garden year instead of after the whole growth.
  std::string start(const std::string& state_json) {
    pending_.reset();
    compose::GardenState state = compose::DefaultGardenState();
    Status s = compose::ApplyGardenStateJson(state_json, &state);
    if (!s.ok()) return ErrorText(s);
    // A mesh ground and mesh objects: the meshes this lab read (loadMesh), by file name.
    s = compose::LoadGardenMeshes(
        [this](const std::string& file) -> Result<geom::TriMesh> {
          const auto it = meshes_.find(file);
          if (it == meshes_.end())
            return Status::Error("", "'" + file +
                                         "' is not loaded in this page; drop the file again (a "
                                         "link does not carry it)");
          return it->second;
        },
        &state);
    if (!s.ok()) return ErrorText(s);
    // A heightmap ground and a mask: the images this lab read (loadImage), by file name.
    s = compose::LoadGardenImages(
        [this](const std::string& field,
               const std::string& file) -> Result<std::vector<unsigned char>> {
          const auto& kept = images_[field == "mask" ? 1 : 0];
          const auto it = kept.find(file);
          if (it == kept.end())
            return Status::Error("", "'" + file +
                                         "' is not loaded in this page; open the file again (a "
                                         "link does not carry it)");
          return it->second;
        },
        &state);
    if (!s.ok()) return ErrorText(s);
    compose::LayOutDefaults(&state);
    s = compose::CheckGardenState(state);
    if (!s.ok()) return ErrorText(s);
    ++grows_;
    // Every year's picture recorded as the clock runs: the year scrubber replays them.
    Result<compose::GardenRun> started =
        compose::GardenRun::Start(state, PageBudget(), /*record_years=*/true);
    if (!started.ok()) return ErrorText(started.status());
    pending_moss_start_ms_ = started->ms_moss();  // the moss's land, before any day
    pending_.emplace(std::move(started).value());
    pending_->set_ivy_extra_bytes_per_bud(ivy::IvyPageMeshBytesPerBud());  // FillObjects' ivy mesh
    return "";
  }

  // Grows the started garden by one garden year (the nursery with the first), or, after the last
  // year, its ivy and barks and the page's buffers: "more" (years remain), "grown" (the run is
  // the lab's last run now, its buffers filled) or an error record. The same calls in the same
  // order as one Advance (GardenRun::Advance stops at a year's start when its observer says no,
  // as it was, and goes on from there), so the garden's bytes do not depend on the steps.
  std::string step() {
    if (!pending_) return ErrorText(Status::Error("run", "no garden started"));
    int years_left = 1;
    const Status s = pending_->Advance([&](const run::Progress& p) {
      if (!progress_.isNull() && !progress_.isUndefined())
        progress_(std::string(p.phase), p.done, p.total);
      if (std::string(p.phase) == "grow" && p.done < p.total) return years_left-- > 0;
      return true;
    });
    if (run::IsCancelled(s)) return "more";
    if (!s.ok()) {
      pending_.reset();
      return ErrorText(s);
    }
    blowStop();  // the wind swayed the trees of the garden before
    run_.emplace(std::move(*pending_));
    pending_.reset();
    hybrid_.clear();  // the hybrid scenes were of the garden before
    hybrid_slots_.clear();
    run_grows_ = grows_;
    moss_start_ms_ = pending_moss_start_ms_;
    const auto t0 = std::chrono::steady_clock::now();
    FillGround();
    FillObjects();
    FillTrees(run_->done(), &trees_);
    ms_mesh_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return "grown";
  }

  // A dropped mesh file's bytes (Draco already decoded by the page), read as `niwa garden grow`
  // reads a garden file's mesh object: "" with the mesh kept by its name for the objects that
  // name it (kind "mesh", file `name`), or the error record naming "mesh". At most 8 are kept (the
  // oldest goes).
  std::string loadMesh(const std::string& bytes, const std::string& name) {
    Result<geom::TriMesh> mesh = io::ReadMeshBytes(bytes, name);
    if (!mesh.ok()) return ErrorText(mesh.status().Within("mesh"));
    Status valid = geom::ValidateMesh(*mesh, name);
    if (!valid.ok()) return ErrorText(valid.Within("mesh"));
    if (meshes_.size() >= 8 && !meshes_.count(name)) meshes_.erase(mesh_order_.front());
    mesh_order_.erase(std::remove(mesh_order_.begin(), mesh_order_.end(), name), mesh_order_.end());
    mesh_order_.push_back(name);
    last_mesh_triangles_ = mesh->triangle_count();
    meshes_[name] = std::move(*mesh);
    return "";
  }
  double meshTriangles() const { return static_cast<double>(last_mesh_triangles_); }

  // An opened PNG (a heightmap, role "heightmap", or a density mask, role "mask"), decoded as the
  // garden decodes it (16-bit samples kept; the browser's canvas is not used): "" with its bytes
  // kept by name for the states that name it, or the error record naming "ground.file" or "mask".
  // At most 4 of each role are kept (the oldest goes).
  std::string loadImage(const std::string& role, const std::string& bytes,
                        const std::string& name) {
    const bool mask = role == "mask";
    if (!mask && role != "heightmap")
      return ErrorText(Status::Error("image", "role must be heightmap or mask"));
    const std::vector<unsigned char> png(bytes.begin(), bytes.end());
    const Status decoded = mask ? compose::DecodeGardenMask(name, png).status()
                                : compose::DecodeGardenHeightmap(name, png).status();
    if (!decoded.ok()) return ErrorText(decoded);
    Result<image::PngInfo> info = image::ReadPngInfo(png.data(), png.size());
    auto& kept = images_[mask ? 1 : 0];
    auto& order = image_order_[mask ? 1 : 0];
    if (kept.size() >= 4 && !kept.count(name)) {
      kept.erase(order.front());
      order.erase(order.begin());
    }
    order.erase(std::remove(order.begin(), order.end(), name), order.end());
    order.push_back(name);
    kept[name] = png;
    ordered_json j;
    j["role"] = role;
    j["name"] = name;
    j["width"] = info.ok() ? info->width : 0;
    j["height"] = info.ok() ? info->height : 0;
    j["bit_depth"] = info.ok() ? info->bit_depth : 0;
    j["colour_type"] = info.ok() ? info->colour_type : 0;
    last_image_ = JsonText(j);
    return "";
  }
  std::string imageJson() const { return last_image_; }

  int grows() const { return grows_; }
  // grows() when the run kept now was grown (a refused grow keeps the run before it).
  int runGrows() const { return run_grows_; }

  std::string yearsJson() const {
    if (!run_) return "{}";
    ordered_json j;
    j["years"] = run_->done();
    ordered_json recorded = ordered_json::array(), bytes = ordered_json::array(),
                 mosses = ordered_json::array(), ivy = ordered_json::array();
    for (const compose::GardenYearRecord& r : run_->years()) {
      recorded.push_back(r.year);
      bytes.push_back(r.bytes);
      mosses.push_back(r.mosses);
      ivy.push_back(r.ivy_internodes);
    }
    j["recorded"] = recorded;
    j["stopped_by"] = run_->record_stopped_by();
    j["record_bytes"] = run_->record_bytes();
    j["bytes"] = bytes;
    j["mosses"] = mosses;
    j["ivy"] = ivy;
    return JsonText(j);
  }

  // The "year" group: the trees and the moss's light of garden year `year`, from the run's record.
  std::string showYear(int year) {
    if (!run_) return ErrorText(Status::Error("year", "nothing grown yet"));
    if (year < 0 || year > run_->done())
      return ErrorText(Status::Error("year", "must be in 0.." + std::to_string(run_->done()) +
                                                 " (got " + std::to_string(year) + ")"));
    if (!compose::GardenYearShown(*run_, year))
      return ErrorText(Status::Error(
          "year",
          "year " + std::to_string(year) + " was not recorded: " + run_->record_stopped_by()));
    year_moss_S_.clear();
    if (year == run_->done()) {  // the last year: the grow's own buffers, not meshed again
      year_ = trees_;
      year_moss_S_ = ground_moss_S_;
    } else {
      FillTrees(year, &year_);
      for (const compose::GardenYearRecord& r : run_->years())
        if (r.year == year) year_moss_S_ = r.moss_light;
    }
    return "";
  }

  // ---- Hybrid trees (thesis ch. 4, as the grove page draws them; render/hybrid.h) ----
  // Each distinct tree's hybrid scene (default RenderOptions) of garden year `year` (the year
  // shown), built once; hybridAtlas(g) then fills "atlas.bark|leaves|flowers" with group g's
  // card-atlas geometry, hybridView(g, slot, ...) its draw list for a camera in its own frame.
  std::string hybridBuild(int year) {
    hybrid_.clear();
    hybrid_models_.clear();
    hybrid_slots_.clear();
    if (!run_) return ErrorText(Status::Error("trees", "nothing grown yet"));
    if (year < 0 || year > run_->done() || !compose::GardenYearShown(*run_, year))
      return ErrorText(Status::Error("year", "year " + std::to_string(year) + " is not shown"));
    hybrid_year_ = year;
    // The card atlases' side: the grove's texels (10 atlases of 2048², the most a page of trees
    // paints and keeps) shared by the distinct trees, a power of two from 512 to 2048 (100
    // distinct trees: 512², 140 MB with their mipmaps where 2048² would be 2.2 GB and minutes of
    // painting on a CPU rasteriser); a tree whose tiles do not fit at that side gets the next
    // side up (to RenderOptions' 2048).
    const RenderOptions defaults;
    const double groups = std::max<double>(1.0, static_cast<double>(run_->groups().size()));
    int side = defaults.atlas_size;
    while (side > kGardenPageAtlasMin && groups * side * side > kGardenPageAtlasTexels) side /= 2;
    for (std::size_t g = 0; g < run_->groups().size(); ++g) {
      const Tree* tree = run_->TreeAtYear(static_cast<int>(g), year);
      if (tree == nullptr) return ErrorText(Status::Error("year", "no tree of that year"));
      RenderOptions options = defaults;
      options.atlas_size = side;
      HybridScene scene = BuildHybridScene(*tree, options);
      while (!scene.atlas_fits && options.atlas_size < defaults.atlas_size) {
        options.atlas_size *= 2;
        scene = BuildHybridScene(*tree, options);
      }
      hybrid_.push_back(std::move(scene));
      // The tree's sway model (its node points: the skin of its draw lists, numbered as Blow's
      // compose/garden_wind simulators number them; the numbering is the tree's, not the rows').
      hybrid_models_.push_back(
          BuildSwayModel(*tree, SwayParams(run_->groups()[g].run->state().params)));
      if (!hybrid_.back().atlas_fits)
        return ErrorText(Status::Error("trees", "a tree's card atlas does not fit; use full"));
    }
    return "";
  }
  int hybridGroups() const { return static_cast<int>(hybrid_.size()); }
  // Group `group`'s sway node points (its pose block's length; Blow's GardenWind::nodes), 0 for no
  // such group.
  int hybridNodes(int group) const {
    if (group < 0 || group >= static_cast<int>(hybrid_models_.size())) return 0;
    return static_cast<int>(hybrid_models_[group].nodes.size());
  }
  // Group `group`'s atlas geometry into "atlas.*"; its atlas side (texels), 0 for no such group.
  int hybridAtlas(int group) {
    if (group < 0 || group >= hybridGroups()) return 0;
    const TreeMesh mesh = compose::GardenGroupMeshAt(*run_, group, hybrid_year_);
    // A tree in simulated bark: the cards' bark wraps its tile, as the full trees' "uvs" do.
    const std::vector<float> bark_uvs =
        compose::GardenGroupBarkUvs(*run_, group, hybrid_year_, mesh);
    atlas_ = BuildAtlasMesh(mesh, hybrid_[group], bark_uvs.empty() ? nullptr : &bark_uvs);
    return hybrid_[group].atlas_size;
  }
  // Eq. 4.1 per branch of group `group` for a camera in its own frame (metres, radians, pixels)
  // with the hysteresis of `slot` (0..255, per group), lines lit from (lx, ly, lz); with `bark`
  // and the group in simulated bark, the lines' C_b is its base colour map's mean (else the
  // procedural brown); fills "cards" and "lines" with their sway skin (render/atlas_mesh
  // BuildDrawListSkin over the group's sway model: node points numbered as Blow's poses, so a
  // copy's cards and lines sway with its pose block). "" or an error record naming "view".
  std::string hybridView(int group, int slot, double ex, double ey, double ez, double tx, double ty,
                         double tz, double fov_y, int width, int height, double lx, double ly,
                         double lz, bool bark) {
    if (group < 0 || group >= hybridGroups() || slot < 0 || slot > 255)
      return ErrorText(Status::Error("view", "group or slot out of range (no hybrid scene?)"));
    const Tree* tree = run_->TreeAtYear(group, hybrid_year_);
    const RenderCamera camera = ViewCamera(ex, ey, ez, tx, ty, tz, fov_y, width, height);
    HybridSelection& previous = hybrid_slots_[group * 256 + slot];
    HybridSelection selection =
        SelectHybrid(*tree, hybrid_[group], camera, previous.draw.empty() ? nullptr : &previous);
    LineShading shading;
    shading.light_dir =
        glm::vec3(static_cast<float>(lx), static_cast<float>(ly), static_cast<float>(lz));
    if (const compose::BarkFrame* frame = bark ? compose::GardenGroupBark(*run_, group) : nullptr) {
      const std::array<double, 3>& c = frame->mean_colour;
      shading.branch_color =
          glm::vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
    }
    draw_ = BuildDrawList(*tree, hybrid_[group], selection, camera, shading);
    previous = std::move(selection);
    draw_skin_ = BuildDrawListSkin(*tree, hybrid_[group], draw_, hybrid_models_[group]);
    return "";
  }

  // ---- Blow: the wind over the last grown year's trees (compose/garden_wind) ----
  std::string blowStart(const std::string& wind_json) {
    blowStop();
    if (!run_) return ErrorText(Status::Error("wind", "nothing grown yet"));
    Result<ParamSet> rows =
        compose::GardenWindRows(run_->scene().ground.size, run_->state().wind, wind_json);
    if (!rows.ok()) return ErrorText(rows.status());
    Result<compose::GardenWind> wind = compose::GardenWind::Start(*run_, *rows, PageBudget());
    if (!wind.ok()) return ErrorText(wind.status());
    // The skin of the "trees" buffers (each group's page mesh: bark, leaves, flowers, as
    // FillTrees appends them) and each copy's first pose block in the instances' order.
    for (int g = 0; g < wind->groups(); ++g) {
      const TreeSkin skin = wind->Skin(*run_, g);
      for (const VertexSkin* part : {&skin.bark, &skin.leaves, &skin.flowers}) {
        skin_joints_.insert(skin_joints_.end(), part->joint.begin(), part->joint.end());
        skin_weights_.insert(skin_weights_.end(), part->weight.begin(), part->weight.end());
      }
      for (std::size_t k = 0; k < run_->groups()[g].trees.size(); ++k)
        skin_blocks_.push_back(static_cast<float>(wind->first_block(g, static_cast<int>(k))));
    }
    if (skin_joints_.size() != trees_.positions.size() / 3) {
      blowStop();
      return ErrorText(Status::Error("wind", "the trees' sway skin does not match their mesh"));
    }
    blow_.emplace(std::move(wind).value());
    poses_.assign(blow_->blocks() * kSwayPoseFloats, 0.0f);
    blow_->WritePoses(poses_.data());
    return "";
  }
  // The garden's wind rows ({wind_speed: 12, ...}: compose::ApplyGardenWindJson) set on the last
  // run (nothing regrows; hash() and stateJson() carry them): "" or an error record naming
  // "wind.<key>".
  std::string setWind(const std::string& json) {
    if (!run_) return ErrorText(Status::Error("wind", "nothing grown yet"));
    return ErrorText(run_->SetWind(json));
  }
  double blowStep(int steps) {
    if (!blow_) return 0;
    blow_->Step(std::clamp(steps, 0, 64));
    blow_->WritePoses(poses_.data());
    return blow_->time();
  }
  void blowStop() {
    blow_.reset();
    skin_joints_.clear();
    skin_weights_.clear();
    skin_blocks_.clear();
    poses_.clear();
  }
  double blowDt() const { return blow_ ? blow_->dt() : 0; }
  double blowDuration() const { return blow_ ? blow_->duration() : 0; }
  int blowStepsPerTick() const { return blow_ ? blow_->steps_per_tick() : 0; }
  double blowSpeed() const { return blow_ ? blow_->speed() : 0; }
  double blowWindSpeed() const { return blow_ ? blow_->SpeedAt(0, 0) : 0; }
  double blowBlocks() const { return blow_ ? static_cast<double>(blow_->blocks()) : 0; }

  std::string statsJson() const { return run_ ? run_->StatsJson() : "{}"; }
  // Where the last grow's time went in this worker, ms (docs/garden-model.md "Where the garden's
  // time goes"): {ground, plant, moss_start (the moss's land, in start()), growth (the trees' own
  // years), moss (its days), records (the year records), ivy, bark, mesh (the page's buffers:
  // FillGround, FillObjects, FillTrees)}.
  std::string phasesJson() const {
    if (!run_) return "{}";
    nlohmann::ordered_json j;
    j["ground"] = run_->ms_ground();
    j["plant"] = run_->ms_plant();
    j["growth"] = run_->ms_growth();
    j["moss_start"] = moss_start_ms_;
    j["moss"] = run_->ms_moss() - moss_start_ms_;
    j["records"] = run_->ms_records();
    j["ivy"] = run_->ms_ivy();
    j["bark"] = run_->ms_bark();
    j["mesh"] = ms_mesh_;
    return j.dump();
  }
  std::string hash() const { return run_ ? run_->Hash("") : ""; }
  std::string stateJson() const { return run_ ? compose::GardenStateJson(run_->state()) : "{}"; }

  // {size, n, cell, relief (m), min, max (the ground's and the trees' box), groups: [{name,
  // species, seed, age, trees, shaded, crown (m)}], trees: [{species, seed, age, pos: [x, y, z],
  // rot, hand, group}]}.
  std::string boundsJson() const {
    if (!run_) return "{}";
    const compose::GardenGround& g = run_->scene().ground;
    ordered_json j;
    j["size"] = g.size;
    j["n"] = g.n;
    j["cell"] = g.cell;
    j["relief"] = g.relief;
    double top = g.relief;
    for (const float y : trees_.positions) top = std::max(top, g.relief + static_cast<double>(y));
    j["min"] = {-g.size / 2, 0.0, -g.size / 2};
    j["max"] = {g.size / 2, top, g.size / 2};
    ordered_json groups = ordered_json::array();
    for (std::size_t k = 0; k < run_->groups().size(); ++k) {
      const compose::GardenTreeGroup& grp = run_->groups()[k];
      groups.push_back({{"name", grp.name},
                        {"species", grp.species},
                        {"seed", grp.seed},
                        {"age", grp.age},
                        {"trees", grp.trees.size()},
                        {"shaded", grp.shaded},
                        {"crown", run_->CrownRadius(static_cast<int>(k))}});
    }
    j["groups"] = groups;
    ordered_json trees = ordered_json::array();
    const std::vector<compose::PlacedTree>& placed = run_->planting().trees;
    for (std::size_t t = 0; t < placed.size(); ++t) {
      const compose::PlacedTree& p = placed[t];
      trees.push_back({{"species", p.species},
                       {"seed", p.seed},
                       {"age", p.age},
                       {"pos", {p.x, p.y, p.z}},
                       {"rot", p.rot},
                       {"hand", p.hand},
                       {"group", run_->group_of(static_cast<int>(t))}});
    }
    j["trees"] = trees;
    return JsonText(j);
  }

  // One download of the last run into the "download" group: "" or an error record naming
  // "download" (over the page's memory budget, or the export's own field).
  std::string build(const std::string& format) {
    download_.clear();
    if (!run_) return ErrorText(Status::Error("download", "nothing grown yet"));
    Result<Estimate> needs = run_->ExportEstimate(format);
    if (!needs.ok()) return ErrorText(needs.status().Within("download"));
    const Status fits =
        CheckEstimate(*needs, PageBudget(), "lower max_triangles or shapes, or the trees (density, size)");
    if (!fits.ok()) return ErrorText(fits);
    Result<std::string> bytes = run_->Export(format);
    if (!bytes.ok()) return ErrorText(bytes.status().Within("download"));
    download_.assign(bytes->begin(), bytes->end());
    return "";
  }

  // {width, height, pixels: Uint8Array RGBA (a copy; row 0 = v 0), digest} of distinct tree
  // `group`'s simulated bark map, kind "bark" (base colour) or "barkNormal" (the OpenGL normal
  // map): the PNGs the garden .glb's tree wears, decoded (compose/garden_view
  // GardenGroupBarkImage); null when that tree wears the procedural bark, or another kind.
  emscripten::val barkTexture(int group, const std::string& kind) const {
    const compose::BarkFrame* frame = run_ ? compose::GardenGroupBark(*run_, group) : nullptr;
    if (frame == nullptr || (kind != "bark" && kind != "barkNormal"))
      return emscripten::val::null();
    const Result<image::Rgba8Image> decoded =
        compose::GardenGroupBarkImage(*run_, group, kind == "barkNormal");
    if (!decoded.ok()) return emscripten::val::null();
    const image::Rgba8Image& image = *decoded;
    emscripten::val out = ImageToJs(image);
    out.set("digest", "bark-sim-" + kind + "-" + frame->hash);
    return out;
  }

  emscripten::val buffers(const std::string& group) const {
    NamedBuffers out;
    if (group == "ground") {
      out.Add("positions", ground_positions_)
          .Add("normals", ground_normals_)
          .Add("indices", ground_indices_)
          .Add("heights", ground_heights_)
          .Add("moss_S", ground_moss_S_);
    } else if (group == "objects") {
      out.Add("positions", object_positions_)
          .Add("normals", object_normals_)
          .Add("indices", object_indices_)
          .Add("kind", object_kind_)
          .Add("birth", object_birth_);
    } else if (group == "trees" || group == "year") {
      const TreeBuffers& t = group == "trees" ? trees_ : year_;
      out.Add("positions", t.positions)
          .Add("normals", t.normals)
          .Add("indices", t.indices)
          .Add("part", t.part)
          .Add("ranges", t.ranges)
          .Add("instances", t.instances)
          .Add("uvs", t.uvs);
      if (group == "year") out.Add("moss_S", year_moss_S_);
    } else if (group == "skin") {
      out.Add("joints", skin_joints_).Add("weights", skin_weights_).Add("blocks", skin_blocks_);
    } else if (group == "wind") {
      out.Add("poses", poses_);
    } else if (group == "atlas.bark" || group == "atlas.leaves" || group == "atlas.flowers") {
      const MeshBuffers& m = group == "atlas.bark"     ? atlas_.bark
                             : group == "atlas.leaves" ? atlas_.leaves
                                                       : atlas_.flowers;
      out.Add("positions", m.positions)
          .Add("normals", m.normals)
          .Add("uvs", m.uvs)
          .Add("indices", m.indices);
    } else if (group == "cards") {
      out.Add("positions", draw_.card_positions)
          .Add("uvs", draw_.card_uvs)
          .Add("indices", draw_.card_indices)
          .Add("joints", draw_skin_.cards.joint)
          .Add("weights", draw_skin_.cards.weight);
    } else if (group == "lines") {
      out.Add("positions", draw_.line_positions)
          .Add("colors", draw_.line_colors)
          .Add("widths", draw_.line_widths)
          .Add("joints", draw_skin_.lines.joint)
          .Add("weights", draw_skin_.lines.weight);
    } else if (group == "download") {
      out.Add("bytes", download_);
    } else {
      return emscripten::val::null();
    }
    return out.ToJs();
  }

 private:
  void FillGround() {
    const compose::GardenGround& g = run_->scene().ground;
    ground_positions_.clear();
    ground_normals_.clear();
    ground_indices_.clear();
    AppendMesh(g.Mesh(), &ground_positions_, &ground_normals_, &ground_indices_);
    ground_heights_.assign(g.h.begin(), g.h.end());
    ground_moss_S_.clear();
    if (run_->moss() != nullptr) ground_moss_S_ = compose::GardenMossGroundLight(*run_->moss(), g);
  }

  void FillObjects() {
    object_positions_.clear();
    object_normals_.clear();
    object_indices_.clear();
    object_kind_.clear();
    object_birth_.clear();
    for (const compose::PlacedObject& o : run_->scene().objects) {
      AppendMesh(o.mesh, &object_positions_, &object_normals_, &object_indices_);
      const float kind = o.kind == "wall" ? 0.f : o.kind == "rock" ? 1.f : 2.f;
      object_kind_.resize(object_positions_.size() / 3, kind);
    }
    object_birth_.resize(object_kind_.size(), 0.f);
    const double steps_a_year =
        std::max(1, run_->state().params.GetInt(compose::GardenParam::kIvySteps));
    // The ivy grown on the garden (in its frame, metres), as the .glb has it: its stems (kind 3)
    // and leaves (kind 4), the suckers left out (under a centimetre: invisible at this scale).
    if (const ivy::IvyRun* ivy = run_->ivy()) {
      for (const run::Part& part : ivy->Parts()) {
        if (part.mode != gltf::Mode::kTriangles || part.name.find("sucker") != std::string::npos)
          continue;
        AppendMesh(part.mesh, &object_positions_, &object_normals_, &object_indices_);
        const float kind = part.name.find("leaves") != std::string::npos ? 4.f : 3.f;
        object_kind_.resize(object_positions_.size() / 3, kind);
        // The garden year each vertex's ivy step falls in (step s of year ceil(s / ivy_steps)).
        const geom::VertexAttribute* birth = part.mesh.FindAttribute("birth_step");
        for (std::size_t v = 0; v < part.mesh.vertex_count(); ++v)
          object_birth_.push_back(
              birth != nullptr && v < birth->values.size()
                  ? static_cast<float>(std::ceil(birth->values[v] / steps_a_year))
                  : 0.f);
      }
    }
  }

  // Each distinct tree's page mesh as it stood after garden year `year` (the last grown: the run's
  // own trees), with every placement.
  // uvs: u, v per vertex when any group wears simulated bark (its bark wrapping the tile, 0 on
  // the leaves, flowers and procedural bark), else empty.
  struct TreeBuffers {
    std::vector<float> positions, normals, part, instances, uvs;
    std::vector<uint32_t> indices, ranges;
  };
  void FillTrees(int year, TreeBuffers* out) {
    *out = TreeBuffers{};
    const std::vector<compose::PlacedTree>& placed = run_->planting().trees;
    bool simulated = false;  // any group wears simulated bark: the buffers carry uvs
    for (std::size_t k = 0; k < run_->groups().size(); ++k)
      simulated = simulated || compose::GardenGroupBark(*run_, static_cast<int>(k)) != nullptr;
    for (std::size_t k = 0; k < run_->groups().size(); ++k) {
      const compose::GardenTreeGroup& grp = run_->groups()[k];
      const TreeMesh mesh = compose::GardenGroupMeshAt(*run_, static_cast<int>(k), year);
      const auto first_index = static_cast<uint32_t>(out->indices.size());
      if (simulated && out->uvs.empty()) out->uvs.assign(out->positions.size() / 3 * 2, 0.f);
      AppendPart(mesh.bark, 0.f, &out->positions, &out->normals, &out->part, &out->indices);
      if (simulated) {
        std::vector<float> uvs =
            compose::GardenGroupBarkUvs(*run_, static_cast<int>(k), year, mesh);
        uvs.resize(mesh.bark.vertex_count() * 2, 0.f);
        out->uvs.insert(out->uvs.end(), uvs.begin(), uvs.end());
      }
      AppendPart(mesh.leaves, 1.f, &out->positions, &out->normals, &out->part, &out->indices);
      AppendPart(mesh.flowers, 2.f, &out->positions, &out->normals, &out->part, &out->indices);
      if (simulated) out->uvs.resize(out->positions.size() / 3 * 2, 0.f);
      out->ranges.push_back(first_index);
      out->ranges.push_back(static_cast<uint32_t>(out->indices.size()) - first_index);
      out->ranges.push_back(static_cast<uint32_t>(out->instances.size() / 4));
      out->ranges.push_back(static_cast<uint32_t>(grp.trees.size()));
      for (int t : grp.trees) {
        const compose::PlacedTree& p = placed[t];
        out->instances.insert(out->instances.end(),
                              {static_cast<float>(p.x), static_cast<float>(p.y),
                               static_cast<float>(p.z), static_cast<float>(p.rot * kPi / 180.0)});
      }
    }
  }

  // The last grow's phases (phasesJson): the page's buffers, and the moss's land in start().
  double ms_mesh_ = 0;
  double moss_start_ms_ = 0, pending_moss_start_ms_ = 0;

  std::optional<compose::GardenRun> run_;
  std::optional<compose::GardenRun> pending_;    // started by start(), grown by step()
  std::map<std::string, geom::TriMesh> meshes_;  // loadMesh's, by file name
  std::vector<std::string> mesh_order_;          // their names, oldest first
  std::size_t last_mesh_triangles_ = 0;
  // loadImage's bytes by file name: [0] heightmaps, [1] masks; their names, oldest first.
  std::map<std::string, std::vector<unsigned char>> images_[2];
  std::vector<std::string> image_order_[2];
  std::string last_image_ = "{}";
  std::vector<float> ground_positions_, ground_normals_, ground_heights_, ground_moss_S_;
  std::vector<uint32_t> ground_indices_;
  std::vector<float> object_positions_, object_normals_, object_kind_, object_birth_;
  std::vector<uint32_t> object_indices_;
  TreeBuffers trees_;  // the last year's (group "trees")
  TreeBuffers year_;   // the year last shown (group "year")
  std::vector<float> year_moss_S_;
  int grows_ = 0, run_grows_ = 0;
  std::vector<unsigned char> download_;      // the last build's bytes (group "download")
  std::optional<compose::GardenWind> blow_;  // Blow's wind over the last run's trees
  std::vector<uint32_t> skin_joints_;        // group "skin"
  std::vector<float> skin_weights_, skin_blocks_;
  std::vector<float> poses_;  // group "wind": blow_->blocks() x 16 floats
  emscripten::val progress_ = emscripten::val::null();
  std::vector<HybridScene> hybrid_;  // per group, of hybrid_year_ (hybridBuild)
  int hybrid_year_ = 0;
  std::map<int, HybridSelection> hybrid_slots_;  // group * 256 + slot: hybridView's hysteresis
  AtlasMesh atlas_;                              // group "atlas.*": the last hybridAtlas's
  HybridDrawList draw_;                          // groups "cards", "lines": the last hybridView's
  DrawListSkin draw_skin_;  // the last hybridView's sway skin (its group's hybrid_models_)
  std::vector<SwayModel> hybrid_models_;  // per group, of hybrid_year_ (hybridBuild)
};

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_garden) {
  using namespace emscripten;
  function("gardenTableJson", &niwa::GardenTableJson);
  function("gardenWindTableJson", &niwa::GardenWindTableJson);
  function("gardenDecodeJson", &niwa::GardenDecodeJson);
  class_<niwa::GardenLab>("GardenLab")
      .constructor<>()
      .function("setProgress", &niwa::GardenLab::setProgress)
      .function("start", &niwa::GardenLab::start)
      .function("loadMesh", &niwa::GardenLab::loadMesh)
      .function("meshTriangles", &niwa::GardenLab::meshTriangles)
      .function("loadImage", &niwa::GardenLab::loadImage)
      .function("imageJson", &niwa::GardenLab::imageJson)
      .function("step", &niwa::GardenLab::step)
      .function("statsJson", &niwa::GardenLab::statsJson)
      .function("phasesJson", &niwa::GardenLab::phasesJson)
      .function("hash", &niwa::GardenLab::hash)
      .function("stateJson", &niwa::GardenLab::stateJson)
      .function("boundsJson", &niwa::GardenLab::boundsJson)
      .function("buffers", &niwa::GardenLab::buffers)
      .function("barkTexture", &niwa::GardenLab::barkTexture)
      .function("build", &niwa::GardenLab::build)
      .function("grows", &niwa::GardenLab::grows)
      .function("runGrows", &niwa::GardenLab::runGrows)
      .function("yearsJson", &niwa::GardenLab::yearsJson)
      .function("showYear", &niwa::GardenLab::showYear)
      .function("blowStart", &niwa::GardenLab::blowStart)
      .function("blowStep", &niwa::GardenLab::blowStep)
      .function("setWind", &niwa::GardenLab::setWind)
      .function("blowStop", &niwa::GardenLab::blowStop)
      .function("blowDt", &niwa::GardenLab::blowDt)
      .function("blowDuration", &niwa::GardenLab::blowDuration)
      .function("blowStepsPerTick", &niwa::GardenLab::blowStepsPerTick)
      .function("blowSpeed", &niwa::GardenLab::blowSpeed)
      .function("blowWindSpeed", &niwa::GardenLab::blowWindSpeed)
      .function("blowBlocks", &niwa::GardenLab::blowBlocks)
      .function("hybridBuild", &niwa::GardenLab::hybridBuild)
      .function("hybridGroups", &niwa::GardenLab::hybridGroups)
      .function("hybridNodes", &niwa::GardenLab::hybridNodes)
      .function("hybridAtlas", &niwa::GardenLab::hybridAtlas)
      .function("hybridView", &niwa::GardenLab::hybridView);
}
