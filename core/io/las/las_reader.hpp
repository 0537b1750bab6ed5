#pragma once
// LAS 1.0-1.4 reader, point data record formats 0-10 (uncompressed).
//
// Rules (see also docs/LAS_FORMAT.md):
// - Positions: world = record_int32 * scale + header offset, computed in double. The cloud's
//   double `offset` is the centre of the header bounds rounded to 1 m (the first point
//   rounded to 1 m when the header bounds are absent or do not contain it), so float local
//   coordinates keep sub-millimetre precision for georeferenced data.
// - Intensity is kept as stored (0..65535, no rescale); return number/count and
//   classification as stored (PDRF 0-5: class = bits 0-4 of the class byte; 6-10: full byte).
// - RGB: LAS channels are 16-bit. If any channel of any point exceeds 255 the file is 16-bit
//   and each channel becomes value >> 8 (the high byte; the writer stores v * 257, so a
//   round trip is exact). If no channel exceeds 255 the writer stored 8-bit values (common
//   in older files) and they are kept as they are.
// - Scan angle (degrees), user data, point source ID, classification flags, scanner channel
//   and scan direction/edge flags go to their PointCloud columns; a field that is 0 for every
//   point has no column (the LAS writer writes 0 for it). NIR (formats 8/10) is the
//   ScalarField "nir".
// - GPS time goes to `timestamps` as stored; its kind (week time / adjusted standard) is in
//   the metadata ("GPS time").
// - Extra bytes described by the Extra Bytes VLR (LASF_Spec 4) become ScalarFields named after
//   their descriptor (arrays: "name[0]".."name[2]"), scale/offset applied. Undescribed extra
//   bytes are ignored with a "warning" metadata entry.
// - VLRs/EVLRs are listed in the metadata ("VLR n" / "EVLR n"). The coordinate system comes
//   from the WKT record (2112), else "EPSG:<code>" from the GeoTIFF keys (34735), else the
//   GeoTIFF ASCII citation.
// - Every malformed header, VLR or record is a FileError with the byte offset. Counts are
//   checked against the file size before anything is allocated.
// - LAZ (compression bits in the point format byte, the LASzip VLR, or a .laz name) is refused
//   with a message saying how to decompress it (laszip / las2las).
#include <cstdint>
#include <filesystem>
#include <span>

#include "common/progress.hpp"
#include "io/stream/chunk_sink.hpp"
#include "model/dataset.hpp"

namespace plumb {

struct LasReadOptions {
  /// Keep described extra bytes as ScalarFields.
  bool extra_bytes = true;
  /// Ignored, kept for source compatibility: scan angle, user data, point source ID,
  /// classification flags, scanner channel, scan direction/edge flags always go to their PointCloud columns (freed
  /// when 0 for every point), NIR (formats 8/10) to the ScalarField "nir".
  bool auxiliary_fields = false;
};

/// Reads an uncompressed LAS file into a one-scan Dataset (format "las").
Dataset readLas(const std::filesystem::path& path, const LasReadOptions& options = {},
                Progress* progress = nullptr);

/// Streams the file to `sink` (io/stream/chunk_sink.hpp) in chunks decoded as readLas decodes
/// them (same offset and values; every chunk has every LAS field column of the format, those
/// readLas drops for being 0 everywhere are left out of StreamScanEnd::fields). A coloured
/// file is first scanned for a channel above 255 to apply readLas's RGB rule (the scan stops
/// at the first such value). Metadata and warnings are readLas's, complete at ChunkSink::end.
void streamLas(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
               Progress* progress = nullptr);

/// Same, from bytes in memory (fuzzing, tests, embedded data). `name` is used in errors.
Dataset readLasBuffer(std::span<const std::uint8_t> bytes,
                      const std::filesystem::path& name = "<memory>",
                      const LasReadOptions& options = {}, Progress* progress = nullptr);

}  // namespace plumb
