// Image baselines of the report's pictures: fixed inputs (a room and a façade line as points,
// a distance histogram, residuals) drawn to SVG and compared with the stored files byte for
// byte. PLUMB_UPDATE_BASELINES=1 rewrites them (then look at them in a browser and commit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "report/report_pictures.hpp"
#include "support/test_support.hpp"

using namespace plumb;
using namespace plumb::report;

namespace {

/// The walls of a 6 x 4 m room, 3 m high, at Lambert-93 coordinates (every 20 cm, 7 rows).
std::vector<Eigen::Vector3d> room(const Eigen::Vector3d& at, double shift) {
  std::vector<Eigen::Vector3d> p;
  for (double z = 0.0; z <= 3.0; z += 0.5)
    for (double s = 0.0; s < 20.0; s += 0.2) {
      const double u = std::fmod(s, 20.0);
      const Eigen::Vector2d xy = u < 6 ? Eigen::Vector2d(u, 0) : u < 10 ? Eigen::Vector2d(6, u - 6)
                               : u < 16 ? Eigen::Vector2d(16 - u, 4) : Eigen::Vector2d(0, 20 - u);
      p.push_back(at + Eigen::Vector3d(xy.x() + shift, xy.y(), z));
    }
  return p;
}

void expectBaseline(const std::string& name, const std::string& svg) {
  const auto path = std::filesystem::path(PLUMB_REPORT_BASELINES) / (name + ".svg");
  if (std::getenv("PLUMB_UPDATE_BASELINES")) test::writeAll(path, svg);
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " (run with PLUMB_UPDATE_BASELINES=1)";
  EXPECT_EQ(svg, test::readAll(path)) << name << " differs from its baseline " << path;
}

const Eigen::Vector3d kGrid(651000.0, 6860000.0, 40.0);

}  // namespace

TEST(ReportBaselines, PlanView) {
  expectBaseline("plan", planPicture(room(kGrid, 0.02), room(kGrid, 0.0)).svg);
}

TEST(ReportBaselines, Section) {
  expectBaseline("section", sectionPicture(room(kGrid, 0.02), room(kGrid, 0.0), kGrid + Eigen::Vector3d(3, 2, 1.5)).svg);
}

TEST(ReportBaselines, DistanceHistogram) {
  DistanceSummary d;
  d.sampled = 1000, d.matched = 900, d.max_distance = 0.1, d.rms = 0.012, d.p95 = 0.031;
  for (int i = 0; i < 40; ++i) d.histogram.push_back(static_cast<std::size_t>(200.0 * std::exp(-0.2 * i)));
  expectBaseline("histogram", histogramPicture(d).svg);
}

TEST(ReportBaselines, Residuals) {
  std::vector<FeatureResidual> r;
  for (std::size_t i = 0; i < 12; ++i)
    r.push_back({i < 6 ? "plane" : i < 9 ? "opening" : "segment", i, 1.0, i != 4, 0.001 * (i + 1), 0.1 * i});
  expectBaseline("residuals", residualPicture(r).svg);
}
