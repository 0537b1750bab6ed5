#pragma once
// The LAS Public Header Block (ASPRS LAS 1.4 R16, section 2 of docs/LAS_FORMAT.md):
// parsing with every check of the reader checklist (section 5), and serialisation for the
// writer. Internal to io/las; readers outside use las_reader.hpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace plumb::las {

inline constexpr std::size_t kHeaderSize12 = 227;  ///< LAS 1.0, 1.1, 1.2
inline constexpr std::size_t kHeaderSize13 = 235;
inline constexpr std::size_t kHeaderSize14 = 375;
inline constexpr std::size_t kVlrHeaderSize = 54;
inline constexpr std::size_t kEvlrHeaderSize = 60;

/// Byte offsets of the header fields the reader reports in errors.
namespace at {
inline constexpr std::uint64_t kVersion = 24, kHeaderSize = 94, kOffsetToPoints = 96,
                               kVlrCount = 100, kFormat = 104, kRecordLength = 105,
                               kLegacyCount = 107, kScale = 131, kOffset = 155, kBounds = 179,
                               kEvlrStart = 235, kEvlrCount = 243, kCount64 = 247;
}

/// Layout of one point data record format: where each optional field sits (-1: absent).
struct PointLayout {
  int format = 0;
  std::size_t min_size = 0;  ///< bytes the format itself uses; the rest are extra bytes
  bool extended = false;     ///< PDRF 6-10: 4-bit returns, full-byte class, int16 angle
  int gps_at = -1;
  int rgb_at = -1;
  int nir_at = -1;
  int wave_at = -1;
};

/// Layout of a PDRF 0..10; throws std::out_of_range for others.
PointLayout pointLayout(int format);
/// True when LAS 1.minor allows format (1.0-1.2: 0-3, 1.3: 0-5, 1.4: 0-10).
bool formatAllowedInVersion(int format, int minor);

struct LasHeader {
  std::uint16_t file_source_id = 0;
  std::uint16_t global_encoding = 0;
  std::array<std::uint8_t, 16> guid{};
  std::uint8_t version_major = 1;
  std::uint8_t version_minor = 4;
  std::string system_identifier;
  std::string generating_software;
  std::uint16_t creation_day = 0;
  std::uint16_t creation_year = 0;
  std::uint16_t header_size = kHeaderSize14;
  std::uint32_t offset_to_points = kHeaderSize14;
  std::uint32_t vlr_count = 0;
  std::uint8_t format_byte = 7;  ///< as stored, compression bits included
  std::uint16_t record_length = 36;
  std::uint32_t legacy_count = 0;
  std::array<std::uint32_t, 5> legacy_by_return{};
  std::array<double, 3> scale{0.0001, 0.0001, 0.0001};
  std::array<double, 3> offset{0, 0, 0};
  std::array<double, 3> min{0, 0, 0};
  std::array<double, 3> max{0, 0, 0};
  std::uint64_t waveform_start = 0;
  std::uint64_t evlr_start = 0;
  std::uint32_t evlr_count = 0;
  std::uint64_t count64 = 0;
  std::array<std::uint64_t, 15> by_return{};

  // --- derived by parseHeader ------------------------------------------------------------
  std::uint64_t point_count = 0;  ///< the count the reader uses (LAS_FACTS section 2 rule)
  std::vector<std::string> warnings;

  int format() const { return format_byte & 0x3F; }
  bool compressed() const { return (format_byte & 0xC0) != 0; }
};

/// Parses and validates the header from the file's first bytes (`bytes` may be longer than
/// the header). `file_size` is the whole file's size, for the count check. Throws FileError
/// naming `file` and the byte offset of the offending field. LAZ (compression bits in the
/// format byte) is refused with a message saying how to decompress.
LasHeader parseHeader(std::span<const std::uint8_t> bytes, std::uint64_t file_size,
                      const std::filesystem::path& file);

// --- the steps of parseHeader, in its order (each throws FileError at its field's byte) ---

/// The "LASF" signature and at least the 227 bytes of a LAS 1.0-1.2 header in `bytes`.
void checkSignatureAndSize(std::span<const std::uint8_t> bytes, std::uint64_t file_size,
                           const std::filesystem::path& file);
/// The fields of the first 227 bytes, as stored (no check).
LasHeader loadHeaderFields(const std::uint8_t* p);
/// Version 1.0 to 1.4 and a header size of at least what the version requires, within the
/// file and within the `available` bytes read.
void checkVersionAndHeaderSize(const LasHeader& h, std::size_t available, std::uint64_t file_size,
                               const std::filesystem::path& file);
/// The 1.3 waveform start and the 1.4 EVLR and 64-bit count fields, per h.version_minor.
void loadVersionFields(LasHeader& h, const std::uint8_t* p);
/// Not LAZ, a format 0..10 (a warning when the version does not define it) and a record
/// length that holds the format's fields.
void checkPointFormat(LasHeader& h, const std::filesystem::path& file);
/// Finite, non-zero scale factors and finite offsets.
void checkScaleAndOffset(const LasHeader& h, const std::filesystem::path& file);
/// Offset to point data after the header and within the file.
void checkOffsetToPoints(const LasHeader& h, std::uint64_t file_size, const std::filesystem::path& file);
/// Sets h.point_count (LAS_FACTS section 2 rule, a warning when the 1.4 counts disagree) and
/// returns the byte offset of the count it used.
std::uint64_t choosePointCount(LasHeader& h);
/// h.point_count records of h.record_length bytes fit between the point data and the end of
/// the points (the EVLRs after them, else the end of the file); `count_at` names the count.
void checkPointCount(const LasHeader& h, std::uint64_t count_at, std::uint64_t file_size,
                     const std::filesystem::path& file);

/// Serialises a header of h.header_size bytes (227 for 1.2, 375 for 1.4).
std::vector<std::uint8_t> serializeHeader(const LasHeader& h);

/// The FileError message for LAZ input (shared by the extension and content checks).
std::string lazMessage(const std::string& why);

}  // namespace plumb::las
