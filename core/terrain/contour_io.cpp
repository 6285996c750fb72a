// Contour JSON and GeoJSON reading, contour-tree JSON writing (see contour_io.h).
#include "terrain/contour_io.h"

#include <nlohmann/json.hpp>

#include "params/json_guard.h"
#include "terrain/generate.h"

namespace niwa::terrain {
namespace {

Status Bad(const std::string& what) {
  return Status::Error("contour", what +
                                      "; must be {\"points\": [[x, y], ...]} in metres or a "
                                      "GeoJSON Polygon or LineString");
}

Result<Ring> ReadPoints(const nlohmann::json& pts) {
  if (!pts.is_array()) return Bad("points is not an array");
  if (pts.size() > kMaxSeedPoints + 1) {
    return Status::Error("contour",
                         std::to_string(pts.size()) + " points; must have 3 to 1000000 points");
  }
  Ring r;
  r.reserve(pts.size());
  for (const auto& p : pts) {
    if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number()) {
      return Bad("a point is not [x, y] numbers");
    }
    r.push_back({p[0].get<double>(), p[1].get<double>()});
  }
  // A closed ring may repeat its first point at the end (GeoJSON does).
  if (r.size() >= 2 && r.front() == r.back()) r.pop_back();
  return r;
}

// The member `key` of an object, or nullptr (never inserts, never reads past: the document is
// const and every lookup goes through find()).
const nlohmann::json* Member(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// The member "type" when it is a string, else "" (a number, null or missing type is no type).
std::string TypeOf(const nlohmann::json& object) {
  const nlohmann::json* t = Member(object, "type");
  return t != nullptr && t->is_string() ? t->get<std::string>() : "";
}

}  // namespace

Result<SeedFile> ParseContourJson(const std::string& text) {
  if (Status keys = CheckJsonKeys(text, "contour"); !keys.ok()) return keys;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return Bad("not a JSON object");
  SeedFile out;
  if (const nlohmann::json* e = Member(j, "elevation")) {
    if (!e->is_number()) return Bad("elevation is not a number");
    out.has_elevation = true;
    out.elevation = e->get<double>();
  }
  if (const nlohmann::json* pts = Member(j, "points")) {
    Result<Ring> r = ReadPoints(*pts);
    if (!r.ok()) return r.status();
    out.ring = std::move(r).value();
    return out;
  }
  if (const nlohmann::json* t = Member(j, "type"); t != nullptr && !t->is_string()) {
    return Bad("type is not a string");
  }
  const nlohmann::json* g = &j;
  if (TypeOf(j) == "Feature") {
    g = Member(j, "geometry");
    if (g == nullptr) return Bad("Feature without geometry");
    if (!g->is_object()) return Bad("Feature geometry is not an object");
    if (const nlohmann::json* t = Member(*g, "type"); t != nullptr && !t->is_string()) {
      return Bad("geometry type is not a string");
    }
  }
  const std::string type = TypeOf(*g);
  if (type != "Polygon" && type != "LineString") return Bad("no points, Polygon or LineString");
  const nlohmann::json* coordinates = Member(*g, "coordinates");
  if (coordinates == nullptr) return Bad(type + " without coordinates");
  if (!coordinates->is_array()) return Bad(type + " coordinates is not an array");
  if (type == "Polygon") {
    if (coordinates->empty()) return Bad("Polygon without a ring");
    coordinates = &(*coordinates)[0];  // the outer ring (const: bounds checked just above)
  }
  Result<Ring> r = ReadPoints(*coordinates);
  if (!r.ok()) return r.status();
  out.ring = std::move(r).value();
  return out;
}

std::string TerrainToJson(const Terrain& t) {
  nlohmann::json j;
  j["h0"] = t.h0;
  j["dh"] = t.dh;
  j["d"] = t.d;
  nlohmann::json cs = nlohmann::json::array();
  for (std::size_t i = 0; i < t.contours.size(); ++i) {
    const ContourNode& c = t.contours[i];
    nlohmann::json pts = nlohmann::json::array();
    for (const Vec2& v : c.ring) pts.push_back({v.x, v.y});
    cs.push_back({{"id", i},
                  {"level", c.level},
                  {"elevation", c.elevation},
                  {"parent", c.parent},
                  {"children", c.children},
                  {"points", pts}});
  }
  j["contours"] = cs;
  nlohmann::json ss = nlohmann::json::array();
  for (const Summit& s : t.summits)
    ss.push_back({{"contour", s.contour},
                  {"x", s.position.x},
                  {"y", s.position.y},
                  {"elevation", s.elevation}});
  j["summits"] = ss;
  return j.dump();
}

}  // namespace niwa::terrain
