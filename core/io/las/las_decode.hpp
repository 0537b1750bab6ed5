#pragma once
// Decoding of point data records into PointCloud columns, chunk by chunk. Internal to io/las.
#include <array>
#include <cstdint>
#include <vector>

#include "io/las/las_header.hpp"
#include "io/las/las_vlr.hpp"
#include "model/point_cloud.hpp"

namespace plumb::las {

class PointDecoder {
 public:
  /// Prepares `cloud` (its offset must already be set) to receive h.point_count points:
  /// every LAS field goes to its column (scan_angle, user_data, ... ; NIR to the scalar
  /// field "nir").
  PointDecoder(const LasHeader& h, std::vector<ExtraField> extras, PointCloud& cloud);
  /// Same for a chunk of `capacity` points of a streamed file: every LAS field column of the
  /// format is allocated (zeros), so every chunk has the same columns, and colours are decoded
  /// as 16-bit (high byte) when `rgb16`, else as they are (the caller decided the RGB rule
  /// for the whole file first).
  PointDecoder(const LasHeader& h, std::vector<ExtraField> extras, PointCloud& cloud,
               std::size_t capacity, bool rgb16);

  /// Decodes `n` records starting at `records` (h.record_length apart) as points
  /// [first, first+n).
  void decode(const std::uint8_t* records, std::size_t n, std::size_t first);

  /// After the last chunk: true when the file held 16-bit colour (the RGB rule). LAS field
  /// columns exist only for fields that are not 0 for every point.
  bool finish();
  /// Min/max of the decoded world coordinates (empty when no point).
  Bounds worldBounds() const;
  /// Points whose return number is outside 1..number of returns (checklist item 10).
  std::uint64_t badReturns() const { return bad_returns_; }

 private:
  PointDecoder(const LasHeader& h, std::vector<ExtraField> extras, PointCloud& cloud, std::size_t n,
               bool rgb16, bool dense);
  void decodeAuxiliary(const std::uint8_t* records, std::size_t n, std::size_t first);

  PointLayout layout_;
  std::size_t total_ = 0;  ///< points in the file
  std::size_t stride_;
  std::array<double, 3> scale_;
  std::array<double, 3> shift_;  ///< header offset - cloud offset
  std::array<double, 3> world_offset_;
  std::vector<ExtraField> extras_;
  PointCloud& cloud_;
  std::array<std::int32_t, 3> raw_min_, raw_max_;
  std::uint16_t color_max_ = 0;
  std::uint64_t bad_returns_ = 0;
  ScalarField* nir_ = nullptr;
  std::vector<ScalarField*> extra_fields_;
};

}  // namespace plumb::las
