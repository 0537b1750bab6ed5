#include "io/mesh/ifc_map_conversion.hpp"

#include <cmath>
#include <cstdlib>
#include <unordered_map>

#include "common/error.hpp"
#include "io/mesh/ifc_georef.hpp"
#include "io/mesh/step_entities.hpp"

namespace plumb::ifc_georef {
namespace {

/// Map units per metre of the model: a micrometre to a thousand kilometres. Beyond that the
/// file is wrong, and a vertex could be moved to infinity.
constexpr double kSmallestScale = 1e-6, kLargestScale = 1e6;

/// A STEP real, or `fallback` for "$" (an omitted optional attribute).
std::optional<double> real(std::string_view arg, double fallback) {
  if (arg == "$" || arg.empty()) return fallback;
  const std::string s(arg);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string unquoted(std::string_view s) {
  if (s.size() >= 2 && s.front() == '\'' && s.back() == '\'') return std::string(s.substr(1, s.size() - 2));
  return {};
}

[[noreturn]] void unusable(const step::Entity& e, const std::string& what) {
  throw InputError("IFCMAPCONVERSION #" + std::to_string(e.id) + " (line " + std::to_string(e.line) +
                   "): " + what);
}

MapConversion parse(const step::Entity& e, const std::unordered_map<std::uint64_t, std::string>& crs_names,
                    double length_unit) {
  const auto a = step::splitArguments(e.args);
  if (a.size() < 5) unusable(e, "fewer than 5 attributes");
  const auto east = real(a[2], 0.0), north = real(a[3], 0.0), height = real(a[4], 0.0);
  const auto abscissa = real(a.size() > 5 ? a[5] : "$", 1.0), ordinate = real(a.size() > 6 ? a[6] : "$", 0.0);
  const auto scale = real(a.size() > 7 ? a[7] : "$", 1.0);
  if (!east || !north || !height || !abscissa || !ordinate || !scale) unusable(e, "a number cannot be read");
  if (std::hypot(*abscissa, *ordinate) < 1e-12) unusable(e, "the x axis (XAxisAbscissa, XAxisOrdinate) is zero");
  if (!(*scale > 0.0)) unusable(e, "Scale must be positive");
  MapConversion m;
  m.origin = {*east, *north, *height};
  m.rotation_rad = std::atan2(*ordinate, *abscissa);
  m.scale = *scale / length_unit;
  if (!(m.scale >= kSmallestScale && m.scale <= kLargestScale))
    unusable(e, "Scale " + std::to_string(*scale) + " makes one metre of the model " + std::to_string(m.scale) +
                    " map units (accepted: 1e-6 to 1e6)");
  m.line = e.line;
  if (const auto it = crs_names.find(step::reference(a[1])); it != crs_names.end()) m.crs = it->second;
  return m;
}

}  // namespace

std::optional<MapConversion> readMapConversion(std::string_view text) {
  std::unordered_map<std::uint64_t, std::string> crs_names;
  std::unordered_map<std::uint64_t, bool> contexts;
  std::vector<step::Entity> conversions;
  step::forEachEntity(text, [&](const step::Entity& e) {
    if (e.type == "IFCPROJECTEDCRS") {
      const auto a = step::splitArguments(e.args);
      if (!a.empty()) crs_names[e.id] = unquoted(a[0]);
    }
    else if (e.type == "IFCGEOMETRICREPRESENTATIONCONTEXT") contexts[e.id] = true;
    else if (e.type == "IFCMAPCONVERSION") conversions.push_back(e);
  });
  for (const auto& e : conversions) {
    const auto a = step::splitArguments(e.args);
    if (!a.empty() && contexts.count(step::reference(a[0]))) {
      const double unit = lengthUnit(text);  // a second pass over the file, only when needed
      return parse(e, crs_names, unit > 0 ? unit : 1.0);
    }
  }
  return std::nullopt;
}

void applyMapConversion(const MapConversion& m, TriangleMesh& mesh) {
  const double c = m.scale * std::cos(m.rotation_rad), s = m.scale * std::sin(m.rotation_rad);
  for (auto& v : mesh.vertices)
    v = Eigen::Vector3d(m.origin.x() + c * v.x() - s * v.y(), m.origin.y() + s * v.x() + c * v.y(),
                        m.origin.z() + v.z());
  if (!mesh.vertex_normals.empty()) {
    const float cf = static_cast<float>(std::cos(m.rotation_rad)), sf = static_cast<float>(std::sin(m.rotation_rad));
    for (auto& n : mesh.vertex_normals) n = Eigen::Vector3f(cf * n.x() - sf * n.y(), sf * n.x() + cf * n.y(), n.z());
  }
}

}  // namespace plumb::ifc_georef
