#include "ui/network/control_settings.hpp"

#include <charconv>
#include <optional>

#include "common/error.hpp"
#include "registration/network/georeference.hpp"

namespace plumb::ui {

namespace {

/// The grid field as a number, or nullopt when it is not one (then it names a CRS).
std::optional<double> scaleNumber(const std::string& grid) {
  double k = 0.0;
  const auto [end, ec] = std::from_chars(grid.data(), grid.data() + grid.size(), k);
  if (ec != std::errc() || end != grid.data() + grid.size()) return std::nullopt;
  return k;
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

void checkSettings(const ControlSettings& s) {
  if (s.control.empty() || s.targets.empty())
    throw InputError("control points: give both the control points file and the targets file");
  if (!(s.target_sigma >= 1e-5 && s.target_sigma <= 1.0))
    throw InputError("control points: the target sigma must lie in [0.01, 1000] mm");
}

}  // namespace

std::shared_ptr<const ControlSurvey> loadControlSurvey(const ControlSettings& settings,
                                                       const std::vector<std::string>& station_names) {
  if (settings.empty()) return nullptr;
  checkSettings(settings);
  const std::string grid = trimmed(settings.grid);
  const std::optional<double> k = grid.empty() ? 1.0 : scaleNumber(grid);
  if (k && !(*k > 0.9 && *k < 1.1))
    throw InputError("control points: the grid scale factor must lie in (0.9, 1.1) (a map projection's)");
  auto c = std::make_shared<ControlSurvey>();
  c->points = readControlPoints(settings.control);
  c->observations = readTargetObservations(settings.targets);
  c->targets_file = settings.targets;
  c->sigma = settings.target_sigma;
  const std::string crs = k ? std::string() : grid;
  c->grid = makeGridFrame(c->points, 1.0, crs);
  c->grid.scale_factor = k ? *k : gridScaleFactor(crs, c->grid.origin);  // PROJ, at the origin (as the CLI)
  checkObservations(*c, station_names);  // before minutes of features
  return c;
}

}  // namespace plumb::ui
