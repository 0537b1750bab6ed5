#pragma once
// What the fields of an E57 point prototype mean to Plumb: each field's role (coordinate,
// colour, grid index...), the value range it can hold, and how colours scale to 8 bits.
// Internal to the E57 reader; declared here so tests can reach the steps alone.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "io/e57/e57_xml.hpp"

namespace plumb::e57::detail {

enum Role {
  X, Y, Z, Range, Azimuth, Elevation, CartesianState, SphericalState, Intensity, Red, Green,
  Blue, Row, Column, ReturnIndex, ReturnCount, TimeStamp, NormalX, NormalY, NormalZ,
  Classification, IntensityInvalid, ColorInvalid, TimeInvalid, SensorX, SensorY, SensorZ,
  // LAS attributes in Plumb's extension namespace (e57_extension_fields.hpp)
  ClassificationFlags, ScannerChannel, ScanFlags, UserData, PointSourceId, ScanAngle, RoleCount
};

/// Role of a prototype field by name (extensions matched under any namespace prefix), or -1.
int roleOf(const std::string& name);

/// Which prototype field holds each role (the first one naming it); the rest are `others`,
/// kept as scalar fields.
struct FieldRoles {
  std::array<int, RoleCount> column;
  std::vector<std::size_t> others;
  bool has(Role r) const { return column[r] >= 0; }
  bool hasAll(Role a, Role b, Role c) const { return has(a) && has(b) && has(c); }
};
FieldRoles assignRoles(const std::vector<FieldSpec>& fields);

/// "name:type" of one field, as listed in the scan's `prototype` metadata.
std::string describeField(const FieldSpec& f);

/// Range of values a field can hold, used to scale colours to 8 bits.
Limits fieldRange(const FieldSpec& f);

/// "min .. max" as printed in metadata.
std::string limitsText(const Limits& l);

// 8-bit colour from a value in [lo, hi]: integer ranges keep the top 8 bits (65280 of 0..65535
// -> 255), other ranges scale linearly.
struct ColorScale {
  double lo = 0, factor = 1;
  bool integer = true;
  ColorScale(const Limits& l, bool integral) : lo(l.minimum), integer(integral) {
    const double span = l.maximum - l.minimum;
    if (!(span > 0) || !std::isfinite(span)) {
      lo = 0;
      factor = 1;
    } else {
      factor = integral ? 256.0 / (span + 1.0) : 255.0 / span;
    }
  }
  std::uint8_t operator()(double v) const {
    const double s = (v - lo) * factor;
    const double c = integer ? std::floor(s) : std::nearbyint(s);
    return static_cast<std::uint8_t>(std::clamp(std::isnan(c) ? 0.0 : c, 0.0, 255.0));
  }
};

/// How the red, green and blue fields become 8-bit colours: `direct` when they are Integer
/// 0..255 with limits 0..255 (the decoded values are the colours), else through `scale`.
struct ColorDecoding {
  std::array<ColorScale, 3> scale{ColorScale({0, 255}, true), ColorScale({0, 255}, true),
                                  ColorScale({0, 255}, true)};
  bool direct = false;
};
/// Requires the red, green and blue roles to be present.
ColorDecoding colorDecoding(const ScanInfo& info, const FieldRoles& roles);

/// `v` converted to T, clamped to T's range; NaN becomes 0.
template <class T>
T clampTo(double v) {
  if (std::isnan(v)) return T{0};
  return static_cast<T>(std::clamp(v, static_cast<double>(std::numeric_limits<T>::lowest()),
                                   static_cast<double>(std::numeric_limits<T>::max())));
}

}  // namespace plumb::e57::detail
