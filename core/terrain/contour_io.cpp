// Contour JSON and GeoJSON reading, contour-tree JSON writing (see contour_io.h).
#include "terrain/contour_io.h"

#include <nlohmann/json.hpp>

#include "params/param_json.h"
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

}  // namespace

Result<SeedFile> ParseContourJson(const std::string& text) {
  if (Status keys = CheckJsonKeys(text, "contour"); !keys.ok()) return keys;
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return Bad("not a JSON object");
  SeedFile out;
  if (j.contains("elevation")) {
    if (!j["elevation"].is_number()) return Bad("elevation is not a number");
    out.has_elevation = true;
    out.elevation = j["elevation"].get<double>();
  }
  if (j.contains("points")) {
    Result<Ring> r = ReadPoints(j["points"]);
    if (!r.ok()) return r.status();
    out.ring = std::move(r).value();
    return out;
  }
  const nlohmann::json* g = &j;
  if (j.value("type", "") == "Feature") {
    if (!j.contains("geometry")) return Bad("Feature without geometry");
    g = &j["geometry"];
  }
  const std::string type = g->is_object() ? g->value("type", "") : "";
  if (type == "Polygon" && (*g)["coordinates"].is_array() && !(*g)["coordinates"].empty()) {
    Result<Ring> r = ReadPoints((*g)["coordinates"][0]);
    if (!r.ok()) return r.status();
    out.ring = std::move(r).value();
    return out;
  }
  if (type == "LineString") {
    Result<Ring> r = ReadPoints((*g)["coordinates"]);
    if (!r.ok()) return r.status();
    out.ring = std::move(r).value();
    return out;
  }
  return Bad("no points, Polygon or LineString");
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
