#pragma once
// The point prototype the E57 writer gives one scan (e57_writer.hpp lists the fields), one
// step per group of fields: each step appends its OutFields and fills the bookkeeping the XML
// section needs (bounds, limits) in the WrittenScan. The fields' callbacks keep a reference
// to the cloud, which must outlive them. Internal to io/e57; declared here so the unit tests
// can check each step alone.
#include <vector>

#include "io/e57/e57_packet_writer.hpp"
#include "io/e57/e57_writer.hpp"
#include "io/e57/e57_xml_writer.hpp"

namespace plumb::e57 {

/// Bounds of the finite positions (world coordinates), stored in w.bounds when there is one,
/// and whether any position is not finite. Throws InputError when a coordinate is too large
/// for the ScaledInteger quantum (unless positions are written as Float).
struct PositionExtent {
  Bounds bounds;
  bool any_invalid = false;
};
PositionExtent positionExtent(const PointCloud& cloud, const E57WriteOptions& options, WrittenScan& w);

/// cartesianX/Y/Z: Float double, or ScaledInteger of quantum options.scaled_precision over the
/// quantized bounds (then w.bounds becomes the bounds of the stored values).
void appendPositionFields(const PointCloud& cloud, const E57WriteOptions& options, const Bounds& b,
                          WrittenScan& w, std::vector<OutField>& fields);
/// cartesianInvalidState: 0 for a finite position, 2 (no position) for the others.
OutField invalidStateField(const PointCloud& cloud);
/// intensity: Integer over its limits when every value is a whole number, else Float single;
/// w.intensity (limits, 0..0 when none is finite) and w.intensity_integer are set.
OutField intensityField(const PointCloud& cloud, WrittenScan& w);
/// colorRed/Green/Blue 0..255 and, when the cloud has one per point, isColorInvalid.
void appendColorFields(const PointCloud& cloud, WrittenScan& w, std::vector<OutField>& fields);
/// rowIndex/columnIndex (with w.rows, w.columns) when the cloud has a grid; returnIndex
/// (0-based) and returnCount (with w.returns) when it has returns.
void appendIndexFields(const PointCloud& cloud, WrittenScan& w, std::vector<OutField>& fields);
/// timeStamp, the nor:normalX/Y/Z extension and the plumb:sensorOrigin extension, for the
/// attributes the cloud has.
void appendTimeNormalAndOriginFields(const PointCloud& cloud, std::vector<OutField>& fields);

/// Every field of one scan, in prototype order, and w.prototype and w.records.
std::vector<OutField> describeScan(const PointCloud& cloud, const E57WriteOptions& options, WrittenScan& w);

}  // namespace plumb::e57
