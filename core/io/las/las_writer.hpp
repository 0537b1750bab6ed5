#pragma once
// LAS writer: LAS 1.2 (point format 3 with GPS time, else 2) or LAS 1.4 (point format 7).
//
// - Scans are merged in the dataset frame (LAS holds one cloud). Points with a non-finite
//   position are skipped and counted in WriteReport::dropped.
// - Coordinates: record = round((world - offset) / scale). Default scale 0.1 mm; the offset is
//   the centre of the bounds rounded to 1 m unless given. Throws FileError when the extent
//   does not fit int32 records at that scale (+-214 km from the offset at 0.1 mm), and when a
//   scan's dataset-frame coordinates (its pose applied) are not finite or so large that
//   |coordinate| / scale exceeds 2^53 (the header offset could not hold them to the scale).
// - Point format: 1.2 -> 0..3 and 1.4 -> 6..8, with RGB only when the cloud has colours
//   (no invented black), GPS time (1.2) only with timestamps, NIR (format 8) from the
//   ScalarField "nir" when there is colour too.
// - RGB 8-bit v is written as v * 257 (0..65535). Intensity: integers within 0..65535 as they
//   are; otherwise scaled linearly from [min, max] (the E57 intensity limits when the
//   metadata has them) to 0..65535, said in WriteReport::notes. Return number 0 is written
//   as 1 (count at least the return), clamped to 3 bits (1.2) or 4 bits (1.4);
//   classification & 31 for 1.2.
// - The PointCloud columns scan_angle, user_data, point_source_id, classification_flags,
//   scanner_channel, scan_flags (or ScalarFields of those names) go to their LAS fields; every other
//   ScalarField is written as a float extra byte described by an Extra Bytes VLR.
// - coordinate_system: see las_crs.hpp. WKT text goes to an OGC WKT VLR (LASF_Projection
//   2112); "EPSG:<code>" to GeoTIFF keys in LAS 1.2 and to the code's WKT (from PROJ) in
//   LAS 1.4, whose formats 6-10 allow WKT only; what cannot be written is said in
//   WriteReport::notes.
// - Written atomically through a temporary file.
#include <filesystem>
#include <optional>
#include <utility>
#include <string>

#include <Eigen/Core>

#include "common/progress.hpp"
#include "io/write_report.hpp"
#include "model/dataset.hpp"

namespace plumb {

struct LasWriteOptions {
  int version_minor = 4;                   ///< 2 (LAS 1.2, format 0-3) or 4 (LAS 1.4, format 6-8)
  double scale = 1e-4;                     ///< coordinate quantum, metres, > 0 (0.1 mm)
  std::optional<Eigen::Vector3d> offset;   ///< header offset; default: bounds centre, 1 m
  bool extra_fields = true;                ///< write other ScalarFields as extra bytes
  std::string software = "Plumb";          ///< Generating Software field
  WriteReport* report = nullptr;           ///< filled when given: counts and conversions
};

/// The E57 intensity limits of every scan of `data` (the "scan K intensity limits" metadata
/// the E57 reader leaves), joined; empty unless every scan has them. writeLas scales
/// intensity that is not whole numbers within 0..65535 from these when known.
std::optional<std::pair<double, double>> lasIntensityLimits(const Dataset& data);

/// Throws InputError for a version other than 1.2/1.4 or a scale that is not a positive number.
void checkLasWriteOptions(const LasWriteOptions& options);

void writeLas(const std::filesystem::path& path, const Dataset& data,
              const LasWriteOptions& options = {}, Progress* progress = nullptr);

}  // namespace plumb
