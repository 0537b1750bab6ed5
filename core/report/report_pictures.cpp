#include "report/report_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/svg_plots.hpp"

namespace plumb::report {
namespace {

constexpr const char* kSourceColour = "#e65100";
constexpr const char* kTargetColour = "#607d8b";

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

/// Robust horizontal box of the points (2nd to 98th percentile on x and y).
std::pair<Eigen::Vector2d, Eigen::Vector2d> robustBox(const std::vector<Eigen::Vector3d>& p) {
  std::vector<double> x, y;
  for (const auto& q : p) x.push_back(q.x()), y.push_back(q.y());
  return {{quantile(x, 0.02), quantile(y, 0.02)}, {quantile(x, 0.98), quantile(y, 0.98)}};
}

/// Every k-th point projected by `project`, at most `max` of them.
template <class Keep, class Project>
std::vector<Eigen::Vector2d> thin(const std::vector<Eigen::Vector3d>& pts, std::size_t max, Keep keep,
                                  Project project) {
  std::vector<Eigen::Vector2d> kept;
  for (const auto& p : pts)
    if (keep(p)) kept.push_back(project(p));
  if (kept.size() <= max) return kept;
  std::vector<Eigen::Vector2d> out;
  const double step = static_cast<double>(kept.size()) / static_cast<double>(max);
  for (std::size_t i = 0; i < max; ++i) out.push_back(kept[static_cast<std::size_t>(i * step)]);
  return out;
}

std::string origin(const Eigen::Vector2d& o) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "x %.2f, y %.2f", o.x(), o.y());
  return buf;
}

}  // namespace

Picture planPicture(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                    const PictureParams& params) {
  auto [lo, hi] = robustBox(source.empty() ? target : source);
  const Eigen::Vector2d grow = 0.5 * (hi - lo) + Eigen::Vector2d::Constant(2.0);
  lo -= grow;
  hi += grow;
  auto inside = [&](const Eigen::Vector3d& p) {
    return p.x() >= lo.x() && p.y() >= lo.y() && p.x() <= hi.x() && p.y() <= hi.y();
  };
  auto local = [&](const Eigen::Vector3d& p) { return Eigen::Vector2d(p.x() - lo.x(), p.y() - lo.y()); };
  ScatterPicture s;
  s.title = "Plan view: registered source over the target";
  s.x_label = "x (m)";
  s.y_label = "y (m)";
  s.max = hi - lo;
  s.layers.push_back({"target", kTargetColour, thin(target, params.max_points, inside, local)});
  s.layers.push_back({"source (registered)", kSourceColour, thin(source, params.max_points, inside, local)});
  return {"Plan view from above, origin at " + origin(lo) + " (world frame of the target).", scatterSvg(s)};
}

Picture sectionPicture(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                       const Eigen::Vector3d& centre, const PictureParams& params) {
  const auto [lo, hi] = robustBox(source.empty() ? target : source);
  const bool along_x = (hi.x() - lo.x()) >= (hi.y() - lo.y());
  const int u = along_x ? 0 : 1, n = along_x ? 1 : 0;
  const double half = 0.5 * params.section_thickness;
  const double u0 = (along_x ? lo.x() : lo.y()) - 2.0, u1 = (along_x ? hi.x() : hi.y()) + 2.0;
  auto inSlab = [&](const Eigen::Vector3d& p) { return std::abs(p[n] - centre[n]) <= half && p[u] >= u0 && p[u] <= u1; };
  auto local = [&](const Eigen::Vector3d& p) { return Eigen::Vector2d(p[u] - u0, p.z() - centre.z()); };
  ScatterPicture s;
  s.title = "Section through the overlap";
  s.x_label = std::string(along_x ? "x" : "y") + " (m)";
  s.y_label = "height above the section centre (m)";
  s.layers.push_back({"target", kTargetColour, thin(target, params.max_points, inSlab, local)});
  s.layers.push_back({"source (registered)", kSourceColour, thin(source, params.max_points, inSlab, local)});
  double zlo = -1.0, zhi = 1.0;
  for (const auto& l : s.layers)
    for (const auto& q : l.points) zlo = std::min(zlo, q.y()), zhi = std::max(zhi, q.y());
  s.min = {0.0, zlo - 0.2};
  s.max = {u1 - u0, zhi + 0.2};
  char where[160];
  std::snprintf(where, sizeof where, "Vertical section %.0f mm thick at %s = %.2f m, through the centre of the "
                "matched points (%.2f, %.2f, %.2f).", params.section_thickness * 1e3, along_x ? "y" : "x",
                centre[n], centre.x(), centre.y(), centre.z());
  return {where, scatterSvg(s)};
}

Picture histogramPicture(const DistanceSummary& d) {
  BarPicture b;
  b.title = "Distances from the registered source to the target";
  b.x_label = "distance, 0 to " + std::to_string(static_cast<int>(std::lround(d.max_distance * 1e3))) + " mm";
  b.y_label = "points";
  const double width = d.histogram.empty() ? 1.0 : d.max_distance / static_cast<double>(d.histogram.size());
  for (std::size_t i = 0; i < d.histogram.size(); ++i)
    b.bars.push_back({std::to_string(d.histogram[i]) + " points at " + std::to_string(i * width * 1e3).substr(0, 5) +
                          " mm", static_cast<double>(d.histogram[i]), "#1565c0"});
  if (width > 0) {
    b.markers.emplace_back("RMS", d.rms / width);
    b.markers.emplace_back("95 %", d.p95 / width);
  }
  return {"Histogram of the distances from " + std::to_string(d.matched) + " matched source points (of " +
          std::to_string(d.sampled) + " sampled) to the nearest target point, or to the model's surface; "
          "cloud-to-cloud distances include the target's point spacing.", barsSvg(b)};
}

Picture residualPicture(const std::vector<FeatureResidual>& residuals) {
  BarPicture b;
  b.title = "Per-feature residuals";
  b.x_label = "matched source features: planes (orange), openings (green), segments (blue)";
  b.y_label = "residual (mm)";
  for (const auto& r : residuals) {
    if (!r.matched) continue;
    const char* colour = r.kind == "plane" ? "#ef6c00" : r.kind == "opening" ? "#2e7d32" : "#1565c0";
    char label[96];
    std::snprintf(label, sizeof label, "%s %zu: %.1f mm, %.2f deg", r.kind.c_str(), r.index, r.distance_m * 1e3,
                  r.angle_deg);
    b.bars.push_back({label, r.distance_m * 1e3, colour});
  }
  return {"Residual of each matched source feature after registration (plane: centroid to target plane; "
          "opening: centre offset within the facade; segment: midpoint to target segment).", barsSvg(b)};
}

}  // namespace plumb::report
