#include "io/e57/e57_header.hpp"

#include <cstring>
#include <string>

namespace plumb::e57 {
namespace {
constexpr char kSignature[8] = {'A', 'S', 'T', 'M', '-', 'E', '5', '7'};

template <class T>
void put(std::uint8_t* p, T v) {
  std::memcpy(p, &v, sizeof v);  // little-endian host
}
template <class T>
T get(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
}  // namespace

std::array<std::uint8_t, kHeaderSize> encodeHeader(const FileHeader& h) {
  std::array<std::uint8_t, kHeaderSize> b{};
  std::memcpy(b.data(), kSignature, 8);
  put(b.data() + 8, h.major);
  put(b.data() + 12, h.minor);
  put(b.data() + 16, h.physical_length);
  put(b.data() + 24, h.xml_physical_offset);
  put(b.data() + 32, h.xml_logical_length);
  put(b.data() + 40, h.page_size);
  return b;
}

FileHeader readHeader(const ByteSource& source, PagedReader& file) {
  const std::uint64_t size = source.size();
  if (size < kHeaderSize) file.fail("too small to be an E57 file (" + std::to_string(size) + " bytes)", atByte(0));
  std::uint8_t raw[kHeaderSize];
  source.read(0, kHeaderSize, raw);
  if (std::memcmp(raw, kSignature, 8) != 0) file.fail("not an E57 file (no ASTM-E57 signature)", atByte(0, "header"));
  FileHeader h;
  h.major = get<std::uint32_t>(raw + 8);
  h.minor = get<std::uint32_t>(raw + 12);
  h.physical_length = get<std::uint64_t>(raw + 16);
  h.xml_physical_offset = get<std::uint64_t>(raw + 24);
  h.xml_logical_length = get<std::uint64_t>(raw + 32);
  h.page_size = get<std::uint64_t>(raw + 40);
  if (h.major > 1 || (h.major == 1 && h.minor > 0))
    file.fail("unsupported E57 version " + std::to_string(h.major) + "." + std::to_string(h.minor),
              atByte(8, "header"));
  if (h.page_size != kPageSize)
    file.fail("unsupported page size " + std::to_string(h.page_size) + " (expected 1024)",
              atByte(40, "header"));
  if (size % kPageSize != 0)
    file.fail("file size " + std::to_string(size) +
                  " is not a whole number of 1024-byte pages (truncated or damaged)",
              atByte(size));
  if (h.physical_length != size)
    file.fail("header says the file is " + std::to_string(h.physical_length) + " bytes but it is " +
                  std::to_string(size) + " (truncated or damaged)",
              atByte(16, "header"));
  std::uint8_t checked[kHeaderSize];
  file.readLogical(0, kHeaderSize, checked, "file header");  // verifies page 0's CRC
  if (h.xml_physical_offset >= size || isInChecksum(h.xml_physical_offset) ||
      physicalToLogical(h.xml_physical_offset) < kHeaderSize)
    file.fail("XML section offset " + std::to_string(h.xml_physical_offset) + " is invalid",
              atByte(24, "header"));
  const std::uint64_t xml_logical = physicalToLogical(h.xml_physical_offset);
  if (h.xml_logical_length == 0 || h.xml_logical_length > file.logicalSize() - xml_logical)
    file.fail("XML section length " + std::to_string(h.xml_logical_length) +
                  " extends past the end of the file",
              atByte(32, "header"));
  return h;
}

}  // namespace plumb::e57
