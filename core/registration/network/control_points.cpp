// Control points, target observations and the grid frame (control_points.hpp).
#include "registration/network/control_points.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "common/error.hpp"
#include "common/proj_context.hpp"

namespace plumb {
namespace {

/// The fields of one line: separated by commas, semicolons, tabs or blanks; empty when the line
/// is blank or a comment.
std::vector<std::string> fieldsOf(std::string line) {
  if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
  for (char& c : line)
    if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string f; in >> f;) out.push_back(f);
  return out;
}

bool parseNumber(const std::string& s, double& v) {
  try {
    std::size_t used = 0;
    v = std::stod(s, &used);
    return used == s.size() && std::isfinite(v);
  } catch (const std::exception&) {
    return false;
  }
}

/// Calls f(fields, line) for each non-blank line; the first line may be a header (its
/// `number_at` field is not a number).
template <class F>
void forEachRecord(const std::filesystem::path& file, std::size_t number_at, F&& f) {
  std::ifstream in(file);
  if (!in) throw FileError(file, "cannot be opened");
  std::string line;
  bool first = true;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const auto fields = fieldsOf(line);
    if (fields.empty()) continue;
    double v = 0;
    if (first && fields.size() > number_at && !parseNumber(fields[number_at], v)) {
      first = false;  // a header
      continue;
    }
    first = false;
    f(fields, n);
  }
}

Eigen::Vector3d coordinates(const std::filesystem::path& file, const std::vector<std::string>& fields,
                            std::size_t at, std::size_t line) {
  Eigen::Vector3d p;
  for (int k = 0; k < 3; ++k)
    if (!parseNumber(fields[at + k], p[k]))
      throw FileError(file, "'" + fields[at + k] + "' is not a coordinate", atLine(line));
  return p;
}

}  // namespace

Eigen::Vector3d GridFrame::toGround(const Eigen::Vector3d& g) const {
  const Eigen::Vector3d d = g - origin;
  return {d.x() / scale_factor, d.y() / scale_factor, d.z()};
}

Eigen::Vector3d GridFrame::toGrid(const Eigen::Vector3d& ground) const {
  return origin + Eigen::Vector3d(ground.x() * scale_factor, ground.y() * scale_factor, ground.z());
}

std::vector<ControlPoint> readControlPoints(const std::filesystem::path& file) {
  std::vector<ControlPoint> out;
  std::set<std::string> names;
  forEachRecord(file, 1, [&](const std::vector<std::string>& f, std::size_t line) {
    if (f.size() != 4 && f.size() != 5)
      throw FileError(file, "expected 'name, E, N, H[, control|check]', got " + std::to_string(f.size()) + " fields",
                      atLine(line));
    ControlPoint p{f[0], coordinates(file, f, 1, line), false};
    if (f.size() == 5) {
      if (f[4] != "control" && f[4] != "check")
        throw FileError(file, "the role must be 'control' or 'check', not '" + f[4] + "'", atLine(line));
      p.check = f[4] == "check";
    }
    if (!names.insert(p.name).second) throw FileError(file, "point '" + p.name + "' is given twice", atLine(line));
    out.push_back(std::move(p));
  });
  if (std::none_of(out.begin(), out.end(), [](const ControlPoint& p) { return !p.check; }))
    throw FileError(file, "holds no control point (only check points, or nothing)");
  return out;
}

std::vector<TargetObservation> readTargetObservations(const std::filesystem::path& file) {
  std::vector<TargetObservation> out;
  forEachRecord(file, 2, [&](const std::vector<std::string>& f, std::size_t line) {
    if (f.size() != 5)
      throw FileError(file, "expected 'station, point, x, y, z', got " + std::to_string(f.size()) + " fields",
                      atLine(line));
    out.push_back({f[0], f[1], coordinates(file, f, 2, line), line});
  });
  if (out.empty()) throw FileError(file, "holds no target observation");
  return out;
}

double gridScaleFactor(const std::string& crs, const Eigen::Vector3d& grid) {
  ProjContext proj;
  ProjObject projected(proj_create(proj.ctx, crs.c_str()), &proj_destroy);
  if (!projected || proj_get_type(projected.get()) != PJ_TYPE_PROJECTED_CRS)
    throw InputError("--crs '" + crs + "' is not a projected coordinate system PROJ knows");
  ProjObject geographic(proj_crs_get_geodetic_crs(proj.ctx, projected.get()), &proj_destroy);
  ProjObject to_grid(proj_create_crs_to_crs_from_pj(proj.ctx, geographic.get(), projected.get(), nullptr, nullptr),
                     &proj_destroy);
  if (!geographic || !to_grid) throw InputError("--crs '" + crs + "': PROJ finds no conversion from its datum");
  ProjObject normalised(proj_normalize_for_visualization(proj.ctx, to_grid.get()), &proj_destroy);
  // Grid -> longitude, latitude (degrees, visualisation order), then the factors there.
  PJ_COORD c = proj_coord(grid.x(), grid.y(), 0, 0);
  const PJ_COORD lonlat = proj_trans(normalised.get(), PJ_INV, c);
  if (!std::isfinite(lonlat.lp.lam) || !std::isfinite(lonlat.lp.phi))
    throw InputError("--crs '" + crs + "': the control points lie outside its domain");
  const PJ_COORD at = proj_coord(proj_torad(lonlat.lp.lam), proj_torad(lonlat.lp.phi), 0, 0);
  const PJ_FACTORS f = proj_factors(projected.get(), at);
  if (proj_errno(projected.get()) != 0 || !(f.meridional_scale > 0))
    throw InputError("--crs '" + crs + "': PROJ cannot compute its scale factor at the control points");
  // Conformal projections (UTM, Lambert): the same factor in every direction.
  return 0.5 * (f.meridional_scale + f.parallel_scale);
}

GridFrame makeGridFrame(const std::vector<ControlPoint>& points, double scale_factor, std::string crs) {
  GridFrame g;
  g.scale_factor = scale_factor;
  g.crs = std::move(crs);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (const auto& p : points)
    if (!p.check) {
      sum += p.grid;
      ++n;
    }
  if (n > 0) g.origin = (sum / n).array().round();
  return g;
}

}  // namespace plumb
