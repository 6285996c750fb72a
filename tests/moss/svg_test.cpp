// The photon picture (core/moss/moss_svg.h, MossRun::PhotonsSvg): one dot per stored photon on a
// face turned to the viewer, first hits and bounced in their two colours and counted in the
// caption; with indirect off no bounced dot; the title escaped; the same run gives the same bytes.
#include <gtest/gtest.h>

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
  const glm::dvec3 toward = glm::normalize(glm::dvec3(0, 0.6, 1));
  std::size_t direct = 0, bounced = 0;
  for (const Photon& p : map.photons)
    if (glm::dot(p.normal, toward) > 0) ++(p.depth == 0 ? direct : bounced);
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
