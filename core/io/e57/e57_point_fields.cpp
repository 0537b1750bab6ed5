#include "io/e57/e57_point_fields.hpp"

#include <sstream>
#include <utility>

namespace plumb::e57::detail {
namespace {

std::string localName(const std::string& name) {
  const auto colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

}  // namespace

int roleOf(const std::string& name) {
  static const std::pair<const char*, Role> standard[] = {
      {"cartesianX", X}, {"cartesianY", Y}, {"cartesianZ", Z}, {"sphericalRange", Range},
      {"sphericalAzimuth", Azimuth}, {"sphericalElevation", Elevation},
      {"cartesianInvalidState", CartesianState}, {"sphericalInvalidState", SphericalState},
      {"intensity", Intensity}, {"colorRed", Red}, {"colorGreen", Green}, {"colorBlue", Blue},
      {"rowIndex", Row}, {"columnIndex", Column}, {"returnIndex", ReturnIndex},
      {"returnCount", ReturnCount}, {"timeStamp", TimeStamp},
      {"isIntensityInvalid", IntensityInvalid}, {"isColorInvalid", ColorInvalid},
      {"isTimeStampInvalid", TimeInvalid}};
  for (const auto& [n, r] : standard)
    if (name == n) return r;
  const std::string local = localName(name);  // extensions: any namespace prefix
  if (local == "normalX") return NormalX;
  if (local == "normalY") return NormalY;
  if (local == "normalZ") return NormalZ;
  if (local == "classification") return Classification;
  if (local == "sensorOriginX") return SensorX;  // Plumb's extension: per-point sensor origin
  if (local == "sensorOriginY") return SensorY;  // (MMS trajectory), file frame like cartesian*
  if (local == "sensorOriginZ") return SensorZ;
  static const std::pair<const char*, Role> las[] = {  // Plumb's extension: LAS attributes
      {"classificationFlags", ClassificationFlags}, {"scannerChannel", ScannerChannel},
      {"scanFlags", ScanFlags}, {"userData", UserData}, {"pointSourceId", PointSourceId},
      {"scanAngle", ScanAngle}};
  for (const auto& [n, r] : las)
    if (local == n) return r;
  return -1;
}

FieldRoles assignRoles(const std::vector<FieldSpec>& fields) {
  FieldRoles roles;
  roles.column.fill(-1);
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const int r = roleOf(fields[f].name);
    if (r >= 0 && roles.column[r] < 0) {
      roles.column[r] = static_cast<int>(f);
    } else {
      roles.others.push_back(f);
    }
  }
  return roles;
}

std::string describeField(const FieldSpec& f) {
  std::ostringstream s;
  s << f.name << ":";
  switch (f.type) {
    case FieldType::Float: s << (f.single ? "float32" : "float64"); break;
    case FieldType::Integer: s << "int" << f.bits() << "b[" << f.minimum << "," << f.maximum << "]"; break;
    case FieldType::ScaledInteger: s << "scaled" << f.bits() << "b(" << f.scale << ")"; break;
  }
  return s.str();
}

Limits fieldRange(const FieldSpec& f) {
  if (f.type == FieldType::Float) return f.has_float_limits ? Limits{f.float_min, f.float_max} : Limits{0, 255};
  const double lo = static_cast<double>(f.minimum), hi = static_cast<double>(f.maximum);
  if (f.type == FieldType::ScaledInteger) return {lo * f.scale + f.offset, hi * f.scale + f.offset};
  return {lo, hi};
}

std::string limitsText(const Limits& l) {
  std::ostringstream s;
  s << l.minimum << " .. " << l.maximum;
  return s.str();
}

ColorDecoding colorDecoding(const ScanInfo& info, const FieldRoles& roles) {
  ColorDecoding d;
  d.direct = true;
  for (int c = 0; c < 3; ++c) {
    const FieldSpec& f = info.fields[roles.column[Red + c]];
    const Limits l = info.color_limits ? (*info.color_limits)[c] : fieldRange(f);
    const bool integral = f.type == FieldType::Integer && std::floor(l.minimum) == l.minimum &&
                          std::floor(l.maximum) == l.maximum;
    d.scale[c] = ColorScale(l, integral);
    d.direct = d.direct && f.type == FieldType::Integer && f.minimum >= 0 && f.maximum <= 255 &&
               l.minimum == 0 && l.maximum == 255;
  }
  return d;
}

}  // namespace plumb::e57::detail
