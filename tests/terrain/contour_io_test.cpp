// Contour file reading (terrain/contour_io) on hostile files: a GeoJSON geometry without
// coordinates, a type that is not a string, repeated keys and deep nesting each give one line
// naming "contour", never an internal error or a read past the document; valid files still read.
#include "terrain/contour_io.h"

#include <gtest/gtest.h>

#include <string>

namespace niwa::terrain {
namespace {

const std::string kAllowed =
    "; must be {\"points\": [[x, y], ...]} in metres or a GeoJSON Polygon or LineString";

std::string LineOf(const std::string& text) {
  Result<SeedFile> file = ParseContourJson(text);
  return file.ok() ? "(read " + std::to_string(file->ring.size()) + " points)"
                   : file.status().Line();
}

TEST(ContourIo, GeometryWithoutCoordinatesIsRefused) {
  EXPECT_EQ(LineOf(R"({"type": "Polygon"})"), "contour: Polygon without coordinates" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "LineString"})"),
            "contour: LineString without coordinates" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "Feature", "geometry": {"type": "Polygon"}})"),
            "contour: Polygon without coordinates" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "Feature", "geometry": {"type": "LineString"}})"),
            "contour: LineString without coordinates" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "Feature", "geometry": null})"),
            "contour: Feature geometry is not an object" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "Polygon", "coordinates": 5})"),
            "contour: Polygon coordinates is not an array" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "Polygon", "coordinates": []})"),
            "contour: Polygon without a ring" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "Polygon", "coordinates": [7]})"),
            "contour: points is not an array" + kAllowed);
}

TEST(ContourIo, TypeThatIsNotAStringIsRefused) {
  EXPECT_EQ(LineOf(R"({"type": null})"), "contour: type is not a string" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": 7})"), "contour: type is not a string" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": ["Polygon"]})"), "contour: type is not a string" + kAllowed);
  EXPECT_EQ(LineOf(R"({"type": "Feature", "geometry": {"type": 3, "coordinates": []}})"),
            "contour: geometry type is not a string" + kAllowed);
  EXPECT_EQ(LineOf(R"({"elevation": "high", "points": []})"),
            "contour: elevation is not a number" + kAllowed);
}

TEST(ContourIo, RepeatedKeysAndDeepNestingAreRefused) {
  EXPECT_EQ(LineOf(R"({"points": [[0, 0], [1, 0], [0, 1]], "points": [[0, 0], [2, 0], [0, 2]]})"),
            "points: given twice in one object");
  EXPECT_EQ(LineOf(R"({"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0, 0],
                [1, 0], [0, 1]]], "type": "LineString"}})"),
            "type: given twice in one object");
  const std::string deep = "{\"type\": \"Feature\", \"properties\": " + std::string(30000, '[') +
                           std::string(30000, ']') + "}";
  EXPECT_EQ(LineOf(deep), "contour: nested deeper than 32 levels");
}

TEST(ContourIo, ValidFilesStillRead) {
  EXPECT_EQ(LineOf(R"({"points": [[0, 0], [1, 0], [0, 1]], "elevation": 3})"), "(read 3 points)");
  EXPECT_EQ(LineOf(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1], [0, 0]]]})"),
            "(read 3 points)");
  EXPECT_EQ(LineOf(R"({"type": "Feature", "properties": {"a": {"b": 1}}, "geometry":
                {"type": "LineString", "coordinates": [[0, 0], [1, 0], [1, 1], [0, 1]]}})"),
            "(read 4 points)");
  EXPECT_EQ(LineOf(R"({"type": "Point", "coordinates": [0, 0]})"),
            "contour: no points, Polygon or LineString" + kAllowed);
}

}  // namespace
}  // namespace niwa::terrain
