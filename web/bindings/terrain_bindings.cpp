// The terrain study's bindings (paper 002, Misawa, Chiba, Saito): TerrainLab, the last mountain
// grown from a state (a built-in seed or a drawn contour, through core/terrain/terrain_state), for
// the worker (web/worker/terrain_handler.js); and the terrain table, presets, seeds and hash codec
// as JSON.
//
// Design (as the tree's "JS BINDINGS DESIGN" note in tree_bindings.cpp): everything from
// JavaScript arrives as text and is checked by the core (ApplyTerrainStateJson, CheckSeed, Grow);
// nothing throws, errors come back as one line ("" = success). Buffers leave through
// buffers(group) (buffers.h), copied once by the worker. Groups:
//   "surface"   positions (Float32 xyz: glTF's y-up (x, h, −y), one vertex per heightfield cell
//               centre), normals (Float32 xyz, central differences), colours (Float32 rgb: the
//               hypsometric tint of terrain_output.h)
//   "surfaceIndices"  indices (Uint32 triangles; the page builds the same list itself from
//               boundsJson's width and height, web/terrain/grid_indices.js, so a regrow copies
//               6 MB less at 512²)
//   "contours"  positions (Float32 xyz, LINES: two vertices per ring edge at the ring's
//               elevation), height (Float32 per vertex, m), level (Float32 per vertex)
//   "summits"   positions (Float32 xyz), radius (Float32: inscribed-circle radius, m)
//   "download"  bytes (Uint8, after build(format))
// terrainRepairContour(pointsJson): a drawn contour that crosses itself made simple (below);
// terrainParseContour(text): an imported contour file's points (below).
// Calls: grow(stateJson) -> ""/error record, then statsJson() (the CLI's --stats minus ms*),
// hash(), stateJson(), buffers(..), build(format) with format glb | heightmap | sidecar | json |
// geojson | svg -> ""/error record. Does not: draw, keep more than one mountain, read files, or
// time anything the stats compare.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "base/budget.h"
#include "buffers.h"
#include "error_record.h"
#include "page_budget.h"
#include "params/json_guard.h"
#include "run/field_names.h"
#include "terrain/contour_io.h"
#include "terrain/contour_repair.h"
#include "terrain/generate.h"
#include "terrain/seeds.h"
#include "terrain/terrain_params.h"
#include "terrain/terrain_run.h"
#include "terrain/terrain_state.h"
#include "terrain/terrain_surface.h"

namespace niwa {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

// The most contour vertices a grown mountain may bring to the page (every builtin grows < 2,000).
constexpr double kPageMaxContourVertices = 500000;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

ordered_json StateObject(const terrain::TerrainState& state) {
  return ordered_json::parse(terrain::TerrainStateJson(state));
}

}  // namespace

// [{name, source, points, d, dh, h0}] of the built-in seeds (as `niwa terrain seeds`).
std::string TerrainSeedsJson() {
  ordered_json out = ordered_json::array();
  for (const terrain::SeedInfo& s : terrain::BuiltinSeeds()) {
    Result<terrain::Ring> r = terrain::BuiltinSeed(s.name);
    out.push_back({{"name", s.name},
                   {"source", s.source},
                   {"points", r.ok() ? r->size() : 0},
                   {"d", s.d},
                   {"dh", s.dh},
                   {"h0", s.h0}});
  }
  return out.dump();
}

// A drawn seed contour ([[x, y], ...] in metres, at most kMaxStatePoints: it goes into the link)
// checked as Grow checks a seed and, when it crosses itself, repaired by core/terrain/
// contour_repair.h (what `niwa terrain grow --repair` does). Returns {points, repaired,
// loops_removed} when nothing was wrong (the points as given), {method: "loops" | "union", points,
// repaired, loops_removed, reason} when repaired (snapped to the 1/1024 m grid, counter-
// clockwise), with {simplified: {from, to, quantum}} when its link would have been too long
// (FitContourToLink), or an error record naming "contour" (error_record.h).
std::string TerrainRepairContour(const std::string& points_json) {
  ordered_json out;
  if (Status guard = CheckJsonKeys(points_json, "contour"); !guard.ok()) {
    return ErrorRecordJson(guard);
  }
  json j = json::parse(points_json, nullptr, false);
  terrain::Ring ring;
  bool shape_ok = j.is_array();
  if (shape_ok) {
    for (const json& p : j) {
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
        shape_ok = false;
        break;
      }
      ring.push_back({p[0].get<double>(), p[1].get<double>()});
    }
  }
  if (!shape_ok) {
    return ErrorRecordJson(Status::Error("contour", "must be [[x, y], ...] numbers in metres"));
  }
  terrain::TerrainState probe;
  Status points_ok = terrain::SetTerrainPoints(ring, &probe);
  if (!points_ok.ok()) {
    return ErrorRecordJson(points_ok);
  }
  // Within what a link carries first (a drawn 2,000-point contour wrote a 32,618-character link
  // the page could not read back), then repaired; a repair's new points are fitted once more.
  const terrain::LinkFit fit = terrain::FitContourToLink(ring, terrain::kMaxLinkContourChars);
  Result<terrain::ContourRepair> r = terrain::RepairContour(fit.ring);
  if (!r.ok()) {
    return ErrorRecordJson(r.status());
  }
  bool fitted = fit.changed;
  if (r->repaired) {
    const terrain::LinkFit again =
        terrain::FitContourToLink(r->ring, terrain::kMaxLinkContourChars);
    if (again.changed) {
      Result<terrain::Ring> checked = terrain::CheckSeed(again.ring);
      if (!checked.ok()) return ErrorRecordJson(checked.status());
      r->ring = again.ring;
      fitted = true;
    }
  }
  if (!r->repaired && !fitted) {
    out["points"] = j;
    out["repaired"] = false;
    out["loops_removed"] = 0;
    return JsonText(out);
  }
  json pts = json::array();
  for (const terrain::Vec2& v : r->ring) pts.push_back({v.x, v.y});
  if (r->repaired) out["method"] = r->method;
  out["points"] = pts;
  out["repaired"] = r->repaired;
  out["loops_removed"] = r->loops_removed;
  if (r->repaired) out["reason"] = r->reason;
  if (fitted) {
    out["simplified"] = {{"from", ring.size()}, {"to", r->ring.size()}, {"quantum", fit.quantum}};
  }
  return JsonText(out);
}

// A contour file's text (what `niwa terrain grow --contour FILE` reads: {"points": [[x, y], ...]}
// in metres with an optional "elevation", or a GeoJSON Polygon or LineString), for the page's
// import: {points, elevation?} or an error record naming "contour" (error_record.h). The points go
// into the page's state (the link), so a file of more than kMaxStatePoints points is refused here
// with the limit; its geometry is checked (and a crossing repaired) as a drawing's is.
std::string TerrainParseContour(const std::string& text) {
  ordered_json out;
  // No C++ exception may reach the page (a GeoJSON "type": 7 threw a json type_error, and the
  // worker's reply never came): one record naming the field instead.
  Result<terrain::SeedFile> file = Status::Error("contour", "could not be read");
  try {
    file = terrain::ParseContourJson(text);
  } catch (const std::exception&) {
    return ErrorRecordJson(
        Status::Error("contour",
                      "not a contour file; must be {\"points\": [[x, y], ...]} in metres or a "
                      "GeoJSON Polygon or LineString"));
  }
  if (!file.ok()) {
    // The file's own error names "contour" (a key inside it, "points: given twice", is the
    // message).
    return ErrorRecordJson(file.status().field() == "contour" ? file.status()
                                                              : file.status().Within("contour"));
  }
  terrain::TerrainState probe;
  const Status fits = terrain::SetTerrainPoints(file->ring, &probe);
  if (!fits.ok()) {
    return ErrorRecordJson(fits);
  }
  json pts = json::array();
  for (const terrain::Vec2& v : file->ring) pts.push_back({v.x, v.y});
  out["points"] = pts;
  if (file->has_elevation) out["elevation"] = file->elevation;
  return JsonText(out);
}

// An adapter over core/terrain/terrain_run.h: one TerrainRun kept from grow to grow (an edit of
// tint, res or an erosion row re-does only its stage, TerrainRun::Update), the page's surface
// buffers filled from it.
class TerrainLab {
 public:
  // Grows the state (JSON, as ApplyTerrainStateJson reads it) and builds its heightfield: "" or
  // the error record naming the field (the last mountain is kept on error).
  std::string grow(const std::string& state_json) {
    const auto t0 = Clock::now();
    terrain::TerrainState state;
    Status s = terrain::ApplyTerrainStateJson(state_json, &state);
    if (s.ok()) s = terrain::CheckTerrainParams(state.params);
    if (!s.ok()) return ErrorText(s);
    // The page's budget (docs/budgets.md): the contours stop at a level with the line in the
    // stats; a heightfield and surface buffers (about the .glb's mesh) beyond it are refused
    // before they are built.
    if (!run_) {
      terrain::TerrainRunPlan plan;
      plan.outputs = {terrain::TerrainOutput::kGlb};
      // What the page draws (the plan view's paths on the main thread, the line buffers) is
      // capped: `down` at its largest (1,000 enlarged contours, 1.9 M vertices) stalled the main
      // thread for 71 s. The run refuses right after growing, naming down or max_levels, before
      // the heightfield's estimate (whose advice, res, would not help).
      plan.max_contour_vertices = kPageMaxContourVertices;
      plan.contour_vertex_holder = "the page draws";
      Result<terrain::TerrainRun> run = terrain::TerrainRun::Start(state, PageBudget(), plan);
      if (!run.ok()) return ErrorText(run.status());
      run_.emplace(std::move(run).value());
    } else {
      s = run_->Update(state);
      if (!s.ok()) return ErrorText(s);
    }
    const int built = run_->counts().heightfields, eroded = run_->counts().erosions;
    s = run_->Advance({});
    if (!s.ok()) return ErrorText(s);
    ms_heightfield_ = run_->ms_heightfield();
    ms_erosion_ = run_->counts().erosions != eroded ? run_->ms_erosion() : 0.0;
    ms_grow_ = Ms(t0, Clock::now()) - ms_heightfield_ - ms_erosion_;
    const auto t2 = Clock::now();
    // The surface changed when it was rebuilt or re-eroded (an erosion row's edit: only that).
    if (run_->counts().heightfields != built || run_->counts().erosions != eroded || !grown_)
      run_->FillSurfaceBuffers(&flat_);
    ms_buffers_ = Ms(t2, Clock::now());
    download_.clear();
    grown_ = true;
    return "";
  }

  // The --stats object of `niwa terrain grow --url HASH --stats` for the last grow, without its
  // ms* fields (timings are in timingsJson), or "{}".
  std::string statsJson() const { return grown_ ? run_->StatsJson() : "{}"; }

  // {ms_grow, ms_heightfield, ms_erosion, ms_buffers, ms_shrink, ms_mpd, ms_fd, ms_loops, grows,
  // heightfields, erosions} of the last grow (the core's four of the grow its contours come from;
  // grows, heightfields and erosions: how many the lab's run has done, so an edit that re-did less
  // is seen; ms_erosion 0 when the last update did not erode).
  std::string timingsJson() const {
    const terrain::GrowCounts counts = grown_ ? run_->terrain().counts : terrain::GrowCounts{};
    ordered_json j;
    j["ms_grow"] = ms_grow_;
    j["ms_heightfield"] = ms_heightfield_;
    j["ms_erosion"] = ms_erosion_;
    j["ms_buffers"] = ms_buffers_;
    j["ms_shrink"] = counts.ms_shrink;
    j["ms_mpd"] = counts.ms_mpd;
    j["ms_fd"] = counts.ms_fd;
    j["ms_loops"] = counts.ms_loops;
    j["grows"] = run_ ? run_->counts().grows : 0;
    j["heightfields"] = run_ ? run_->counts().heightfields : 0;
    j["erosions"] = run_ ? run_->counts().erosions : 0;
    return JsonText(j);
  }

  std::string hash() const { return grown_ ? run_->Hash("") : ""; }
  std::string stateJson() const { return grown_ ? JsonText(StateObject(run_->state())) : "{}"; }

  // {min: [x, y], max: [x, y], h_min, h_max, h0, dh, level_min, level_max, width, height}: the
  // heightfield's box (plan metres), its elevations, the contour levels (negative below the seed:
  // `down`) and its grid.
  std::string boundsJson() const {
    if (!grown_) return "{}";
    const terrain::Heightfield& hf = run_->heightfield();
    const terrain::Terrain& t = run_->terrain();
    ordered_json j;
    j["min"] = {hf.x0, hf.y1 - hf.height * hf.cell};
    j["max"] = {hf.x0 + hf.width * hf.cell, hf.y1};
    const auto [lo, hi] = std::minmax_element(hf.h.begin(), hf.h.end());
    j["h_min"] = hf.h.empty() ? 0.0 : *lo;
    j["h_max"] = hf.h.empty() ? 0.0 : *hi;
    j["h0"] = t.h0;
    j["dh"] = t.dh;
    int level_min = 0, level_max = 0;
    for (const terrain::ContourNode& node : t.contours) {
      level_min = std::min(level_min, node.level);
      level_max = std::max(level_max, node.level);
    }
    j["level_min"] = level_min;
    j["level_max"] = level_max;
    j["width"] = hf.width;  // the surface grid's vertices per row and rows
    j["height"] = hf.height;
    return JsonText(j);
  }

  // One download of the last grow into the "download" group: "" or an error record.
  // glb: the bytes of `niwa terrain grow --url HASH --out F.glb` (the run's one document);
  // heightmap / sidecar: --heightmap's .png and its .json; json / geojson / svg: --contours.
  std::string build(const std::string& format) {
    if (!grown_) return ErrorText(Status::Error("download", "nothing grown yet"));
    const run::FieldNames names = {{"format", "download"}};
    const Status fits = run_->CheckExport(format);
    if (!fits.ok()) return ErrorText(run::RenameField(fits, names));
    Result<std::string> bytes = run_->Export(format);
    if (!bytes.ok()) {
      return ErrorText(format == "glb" ? bytes.status().Within("download")
                                       : run::RenameField(bytes.status(), names));
    }
    download_.assign(bytes->begin(), bytes->end());
    return "";
  }

  emscripten::val buffers(const std::string& group) const {
    NamedBuffers out;
    if (group == "surface") {
      out.Add("positions", flat_.positions)
          .Add("normals", flat_.normals)
          .Add("colours", flat_.colours);
    } else if (group == "surfaceIndices") {
      out.Add("indices", flat_.indices);
    } else if (group == "contours") {
      out.Add("positions", flat_.line_positions)
          .Add("height", flat_.line_height)
          .Add("level", flat_.line_level);
    } else if (group == "summits") {
      out.Add("positions", flat_.summit_positions).Add("radius", flat_.summit_radius);
    } else if (group == "download") {
      out.Add("bytes", download_);
    } else {
      return emscripten::val::null();
    }
    return out.ToJs();
  }

 private:
  bool grown_ = false;
  std::optional<terrain::TerrainRun> run_;
  double ms_grow_ = 0, ms_heightfield_ = 0, ms_erosion_ = 0, ms_buffers_ = 0;
  terrain::SurfaceBuffers flat_;  // core/terrain/terrain_surface.h: reused from grow to grow
  std::vector<unsigned char> download_;
};

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_terrain) {
  using namespace emscripten;
  function("terrainSeedsJson", &niwa::TerrainSeedsJson);
  function("terrainRepairContour", &niwa::TerrainRepairContour);
  function("terrainParseContour", &niwa::TerrainParseContour);
  class_<niwa::TerrainLab>("TerrainLab")
      .constructor<>()
      .function("grow", &niwa::TerrainLab::grow)
      .function("statsJson", &niwa::TerrainLab::statsJson)
      .function("timingsJson", &niwa::TerrainLab::timingsJson)
      .function("hash", &niwa::TerrainLab::hash)
      .function("stateJson", &niwa::TerrainLab::stateJson)
      .function("boundsJson", &niwa::TerrainLab::boundsJson)
      .function("build", &niwa::TerrainLab::build)
      .function("buffers", &niwa::TerrainLab::buffers);
}
