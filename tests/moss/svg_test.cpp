// The photon picture (core/moss/moss_svg.h, MossRun::PhotonsSvg): one dot per stored photon on a
// face turned to the viewer, first hits and bounced in their two colours and counted in the
// caption; with indirect off no bounced dot; the title escaped; the same run gives the same bytes.
#include <gtest/gtest.h>

#include <cstdio>
#include <glm/geometric.hpp>

#include "moss/moss_run.h"
#include "moss/moss_svg.h"

namespace niwa::moss {
namespace {

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

MossRun ThesisRun(int days, bool indirect) {
  MossState state;
  EXPECT_TRUE(SetMossScene("thesis", &state).ok());
  state.days = days;
  EXPECT_TRUE(state.params.Set(MossParam::kPhotons, 2048).ok());
  EXPECT_TRUE(state.params.Set(MossParam::kIndirect, indirect ? 1 : 0).ok());
  Result<MossRun> run = MossRun::Start(state, Budget{});
  EXPECT_TRUE(run.ok());
  EXPECT_TRUE(run->Advance(nullptr).ok());
  return std::move(*run);
}

TEST(MossPhotonSvg, OneDotPerVisiblePhotonInTwoColours) {
  const MossRun run = ThesisRun(2, true);
  const PhotonMap& map = run.photon_map();
  const glm::dvec3 eye = PhotonViewOf(run.cells()).eye;
  std::size_t direct = 0, bounced = 0;
  for (const Photon& p : map.photons)
    if (glm::dot(glm::dvec3(p.normal), eye - glm::dvec3(p.position)) > 0)
      ++(p.depth == 0 ? direct : bounced);
  ASSERT_GT(direct, 0u);
  ASSERT_GT(bounced, 0u);
  const std::string svg = run.PhotonsSvg(false);
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_EQ(Count(svg, "fill=\"#e8a317\"/>"), direct);
  EXPECT_EQ(Count(svg, "fill=\"#2a6fdb\"/>"), bounced);
  EXPECT_NE(svg.find(std::to_string(direct) + " first hits"), std::string::npos);
  EXPECT_NE(svg.find(std::to_string(bounced) + " bounced"), std::string::npos);
  EXPECT_NE(svg.find("moss photons day 2, thesis, indirect on"), std::string::npos);
  EXPECT_EQ(svg, run.PhotonsSvg(false));
  // The next day's map is traced without advancing: day 3, and the run unchanged.
  EXPECT_NE(run.PhotonsSvg(true).find("day 3"), std::string::npos);
  EXPECT_EQ(run.done(), 2);
}

// The photon picture's viewpoint on the thesis scene is the figures' (scripts/lib/figures_moss.js
// kEye, kAt), so figs 4.1/4.2's mosses and photons are seen from one place; the land fits the frame.
TEST(MossPhotonSvg, TheThesisViewIsTheFiguresCameraAndTheLandFits) {
  const MossRun run = ThesisRun(1, true);
  const PhotonView v = PhotonViewOf(run.cells());
  EXPECT_NEAR(v.eye.x, 0.45, 0.02);
  EXPECT_NEAR(v.eye.y, 0.75, 0.02);
  EXPECT_NEAR(v.eye.z, 3.6, 0.02);
  EXPECT_NEAR(v.at.x, 0.0, 0.02);
  EXPECT_NEAR(v.at.y, 0.45, 0.02);
  EXPECT_NEAR(v.at.z, -0.4, 0.02);
  const std::string svg = run.PhotonsSvg(false);
  // Every triangle's corners inside the 800 x 600 frame.
  std::size_t paths = 0;
  for (std::size_t at = svg.find("<path d=\"M"); at != std::string::npos;
       at = svg.find("<path d=\"M", at + 1), ++paths) {
    const std::string d = svg.substr(at + 10, svg.find('"', at + 10) - at - 10);
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    ASSERT_EQ(std::sscanf(d.c_str(), "%lf %lfL%lf %lfL%lf %lfZ", &x0, &y0, &x1, &y1, &x2, &y2), 6)
        << d;
    for (const double x : {x0, x1, x2}) EXPECT_TRUE(x >= 0 && x <= 800) << d;
    for (const double y : {y0, y1, y2}) EXPECT_TRUE(y >= 0 && y <= 600) << d;
  }
  EXPECT_GT(paths, 100u);
}

TEST(MossPhotonSvg, IndirectOffHasNoBouncedDotAndTheTitleIsEscaped) {
  const MossRun run = ThesisRun(1, false);
  const std::string svg = run.PhotonsSvg(false);
  EXPECT_EQ(Count(svg, "fill=\"#2a6fdb\"/>"), 0u);
  EXPECT_GT(Count(svg, "fill=\"#e8a317\"/>"), 0u);
  const std::string titled = PhotonSvg(run.cells(), run.photon_map(), "a<b & \"c\"");
  EXPECT_EQ(titled.find("a<b"), std::string::npos);
  EXPECT_NE(titled.find("a&lt;b &amp;"), std::string::npos);
}

}  // namespace
}  // namespace niwa::moss
