#include "io/las/las_point_fields.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>

#include "io/las/las_bytes.hpp"

namespace plumb::las {
namespace {

template <class T>
T clampRound(double v) {
  if (!(v == v)) return 0;
  v = std::round(v);
  return static_cast<T>(std::clamp(v, static_cast<double>(std::numeric_limits<T>::min()),
                                   static_cast<double>(std::numeric_limits<T>::max())));
}

/// `column` when it has one value per point, else the ScalarField `name` converted into
/// `store`, else null.
template <class T, class V>
const T* fieldSource(const PointCloud& cloud, const V& column, const char* name,
                     std::vector<T>& store) {
  if (!column.empty() && column.size() == cloud.size()) return column.data();
  const ScalarField* f = cloud.findScalarField(name);
  if (!f || f->values.size() != cloud.size()) return nullptr;
  store.resize(f->values.size());
  for (std::size_t i = 0; i < store.size(); ++i) {
    if constexpr (std::is_floating_point_v<T>) store[i] = f->values[i];
    else store[i] = clampRound<T>(f->values[i]);
  }
  return store.data();
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

std::uint16_t IntensityMap::operator()(float v) const {
  const double x = scaled ? (v - lo) * factor : v;
  if (!(x > 0)) return 0;  // also NaN
  if (x >= 65535) return 65535;
  return static_cast<std::uint16_t>(x + 0.5);  // round half away from zero, as std::round
}

std::optional<IntensityRange> intensityRange(const PointCloud& cloud,
                                             std::optional<std::pair<double, double>> limits) {
  if (!cloud.hasIntensity()) return std::nullopt;
  bool integral = true;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (float v : cloud.intensity) {
    if (!std::isfinite(v)) continue;
    integral = integral && v >= 0 && v <= 65535 && std::floor(v) == v;
    lo = std::min<double>(lo, v), hi = std::max<double>(hi, v);
  }
  if (integral) return std::nullopt;
  const bool from_limits = limits && limits->first < limits->second;
  if (from_limits) lo = limits->first, hi = limits->second;
  return IntensityRange{lo, hi, from_limits ? "the E57 intensity limits" : "the data's min/max"};
}

IntensityMap intensityMap(const PointCloud& cloud, std::optional<std::pair<double, double>> limits,
                          std::vector<std::string>& notes) {
  const auto range = intensityRange(cloud, limits);
  return range ? scaledIntensity(range->lo, range->hi, range->source, notes) : IntensityMap{};
}

IntensityMap scaledIntensity(double lo, double hi, const std::string& source, std::vector<std::string>& notes) {
  IntensityMap m;
  m.scaled = true;
  m.lo = lo;
  m.factor = hi > lo ? 65535.0 / (hi - lo) : 0.0;
  notes.push_back("intensity scaled linearly from [" + num(lo) + ", " + num(hi) + "] (" + source +
                  ") to LAS 0..65535");
  return m;
}

std::optional<std::pair<double, double>> knownIntensityLimits(const Dataset& data) {
  std::optional<std::pair<double, double>> out;
  for (std::size_t k = 0; k < data.scans.size(); ++k) {
    const std::string key = "scan " + std::to_string(k) + " intensity limits";
    bool found = false;
    for (const auto& [name, value] : data.metadata) {
      double lo = 0, hi = 0;
      if (name != key || std::sscanf(value.c_str(), "%lf .. %lf", &lo, &hi) != 2) continue;
      found = true;
      out = out ? std::pair{std::min(out->first, lo), std::max(out->second, hi)} : std::pair{lo, hi};
    }
    if (!found) return std::nullopt;
  }
  return out;
}

int chooseFormat(const PointCloud& cloud, bool v14) {
  const bool rgb = cloud.hasColors();
  if (v14) {
    const ScalarField* nir = cloud.findScalarField("nir");
    return rgb ? (nir && nir->values.size() == cloud.size() ? 8 : 7) : 6;
  }
  return cloud.hasTimestamps() ? (rgb ? 3 : 1) : (rgb ? 2 : 0);
}

bool isLasFieldName(const std::string& name) {
  return name == "scan_angle" || name == "user_data" || name == "point_source_id" ||
         name == "classification_flags" || name == "scanner_channel" || name == "scan_flags";
}

RecordFields::RecordFields(const PointCloud& cloud, const PointLayout& layout, IntensityMap intensity,
                           std::vector<const ScalarField*> extras)
    : cloud_(cloud), layout_(layout), intensity_(intensity), extras_(std::move(extras)) {
  angle_ = fieldSource(cloud, cloud.scan_angle, "scan_angle", angle_store_);
  user_ = fieldSource(cloud, cloud.user_data, "user_data", user_store_);
  source_ = fieldSource(cloud, cloud.point_source_id, "point_source_id", source_store_);
  flags_ = fieldSource(cloud, cloud.classification_flags, "classification_flags", flags_store_);
  channel_ = fieldSource(cloud, cloud.scanner_channel, "scanner_channel", channel_store_);
  scan_flags_ = fieldSource(cloud, cloud.scan_flags, "scan_flags", scan_flags_store_);
  if (layout.nir_at >= 0) nir_ = cloud.findScalarField("nir")->values.data();
}

void RecordFields::storeReturns(std::uint8_t* r, std::size_t i) {
  // Return numbers are 1..number of returns: 0 (unknown) is written as 1, and the count is
  // at least the return number, so the header's by-return counts match the records.
  const int max_return = layout_.extended ? 15 : 7;
  int ret = cloud_.hasReturns() ? std::min<int>(cloud_.return_index[i], max_return) : 1;
  if (ret == 0) ++zero_returns_, ret = 1;
  const int cnt = std::max(ret, cloud_.hasReturns() ? std::min<int>(cloud_.return_count[i], max_return) : 1);
  ++by_return_[ret - 1];
  r[14] = static_cast<std::uint8_t>(layout_.extended ? ret | (cnt << 4) : ret | (cnt << 3));
  // Scan direction and edge of flight line: bits 6-7 of byte 15 (PDRF 6-10) or 14 (0-5).
  if (scan_flags_) r[layout_.extended ? 15 : 14] |= static_cast<std::uint8_t>((scan_flags_[i] & 3) << 6);
}

void RecordFields::storeClassAndAngle(std::uint8_t* r, std::size_t i) {
  const int cls = cloud_.hasClassification() ? cloud_.classification[i] : 0;
  const int fl = flags_ ? flags_[i] : 0;
  const double angle = angle_ ? angle_[i] : 0.0;
  r[17] = user_ ? user_[i] : 0;
  if (layout_.extended) {
    r[15] |= static_cast<std::uint8_t>((fl & 0x0F) | ((channel_ ? channel_[i] & 3 : 0) << 4));
    r[16] = static_cast<std::uint8_t>(cls);
    store<std::int16_t>(r + 18, clampRound<std::int16_t>(angle / 0.006));
    store<std::uint16_t>(r + 20, source_ ? source_[i] : 0);
  } else {
    r[15] = static_cast<std::uint8_t>((cls & 0x1F) | ((fl & 0x07) << 5));
    r[16] = static_cast<std::uint8_t>(clampRound<std::int8_t>(angle));
    store<std::uint16_t>(r + 18, source_ ? source_[i] : 0);
  }
}

void RecordFields::write(std::uint8_t* records, std::size_t record_length, std::size_t begin,
                         std::size_t end, const std::uint8_t* keep) {
  std::uint8_t* r = records;
  for (std::size_t i = begin; i < end; ++i)
    if (keep[i]) writeOne(r, i), r += record_length;
}

void RecordFields::writeOne(std::uint8_t* r, std::size_t i) {
  if (cloud_.hasIntensity()) store<std::uint16_t>(r + 12, intensity_(cloud_.intensity[i]));
  storeReturns(r, i);
  storeClassAndAngle(r, i);
  if (layout_.gps_at >= 0 && cloud_.hasTimestamps()) store<double>(r + layout_.gps_at, cloud_.timestamps[i]);
  if (layout_.rgb_at >= 0) {
    const Rgb8& c = cloud_.colors[i];
    for (int k = 0; k < 3; ++k)
      store<std::uint16_t>(r + layout_.rgb_at + 2 * k, static_cast<std::uint16_t>(c[k] * 257));
  }
  if (nir_) store<std::uint16_t>(r + layout_.nir_at, clampRound<std::uint16_t>(nir_[i]));
  for (std::size_t e = 0; e < extras_.size(); ++e)
    store<float>(r + layout_.min_size + 4 * e, extras_[e]->values[i]);
}

}  // namespace plumb::las
