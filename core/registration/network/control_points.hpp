#pragma once
// Control and check points of a campaign (issue 15, docs/NETWORK.md "Control points"): survey
// targets whose coordinates in the project's grid are known (a CSV of name, E, N, H and the
// role), and where each station saw them (a CSV of station, point, x, y, z in the station's own
// frame, as scanner software exports its targets). Control points enter the adjustment and
// georeference the network; check points stay out of it and their residuals are reported.
//
// The grid is a map projection: its distances are ground distances times the grid scale factor
// k (UTM: 0.9996 on the central meridian, 40 cm per km). The adjustment works in a ground frame
// whose origin is the control points' centroid (to the metre, in grid coordinates): a grid
// coordinate G becomes ((G_E - O_E) / k, (G_N - O_N) / k, G_H - O_H) before any residual is
// computed. The registered stations are written in that frame moved to O: grid coordinates at
// O, ground distances about it.
#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace plumb {

struct ControlPoint {
  std::string name;
  Eigen::Vector3d grid = Eigen::Vector3d::Zero();  ///< E, N, H (m)
  bool check = false;  ///< a check point: not used by the adjustment, residual reported
};

struct TargetObservation {
  std::string station;  ///< the station's name in the network
  std::string point;    ///< a ControlPoint name
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< in the station's own frame (m)
  std::size_t line = 0;  ///< in its file (for messages)
};

/// The project's grid and the ground frame the adjustment works in (header comment).
struct GridFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< grid coordinates of the ground origin
  double scale_factor = 1.0;  ///< grid distance / ground distance
  std::string crs;            ///< the coordinate system the factor was computed from, if any
  Eigen::Vector3d toGround(const Eigen::Vector3d& grid) const;
  Eigen::Vector3d toGrid(const Eigen::Vector3d& ground) const;
};

struct ControlSurvey {
  std::vector<ControlPoint> points;
  std::vector<TargetObservation> observations;
  GridFrame grid;
  /// Standard deviation of one coordinate of a target observation, m (target centre fit and
  /// the control point's own survey).
  double sigma = 0.002;
  std::filesystem::path targets_file;  ///< for messages
};

/// Reads "name, E, N, H[, control|check]" lines (comma, semicolon or blank separated; '#'
/// comments and a header line allowed). Throws FileError naming the file and line for a bad
/// line, a repeated name or no control point at all.
std::vector<ControlPoint> readControlPoints(const std::filesystem::path& file);

/// Reads "station, point, x, y, z" lines (same syntax). Throws FileError naming the line.
std::vector<TargetObservation> readTargetObservations(const std::filesystem::path& file);

/// The grid scale factor of the projected coordinate system `crs` (PROJ: "EPSG:32632", a
/// PROJ string or WKT) at grid position (E, N). Throws InputError when PROJ does not know the
/// system, it is not projected, or the position lies outside its domain.
double gridScaleFactor(const std::string& crs, const Eigen::Vector3d& grid);

/// The ground frame of a survey: its origin is the control points' centroid rounded to the
/// metre (check points excluded).
GridFrame makeGridFrame(const std::vector<ControlPoint>& points, double scale_factor, std::string crs = {});

}  // namespace plumb
