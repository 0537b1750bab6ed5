#include "io/las/las_header.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "common/error.hpp"
#include "io/las/las_bytes.hpp"

namespace plumb::las {

PointLayout pointLayout(int format) {
  PointLayout l;
  l.format = format;
  switch (format) {
    case 0: l.min_size = 20; break;
    case 1: l.min_size = 28; l.gps_at = 20; break;
    case 2: l.min_size = 26; l.rgb_at = 20; break;
    case 3: l.min_size = 34; l.gps_at = 20; l.rgb_at = 28; break;
    case 4: l.min_size = 57; l.gps_at = 20; l.wave_at = 28; break;
    case 5: l.min_size = 63; l.gps_at = 20; l.rgb_at = 28; l.wave_at = 34; break;
    case 6: l.min_size = 30; break;
    case 7: l.min_size = 36; l.rgb_at = 30; break;
    case 8: l.min_size = 38; l.rgb_at = 30; l.nir_at = 36; break;
    case 9: l.min_size = 59; l.wave_at = 30; break;
    case 10: l.min_size = 67; l.rgb_at = 30; l.nir_at = 36; l.wave_at = 38; break;
    default: throw std::out_of_range("LAS point format " + std::to_string(format));
  }
  if (format >= 6) {
    l.extended = true;
    l.gps_at = 22;
  }
  return l;
}

bool formatAllowedInVersion(int format, int minor) {
  if (minor <= 2) return format <= 3;
  if (minor == 3) return format <= 5;
  return format <= 10;
}

std::string lazMessage(const std::string& why) {
  return "is LAZ-compressed (" + why +
         "); Plumb reads uncompressed LAS only: decompress it first, e.g. "
         "'laszip -i FILE.laz -o FILE.las' or 'las2las -i FILE.laz -o FILE.las' (LAStools), "
         "or 'pdal translate FILE.laz FILE.las'";
}

namespace {
std::string str(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// The FileError of a header field at byte `offset`.
[[noreturn]] void headerError(const std::filesystem::path& file, std::uint64_t offset, const std::string& msg) {
  throw FileError(file, msg, atByte(offset, "LAS header"));
}
}  // namespace

void checkSignatureAndSize(std::span<const std::uint8_t> bytes, std::uint64_t file_size,
                           const std::filesystem::path& file) {
  if (bytes.size() < 4 || load<std::uint32_t>(bytes.data()) != 0x4653414Cu /* "LASF" */) {
    std::string sig;
    for (std::size_t i = 0; i < bytes.size() && i < 4; ++i)
      sig += (bytes[i] >= 32 && bytes[i] < 127) ? static_cast<char>(bytes[i]) : '?';
    headerError(file, 0, "not a LAS file: signature is '" + sig + "' instead of 'LASF'");
  }
  if (bytes.size() < kHeaderSize12)
    headerError(file, bytes.size(), "truncated LAS header: the file has " + std::to_string(file_size) +
                                        " bytes, a LAS header needs at least 227");
}

LasHeader loadHeaderFields(const std::uint8_t* p) {
  LasHeader h;
  h.file_source_id = load<std::uint16_t>(p + 4);
  h.global_encoding = load<std::uint16_t>(p + 6);
  std::memcpy(h.guid.data(), p + 8, 16);
  h.version_major = p[24];
  h.version_minor = p[25];
  h.system_identifier = loadText(p + 26, 32);
  h.generating_software = loadText(p + 58, 32);
  h.creation_day = load<std::uint16_t>(p + 90);
  h.creation_year = load<std::uint16_t>(p + 92);
  h.header_size = load<std::uint16_t>(p + 94);
  h.offset_to_points = load<std::uint32_t>(p + 96);
  h.vlr_count = load<std::uint32_t>(p + 100);
  h.format_byte = p[104];
  h.record_length = load<std::uint16_t>(p + 105);
  h.legacy_count = load<std::uint32_t>(p + 107);
  for (int i = 0; i < 5; ++i) h.legacy_by_return[i] = load<std::uint32_t>(p + 111 + 4 * i);
  for (int a = 0; a < 3; ++a) {
    h.scale[a] = load<double>(p + 131 + 8 * a);
    h.offset[a] = load<double>(p + 155 + 8 * a);
    h.max[a] = load<double>(p + 179 + 16 * a);  // max before min, per axis
    h.min[a] = load<double>(p + 187 + 16 * a);
  }
  return h;
}

void checkVersionAndHeaderSize(const LasHeader& h, std::size_t available, std::uint64_t file_size,
                               const std::filesystem::path& file) {
  if (h.version_major != 1 || h.version_minor > 4)
    headerError(file, at::kVersion, "unsupported LAS version " + std::to_string(h.version_major) + "." +
                                        std::to_string(h.version_minor) + " (Plumb reads 1.0 to 1.4)");
  const std::size_t min_header = h.version_minor >= 4   ? kHeaderSize14
                                 : h.version_minor == 3 ? kHeaderSize13
                                                        : kHeaderSize12;
  if (h.header_size < min_header)
    headerError(file, at::kHeaderSize, "header size " + std::to_string(h.header_size) + " is below the " +
                                           std::to_string(min_header) + " bytes LAS 1." +
                                           std::to_string(h.version_minor) + " requires");
  if (h.header_size > file_size || h.header_size > available)
    headerError(file, at::kHeaderSize, "header size " + std::to_string(h.header_size) +
                                           " runs past the end of the file (" + std::to_string(file_size) +
                                           " bytes): truncated file");
}

void loadVersionFields(LasHeader& h, const std::uint8_t* p) {
  if (h.version_minor >= 3) h.waveform_start = load<std::uint64_t>(p + 227);
  if (h.version_minor >= 4) {
    h.evlr_start = load<std::uint64_t>(p + 235);
    h.evlr_count = load<std::uint32_t>(p + 243);
    h.count64 = load<std::uint64_t>(p + 247);
    for (int i = 0; i < 15; ++i) h.by_return[i] = load<std::uint64_t>(p + 255 + 8 * i);
  }
}

void checkPointFormat(LasHeader& h, const std::filesystem::path& file) {
  if (h.compressed())
    headerError(file, at::kFormat, lazMessage("point format byte is " + std::to_string(h.format_byte) +
                                              ", compression bit set"));
  const int format = h.format();
  if (format > 10)
    headerError(file, at::kFormat, "unknown point data record format " + std::to_string(format) +
                                       " (LAS defines 0 to 10)");
  if (!formatAllowedInVersion(format, h.version_minor))
    h.warnings.push_back("point format " + std::to_string(format) + " is not defined for LAS 1." +
                         std::to_string(h.version_minor) + "; read anyway");
  const PointLayout layout = pointLayout(format);
  if (h.record_length < layout.min_size)
    headerError(file, at::kRecordLength, "point record length " + std::to_string(h.record_length) +
                                             " is shorter than the " + std::to_string(layout.min_size) +
                                             " bytes of point format " + std::to_string(format));
}

void checkScaleAndOffset(const LasHeader& h, const std::filesystem::path& file) {
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(h.scale[a]) || h.scale[a] == 0.0)
      headerError(file, at::kScale + 8 * a, std::string("scale factor of ") + "XYZ"[a] + " is " +
                                                str(h.scale[a]) + " (must be finite and non-zero)");
    if (!std::isfinite(h.offset[a]))
      headerError(file, at::kOffset + 8 * a, std::string("offset of ") + "XYZ"[a] + " is not finite");
  }
}

void checkOffsetToPoints(const LasHeader& h, std::uint64_t file_size, const std::filesystem::path& file) {
  if (h.offset_to_points < h.header_size)
    headerError(file, at::kOffsetToPoints, "offset to point data " + std::to_string(h.offset_to_points) +
                                               " is inside the header (" + std::to_string(h.header_size) +
                                               " bytes)");
  if (h.offset_to_points > file_size)
    headerError(file, at::kOffsetToPoints, "offset to point data " + std::to_string(h.offset_to_points) +
                                               " is past the end of the file (" + std::to_string(file_size) +
                                               " bytes): truncated file");
}

std::uint64_t choosePointCount(LasHeader& h) {
  // Point count (LAS_FACTS section 2): 1.4 uses the 64-bit count unless a non-zero legacy
  // count disagrees, in which case the spec says to trust the legacy one.
  h.point_count = h.legacy_count;
  if (h.version_minor < 4) return at::kLegacyCount;
  if (h.legacy_count == 0 || h.legacy_count == h.count64) {
    h.point_count = h.count64;
    return at::kCount64;
  }
  h.warnings.push_back("legacy point count " + std::to_string(h.legacy_count) +
                       " disagrees with the 64-bit count " + std::to_string(h.count64) +
                       "; using the legacy count as the LAS 1.4 specification says");
  return at::kLegacyCount;
}

void checkPointCount(const LasHeader& h, std::uint64_t count_at, std::uint64_t file_size,
                     const std::filesystem::path& file) {
  // Point records end at the EVLRs when a 1.4 file has them after the points, else at the end.
  const std::uint64_t end =
      (h.version_minor >= 4 && h.evlr_count > 0 && h.evlr_start > h.offset_to_points &&
       h.evlr_start <= file_size)
          ? h.evlr_start
          : file_size;
  const std::uint64_t room = end - h.offset_to_points;
  if (h.point_count > room / h.record_length)
    headerError(file, count_at, "header declares " + std::to_string(h.point_count) + " points of " +
                                    std::to_string(h.record_length) + " bytes from byte " +
                                    std::to_string(h.offset_to_points) + ", but only " +
                                    std::to_string(room) + " bytes of point data exist (truncated file or " +
                                    "wrong count)");
}

LasHeader parseHeader(std::span<const std::uint8_t> bytes, std::uint64_t file_size,
                      const std::filesystem::path& file) {
  checkSignatureAndSize(bytes, file_size, file);
  LasHeader h = loadHeaderFields(bytes.data());
  checkVersionAndHeaderSize(h, bytes.size(), file_size, file);
  loadVersionFields(h, bytes.data());
  checkPointFormat(h, file);
  checkScaleAndOffset(h, file);
  checkOffsetToPoints(h, file_size, file);
  const std::uint64_t count_at = choosePointCount(h);
  checkPointCount(h, count_at, file_size, file);
  if (h.format() >= 6 && !(h.global_encoding & 0x10))
    h.warnings.push_back("point format " + std::to_string(h.format()) +
                         " requires the WKT bit of the global encoding, which is clear");
  return h;
}

std::vector<std::uint8_t> serializeHeader(const LasHeader& h) {
  std::vector<std::uint8_t> out(h.header_size, 0);
  std::uint8_t* p = out.data();
  std::memcpy(p, "LASF", 4);
  store<std::uint16_t>(p + 4, h.file_source_id);
  store<std::uint16_t>(p + 6, h.global_encoding);
  std::memcpy(p + 8, h.guid.data(), 16);
  p[24] = h.version_major;
  p[25] = h.version_minor;
  storeText(p + 26, 32, h.system_identifier);
  storeText(p + 58, 32, h.generating_software);
  store<std::uint16_t>(p + 90, h.creation_day);
  store<std::uint16_t>(p + 92, h.creation_year);
  store<std::uint16_t>(p + 94, h.header_size);
  store<std::uint32_t>(p + 96, h.offset_to_points);
  store<std::uint32_t>(p + 100, h.vlr_count);
  p[104] = h.format_byte;
  store<std::uint16_t>(p + 105, h.record_length);
  store<std::uint32_t>(p + 107, h.legacy_count);
  for (int i = 0; i < 5; ++i) store<std::uint32_t>(p + 111 + 4 * i, h.legacy_by_return[i]);
  for (int a = 0; a < 3; ++a) {
    store<double>(p + 131 + 8 * a, h.scale[a]);
    store<double>(p + 155 + 8 * a, h.offset[a]);
    store<double>(p + 179 + 16 * a, h.max[a]);
    store<double>(p + 187 + 16 * a, h.min[a]);
  }
  if (h.header_size >= kHeaderSize13) store<std::uint64_t>(p + 227, h.waveform_start);
  if (h.header_size >= kHeaderSize14) {
    store<std::uint64_t>(p + 235, h.evlr_start);
    store<std::uint32_t>(p + 243, h.evlr_count);
    store<std::uint64_t>(p + 247, h.count64);
    for (int i = 0; i < 15; ++i) store<std::uint64_t>(p + 255 + 8 * i, h.by_return[i]);
  }
  return out;
}

}  // namespace plumb::las
