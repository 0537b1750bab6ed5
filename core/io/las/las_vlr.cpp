#include "io/las/las_vlr.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "io/las/las_bytes.hpp"
#include "io/las/las_source.hpp"

namespace plumb::las {

namespace {
constexpr std::uint64_t kMaxKeptPayload = 16u << 20;  // interpreted records are small

bool interpreted(const std::string& user, std::uint16_t id) {
  if (user == "LASF_Projection") return id == 2112 || id == 34735 || id == 34736 || id == 34737;
  if (user == "LASF_Spec") return id == 4;
  return false;
}

std::string vlrName(const char* kind, std::size_t index) {
  return std::string(kind) + " " + std::to_string(index + 1);
}

// The fields of a 54-byte VLR or 60-byte EVLR header (uint16 vs uint64 length).
LasVlr vlrHeader(const std::uint8_t* p, bool extended, std::uint64_t at) {
  LasVlr v;
  v.extended = extended;
  v.at = at;
  v.user_id = loadText(p + 2, 16);
  v.record_id = load<std::uint16_t>(p + 18);
  v.length = extended ? load<std::uint64_t>(p + 20) : load<std::uint16_t>(p + 20);
  v.description = loadText(p + (extended ? 28 : 22), 32);
  return v;
}
}  // namespace

std::vector<LasVlr> parseVlrs(std::span<const std::uint8_t> prefix, const LasHeader& h,
                              const std::filesystem::path& file) {
  std::vector<LasVlr> out;
  std::uint64_t pos = h.header_size;
  const std::uint64_t end = std::min<std::uint64_t>(h.offset_to_points, prefix.size());
  for (std::uint32_t i = 0; i < h.vlr_count; ++i) {
    if (pos > end || end - pos < kVlrHeaderSize)
      throw FileError(file,
                      "VLR header runs past the start of the point data (byte " +
                          std::to_string(h.offset_to_points) + "); the header declares " +
                          std::to_string(h.vlr_count) + " VLRs",
                      atByte(pos, vlrName("VLR", i)));
    const std::uint8_t* p = prefix.data() + pos;
    LasVlr v = vlrHeader(p, false, pos);
    if (v.length > end - pos - kVlrHeaderSize)
      throw FileError(file,
                      "VLR '" + v.user_id + "' " + std::to_string(v.record_id) + " of " +
                          std::to_string(v.length) + " bytes runs past the start of the point "
                          "data (byte " + std::to_string(h.offset_to_points) + ")",
                      atByte(pos, vlrName("VLR", i)));
    if (interpreted(v.user_id, v.record_id))
      v.payload.assign(p + kVlrHeaderSize, p + kVlrHeaderSize + v.length);
    pos += kVlrHeaderSize + v.length;
    out.push_back(std::move(v));
  }
  return out;
}

void parseEvlrs(const ByteSource& src, const LasHeader& h, const std::filesystem::path& file,
                std::vector<LasVlr>& out, std::vector<std::string>& warnings) {
  if (h.version_minor < 4 || h.evlr_count == 0) return;
  const std::uint64_t size = src.size();
  const std::uint64_t points_end = h.offset_to_points + h.point_count * h.record_length;
  if (h.evlr_start < points_end || h.evlr_start > size) {
    throw FileError(file,
                    "start of first EVLR (" + std::to_string(h.evlr_start) +
                        ") is not between the end of the point data (" +
                        std::to_string(points_end) + ") and the end of the file (" +
                        std::to_string(size) + ")",
                    atByte(at::kEvlrStart, "LAS header"));
  }
  std::uint64_t pos = h.evlr_start;
  for (std::uint32_t i = 0; i < h.evlr_count; ++i) {
    if (size - pos < kEvlrHeaderSize)
      throw FileError(file, "EVLR header runs past the end of the file (truncated file?)",
                      atByte(pos, vlrName("EVLR", i)));
    std::uint8_t hdr[kEvlrHeaderSize];
    src.read(pos, hdr, kEvlrHeaderSize);
    LasVlr v = vlrHeader(hdr, true, pos);
    if (v.length > size - pos - kEvlrHeaderSize)
      throw FileError(file,
                      "EVLR '" + v.user_id + "' " + std::to_string(v.record_id) + " of " +
                          std::to_string(v.length) + " bytes runs past the end of the file",
                      atByte(pos, vlrName("EVLR", i)));
    if (interpreted(v.user_id, v.record_id)) {
      if (v.length <= kMaxKeptPayload) {
        v.payload.resize(v.length);
        src.read(pos + kEvlrHeaderSize, v.payload.data(), v.length);
      } else {
        warnings.push_back("EVLR '" + v.user_id + "' " + std::to_string(v.record_id) +
                           " is too large to interpret (" + std::to_string(v.length) +
                           " bytes); ignored");
      }
    }
    pos += kEvlrHeaderSize + v.length;
    out.push_back(std::move(v));
  }
}

std::size_t extraTypeSize(int type) {
  static constexpr std::size_t sizes[] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
  return (type >= 1 && type <= 10) ? sizes[type] : 0;
}

std::vector<ExtraField> parseExtraBytes(const LasVlr& vlr, std::size_t extra_bytes,
                                        const std::filesystem::path& file,
                                        std::vector<std::string>& warnings) {
  constexpr std::size_t kDesc = 192;
  std::vector<ExtraField> fields;
  if (vlr.payload.size() % kDesc != 0)
    warnings.push_back("Extra Bytes VLR length " + std::to_string(vlr.payload.size()) +
                       " is not a multiple of 192; trailing bytes ignored");
  const std::size_t n = vlr.payload.size() / kDesc;
  std::size_t offset = 0;  // descriptors describe the extra bytes in order
  const std::uint64_t header_len = vlr.extended ? kEvlrHeaderSize : kVlrHeaderSize;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* d = vlr.payload.data() + i * kDesc;
    const int data_type = d[2];
    const int options = d[3];
    const std::string name = loadText(d + 4, 32);
    const std::uint64_t desc_at = vlr.at + header_len + i * kDesc;
    std::size_t elements = 1;
    int base = data_type;
    if (data_type >= 11 && data_type <= 20) elements = 2, base = data_type - 10;
    if (data_type >= 21 && data_type <= 30) elements = 3, base = data_type - 20;
    const std::size_t bytes = data_type == 0 ? static_cast<std::size_t>(options)
                                             : elements * extraTypeSize(base);
    if (data_type > 30 || (data_type == 0 && options == 0))
      throw FileError(file,
                      "Extra Bytes descriptor '" + name + "' has invalid data type " +
                          std::to_string(data_type),
                      atByte(desc_at, "extra bytes descriptor " + std::to_string(i)));
    if (bytes > extra_bytes - std::min(offset, extra_bytes))
      throw FileError(file,
                      "Extra Bytes descriptor '" + name + "' (" + std::to_string(bytes) +
                          " bytes at extra byte " + std::to_string(offset) +
                          ") does not fit the " + std::to_string(extra_bytes) +
                          " extra bytes of each point record",
                      atByte(desc_at, "extra bytes descriptor " + std::to_string(i)));
    if (data_type == 0) {
      warnings.push_back("extra bytes '" + name + "' (" + std::to_string(bytes) +
                         " bytes, undocumented type) ignored");
    } else {
      const bool has_scale = options & 0x08;
      const bool has_offset = options & 0x10;
      for (std::size_t e = 0; e < elements; ++e) {
        ExtraField f;
        f.name = name.empty() ? "extra_" + std::to_string(i) : name;
        if (elements > 1) f.name += "[" + std::to_string(e) + "]";
        f.type = base;
        f.offset = offset + e * extraTypeSize(base);
        if (has_scale) f.scale = load<double>(d + 112 + 8 * e);
        if (has_offset) f.add = load<double>(d + 136 + 8 * e);
        if (!std::isfinite(f.scale) || !std::isfinite(f.add)) {
          warnings.push_back("extra bytes '" + f.name + "' has a non-finite scale/offset; "
                             "raw values kept");
          f.scale = 1.0;
          f.add = 0.0;
        }
        fields.push_back(std::move(f));
      }
    }
    offset += bytes;
  }
  if (offset < extra_bytes)
    warnings.push_back(std::to_string(extra_bytes - offset) +
                       " extra bytes per point are not described by the Extra Bytes VLR; "
                       "ignored");
  return fields;
}

namespace {
std::string trimmedText(const std::vector<std::uint8_t>& payload) {
  std::string s(payload.begin(), payload.end());
  while (!s.empty() && (s.back() == '\0' || std::isspace(static_cast<unsigned char>(s.back()))))
    s.pop_back();
  return s;
}

// GeoKeyDirectoryTag: 4 uint16 header (version, revision, minor, key count) then 4 uint16
// per key (id, tag location, count, value). EPSG codes live inline (location 0).
std::string epsgFromGeoKeys(const std::vector<std::uint8_t>& payload) {
  const std::size_t words = payload.size() / 2;
  if (words < 4) return {};
  const std::size_t keys = std::min<std::size_t>(load<std::uint16_t>(payload.data() + 6),
                                                 (words - 4) / 4);
  std::uint16_t projected = 0, geographic = 0;
  for (std::size_t k = 0; k < keys; ++k) {
    const std::uint8_t* e = payload.data() + 8 + 8 * k;
    const auto id = load<std::uint16_t>(e);
    const auto location = load<std::uint16_t>(e + 2);
    const auto value = load<std::uint16_t>(e + 6);
    if (location != 0 || value == 0 || value == 32767) continue;  // user-defined/elsewhere
    if (id == 3072) projected = value;   // ProjectedCSTypeGeoKey
    if (id == 2048) geographic = value;  // GeographicTypeGeoKey
  }
  const std::uint16_t code = projected ? projected : geographic;
  return code ? "EPSG:" + std::to_string(code) : std::string();
}
}  // namespace

std::string coordinateSystem(const std::vector<LasVlr>& vlrs, const LasHeader& h,
                             std::vector<std::string>& warnings) {
  std::string wkt, epsg, citation;
  int wkt_records = 0, geotiff_records = 0;
  for (const auto& v : vlrs) {
    if (v.user_id != "LASF_Projection" || v.payload.empty()) continue;
    if (v.record_id == 2112) {
      ++wkt_records;
      std::string text = trimmedText(v.payload);
      if (text.find('[') == std::string::npos) {
        warnings.push_back("WKT coordinate system record holds no WKT ('" + text.substr(0, 40) +
                           "'); ignored");
      } else if (wkt.empty()) {
        wkt = std::move(text);
      }
    } else if (v.record_id == 34735) {
      ++geotiff_records;
      if (epsg.empty()) epsg = epsgFromGeoKeys(v.payload);
    } else if (v.record_id == 34737 && citation.empty()) {
      citation = trimmedText(v.payload);
      std::replace(citation.begin(), citation.end(), '|', ' ');
      while (!citation.empty() && citation.back() == ' ') citation.pop_back();
    }
  }
  if (wkt_records > 1 || geotiff_records > 1)
    warnings.push_back("more than one WKT or GeoTIFF coordinate system record; the first is used");
  const bool wkt_bit = h.global_encoding & 0x10;
  if (wkt_bit && !wkt.empty()) return wkt;
  if (!epsg.empty()) return epsg;
  if (!wkt.empty()) return wkt;
  return citation;
}

std::vector<std::uint8_t> serializeVlr(const std::string& user_id, std::uint16_t record_id,
                                       const std::string& description,
                                       std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> out(kVlrHeaderSize + payload.size(), 0);
  storeText(out.data() + 2, 16, user_id);
  store<std::uint16_t>(out.data() + 18, record_id);
  store<std::uint16_t>(out.data() + 20, static_cast<std::uint16_t>(payload.size()));
  storeText(out.data() + 22, 32, description);
  std::copy(payload.begin(), payload.end(), out.begin() + kVlrHeaderSize);
  return out;
}

std::array<std::uint8_t, 192> floatExtraDescriptor(const std::string& name) {
  std::array<std::uint8_t, 192> d{};
  d[2] = 9;  // float
  storeText(d.data() + 4, 32, name);
  storeText(d.data() + 160, 32, name);
  return d;
}

}  // namespace plumb::las
