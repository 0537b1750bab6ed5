#include "ui/layers/color_ramp.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace plumb::ui {

namespace {

// Viridis sampled at 9 stops (matplotlib's published table, every 32nd entry).
constexpr std::array<std::array<double, 3>, 9> kViridis = {{
    {0.267, 0.005, 0.329},
    {0.283, 0.141, 0.458},
    {0.254, 0.265, 0.530},
    {0.207, 0.372, 0.553},
    {0.164, 0.471, 0.558},
    {0.128, 0.567, 0.551},
    {0.135, 0.659, 0.518},
    {0.478, 0.821, 0.318},
    {0.993, 0.906, 0.144},
}};

std::uint8_t toByte(double v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5);
}

}  // namespace

Rgb rampColor(RampKind ramp, double t) {
  if (!std::isfinite(t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0);
  if (ramp == RampKind::Grey) {
    const auto g = toByte(0.15 + 0.85 * t);
    return {g, g, g};
  }
  if (ramp == RampKind::Distance) {
    // Blue, cyan, green, yellow, red at equal steps (CloudCompare-like deviation scale).
    static constexpr std::array<std::array<double, 3>, 5> kStops = {
        {{0.0, 0.0, 1.0}, {0.0, 1.0, 1.0}, {0.0, 1.0, 0.0}, {1.0, 1.0, 0.0}, {1.0, 0.0, 0.0}}};
    const double x = t * (kStops.size() - 1);
    const auto i = std::min<std::size_t>(static_cast<std::size_t>(x), kStops.size() - 2);
    const double f = x - static_cast<double>(i);
    Rgb c{};
    for (int k = 0; k < 3; ++k) c[k] = toByte(kStops[i][k] * (1 - f) + kStops[i + 1][k] * f);
    return c;
  }
  const double x = t * (kViridis.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(x), kViridis.size() - 2);
  const double f = x - static_cast<double>(i);
  Rgb c{};
  for (int k = 0; k < 3; ++k) c[k] = toByte(kViridis[i][k] * (1 - f) + kViridis[i + 1][k] * f);
  return c;
}

Rgb categoryColor(std::size_t i) {
  // Tableau 10: distinct on dark and light backgrounds.
  static constexpr std::array<Rgb, 10> kPalette = {{
      {78, 121, 167}, {242, 142, 43}, {225, 87, 89}, {118, 183, 178}, {89, 161, 79},
      {237, 201, 72}, {176, 122, 161}, {255, 157, 167}, {156, 117, 95}, {186, 176, 172},
  }};
  return kPalette[i % kPalette.size()];
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
