#pragma once
// The 48-byte E57 file header (docs/E57_FORMAT.md §2).
#include <array>
#include <cstdint>

#include "io/e57/e57_pages.hpp"

namespace plumb::e57 {

struct FileHeader {
  std::uint32_t major = 1;
  std::uint32_t minor = 0;
  std::uint64_t physical_length = 0;
  std::uint64_t xml_physical_offset = 0;
  std::uint64_t xml_logical_length = 0;
  std::uint64_t page_size = kPageSize;
};

constexpr std::size_t kHeaderSize = 48;

std::array<std::uint8_t, kHeaderSize> encodeHeader(const FileHeader& h);

/// Reads and validates the header of `file` (signature, version, length, page size, XML
/// location) including page 0's CRC. Throws FileError.
FileHeader readHeader(const ByteSource& source, PagedReader& file);

}  // namespace plumb::e57
