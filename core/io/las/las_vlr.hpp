#pragma once
// LAS Variable Length Records (after the header) and Extended VLRs (1.4, after the points):
// walking them with bounds checks, the Extra Bytes descriptors (LASF_Spec 4) and the CRS
// records (LASF_Projection 2112 WKT, 34735/34737 GeoTIFF keys). Internal to io/las.
#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "io/las/las_header.hpp"

namespace plumb::las {

class ByteSource;

struct LasVlr {
  bool extended = false;          ///< EVLR (after the points)
  std::uint64_t at = 0;           ///< byte offset of its header in the file
  std::string user_id;
  std::uint16_t record_id = 0;
  std::uint64_t length = 0;       ///< record length after header
  std::string description;
  std::vector<std::uint8_t> payload;  ///< kept only for records the reader interprets
};

/// Walks the header's VLRs in `prefix` (the file's bytes [0, offset_to_points)).
std::vector<LasVlr> parseVlrs(std::span<const std::uint8_t> prefix, const LasHeader& h,
                              const std::filesystem::path& file);
/// Walks the 1.4 EVLRs; appends to `out`.
void parseEvlrs(const ByteSource& src, const LasHeader& h, const std::filesystem::path& file,
                std::vector<LasVlr>& out, std::vector<std::string>& warnings);

/// One value of the Extra Bytes VLR: a scalar or one element of a 2/3-element array.
struct ExtraField {
  std::string name;          ///< descriptor name; arrays get "[0]", "[1]"... appended
  int type = 0;              ///< base type 1..10 (uchar, char, ushort, short, ulong, long,
                             ///< ulonglong, longlong, float, double)
  std::size_t offset = 0;    ///< byte offset inside the record's extra bytes
  double scale = 1.0;        ///< applied when the descriptor says so (value*scale+offset)
  double add = 0.0;
};

/// Size in bytes of base type 1..10.
std::size_t extraTypeSize(int type);
/// Decodes the Extra Bytes descriptors of `vlr` (n x 192 bytes) for records carrying
/// `extra_bytes` bytes after the format's own fields. Undocumented (type 0) and unusable
/// descriptors are skipped with a warning; descriptors beyond the record throw FileError.
std::vector<ExtraField> parseExtraBytes(const LasVlr& vlr, std::size_t extra_bytes,
                                        const std::filesystem::path& file,
                                        std::vector<std::string>& warnings);

/// The coordinate system the records carry: OGC WKT text (2112), else "EPSG:<code>" from
/// the GeoTIFF keys (34735), else the GeoTIFF ASCII citation (34737). Empty if none.
std::string coordinateSystem(const std::vector<LasVlr>& vlrs, const LasHeader& h,
                             std::vector<std::string>& warnings);

/// Serialises one VLR (54-byte header + payload) for the writer.
std::vector<std::uint8_t> serializeVlr(const std::string& user_id, std::uint16_t record_id,
                                       const std::string& description,
                                       std::span<const std::uint8_t> payload);

/// One 192-byte Extra Bytes descriptor for a float (type 9) scalar named `name`.
std::array<std::uint8_t, 192> floatExtraDescriptor(const std::string& name);

}  // namespace plumb::las
