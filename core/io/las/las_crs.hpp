#pragma once
// The coordinate-system VLR a LAS file gets for a dataset's coordinate_system text
// (docs/LAS_FORMAT.md §3). PROJ (libproj, Debian) checks codes and turns an "EPSG:<code>" into
// OGC WKT where the format needs WKT:
//   - "EPSG:<code>" in LAS 1.2: GeoTIFF keys (GeoKeyDirectory, record 34735), projected or
//     geographic as PROJ's database says;
//   - "EPSG:<code>" in LAS 1.4 (formats 6-10 allow WKT only): the code's WKT from PROJ
//     (record 2112, WKT1 as GDAL writes it; WKT2 when the CRS has no WKT1 form);
//   - WKT text: record 2112 as it is, once PROJ has parsed it;
//   - anything PROJ cannot read (a bad or unknown code, free text): no record, and a note
//     saying the coordinate system was not written and why. Never silently dropped.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace plumb::las {

struct CrsRecord {
  std::uint16_t record_id = 0;  ///< 34735 GeoKeyDirectory or 2112 OGC WKT (LASF_Projection)
  std::string description;
  std::vector<std::uint8_t> payload;
};

/// The record for `crs` ("" gives none, without a note). Appends to `notes` when the
/// coordinate system cannot be written.
std::optional<CrsRecord> crsRecord(const std::string& crs, bool las14,
                                   std::vector<std::string>& notes);

}  // namespace plumb::las
