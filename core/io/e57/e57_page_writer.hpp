#pragma once
// Writes the E57 logical byte stream as 1024-byte pages with their CRC-32C (docs/E57_FORMAT.md §3),
// streaming: one page is buffered, plus copies of the few pages the caller asked to retain
// because it will patch them later (the file header, section headers). Patching a page that
// was already written recomputes its CRC and rewrites it in place (pitfall 3).
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>

#include "io/e57/e57_pages.hpp"

namespace plumb::e57 {

class PagedWriter {
 public:
  PagedWriter(std::ostream& out, std::filesystem::path file);

  std::uint64_t logicalPosition() const { return page_index_ * kPagePayload + fill_; }
  std::uint64_t physicalPosition() const { return logicalToPhysical(logicalPosition()); }
  void write(const void* data, std::size_t n);
  void writeZeros(std::size_t n);
  /// Keeps a copy of the pages holding logical bytes [logical, logical+n) when they are
  /// flushed, so patch() can change them later. Call before those bytes are written.
  void retain(std::uint64_t logical, std::size_t n);
  /// Overwrites already written logical bytes; they must lie in retained pages or in the
  /// page being filled.
  void patch(std::uint64_t logical, const void* data, std::size_t n);
  /// Zero-fills and writes the last page. Returns the physical file length.
  std::uint64_t finish();

 private:
  void flushPage();
  void emit(std::uint64_t page, std::array<std::uint8_t, kPageSize>& bytes, bool in_place);
  void checkStream() const;

  std::ostream& out_;
  std::filesystem::path file_;
  std::array<std::uint8_t, kPageSize> page_{};
  std::uint64_t page_index_ = 0;
  std::size_t fill_ = 0;
  std::map<std::uint64_t, std::array<std::uint8_t, kPageSize>> retained_;  ///< by page index
};

}  // namespace plumb::e57
