#include "ui/layers/color_ramp.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace plumb::ui {

namespace {

// Viridis at t = 0, 0.1, ..., 1 (matplotlib's published values). An earlier 9-stop table
// left out t = 0.7 and 0.9 and spread the rest evenly: mid-range colours were off by up to
// 25 levels (viridis(0.5) came out (42, 120, 142) instead of (33, 145, 140)).
constexpr std::array<std::array<double, 3>, 11> kViridis = {{
    {0.267004, 0.004874, 0.329415},
    {0.282623, 0.140926, 0.457517},
    {0.253935, 0.265254, 0.529983},
    {0.206756, 0.371758, 0.553117},
    {0.163625, 0.471133, 0.558148},
    {0.127568, 0.566949, 0.550556},
    {0.134692, 0.658636, 0.517649},
    {0.266941, 0.748751, 0.440573},
    {0.477504, 0.821444, 0.318195},
    {0.741388, 0.873449, 0.149561},
    {0.993248, 0.906157, 0.143936},
}};

// Blue, cyan, green, yellow, red at equal steps (CloudCompare-like deviation scale).
constexpr std::array<std::array<double, 3>, 5> kDeviation = {
    {{0.0, 0.0, 1.0}, {0.0, 1.0, 1.0}, {0.0, 1.0, 0.0}, {1.0, 1.0, 0.0}, {1.0, 0.0, 0.0}}};

// ColorBrewer's RdBu ends and near-white middle, blue first: symmetric around t = 0.5.
constexpr std::array<std::array<double, 3>, 3> kBlueWhiteRed = {
    {{0.129, 0.400, 0.675}, {0.969, 0.969, 0.969}, {0.698, 0.094, 0.169}}};

std::uint8_t toByte(double v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5);
}

/// Linear interpolation between equally spaced stops, t in [0, 1].
template <std::size_t N>
Rgb interpolate(const std::array<std::array<double, 3>, N>& stops, double t) {
  const double x = t * (N - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(x), N - 2);
  const double f = x - static_cast<double>(i);
  Rgb c{};
  for (int k = 0; k < 3; ++k) c[k] = toByte(stops[i][k] * (1 - f) + stops[i + 1][k] * f);
  return c;
}

}  // namespace

Rgb rampColor(RampKind ramp, double t) {
  if (!std::isfinite(t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0);
  if (ramp == RampKind::Grey) {
    const auto g = toByte(0.15 + 0.85 * t);
    return {g, g, g};
  }
  if (ramp == RampKind::Distance) return interpolate(kDeviation, t);
  if (ramp == RampKind::Diverging) return interpolate(kBlueWhiteRed, t);
  return interpolate(kViridis, t);
}

Rgb categoryColor(std::size_t i) {
  // Tableau 10: distinct on dark and light backgrounds.
  static constexpr std::array<Rgb, 10> kPalette = {{
      {78, 121, 167}, {242, 142, 43}, {225, 87, 89}, {118, 183, 178}, {89, 161, 79},
      {237, 201, 72}, {176, 122, 161}, {255, 157, 167}, {156, 117, 95}, {186, 176, 172},
  }};
  return kPalette[i % kPalette.size()];
}

Rgb ifcTypeColor(const std::string& type) {
  if (type.empty()) return {200, 200, 200};
  static const std::map<std::string, Rgb> kTypes = {
      {"IfcWall", {222, 184, 135}},         {"IfcWallStandardCase", {222, 184, 135}},
      {"IfcWallElementedCase", {222, 184, 135}}, {"IfcCurtainWall", {120, 170, 210}},
      {"IfcSlab", {190, 185, 175}},         {"IfcRoof", {178, 90, 70}},
      {"IfcWindow", {110, 180, 235}},       {"IfcPlate", {140, 195, 225}},
      {"IfcDoor", {150, 100, 55}},          {"IfcColumn", {120, 120, 145}},
      {"IfcBeam", {125, 140, 115}},         {"IfcMember", {150, 150, 115}},
      {"IfcStair", {225, 160, 80}},         {"IfcStairFlight", {225, 160, 80}},
      {"IfcRamp", {225, 160, 80}},          {"IfcRailing", {85, 85, 85}},
      {"IfcCovering", {230, 225, 205}},     {"IfcFooting", {140, 128, 118}},
      {"IfcFurnishingElement", {105, 160, 85}}, {"IfcFurniture", {105, 160, 85}},
      {"IfcSpace", {232, 232, 250}},        {"IfcBuildingElementProxy", {200, 120, 200}},
      {"IfcOpeningElement", {250, 250, 250}},
  };
  if (const auto it = kTypes.find(type); it != kTypes.end()) return it->second;
  std::uint32_t h = 2166136261u;  // FNV-1a: the same type name, the same colour, everywhere
  for (const unsigned char c : type) h = (h ^ c) * 16777619u;
  return categoryColor(h);
}

std::pair<double, double> robustRange(std::span<const float> values, double lo, double hi) {
  std::vector<float> sample;
  const std::size_t step = std::max<std::size_t>(1, values.size() / 100000);
  sample.reserve(values.size() / step + 1);
  for (std::size_t i = 0; i < values.size(); i += step)
    if (std::isfinite(values[i])) sample.push_back(values[i]);
  if (sample.empty()) return {0.0, 1.0};
  auto quantile = [&sample](double q) {
    const auto k = static_cast<std::size_t>(q * static_cast<double>(sample.size() - 1));
    std::nth_element(sample.begin(), sample.begin() + static_cast<long>(k), sample.end());
    return static_cast<double>(sample[k]);
  };
  double a = quantile(lo), b = quantile(hi);
  if (!(b > a)) {
    a -= 0.5;
    b += 0.5;
  }
  return {a, b};
}

}  // namespace plumb::ui
