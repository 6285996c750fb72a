// The garden's state, its JSON and its share-link hash (see garden_state.h).
#include "compose/garden_state.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "base/budget.h"
#include "base/echo.h"
#include "image/png.h"
#include "io/hash_codec.h"
#include "ivy/ivy_params.h"
#include "params/param_json.h"
#include "params/param_text.h"
#include "tree/presets.h"

namespace niwa::compose {
namespace {

using json = nlohmann::ordered_json;

std::string GardenIndexed(const char* list, std::size_t i, const char* field) {
  return std::string(list) + "[" + std::to_string(i) + "]." + field;
}

bool KnownObjectKind(const std::string& kind) {
  if (kind == "mesh") return true;
  for (const std::string& k : GardenObjectKinds())
    if (k == kind) return true;
  return false;
}

std::string ObjectKindList() { return "wall, rock, lantern or mesh (with a file)"; }

std::string JoinWindKeys() {
  std::string out;
  for (const std::string& k : GardenWindKeys()) out += (out.empty() ? "" : ", ") + k;
  return out;
}

// A finite number from a JSON value, else the error naming `field`.
Result<double> GardenNumber(const json& v, const std::string& field, const std::string& what) {
  if (!v.is_number()) return Status::Error(field, "must be " + what);
  const double d = v.get<double>();
  if (!std::isfinite(d)) return Status::Error(field, "must be " + what);
  return d;
}

Result<std::pair<double, double>> GardenPos(const json& v, const std::string& field) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
    return Status::Error(field, "must be [x, z], two numbers in metres");
  const double x = v[0].get<double>(), z = v[1].get<double>();
  if (!std::isfinite(x) || !std::isfinite(z))
    return Status::Error(field, "must be [x, z], two finite numbers in metres");
  return std::make_pair(x, z);
}

Status CheckWhole(double v, double lo, double hi, const std::string& field) {
  if (!(v >= lo && v <= hi) || v != std::floor(v))
    return Status::Error(field, FormatNumber(v) + " must be a whole number in [" +
                                    FormatNumber(lo) + ", " + FormatNumber(hi) + "]");
  return Status::Ok();
}

Status CheckIn(double v, double lo, double hi, const std::string& field) {
  if (!(v >= lo && v <= hi))
    return Status::Error(field, FormatNumber(v) + " must be a number in [" + FormatNumber(lo) +
                                    ", " + FormatNumber(hi) + "]");
  return Status::Ok();
}

Result<GardenObject> ParseGardenObject(const json& o, std::size_t i) {
  const std::string at = "objects[" + std::to_string(i) + "]";
  if (!o.is_object()) return Status::Error(at, "must be an object {kind, pos, rot, scale}");
  GardenObject obj;
  for (const auto& [key, v] : o.items()) {
    if (key == "kind") {
      if (!v.is_string()) return Status::Error(at + ".kind", "must be " + ObjectKindList());
      obj.kind = v.get<std::string>();
    } else if (key == "pos") {
      Result<std::pair<double, double>> p = GardenPos(v, at + ".pos");
      if (!p.ok()) return p.status();
      obj.x = p->first, obj.z = p->second;
    } else if (key == "rot") {
      Result<double> d = GardenNumber(v, at + ".rot", "a number of degrees in [-360, 360]");
      if (!d.ok()) return d.status();
      obj.rot = *d;
    } else if (key == "scale") {
      Result<double> d = GardenNumber(v, at + ".scale", "a number in [0.1, 20]");
      if (!d.ok()) return d.status();
      obj.scale = *d;
    } else if (key == "file") {
      if (!v.is_string() || v.get<std::string>().empty())
        return Status::Error(at + ".file", "must name a .glb, .gltf or .obj file");
      obj.file = v.get<std::string>();
    } else {
      return Status::Error(at + "." + Echo(key),
                           "unknown field; an object has kind, pos, rot, scale and file");
    }
  }
  return obj;
}

Result<GardenPlant> ParseGardenPlant(const json& o, std::size_t i) {
  const std::string at = "plants[" + std::to_string(i) + "]";
  if (!o.is_object()) return Status::Error(at, "must be an object {species, seed, age, pos, rot}");
  GardenPlant plant;
  for (const auto& [key, v] : o.items()) {
    if (key == "species") {
      if (!v.is_string()) return Status::Error(at + ".species", "must be one of " + PresetNames());
      plant.species = v.get<std::string>();
    } else if (key == "seed") {
      Result<double> d = GardenNumber(v, at + ".seed", "a whole number in [0, 4294967295]");
      if (!d.ok()) return d.status();
      NIWA_RETURN_IF_ERROR(CheckWhole(*d, 0, kMaxGardenSeed, at + ".seed"));
      plant.seed = static_cast<uint64_t>(*d);
    } else if (key == "age") {
      Result<double> d = GardenNumber(v, at + ".age", "a whole number of years in [0, 60]");
      if (!d.ok()) return d.status();
      NIWA_RETURN_IF_ERROR(CheckWhole(*d, 0, kMaxPlantAge, at + ".age"));
      plant.age = static_cast<int>(*d);
    } else if (key == "pos") {
      Result<std::pair<double, double>> p = GardenPos(v, at + ".pos");
      if (!p.ok()) return p.status();
      plant.x = p->first, plant.z = p->second;
    } else if (key == "rot") {
      Result<double> d = GardenNumber(v, at + ".rot", "a number of degrees in [-360, 360]");
      if (!d.ok()) return d.status();
      plant.rot = *d;
    } else {
      return Status::Error(at + "." + Echo(key),
                           "unknown field; a plant has species, seed, age, pos and rot");
    }
  }
  return plant;
}

const char* GroundKindName(GroundKind kind) {
  switch (kind) {
    case GroundKind::kFlat:
      return "flat";
    case GroundKind::kTerrain:
      return "terrain";
    case GroundKind::kHeightmap:
      return "heightmap";
    case GroundKind::kMesh:
      return "mesh";
  }
  return "flat";
}

std::optional<GroundKind> GroundKindOf(std::string_view name) {
  if (name == "flat") return GroundKind::kFlat;
  if (name == "terrain") return GroundKind::kTerrain;
  if (name == "heightmap") return GroundKind::kHeightmap;
  if (name == "mesh") return GroundKind::kMesh;
  return std::nullopt;
}

// "a:b:c" split at ':'.
std::vector<std::string> SplitOn(std::string_view text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(sep, start);
    parts.emplace_back(text.substr(start, at == std::string_view::npos ? text.npos : at - start));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return parts;
}

}  // namespace

const std::vector<std::string>& GardenObjectKinds() {
  static const std::vector<std::string> kinds = {"wall", "rock", "lantern"};
  return kinds;
}

void LayOutDefaults(GardenState* state) {
  if (!state->default_layout) return;
  const double f = state->params.Get(GardenParam::kSize) / 40.0;
  state->objects = {{"wall", 0, -12 * f, 0, 1},
                    {"rock", 6 * f, 4 * f, 20, 1.2},
                    {"rock", -8 * f, 8 * f, 70, 0.8},
                    {"lantern", 3 * f, -3 * f, 0, 1}};
  state->plants = {{"keyaki", 1, 5, -3 * f, 2 * f, 0}};
  state->ivy_on = {"objects[0]"};
}

GardenState DefaultGardenState() {
  GardenState state;
  (void)terrain::SetTerrainPreset("fig16", &state.terrain);
  LayOutDefaults(&state);
  state.mix = {{"keyaki", 2}, {"sakura", 1}, {"maple", 1}};
  return state;
}

Result<GardenIvyTarget> ParseIvyTarget(std::string_view text, const GardenState& state) {
  GardenIvyTarget t;
  std::size_t count = 0;
  std::string_view rest;
  if (text.rfind("objects[", 0) == 0) {
    t.object = true;
    count = state.objects.size();
    rest = text.substr(8);
  } else if (text.rfind("plants[", 0) == 0) {
    count = state.plants.size();
    rest = text.substr(7);
  } else {
    return Status::Error("ivy", "'" + Echo(text) + "' is not objects[i] or plants[i]");
  }
  const std::size_t close = rest.find(']');
  const std::optional<double> i = close == std::string_view::npos || close + 1 != rest.size()
                                      ? std::nullopt
                                      : ParseNumber(rest.substr(0, close));
  if (!i || *i < 0 || *i != std::floor(*i) || *i >= static_cast<double>(count))
    return Status::Error("ivy", "'" + Echo(text) + "' names no " +
                                    (t.object ? "object" : "hand-placed tree") +
                                    "; the garden has " + std::to_string(count) +
                                    (t.object ? " objects" : " of them"));
  t.index = static_cast<std::size_t>(*i);
  return t;
}

namespace {

// The wind's rows together (the derived gust_on before gust_off, a front that reaches the centre
// within gust_on's range), their errors under "wind.".
Status CheckGardenWind(const GardenState& state) {
  const Result<ParamSet> rows =
      GardenWindRows(state.params.Get(GardenParam::kSize), state.wind, "");
  if (rows.ok()) return Status::Ok();
  const std::string& field = rows.status().field();
  return Status::Error(
      field.empty() || field == "wind" ? "wind" : "wind." + field,
      rows.status().message() +
          (field == "gust_off" ? ", the time the front reaches the garden's centre" : ""));
}

}  // namespace

Status CheckGardenState(const GardenState& state) {
  const double half = state.params.Get(GardenParam::kSize) / 2;
  const std::string range = "[" + FormatNumber(-half) + ", " + FormatNumber(half) + "]";
  if (state.objects.size() > kMaxGardenObjects)
    return Status::Error("objects", std::to_string(state.objects.size()) + " objects; at most " +
                                        std::to_string(kMaxGardenObjects));
  if (state.plants.size() > kMaxGardenPlants)
    return Status::Error("plants", std::to_string(state.plants.size()) + " plants; at most " +
                                       std::to_string(kMaxGardenPlants) +
                                       " by hand (the planting rules place more)");
  for (std::size_t i = 0; i < state.objects.size(); ++i) {
    const GardenObject& o = state.objects[i];
    if (!KnownObjectKind(o.kind))
      return Status::Error(GardenIndexed("objects", i, "kind"),
                           "'" + Echo(o.kind) + "' is not an object; must be " + ObjectKindList());
    if (std::abs(o.x) > half || std::abs(o.z) > half)
      return Status::Error(GardenIndexed("objects", i, "pos"),
                           "[" + FormatNumber(o.x) + ", " + FormatNumber(o.z) +
                               "] is outside the garden; x and z must be in " + range +
                               " (move it or raise size)");
    NIWA_RETURN_IF_ERROR(CheckIn(o.rot, -360, 360, GardenIndexed("objects", i, "rot")));
    NIWA_RETURN_IF_ERROR(CheckIn(o.scale, 0.1, 20, GardenIndexed("objects", i, "scale")));
    if (o.kind == "mesh" && o.file.empty() && o.mesh.triangle_count() == 0)
      return Status::Error(GardenIndexed("objects", i, "file"),
                           "a mesh object needs a .glb, .gltf or .obj file");
    if (o.kind != "mesh" && !o.file.empty())
      return Status::Error(GardenIndexed("objects", i, "file"),
                           "only a mesh object has a file (kind '" + Echo(o.kind) + "')");
  }
  for (std::size_t i = 0; i < state.plants.size(); ++i) {
    const GardenPlant& p = state.plants[i];
    if (FindPreset(p.species) == nullptr)
      return Status::Error(
          GardenIndexed("plants", i, "species"),
          "'" + Echo(p.species) + "' is not a tree preset; must be one of " + PresetNames());
    if (std::abs(p.x) > half || std::abs(p.z) > half)
      return Status::Error(GardenIndexed("plants", i, "pos"),
                           "[" + FormatNumber(p.x) + ", " + FormatNumber(p.z) +
                               "] is outside the garden; x and z must be in " + range +
                               " (move it or raise size)");
    NIWA_RETURN_IF_ERROR(CheckIn(p.rot, -360, 360, GardenIndexed("plants", i, "rot")));
  }
  if (state.mix.size() > kMaxGardenMix)
    return Status::Error("mix", std::to_string(state.mix.size()) + " species; at most " +
                                    std::to_string(kMaxGardenMix));
  for (const SpeciesWeight& w : state.mix) {
    if (FindPreset(w.species) == nullptr)
      return Status::Error(
          "mix", "'" + Echo(w.species) + "' is not a tree preset; must be one of " + PresetNames());
    if (!(w.weight > 0 && w.weight <= 1000))
      return Status::Error("mix." + w.species,
                           FormatNumber(w.weight) + " must be a weight in (0, 1000]");
  }
  for (const std::string& on : state.ivy_on) {
    Result<GardenIvyTarget> t = ParseIvyTarget(on, state);
    if (!t.ok()) return t.status();
  }
  if (state.ivy_on.size() > kMaxGardenIvy)
    return Status::Error("ivy", std::to_string(state.ivy_on.size()) + " seeds; at most " +
                                    std::to_string(kMaxGardenIvy));
  if (const Result<IvyParams> preset = IvyPreset(state.ivy_preset); !preset.ok())
    return Status::Error("ivy.preset", preset.status().message());
  if (state.params.Get(GardenParam::kDensity) > 0 && state.mix.empty())
    return Status::Error("mix", "is empty; density > 0 needs at least one species to plant");
  if (state.params.Get(GardenParam::kAltMin) > state.params.Get(GardenParam::kAltMax))
    return Status::Error("alt_min", FormatNumber(state.params.Get(GardenParam::kAltMin)) +
                                        " is above alt_max " +
                                        FormatNumber(state.params.Get(GardenParam::kAltMax)) +
                                        "; must be at most alt_max");
  if (state.ground == GroundKind::kHeightmap && state.heightmap_png.empty() &&
      state.heightmap_name.empty())
    return Status::Error("ground.file", "a heightmap ground needs a 16-bit grey PNG file");
  if (state.ground == GroundKind::kMesh && state.ground_mesh.triangle_count() == 0 &&
      state.heightmap_name.empty())
    return Status::Error("ground.file", "a mesh ground needs a .glb, .gltf or .obj file");
  return CheckGardenWind(state);
}

Status LoadGardenMeshes(const GardenMeshReader& read, GardenState* state) {
  if (state->ground == GroundKind::kMesh && !state->heightmap_name.empty()) {
    Result<geom::TriMesh> mesh = read(state->heightmap_name);
    if (!mesh.ok()) return mesh.status().Within("ground.file");
    state->ground_mesh = std::move(*mesh);
  }
  for (std::size_t i = 0; i < state->objects.size(); ++i) {
    GardenObject& o = state->objects[i];
    if (o.kind != "mesh" || o.file.empty()) continue;
    Result<geom::TriMesh> mesh = read(o.file);
    if (!mesh.ok()) return mesh.status().Within(GardenIndexed("objects", i, "file"));
    o.mesh = std::move(*mesh);
  }
  return Status::Ok();
}

namespace {

// The checks both images share: the file's bytes, the PNG's chunks and its declared size.
Result<image::PngInfo> GardenImageInfo(const std::string& field, const std::string& name,
                                       const std::vector<unsigned char>& png, int min_side,
                                       const std::string& must) {
  const std::string quoted = "'" + Echo(name) + "'";
  if (png.size() > kMaxGardenImageBytes)
    return Status::Error(field, quoted + " is " + FormatCount(static_cast<double>(png.size())) +
                                    " bytes; at most " +
                                    FormatCount(static_cast<double>(kMaxGardenImageBytes)) + " (" +
                                    FormatBytes(static_cast<double>(kMaxGardenImageBytes)) + ")");
  Result<image::PngInfo> info = image::ReadPngInfo(png.data(), png.size());
  if (!info.ok())
    return Status::Error(field, quoted + ": " + info.status().message() + "; must be " + must);
  if (info->width < min_side || info->height < min_side || info->width > kMaxGardenImageSide ||
      info->height > kMaxGardenImageSide)
    return Status::Error(field, quoted + " is " + std::to_string(info->width) + " x " +
                                    std::to_string(info->height) +
                                    " pixels; each side must be in " + std::to_string(min_side) +
                                    ".." + std::to_string(kMaxGardenImageSide));
  return info;
}

}  // namespace

Result<image::Gray16Image> DecodeGardenHeightmap(const std::string& name,
                                                 const std::vector<unsigned char>& png) {
  const std::string must = "a grey PNG (16-bit or 8-bit)";
  Result<image::PngInfo> info = GardenImageInfo("ground.file", name, png, 2, must);
  if (!info.ok()) return info.status();
  if (!info->is_grey())
    return Status::Error(
        "ground.file",
        "'" + Echo(name) + "' is a " +
            (info->colour_type == 2   ? std::string("colour (RGB)")
             : info->colour_type == 3 ? std::string("palette")
             : info->colour_type == 6 ? std::string("colour (RGBA)")
                                      : "colour type " + std::to_string(info->colour_type)) +
            " PNG; must be " + must);
  Result<image::Gray16Image> img = image::DecodeGray16Png(png.data(), png.size());
  if (!img.ok())
    return Status::Error("ground.file",
                         "'" + Echo(name) + "': " + img.status().message() + "; must be " + must);
  return img;
}

Result<image::Rgba8Image> DecodeGardenMask(const std::string& name,
                                           const std::vector<unsigned char>& png) {
  const std::string must = "a PNG (grey or colour: its luminance the chance a tree is kept)";
  Result<image::PngInfo> info = GardenImageInfo("mask", name, png, 1, must);
  if (!info.ok()) return info.status();
  Result<image::Rgba8Image> img = image::DecodeRgba8Png(png.data(), png.size());
  if (!img.ok())
    return Status::Error("mask",
                         "'" + Echo(name) + "': " + img.status().message() + "; must be " + must);
  return img;
}

Status LoadGardenImages(const GardenFileReader& read, GardenState* state) {
  if (state->ground == GroundKind::kHeightmap && !state->heightmap_name.empty()) {
    Result<std::vector<unsigned char>> png = read("ground.file", state->heightmap_name);
    if (!png.ok()) return png.status().Within("ground.file");
    state->heightmap_png = std::move(*png);
  }
  if (!state->mask_name.empty()) {
    Result<std::vector<unsigned char>> png = read("mask", state->mask_name);
    if (!png.ok()) return png.status().Within("mask");
    state->mask_png = std::move(*png);
  }
  return Status::Ok();
}

moss::MossState GardenMossDefaults() {
  moss::MossState state;
  (void)moss::SetMossPreset("nomura2010-sky", &state);
  moss::MossParams& p = state.params;
  (void)p.Set(moss::MossParam::kPhotons, 8192);
  (void)p.Set(moss::MossParam::kRGather, 1.0);
  (void)p.Set(moss::MossParam::kSoilEdge, 0.5);
  (void)p.Set(moss::MossParam::kLightSmoothingDays, 10);
  // Caps for a garden's moss: its estimate counts every moss and seed the caps allow each day.
  (void)p.Set(moss::MossParam::kMaxMosses, 4096);
  (void)p.Set(moss::MossParam::kSeedCap, 4096);
  // The sun in the south at 55° (a mean of the noon altitudes at 35° N: 31° to 78°), not the
  // thesis's zenith: a garden's north faces and the ground north of a crown are in shade.
  (void)p.Set(moss::MossParam::kSunAltitude, 55);
  (void)p.Set(moss::MossParam::kSunAzimuth, 90);
  return state;
}

namespace {

// {wind_speed: 12, ...} onto `wind`, each key a garden wind row and its value in the row's range;
// errors name "wind.<key>" (or "wind").
Status ApplyWindRows(const json& v, TreeParams* wind) {
  if (!v.is_object())
    return Status::Error(
        "wind", "must be an object {key: value} of the wind rows (" + JoinWindKeys() + ")");
  TreeParams next = *wind;
  for (const auto& [k, value] : v.items()) {
    if (!IsGardenWindKey(k))
      return Status::Error("wind." + Echo(k), "not a wind row; the garden's wind has " +
                                                  JoinWindKeys() +
                                                  " (gust_on follows from the front)");
    if (!value.is_number()) return Status::Error("wind." + Echo(k), "must be a number");
    const Status set = next.SetFromText(k, FormatNumber(value.get<double>()));
    if (!set.ok()) return Status::Error("wind." + Echo(k), set.message());
  }
  *wind = next;
  return Status::Ok();
}

}  // namespace

Status ApplyGardenWindJson(const std::string& text, GardenState* state) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) return Status::Error("wind", "is not JSON; must be {key: value}");
  GardenState next = *state;
  NIWA_RETURN_IF_ERROR(ApplyWindRows(j, &next.wind));
  NIWA_RETURN_IF_ERROR(CheckGardenWind(next));
  state->wind = next.wind;
  return Status::Ok();
}

std::string GardenWindJson(const GardenState& state) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  const TreeParams base = GardenWindBase();
  for (std::size_t r = 0; r < state.wind.size(); ++r) {
    const std::string key = state.wind.table().row(r).key;
    if (IsGardenWindKey(key) && state.wind.Get(r) != base.Get(r)) j[key] = state.wind.Get(r);
  }
  return j.dump();
}

Status ApplyGardenStateJson(const std::string& text, GardenState* state) {
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    return Status::Error("garden",
                         "is not a JSON object; must be {params, ground, objects, "
                         "plants, mix, mask}");
  GardenState next = *state;
  const bool was_default = next.default_layout;
  bool ivy_given = false;
  // The ivy's targets as given: the default layout (laid out when a list is given, in whichever
  // order the keys come, and below) would put back the default wall's.
  std::optional<std::vector<std::string>> ivy_on;
  for (const auto& [key, v] : j.items()) {
    if (key == "params") {
      if (!v.is_object()) return Status::Error("params", "must be an object {key: value}");
      for (const auto& [k, value] : v.items()) {
        if (!value.is_number())
          return Status::Error(Echo(k), "must be a number (niwa params garden)");
        NIWA_RETURN_IF_ERROR(next.params.SetFromText(k, FormatNumber(value.get<double>())));
      }
    } else if (key == "ground") {
      if (!v.is_object())
        return Status::Error("ground",
                             "must be an object {kind: flat, terrain, heightmap or mesh}");
      for (const auto& [k, value] : v.items()) {
        if (k == "kind") {
          const std::optional<GroundKind> kind =
              value.is_string() ? GroundKindOf(value.get<std::string>()) : std::nullopt;
          if (!kind)
            return Status::Error("ground.kind", "must be flat, terrain, heightmap or mesh");
          next.ground = *kind;
        } else if (k == "terrain") {
          NIWA_RETURN_IF_ERROR(
              terrain::ApplyTerrainStateJson(value.dump(), &next.terrain).Within("ground.terrain"));
        } else if (k == "file") {
          if (!value.is_string() || value.get<std::string>().empty())
            return Status::Error("ground.file",
                                 "must name a 16-bit grey PNG file (a heightmap ground) or a .glb, "
                                 ".gltf or .obj file (a mesh ground)");
          next.heightmap_name = value.get<std::string>();
          next.heightmap_png.clear();
          next.ground_mesh = geom::TriMesh{};
        } else {
          return Status::Error("ground." + Echo(k),
                               "unknown field; the ground has kind, terrain and file");
        }
      }
    } else if (key == "moss") {
      if (!v.is_object()) return Status::Error("moss", "must be the moss's state {preset, params}");
      NIWA_RETURN_IF_ERROR(moss::ApplyMossStateJson(v.dump(), &next.moss).Within("moss"));
    } else if (key == "objects" || key == "plants") {
      if (!v.is_array()) return Status::Error(key, "must be an array");
      if (next.default_layout) {
        // The other list stays the default layout's, at the size it has now (this file's size,
        // when it gives one, applies below).
        LayOutDefaults(&next);
        next.default_layout = false;
      }
      if (key == "objects") {
        next.objects.clear();
        for (std::size_t i = 0; i < v.size(); ++i) {
          Result<GardenObject> o = ParseGardenObject(v[i], i);
          if (!o.ok()) return o.status();
          next.objects.push_back(*o);
        }
      } else {
        next.plants.clear();
        for (std::size_t i = 0; i < v.size(); ++i) {
          Result<GardenPlant> p = ParseGardenPlant(v[i], i);
          if (!p.ok()) return p.status();
          next.plants.push_back(*p);
        }
      }
    } else if (key == "mix") {
      if (!v.is_object()) return Status::Error("mix", "must be an object {species: weight}");
      next.mix.clear();
      for (const auto& [species, weight] : v.items()) {
        Result<double> w = GardenNumber(weight, "mix." + Echo(species), "a weight in (0, 1000]");
        if (!w.ok()) return w.status();
        next.mix.push_back({species, *w});
      }
    } else if (key == "ivy") {
      if (!v.is_object()) return Status::Error("ivy", "must be an object {preset, on: [...]}");
      ivy_given = v.contains("on");
      for (const auto& [k, value] : v.items()) {
        if (k == "preset") {
          if (!value.is_string()) return Status::Error("ivy.preset", "must be an ivy preset name");
          next.ivy_preset = value.get<std::string>();
        } else if (k == "on") {
          if (!value.is_array())
            return Status::Error("ivy.on", "must be an array of objects[i] or plants[i]");
          next.ivy_on.clear();
          for (const auto& item : value) {
            if (!item.is_string())
              return Status::Error("ivy.on", "must be an array of objects[i] or plants[i]");
            next.ivy_on.push_back(item.get<std::string>());
          }
          ivy_on = next.ivy_on;
        } else {
          return Status::Error("ivy." + Echo(k), "unknown field; ivy has preset and on");
        }
      }
    } else if (key == "wind") {
      NIWA_RETURN_IF_ERROR(ApplyWindRows(v, &next.wind));
    } else if (key == "mask") {
      if (v.is_null()) {
        next.mask_name.clear();
        next.mask_png.clear();
      } else if (!v.is_string() || v.get<std::string>().empty()) {
        return Status::Error("mask", "must name a PNG file (or be null)");
      } else {
        next.mask_name = v.get<std::string>();
        next.mask_png.clear();
      }
    } else {
      return Status::Error(Echo(key),
                           "unknown field; a garden has params, ground, objects, plants, mix, "
                           "ivy and mask");
    }
  }
  // The default ivy grows on the default wall: a file that places its own objects or plants and
  // names no ivy has none.
  if (was_default && !next.default_layout && !ivy_given) next.ivy_on.clear();
  LayOutDefaults(&next);
  if (ivy_on) next.ivy_on = *ivy_on;
  NIWA_RETURN_IF_ERROR(CheckGardenState(next));
  *state = std::move(next);
  return Status::Ok();
}

std::string GardenStateJson(const GardenState& state) {
  nlohmann::ordered_json j;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (std::size_t r = 0; r < state.params.size(); ++r)
    params[state.params.table().row(r).key] = state.params.Get(r);
  j["params"] = params;
  nlohmann::ordered_json ground;
  ground["kind"] = GroundKindName(state.ground);
  if (state.ground == GroundKind::kTerrain)
    ground["terrain"] = nlohmann::ordered_json::parse(terrain::TerrainStateJson(state.terrain));
  if (state.ground == GroundKind::kHeightmap || state.ground == GroundKind::kMesh)
    ground["file"] = state.heightmap_name;
  j["ground"] = ground;
  j["objects"] = nlohmann::ordered_json::array();
  for (const GardenObject& o : state.objects) {
    nlohmann::ordered_json item = {
        {"kind", o.kind}, {"pos", {o.x, o.z}}, {"rot", o.rot}, {"scale", o.scale}};
    if (o.kind == "mesh") item["file"] = o.file;
    j["objects"].push_back(item);
  }
  j["plants"] = nlohmann::ordered_json::array();
  for (const GardenPlant& p : state.plants)
    j["plants"].push_back({{"species", p.species},
                           {"seed", p.seed},
                           {"age", p.age},
                           {"pos", {p.x, p.z}},
                           {"rot", p.rot}});
  j["mix"] = nlohmann::ordered_json::object();
  for (const SpeciesWeight& w : state.mix) j["mix"][w.species] = w.weight;
  j["ivy"] = {{"preset", state.ivy_preset}, {"on", state.ivy_on}};
  if (!state.mask_name.empty()) j["mask"] = state.mask_name;
  const std::string moss_json = moss::MossStateJson(state.moss);
  if (moss_json != moss::MossStateJson(GardenMossDefaults()))
    j["moss"] = nlohmann::ordered_json::parse(moss_json);
  const std::string wind_json = GardenWindJson(state);
  if (wind_json != "{}") j["wind"] = nlohmann::ordered_json::parse(wind_json);
  return j.dump(2);
}

std::string EncodeGardenHash(const GardenState& state, std::string_view prefix) {
  const std::string pre(prefix);
  const GardenState base = DefaultGardenState();
  std::string hash = "ground=" + std::string(GroundKindName(state.ground));
  hash += EncodeChangedParams(state.params, base.params, prefix);
  auto list = [&](const char* key, const std::vector<std::string>& items) {
    std::string value;
    for (const std::string& item : items) value += (value.empty() ? "" : ",") + item;
    hash += "&" + pre + key + "=" + PercentEncode(value);
  };
  std::vector<std::string> items;
  for (const GardenObject& o : state.objects)
    items.push_back(o.kind + ":" + FormatNumber(o.x) + ":" + FormatNumber(o.z) + ":" +
                    FormatNumber(o.rot) + ":" + FormatNumber(o.scale));
  list("objects", items);
  items.clear();
  for (const GardenPlant& p : state.plants)
    items.push_back(p.species + ":" + std::to_string(p.seed) + ":" + std::to_string(p.age) + ":" +
                    FormatNumber(p.x) + ":" + FormatNumber(p.z) + ":" + FormatNumber(p.rot));
  list("plants", items);
  items.clear();
  for (const SpeciesWeight& w : state.mix)
    items.push_back(w.species + ":" + FormatNumber(w.weight));
  list("mix", items);
  list("ivy", state.ivy_on);
  if (!state.mask_name.empty() || !state.mask_png.empty()) hash += "&" + pre + "mask=1";
  if (state.ivy_preset != base.ivy_preset)
    hash += "&" + pre + "ivy_preset=" + PercentEncode(state.ivy_preset);
  if (state.ground == GroundKind::kTerrain)
    hash += "&" + terrain::EncodeTerrainHash(state.terrain, pre + "terrain.");
  if (moss::MossStateJson(state.moss) != moss::MossStateJson(GardenMossDefaults()))
    hash += "&" + moss::EncodeMossHash(state.moss, pre + "moss.");
  const TreeParams wind_base = GardenWindBase();
  for (std::size_t r = 0; r < state.wind.size(); ++r) {
    const std::string key = state.wind.table().row(r).key;
    if (IsGardenWindKey(key) && state.wind.Get(r) != wind_base.Get(r))
      hash += "&" + pre + "wind." + key + "=" + FormatNumber(state.wind.Get(r));
  }
  return pre + hash;
}

void ApplyGardenHash(std::string_view hash, std::string_view prefix, GardenState* state,
                     std::vector<std::string>* notices) {
  const std::string pre(prefix);
  const std::string terrain_prefix = pre + "terrain.";
  bool terrain_keys = false;
  const bool was_default = state->default_layout;
  bool ivy_given = false;
  // The ivy keys last: they name objects and plants the other keys may replace.
  HashPairs pairs = SplitHash(hash, notices);
  std::stable_partition(pairs.begin(), pairs.end(), [&](const auto& kv) {
    return kv.first != pre + "ivy" && kv.first != pre + "ivy_preset";
  });
  const std::string moss_prefix = pre + "moss.";
  const std::string wind_prefix = pre + "wind.";
  bool moss_keys = false;
  bool wind_keys = false;
  for (const auto& [key, value] : pairs) {
    if (key.rfind(wind_prefix, 0) == 0) {
      // The wind's rows, clamped into range as every table's (io/hash_codec ApplyHashParam).
      if (IsGardenWindKey(std::string_view(key).substr(wind_prefix.size()))) {
        std::vector<std::string> wind_notices;
        ApplyHashParam(key, value, wind_prefix, &state->wind, &wind_notices);
        if (notices != nullptr)
          notices->insert(notices->end(), wind_notices.begin(), wind_notices.end());
        wind_keys = true;
      } else if (notices != nullptr) {
        notices->push_back(Printable(key) + ": not a wind row of the garden (" + JoinWindKeys() +
                           "); dropped");
      }
      continue;
    }
    if (key.rfind(terrain_prefix, 0) == 0) {
      terrain_keys = true;
      continue;
    }
    if (key.rfind(moss_prefix, 0) == 0) {
      moss_keys = true;
      continue;
    }
    if (key.rfind(pre, 0) != 0) continue;
    const std::string bare = key.substr(pre.size());
    if (ApplyHashParam(key, value, prefix, &state->params, notices)) continue;
    auto notice = [&](const std::string& line) {
      if (notices != nullptr) notices->push_back(line);
    };
    if (bare == "ground") {
      const std::optional<GroundKind> kind = GroundKindOf(value);
      if (!kind) {
        notice("ground: '" + Printable(value) +
               "' dropped; must be flat, terrain, heightmap or mesh");
      } else if (*kind == GroundKind::kHeightmap || *kind == GroundKind::kMesh) {
        notice(std::string("ground: a ") + (*kind == GroundKind::kMesh ? "mesh" : "heightmap") +
               " is not carried by a link; the ground is flat");
        state->ground = GroundKind::kFlat;
      } else {
        state->ground = *kind;
      }
    } else if (bare == "mask") {
      notice("mask: a density mask is not carried by a link (its file); no mask");
    } else if (bare == "ivy" || bare == "ivy_preset") {
      ivy_given = ivy_given || bare == "ivy";
      GardenState next = *state;
      if (bare == "ivy_preset") {
        next.ivy_preset = value;
      } else {
        next.ivy_on = value.empty() ? std::vector<std::string>{} : SplitOn(value, ',');
      }
      const Status s = CheckGardenState(next);
      if (s.ok()) {
        *state = std::move(next);
      } else {
        notice(bare + ": dropped; " + s.Line());
      }
    } else if (bare == "objects" || bare == "plants" || bare == "mix") {
      std::vector<GardenObject> objects;
      std::vector<GardenPlant> plants;
      std::vector<SpeciesWeight> mix;
      const std::vector<std::string> items =
          value.empty() ? std::vector<std::string>{} : SplitOn(value, ',');
      for (std::size_t i = 0; i < items.size(); ++i) {
        const std::vector<std::string> f = SplitOn(items[i], ':');
        std::vector<double> n;
        bool numbers = true;
        for (std::size_t k = 1; k < f.size(); ++k) {
          const std::optional<double> d = ParseNumber(f[k]);
          numbers = numbers && d.has_value();
          n.push_back(d.value_or(0));
        }
        const std::string at = bare + "[" + std::to_string(i) + "]";
        if (bare == "objects" && !f.empty() && f[0] == "mesh") {
          notice(at + ": a mesh object is not carried by a link (its file); dropped");
        } else if (bare == "objects" && f.size() == 5 && numbers) {
          objects.push_back({f[0], n[0], n[1], n[2], n[3]});
        } else if (bare == "plants" && f.size() == 6 && numbers && n[0] >= 0 &&
                   n[0] <= kMaxGardenSeed && n[0] == std::floor(n[0]) && n[1] >= 0 &&
                   n[1] <= kMaxPlantAge && n[1] == std::floor(n[1])) {
          plants.push_back(
              {f[0], static_cast<uint64_t>(n[0]), static_cast<int>(n[1]), n[2], n[3], n[4]});
        } else if (bare == "mix" && f.size() == 2 && numbers) {
          mix.push_back({f[0], n[0]});
        } else {
          notice(at + ": '" + Printable(items[i]) + "' dropped; must be " +
                 (bare == "objects"  ? "kind:x:z:rot:scale"
                  : bare == "plants" ? "species:seed:age:x:z:rot"
                                     : "species:weight"));
        }
      }
      GardenState next = *state;
      if (next.default_layout) {
        LayOutDefaults(&next);
        next.default_layout = false;
        next.ivy_on.clear();  // the default ivy is the default wall's; an ivy key comes after
      }
      if (bare == "objects") next.objects = objects;
      if (bare == "plants") next.plants = plants;
      if (bare == "mix") next.mix = mix;
      const Status s = CheckGardenState(next);
      if (s.ok()) {
        *state = std::move(next);
      } else {
        notice(bare + ": dropped; " + s.Line());
      }
    } else {
      notice(Printable(key) + ": not a garden key; dropped");
    }
  }
  if (terrain_keys) terrain::ApplyTerrainHash(hash, terrain_prefix, &state->terrain, notices);
  if (moss_keys) {
    std::vector<std::string> moss_notices;
    moss::ApplyMossHash(hash, moss_prefix, &state->moss, &moss_notices);
    if (notices != nullptr)
      notices->insert(notices->end(), moss_notices.begin(), moss_notices.end());
  }
  if (wind_keys) {
    const Status wind = CheckGardenWind(*state);
    if (!wind.ok()) {
      if (notices != nullptr)
        notices->push_back(wind.Line() + "; the wind is the garden's default");
      state->wind = GardenWindBase();
    }
  }
  if (was_default && !state->default_layout && !ivy_given) state->ivy_on.clear();
  // The default layout anew for the link's size, keeping the ivy's targets a link gave (ivy= alone:
  // no ivy on the default wall).
  const std::vector<std::string> ivy_on = state->ivy_on;
  LayOutDefaults(state);
  if (ivy_given) state->ivy_on = ivy_on;
}

}  // namespace niwa::compose
