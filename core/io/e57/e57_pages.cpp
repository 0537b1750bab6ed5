#include "io/e57/e57_pages.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "io/e57/crc32c.hpp"

namespace plumb::e57 {
namespace {

class FileSource final : public ByteSource {
 public:
  explicit FileSource(const std::filesystem::path& path) : path_(path) {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw FileError(path, std::string("cannot open: ") + std::strerror(errno));
    const off_t end = ::lseek(fd_, 0, SEEK_END);
    if (end < 0) {
      const int err = errno;
      ::close(fd_);
      throw FileError(path, std::string("cannot determine the file size: ") + std::strerror(err));
    }
    size_ = static_cast<std::uint64_t>(end);
  }
  ~FileSource() override { ::close(fd_); }
  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;

  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::size_t n, std::uint8_t* dst) const override {
    if (offset > size_ || n > size_ - offset)
      throw FileError(path_, "read past the end of the file", atByte(offset));
    while (n > 0) {
      const ssize_t got = ::pread(fd_, dst, n, static_cast<off_t>(offset));
      if (got < 0) {
        if (errno == EINTR) continue;
        throw FileError(path_, std::string("read error: ") + std::strerror(errno), atByte(offset));
      }
      if (got == 0) throw FileError(path_, "file shrank while reading", atByte(offset));
      dst += got;
      offset += static_cast<std::uint64_t>(got);
      n -= static_cast<std::size_t>(got);
    }
  }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

class MemorySource final : public ByteSource {
 public:
  MemorySource(const void* data, std::size_t size)
      : data_(static_cast<const std::uint8_t*>(data)), size_(size) {}
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::size_t n, std::uint8_t* dst) const override {
    if (offset > size_ || n > size_ - offset)
      throw FileError("<memory>", "read past the end of the buffer", atByte(offset));
    if (n) std::memcpy(dst, data_ + offset, n);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
};

constexpr std::uint64_t kChunkPages = 64;

}  // namespace

std::unique_ptr<ByteSource> openFileSource(const std::filesystem::path& path) {
  return std::make_unique<FileSource>(path);
}

std::unique_ptr<ByteSource> memorySource(const void* data, std::size_t size) {
  return std::make_unique<MemorySource>(data, size);
}

PagedReader::PagedReader(const ByteSource& source, std::filesystem::path file)
    : source_(source), file_(std::move(file)), page_count_(source.size() / kPageSize),
      verified_(page_count_, 0) {}

void PagedReader::fail(const std::string& message, FileLocation where) const {
  throw FileError(file_, message, std::move(where));
}

void PagedReader::verifyPage(std::uint64_t page, const std::uint8_t* bytes) {
  if (verified_[page]) return;
  const std::uint32_t computed = crc32c(bytes, kPagePayload);
  const std::uint8_t* s = bytes + kPagePayload;  // stored big-endian (pitfall 2)
  const std::uint32_t stored = (std::uint32_t{s[0]} << 24) | (std::uint32_t{s[1]} << 16) |
                               (std::uint32_t{s[2]} << 8) | std::uint32_t{s[3]};
  if (computed != stored) {
    std::ostringstream msg;
    msg << "page checksum mismatch (CRC-32C stored 0x" << std::hex << stored << ", computed 0x"
        << computed << "): the file is corrupted";
    fail(msg.str(), atByte(page * kPageSize, "page " + std::to_string(page)));
  }
  verified_[page] = 1;
}

void PagedReader::readLogical(std::uint64_t logical, std::size_t n, std::uint8_t* dst,
                              const char* what) {
  if (n == 0) return;
  const std::uint64_t size = logicalSize();
  if (logical > size || n > size - logical) {
    std::ostringstream msg;
    msg << what << " extends past the end of the file (" << n << " bytes at logical offset "
        << logical << ", file holds " << size << " logical bytes)";
    fail(msg.str(), atByte(logicalToPhysical(std::min(logical, size)), what));
  }
  std::uint64_t page = logical / kPagePayload;
  std::size_t in_page = static_cast<std::size_t>(logical % kPagePayload);
  const std::uint64_t last_page = (logical + n - 1) / kPagePayload;
  while (page <= last_page) {
    const std::uint64_t pages = std::min<std::uint64_t>(kChunkPages, last_page - page + 1);
    chunk_.resize(static_cast<std::size_t>(pages * kPageSize));
    source_.read(page * kPageSize, chunk_.size(), chunk_.data());
    for (std::uint64_t k = 0; k < pages; ++k) {
      const std::uint8_t* bytes = chunk_.data() + k * kPageSize;
      verifyPage(page + k, bytes);
      const std::size_t take = std::min<std::size_t>(n, kPagePayload - in_page);
      std::memcpy(dst, bytes + in_page, take);
      dst += take;
      n -= take;
      in_page = 0;
    }
    page += pages;
  }
}

}  // namespace plumb::e57
