// The bark study's bindings (paper 003, Hirota, Kato, Kaneko; ../shared/specs/bark.md §6
// "Browser"): BarkLab, one bark run (core/bark/bark_run.h) grown for the worker
// (web/worker/bark_handler.js), with the lattice's triangles flattened for the page's tile view
// (live while it grows, and with each spring's break step so the cycle scrubber replays the
// cracks without growing again), the maps' pixels for the tile and the lit trunk, and the maps'
// PNG bytes, the trunk segment's .glb and the cycles CSV for downloads.
//
// Design (as the tree's "JS BINDINGS DESIGN" note in tree_bindings.cpp): everything from
// JavaScript arrives as text and is checked by the core (ApplyBarkStateJson, the table's ranges,
// CheckBarkState, BarkRun::Start's estimate against the page budget); nothing throws, errors come
// back as the {ok, field, message} record (error_record.h) naming a state field: species, model,
// seed, a row key (the panel's keys are the row keys), or the budget's line. Buffers leave
// through buffers(group) (buffers.h), copied once by the worker. Groups:
//   "tile"  positions (Float32 x, z per vertex, cm in the unrolled patch at its current growth,
//           three vertices per lattice triangle, unwrapped, moved by whole patches so that its
//           lowest x and z lie in the patch: a triangle over the seam reaches past its far edges
//           only), stretch (Float32 per vertex: the triangle's largest intact edge strain
//           over its own break strain, in [0, 1]), broken (Float32 per vertex: the step at which
//           the triangle's first edge broke, -1 while intact), layer (Float32 per vertex: the
//           layer showing in the triangle, 0 S, 1 M1, 2 M2, 3 the inner layer; the 2-layer
//           model's 0 or 3), peel (Float32 per vertex: the worst state of the triangle's S nodes,
//           0 bonded, 1 unbonded from M1 but still there (peeling), 2 peeled off; 0 in the 2-layer
//           model); the run being grown while a progress callback runs, else the last finished run
//   "springs" the surface's broken springs as line segments: positions (Float32 x, z per
//           vertex, two vertices a spring, unwrapped and moved as the tile's), broken (Float32 per
//           vertex: the step it broke at); the same run as "tile"
//   "maps"  base_colour, normal, orm (Uint8 RGBA rows, the maps as drawn at the state's map_size;
//           the size is in boundsJson)
// Calls: setProgress(fn) (fn(stage, done, total) every 256 steps; a false return cancels), grow
// (stateJson) -> ""/error record, then statsJson() (the CLI's `niwa bark grow --stats` without
// its timing fields), hash(), stateJson(), boundsJson(), cyclesCsv(), mapPng(map), glb() (the
// bytes of `niwa bark grow --url HASH --out trunk.glb`: the run's Document(), its estimate checked
// against the page budget first), buffers(group). In the 4-layer model the break steps are those
// of the present S: at a role exchange the springs S brought with it (cracked as M1) take the
// exchange's step. Does not: simulate, measure or draw anything itself (BarkRun does), keep more
// than one run, or time itself (the worker does).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bark/bark_run.h"
#include "bark/bark_state.h"
#include "buffers.h"
#include "io/gltf_writer.h"
#include "error_record.h"
#include "page_budget.h"

namespace niwa {
namespace {

using nlohmann::ordered_json;

}  // namespace

// An adapter over core/bark/bark_run.h: one run grown to its cycles, its lattice and maps
// flattened for the page.
class BarkLab {
 public:
  void setProgress(emscripten::val fn) { progress_ = fn; }

  // The state's checks and estimate against the page's budget, nothing built: "" or the error
  // record (the worker asks before it grows a preview of a state that the full run would refuse).
  std::string check(const std::string& state_json) const {
    bark::BarkState state;
    Status s = bark::ApplyBarkStateJson(state_json, &state);
    if (s.ok()) s = bark::BarkRun::Check(state, PageBudget());
    return s.ok() ? "" : ErrorText(s);
  }

  // Starts the run of the state ({species, model, seed, params: {row: value}}) and grows it to its
  // cycles and settling: "" or the error record (the last run is kept on error or cancel).
  std::string grow(const std::string& state_json) {
    bark::BarkState state;
    Status s = bark::ApplyBarkStateJson(state_json, &state);
    if (!s.ok()) return ErrorText(s);
    Result<bark::BarkRun> started = bark::BarkRun::Start(state, PageBudget());
    if (!started.ok()) return ErrorText(started.status());
    bark::BarkRun run = std::move(started).value();
    std::vector<int32_t> broke_at(run.lattice().springs(), -1);
    s_born_ = kNoLayer;
    growing_ = &run;
    growing_broke_at_ = &broke_at;
    s = run.Advance([&](const run::Progress& p) {
      NoteBreaks(run, &broke_at);
      if (progress_.isNull() || progress_.isUndefined()) return true;
      const emscripten::val going = progress_(std::string(p.phase), p.done, p.total);
      return !(going.isFalse());
    });
    growing_ = nullptr;
    growing_broke_at_ = nullptr;
    if (!s.ok()) return ErrorText(s);
    NoteBreaks(run, &broke_at);
    run_.emplace(std::move(run));
    broke_at_ = std::move(broke_at);
    return "";
  }

  std::string statsJson() const { return run_ ? run_->StatsJson() : "{}"; }
  std::string hash() const { return run_ ? run_->Hash("") : ""; }
  std::string stateJson() const { return run_ ? bark::BarkStateJson(run_->state()) : "{}"; }
  std::string cyclesCsv() const { return run_ ? run_->CyclesCsv() : ""; }

  // {n_r, n_h, circumference, height (cm, at the end of growth), radius (cm), steps,
  // steps_per_cycle, cycles, springs {axial, diagonal}, map {width, height}} of the run the
  // "tile" group shows (the one growing while a progress callback runs).
  std::string boundsJson() const {
    const bark::BarkRun* run = Shown();
    if (!run) return "{}";
    const bark::Lattice& L = run->lattice();
    const bark::Growth g = run->growth();
    ordered_json j;
    j["n_r"] = L.n_r;
    j["n_h"] = L.n_h;
    j["circumference"] = L.circumference() * g.s_theta;
    j["height"] = L.height() * g.s_z;
    j["radius"] = L.radius() * g.s_theta;
    j["steps"] = run->steps();
    j["steps_per_cycle"] = run->mechanics().steps_per_cycle;
    j["cycles"] = run->target();
    j["springs"] = {{"axial", L.axial_count}, {"diagonal", L.springs() - L.axial_count}};
    if (!growing_) {
      const bark::BarkMaps& m = run->maps();
      j["map"] = {{"width", m.base_colour.width}, {"height", m.base_colour.height}};
    }
    return JsonText(j);
  }

  // A map's PNG bytes ("base_colour", "normal", "height", "orm"), or "" with the error in
  // lastError() (its field: "format").
  emscripten::val mapPng(const std::string& map) {
    error_.clear();
    if (!run_) {
      error_ = ErrorText(Status::Error("format", "no bark has grown yet"));
      return emscripten::val::null();
    }
    Result<std::string> png = run_->MapPng(map);
    if (!png.ok()) {
      error_ = ErrorText(png.status());
      return emscripten::val::null();
    }
    png_ = std::move(png).value();
    return emscripten::val(emscripten::typed_memory_view(
        png_.size(), reinterpret_cast<const unsigned char*>(png_.data())));
  }
  std::string lastError() const { return error_; }

  // The trunk segment's .glb (the run's Document(): the bytes `niwa bark grow --url HASH --out
  // trunk.glb` writes), or null with the error in lastError() (the page budget's line, or
  // "bark": nothing grown).
  emscripten::val glb() {
    error_.clear();
    if (!run_) {
      error_ = ErrorText(Status::Error("bark", "nothing grown yet"));
      return emscripten::val::null();
    }
    Result<Estimate> needs = run_->ExportEstimate("glb");
    Status fits =
        needs.ok() ? CheckEstimate(*needs, PageBudget(), "lower map_size") : needs.status();
    if (!fits.ok()) {
      error_ = ErrorText(fits);
      return emscripten::val::null();
    }
    Result<gltf::Document> doc = run_->Document();
    Result<std::vector<unsigned char>> bytes =
        doc.ok() ? gltf::WriteGlb(*doc) : Result<std::vector<unsigned char>>(doc.status());
    if (!bytes.ok()) {
      error_ = ErrorText(bytes.status());
      return emscripten::val::null();
    }
    png_.assign(bytes->begin(), bytes->end());
    return emscripten::val(emscripten::typed_memory_view(
        png_.size(), reinterpret_cast<const unsigned char*>(png_.data())));
  }

  emscripten::val buffers(const std::string& group) {
    NamedBuffers out;
    if (group == "tile") {
      const bark::BarkRun* run = Shown();
      if (!run) return emscripten::val::null();
      FillTile(*run, growing_ ? *growing_broke_at_ : broke_at_);
      out.Add("positions", tile_positions_).Add("stretch", tile_stretch_).Add("broken", tile_broken_);
      out.Add("layer", tile_layer_).Add("peel", tile_peel_);
    } else if (group == "springs") {
      const bark::BarkRun* run = Shown();
      if (!run) return emscripten::val::null();
      FillSprings(*run, growing_ ? *growing_broke_at_ : broke_at_);
      out.Add("positions", spring_positions_).Add("broken", spring_broken_);
    } else if (group == "maps") {
      if (!run_) return emscripten::val::null();
      const bark::BarkMaps& m = run_->maps();
      out.Add("base_colour", m.base_colour.pixels).Add("normal", m.normal.pixels).Add("orm", m.orm.pixels);
    } else {
      return emscripten::val::null();
    }
    return out.ToJs();
  }

 private:
  const bark::BarkRun* Shown() const { return growing_ ? growing_ : (run_ ? &*run_ : nullptr); }

  // Springs broken since the last look get the run's current step; in the 4-layer model a new S
  // (a role exchange) starts its springs' steps afresh.
  void NoteBreaks(const bark::BarkRun& run, std::vector<int32_t>* broke_at) {
    if (run.four_layer() && run.layers().layer[bark::kS].born != s_born_) {
      s_born_ = run.layers().layer[bark::kS].born;
      std::fill(broke_at->begin(), broke_at->end(), -1);
    }
    const std::vector<uint8_t>& broken = run.surface().broken;
    for (std::size_t i = 0; i < broken.size(); ++i)
      if (broken[i] && (*broke_at)[i] < 0) (*broke_at)[i] = run.steps();
  }

  void FillTile(const bark::BarkRun& run, const std::vector<int32_t>& broke_at) {
    const bark::Lattice& L = run.lattice();
    const bark::Surface& s = run.surface();
    const bark::Growth g = run.growth();
    const std::size_t tris = L.tri_nodes.size();
    tile_positions_.resize(tris * 6);
    tile_stretch_.resize(tris * 3);
    tile_broken_.resize(tris * 3);
    tile_layer_.resize(tris * 3);
    tile_peel_.resize(tris * 3);
    std::vector<uint8_t> visible;
    const bark::CorkLayer* S = nullptr;
    if (run.four_layer()) {
      visible = bark::VisibleLayer(L, run.layers());
      S = &run.layers().layer[bark::kS];
    }
    for (std::size_t t = 0; t < tris; ++t) {
      const auto& n = L.tri_nodes[t];
      const auto& o = L.tri_offsets[t];
      const int i0 = n[0] / L.n_h, j0 = n[0] % L.n_h;
      const double x0 = L.x_of(i0) * g.s_theta, z0 = L.z_of(i0, j0) * g.s_z;
      const double ox[3] = {0, o[0], o[2]}, oz[3] = {0, o[1], o[3]};
      double x[3], z[3];
      for (int k = 0; k < 3; ++k) {
        x[k] = x0 + ox[k] * g.s_theta + s.ux[n[k]];
        z[k] = z0 + oz[k] * g.s_z + s.uz[n[k]];
      }
      const auto [dx, dz] = IntoPatch(std::min({x[0], x[1], x[2]}), std::min({z[0], z[1], z[2]}),
                                      L.circumference() * g.s_theta, L.height() * g.s_z);
      for (int k = 0; k < 3; ++k) {
        tile_positions_[6 * t + 2 * k] = static_cast<float>(x[k] + dx);
        tile_positions_[6 * t + 2 * k + 1] = static_cast<float>(z[k] + dz);
      }
      float stretch = 0;
      int32_t first = -1;
      for (int e = 0; e < 3; ++e) {
        const int spring = L.tri_springs[t][e];
        if (s.broken[spring]) {
          const int32_t at = broke_at[spring] >= 0 ? broke_at[spring] : run.steps();
          first = first < 0 ? at : std::min(first, at);
          continue;
        }
        const double limit = std::sqrt(static_cast<double>(s.limit2[L.slot(spring)])) / L.l_o - 1.0;
        const double strain = bark::SpringStrain(L, s, g, spring);
        if (limit > 0) stretch = std::max(stretch, static_cast<float>(strain / limit));
      }
      stretch = std::clamp(stretch, 0.0f, 1.0f);
      const float layer = S ? visible[t] : (first < 0 ? 0.0f : 3.0f);
      float peel = 0;
      if (S) {
        for (int k = 0; k < 3; ++k) {
          const int node = n[k];
          peel = std::max(peel, !S->present[node] ? 2.0f : (!S->bonded[node] ? 1.0f : 0.0f));
        }
      }
      for (int k = 0; k < 3; ++k) {
        tile_stretch_[3 * t + k] = stretch;
        tile_broken_[3 * t + k] = static_cast<float>(first);
        tile_layer_[3 * t + k] = layer;
        tile_peel_[3 * t + k] = peel;
      }
    }
  }

  void FillSprings(const bark::BarkRun& run, const std::vector<int32_t>& broke_at) {
    const bark::Lattice& L = run.lattice();
    const bark::Surface& s = run.surface();
    const bark::Growth g = run.growth();
    spring_positions_.clear();
    spring_broken_.clear();
    for (int i = 0; i < L.springs(); ++i) {
      if (!s.broken[i]) continue;
      const int a = L.a[i], b = L.b[i];
      const int ia = a / L.n_h, ja = a % L.n_h;
      const double xa = L.x_of(ia) * g.s_theta + s.ux[a], za = L.z_of(ia, ja) * g.s_z + s.uz[a];
      const double xb = xa + L.ox[i] * g.s_theta + (s.ux[b] - s.ux[a]);
      const double zb = za + L.oz[i] * g.s_z + (s.uz[b] - s.uz[a]);
      const float at = static_cast<float>(broke_at[i] >= 0 ? broke_at[i] : run.steps());
      const auto [dx, dz] = IntoPatch(std::min(xa, xb), std::min(za, zb),
                                      L.circumference() * g.s_theta, L.height() * g.s_z);
      spring_positions_.insert(spring_positions_.end(), {static_cast<float>(xa + dx),
                                                         static_cast<float>(za + dz),
                                                         static_cast<float>(xb + dx),
                                                         static_cast<float>(zb + dz)});
      spring_broken_.insert(spring_broken_.end(), {at, at});
    }
  }

  // The whole patches (c around, h along) that move a shape whose lowest corner is (x, z) into
  // [0, c) × [0, h).
  static std::pair<double, double> IntoPatch(double x, double z, double c, double h) {
    return {-std::floor(x / c) * c, -std::floor(z / h) * h};
  }

  static constexpr int kNoLayer = -1000000;

  std::optional<bark::BarkRun> run_;
  std::vector<int32_t> broke_at_;
  const bark::BarkRun* growing_ = nullptr;
  std::vector<int32_t>* growing_broke_at_ = nullptr;
  std::vector<float> tile_positions_, tile_stretch_, tile_broken_, tile_layer_, tile_peel_;
  std::vector<float> spring_positions_, spring_broken_;
  int s_born_ = kNoLayer;  // the 4-layer S whose springs broke_at times
  std::string png_, error_;
  emscripten::val progress_ = emscripten::val::null();
};

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_bark) {
  using namespace emscripten;
  class_<niwa::BarkLab>("BarkLab")
      .constructor<>()
      .function("setProgress", &niwa::BarkLab::setProgress)
      .function("check", &niwa::BarkLab::check)
      .function("grow", &niwa::BarkLab::grow)
      .function("statsJson", &niwa::BarkLab::statsJson)
      .function("hash", &niwa::BarkLab::hash)
      .function("stateJson", &niwa::BarkLab::stateJson)
      .function("cyclesCsv", &niwa::BarkLab::cyclesCsv)
      .function("boundsJson", &niwa::BarkLab::boundsJson)
      .function("mapPng", &niwa::BarkLab::mapPng)
      .function("glb", &niwa::BarkLab::glb)
      .function("lastError", &niwa::BarkLab::lastError)
      .function("buffers", &niwa::BarkLab::buffers);
}
