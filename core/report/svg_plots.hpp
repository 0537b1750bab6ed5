#pragma once
// The report's pictures as inline SVG: point scatters (plan view, section), a histogram and a
// bar chart. Coordinates are local to each picture's extent, so grid coordinates (x ~ 651,000)
// never reach the SVG text.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace plumb::report {

/// Points of one layer of a scatter, already projected to the picture's 2D axes.
struct ScatterLayer {
  std::string name;    ///< legend text
  std::string colour;  ///< CSS colour
  std::vector<Eigen::Vector2d> points;
};

struct ScatterPicture {
  std::string title;
  std::string x_label, y_label;  ///< axis meaning, e.g. "east (m)"
  Eigen::Vector2d min = Eigen::Vector2d::Zero(), max = Eigen::Vector2d::Ones();  ///< extent shown
  std::vector<ScatterLayer> layers;
};

/// A scatter with equal scales on both axes, a scale bar and a legend.
std::string scatterSvg(const ScatterPicture& picture, int width = 640, int height = 480);

struct Bar {
  std::string label;   ///< tooltip
  double value = 0.0;
  std::string colour;
};

struct BarPicture {
  std::string title, x_label, y_label;
  std::vector<Bar> bars;
  std::vector<std::pair<std::string, double>> markers;  ///< vertical lines at bar positions (index)
};

/// Bars side by side, y from 0 to the largest value.
std::string barsSvg(const BarPicture& picture, int width = 640, int height = 300);

/// A plan of labelled marks joined by lines (a network of stations and links).
struct PlanMark {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  std::string label, colour;
};
struct PlanLine {
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();
  std::string colour, title;  ///< title: tooltip
  bool dashed = false;
};
struct PlanPicture {
  std::string title, x_label, y_label;
  Eigen::Vector2d min = Eigen::Vector2d::Zero(), max = Eigen::Vector2d::Ones();  ///< extent shown
  std::vector<PlanMark> marks;
  std::vector<PlanLine> lines;
  std::vector<std::pair<std::string, std::string>> legend;  ///< (text, CSS colour)
};

/// Lines under marks, equal scales on both axes, a scale bar and a legend.
std::string planSvg(const PlanPicture& picture, int width = 720, int height = 540);

/// `value` with `digits` decimals ("%.*f"): figures in the reports' tables and pictures.
std::string fixedDigits(double value, int digits);

/// "&amp;" etc.: text safe inside SVG/HTML elements and attribute values.
std::string escapeXml(const std::string& text);

}  // namespace plumb::report
