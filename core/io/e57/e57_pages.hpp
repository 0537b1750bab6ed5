#pragma once
// The E57 paged file layer (docs/E57_FORMAT.md §1-4): the file is a sequence of 1024-byte pages,
// each 1020 bytes of payload followed by a big-endian CRC-32C of that payload. Offsets stored
// in the file are physical; lengths are logical (CRCs not counted). PagedReader reads logical
// bytes and verifies the CRC of every page it touches (once per page).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace plumb::e57 {

constexpr std::uint64_t kPageSize = 1024;
constexpr std::uint64_t kPagePayload = 1020;

inline std::uint64_t physicalToLogical(std::uint64_t physical) {
  const std::uint64_t in_page = physical % kPageSize;
  return (physical / kPageSize) * kPagePayload + (in_page < kPagePayload ? in_page : kPagePayload);
}
inline std::uint64_t logicalToPhysical(std::uint64_t logical) {
  return (logical / kPagePayload) * kPageSize + logical % kPagePayload;
}
/// True when a physical offset points into the 4 CRC bytes at the end of a page.
inline bool isInChecksum(std::uint64_t physical) { return physical % kPageSize >= kPagePayload; }

/// Random access to raw bytes (a file or a memory buffer).
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual std::uint64_t size() const = 0;
  /// Copies bytes [offset, offset+n); throws FileError on I/O errors or if out of range.
  virtual void read(std::uint64_t offset, std::size_t n, std::uint8_t* dst) const = 0;
};

/// A file opened for positional reads. Throws FileError if it cannot be opened.
std::unique_ptr<ByteSource> openFileSource(const std::filesystem::path& path);
/// A non-owning view of bytes in memory (must outlive the source).
std::unique_ptr<ByteSource> memorySource(const void* data, std::size_t size);

class PagedReader {
 public:
  /// `file` names the source in error messages. The source size must be a whole number of
  /// pages (checked by the caller, which can give a better message).
  PagedReader(const ByteSource& source, std::filesystem::path file);

  const std::filesystem::path& file() const { return file_; }
  std::uint64_t physicalSize() const { return source_.size(); }
  std::uint64_t logicalSize() const { return page_count_ * kPagePayload; }

  /// Reads n logical bytes from `logical`, checking the CRC of every page involved. `what`
  /// names the structure being read for error messages. Throws FileError.
  void readLogical(std::uint64_t logical, std::size_t n, std::uint8_t* dst, const char* what);

  [[noreturn]] void fail(const std::string& message, FileLocation where) const;

 private:
  void verifyPage(std::uint64_t page, const std::uint8_t* bytes);

  const ByteSource& source_;
  std::filesystem::path file_;
  std::uint64_t page_count_;
  std::vector<std::uint8_t> verified_;  ///< one flag per page
  std::vector<std::uint8_t> chunk_;     ///< physical pages being copied
};

}  // namespace plumb::e57
