// MMS passes as time-windowed nodes (mms_windows.hpp, docs/NETWORK.md "MMS passes"): a pass is
// cut by point time, every point with a finite time lands in exactly one window, consecutive
// windows are joined by trajectory links at the stated accuracy, and windows are paired with the
// model and the static stations, never by layout among themselves.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "registration/network/mms_windows.hpp"

namespace plumb {
namespace {

/// A pass of `seconds` at 3 m/s along x: 100 points a second on a wall 5 m beside the track,
/// each with its sensor origin and time (starting at GPS time 1000 s).
Scan straightPass(double seconds) {
  Scan s;
  s.name = "mms";
  for (int k = 0; k < int(seconds * 100); ++k) {
    const double t = k / 100.0, x = 3.0 * t;
    s.cloud.positions.push_back(Eigen::Vector3f(float(x), 5.f, float(k % 7) * 0.3f));
    s.cloud.sensor_origins.push_back(Eigen::Vector3f(float(x), 0.f, 2.f));
    s.cloud.timestamps.push_back(1000.0 + t);
  }
  return s;
}

/// A static station of one scan with a pose (its own frame).
Station staticStation(const std::string& name) {
  Station s;
  s.name = name;
  s.input.cloud.positions.push_back(Eigen::Vector3f(1, 2, 3));
  return s;
}

TEST(MmsWindows, APassIsCutByPointTimeAndEveryPointLandsOnce) {
  const Scan pass = straightPass(50.0);  // 5,000 points over 50 s
  ASSERT_TRUE(isMmsPass(pass));
  const auto windows = windowsOf(pass, 20.0);
  ASSERT_EQ(windows.size(), 3u);  // [0, 20), [20, 40), [40, 60) s
  std::size_t points = 0;
  for (std::size_t w = 0; w < windows.size(); ++w) {
    EXPECT_DOUBLE_EQ(windows[w].start, 20.0 * double(w));
    EXPECT_DOUBLE_EQ(windows[w].end, 20.0 * double(w + 1));
    for (std::size_t i : windows[w].points) {
      const double t = pass.cloud.timestamps[i] - 1000.0;
      EXPECT_GE(t, windows[w].start - 1e-9);
      EXPECT_LT(t, windows[w].end);
    }
    points += windows[w].points.size();
  }
  EXPECT_EQ(points, pass.cloud.size());
  EXPECT_EQ(windows[0].points.size(), 2000u);
  EXPECT_EQ(windows[2].points.size(), 1000u);
  EXPECT_THROW(windowsOf(pass, 0.0), InputError);
}

TEST(MmsWindows, EachWindowIsAStationOfThePassFrame) {
  Scan pass = straightPass(50.0);
  pass.pose = RigidTransform::fromYaw(0.3, {10, 20, 0});
  const auto st = mmsWindows(pass, 2, "street.e57", 0, 20.0);
  ASSERT_EQ(st.size(), 3u);
  EXPECT_EQ(st[0].name, "mms@0-20s");
  EXPECT_EQ(st[2].name, "mms@40-60s");
  for (const auto& s : st) {
    EXPECT_EQ(s.mms_pass, 0);
    EXPECT_EQ(s.scan_index, 2u);
    EXPECT_EQ(s.file, "street.e57");
    EXPECT_LT(RigidTransform::translationError(s.file_pose, pass.pose), 1e-12);
    EXPECT_LT(RigidTransform::rotationErrorDeg(s.file_pose, pass.pose), 1e-9);
    EXPECT_TRUE(s.input.cloud.hasSensorOrigins());  // the openings need them
    EXPECT_FALSE(s.is_model);
  }
  EXPECT_EQ(st[1].input.cloud.size(), 2000u);
  // stationsOf cuts passes only when asked; a static scan stays one station.
  Dataset d;
  d.scans = {pass};
  EXPECT_EQ(stationsOf(d, "street.e57").size(), 1u);
  EXPECT_EQ(stationsOf(d, "street.e57", 20.0).size(), 3u);
}

TEST(MmsWindows, TrajectoryLinksJoinConsecutiveWindowsOfOnePass) {
  std::vector<Station> st{staticStation("tls-0")};
  for (auto& w : mmsWindows(straightPass(50.0), 0, "a.e57", 0, 20.0)) st.push_back(std::move(w));
  for (auto& w : mmsWindows(straightPass(30.0), 0, "b.e57", 1, 20.0)) st.push_back(std::move(w));
  ASSERT_EQ(st.size(), 6u);  // tls-0, pass 0: 3 windows, pass 1: 2 windows
  MmsWindowParams p;
  p.sigma_translation = 0.03;
  const auto links = trajectoryLinks(st, p);
  ASSERT_EQ(links.size(), 3u);  // 1-2, 2-3 (pass 0), 4-5 (pass 1); none across passes
  EXPECT_EQ(links[0].a, 1u);
  EXPECT_EQ(links[1].b, 3u);
  EXPECT_EQ(links[2].a, 4u);
  for (const auto& l : links) {
    EXPECT_TRUE(l.accepted && l.registered);
    EXPECT_EQ(l.reason, "trajectory");
    EXPECT_TRUE(l.transform.isIdentity());
    EXPECT_DOUBLE_EQ(l.sigma_translation, 0.03);
  }
}

TEST(MmsWindows, WindowsArePairedWithTheModelAndTheStaticStations) {
  std::vector<Station> st{staticStation("tls-0"), staticStation("tls-1")};
  for (auto& w : mmsWindows(straightPass(30.0), 0, "a.e57", 0, 20.0)) st.push_back(std::move(w));
  Station model;
  model.name = "model:m";
  model.is_model = true;
  st.push_back(std::move(model));
  MmsWindowParams both;
  both.station_pairs = true;
  const auto pairs = mmsPairs(st, both);
  // 2 windows x (the model + 2 static stations)
  ASSERT_EQ(pairs.size(), 6u);
  int with_model = 0, with_stations = 0;
  for (const auto& p : pairs) {
    EXPECT_LT(p.a, p.b);
    if (p.reason == "model") {
      ++with_model;
      EXPECT_EQ(p.b, 4u);
    }
    if (p.reason == "mms") {
      ++with_stations;
      EXPECT_LT(p.a, 2u);
    }
  }
  EXPECT_EQ(with_model, 2);
  EXPECT_EQ(with_stations, 4);
  EXPECT_EQ(mmsPairs(st, MmsWindowParams{}).size(), 2u) << "by default, with the model only";
}

}  // namespace
}  // namespace plumb
