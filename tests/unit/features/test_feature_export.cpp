#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "features/export/feature_export.hpp"
#include "features/planes/plane_extraction.hpp"
#include "support/test_support.hpp"
#include "synthetic_scenes.hpp"

namespace plumb {
namespace {

FeatureSet sampleFeatures() {
  test::RoomSpec spec;
  spec.outside = false;
  spec.spacing = 0.05;
  FeatureSet fs;
  fs.planes = extractPlanes(test::makeRoom(spec), {}).planes;
  fs.facades = {0, 1};
  Opening o;
  o.corners = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(1, 0, 2), Eigen::Vector3d(0, 0, 2)};
  o.facade = 1;
  o.evidence_count = 12;
  fs.openings.push_back(o);
  fs.segments.push_back({Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6), 17});
  return fs;
}

TEST(FeatureExport, JsonHasTheDocumentedArraysAndRoundTrips) {
  const FeatureSet fs = sampleFeatures();
  const auto j = featureSetToJson(fs);
  ASSERT_TRUE(j.at("planes").is_array());
  ASSERT_EQ(j.at("planes").size(), fs.planes.size());
  const auto& p0 = j.at("planes")[0];
  EXPECT_EQ(p0.at("inlier_count").get<std::size_t>(), fs.planes[0].inlier_count);
  EXPECT_EQ(p0.at("normal").size(), 3u);
  EXPECT_EQ(p0.at("rings")[0][0].size(), 3u);  // 3D ring vertices
  // Ring vertices lie on the plane.
  for (const auto& v : p0.at("rings")[0]) {
    const Eigen::Vector3d x(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    EXPECT_NEAR(fs.planes[0].signedDistance(x), 0.0, 1e-6);
  }
  EXPECT_EQ(j.at("openings")[0].at("facade").get<int>(), 1);
  EXPECT_EQ(j.at("openings")[0].at("corners").size(), 4u);
  EXPECT_DOUBLE_EQ(j.at("segments")[0].at("support").get<double>(), 17.0);

  const auto dir = test::scratchDir("feature_export");
  writeFeatureSet(dir / "f.json", fs);
  const FeatureSet back = readFeatureSetJson(dir / "f.json");
  ASSERT_EQ(back.planes.size(), fs.planes.size());
  EXPECT_NEAR((back.planes[0].normal - fs.planes[0].normal).norm(), 0, 1e-12);
  EXPECT_NEAR(back.planes[0].offset, fs.planes[0].offset, 1e-9);
  ASSERT_EQ(back.planes[0].rings.size(), fs.planes[0].rings.size());
  EXPECT_NEAR((back.planes[0].to3d(back.planes[0].rings[0][0]) - fs.planes[0].to3d(fs.planes[0].rings[0][0])).norm(), 0, 1e-9);
  EXPECT_EQ(back.facades, fs.facades);
  EXPECT_EQ(back.openings[0].corners[2], fs.openings[0].corners[2]);
  EXPECT_EQ(back.segments[0].b, fs.segments[0].b);
}

// A project keeps the planes' inliers (the pipeline's structure checks use them); the export
// for other tools leaves them out.
TEST(FeatureExport, InliersRoundTripOnlyWhenAskedFor) {
  const FeatureSet fs = sampleFeatures();
  ASSERT_FALSE(fs.planes.empty());
  ASSERT_FALSE(fs.planes[0].inliers.empty());
  EXPECT_FALSE(featureSetToJson(fs).at("planes")[0].contains("inliers"));
  const auto dir = test::scratchDir("feature_export_inliers");
  writeFeatureSetJson(dir / "with.json", fs, true);
  writeFeatureSetJson(dir / "without.json", fs);
  const FeatureSet with = readFeatureSetJson(dir / "with.json");
  const FeatureSet without = readFeatureSetJson(dir / "without.json");
  ASSERT_EQ(with.planes.size(), fs.planes.size());
  for (std::size_t k = 0; k < fs.planes.size(); ++k) {
    EXPECT_EQ(with.planes[k].inliers, fs.planes[k].inliers) << "plane " << k;
    EXPECT_TRUE(without.planes[k].inliers.empty());
  }
  EXPECT_EQ(with.openings[0].evidence_count, fs.openings[0].evidence_count);
  EXPECT_EQ(with.segments[0].a, fs.segments[0].a);
}

TEST(FeatureExport, PlyHasVerticesAndEdges) {
  const FeatureSet fs = sampleFeatures();
  const auto dir = test::scratchDir("feature_export_ply");
  writeFeatureSet(dir / "f.ply", fs);
  const std::string text = test::readAll(dir / "f.ply");
  std::size_t ring_vertices = 0;
  for (const auto& p : fs.planes)
    for (const auto& r : p.rings) ring_vertices += r.size();
  EXPECT_NE(text.find("element vertex " + std::to_string(ring_vertices + 4 + 2)), std::string::npos);
  EXPECT_NE(text.find("element edge " + std::to_string(ring_vertices + 4 + 1)), std::string::npos);
  EXPECT_THROW(writeFeatureSet(dir / "f.txt", fs), FileError);
}

TEST(FeatureExport, MalformedJsonNamesTheFile) {
  const auto dir = test::scratchDir("feature_export_bad");
  test::writeAll(dir / "bad.json", "{\"segments\": [{\"a\": [1, 2]}]}");
  try {
    readFeatureSetJson(dir / "bad.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("segments[0]"), std::string::npos);
  }
}

}  // namespace
}  // namespace plumb
