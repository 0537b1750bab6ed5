#pragma once
// The non-coordinate fields of a LAS point record written from PointCloud columns: intensity
// mapping, return numbers, classification and its flags, scan angle, user data, point source
// ID, scanner channel, GPS time, RGB, NIR and extra bytes. Internal to io/las (las_writer.cpp).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/las/las_header.hpp"
#include "model/dataset.hpp"

namespace plumb::las {

/// Intensity to LAS uint16. Integer values within 0..65535 are kept as they are; any other
/// intensity (E57 0..1 floats, negative or larger values) is scaled linearly from [lo, hi]
/// to 0..65535, clamped; NaN becomes 0.
struct IntensityMap {
  bool scaled = false;
  double lo = 0, factor = 1;
  std::uint16_t operator()(float v) const;
};

/// The range intensityMap scales from, and where it came from; empty when the intensity is
/// written as stored (none, or whole numbers within 0..65535).
struct IntensityRange {
  double lo = 0, hi = 0;
  std::string source;  ///< "the E57 intensity limits" or "the data's min/max"
};
std::optional<IntensityRange> intensityRange(const PointCloud& cloud,
                                             std::optional<std::pair<double, double>> limits);

/// The map for `cloud`. `limits` (the E57 intensityLimits) replace the data's min/max when
/// known. A scaling is described in `notes`.
IntensityMap intensityMap(const PointCloud& cloud, std::optional<std::pair<double, double>> limits,
                          std::vector<std::string>& notes);

/// The map scaling [lo, hi] to 0..65535, described in `notes` with where the range came from
/// (`source`, e.g. "the E57 intensity limits").
IntensityMap scaledIntensity(double lo, double hi, const std::string& source, std::vector<std::string>& notes);

/// The union of the intensity limits the E57 reader left in the metadata ("scan K intensity
/// limits"), when every scan has them.
std::optional<std::pair<double, double>> knownIntensityLimits(const Dataset& data);

/// Point format for the cloud: LAS 1.2 -> 0..3 (GPS time, RGB only when present); LAS 1.4 ->
/// 6 (no colour), 7 (RGB), 8 (RGB + the ScalarField "nir").
int chooseFormat(const PointCloud& cloud, bool v14);

/// Writes the fields of point i (everything but X/Y/Z) into records of one layout.
class RecordFields {
 public:
  /// `extras`: the ScalarFields written as float extra bytes after the format's fields.
  RecordFields(const PointCloud& cloud, const PointLayout& layout, IntensityMap intensity,
               std::vector<const ScalarField*> extras);

  /// Fields of points [begin, end) with keep[i] != 0, into consecutive records of
  /// `record_length` bytes from `records` (the same records the coordinates went to).
  void write(std::uint8_t* records, std::size_t record_length, std::size_t begin, std::size_t end,
             const std::uint8_t* keep);

  /// Points per return number (1..15) written so far.
  const std::array<std::uint64_t, 15>& byReturn() const { return by_return_; }
  /// Points whose return number was 0 (unknown) and were written as return 1.
  std::uint64_t zeroReturns() const { return zero_returns_; }

 private:
  void writeOne(std::uint8_t* r, std::size_t i);
  void storeReturns(std::uint8_t* r, std::size_t i);
  void storeClassAndAngle(std::uint8_t* r, std::size_t i);

  const PointCloud& cloud_;
  PointLayout layout_;
  IntensityMap intensity_;
  std::vector<const ScalarField*> extras_;
  // Each LAS field: its PointCloud column, else a ScalarField of that name (a cloud read
  // back from PLY/CSV), converted once; null when absent (written as 0).
  std::vector<float> angle_store_;
  std::vector<std::uint8_t> user_store_, flags_store_, channel_store_, scan_flags_store_;
  std::vector<std::uint16_t> source_store_;
  const float* angle_ = nullptr;
  const std::uint8_t *user_ = nullptr, *flags_ = nullptr, *channel_ = nullptr, *scan_flags_ = nullptr;
  const std::uint16_t* source_ = nullptr;
  const float* nir_ = nullptr;
  std::array<std::uint64_t, 15> by_return_{};
  std::uint64_t zero_returns_ = 0;
};

/// True for the ScalarField names RecordFields writes into LAS fields (not extra bytes).
bool isLasFieldName(const std::string& name);

}  // namespace plumb::las
