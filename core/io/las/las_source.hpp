#pragma once
// Where the LAS reader gets bytes from: a file (read with pread, bounded buffers) or a
// memory buffer (the fuzzer's and tests' entry). Internal to io/las.
#include <cstdint>
#include <filesystem>
#include <span>

namespace plumb::las {

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual std::uint64_t size() const = 0;
  /// Copies [offset, offset+n) into dst; throws FileError if the bytes cannot be read.
  virtual void read(std::uint64_t offset, std::uint8_t* dst, std::size_t n) const = 0;
  /// The whole content when it is in memory, else nullptr (lets the decoder skip a copy).
  virtual const std::uint8_t* data() const { return nullptr; }
};

class MemorySource final : public ByteSource {
 public:
  MemorySource(std::span<const std::uint8_t> bytes, std::filesystem::path name)
      : bytes_(bytes), name_(std::move(name)) {}
  std::uint64_t size() const override { return bytes_.size(); }
  void read(std::uint64_t offset, std::uint8_t* dst, std::size_t n) const override;
  const std::uint8_t* data() const override { return bytes_.data(); }

 private:
  std::span<const std::uint8_t> bytes_;
  std::filesystem::path name_;
};

class FileSource final : public ByteSource {
 public:
  explicit FileSource(std::filesystem::path path);  ///< throws FileError if it cannot open
  ~FileSource() override;
  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::uint8_t* dst, std::size_t n) const override;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

}  // namespace plumb::las
