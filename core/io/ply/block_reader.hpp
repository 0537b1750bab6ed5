#pragma once
// Sequential file reading in large blocks with read(2): the caller sees a contiguous window of
// the file, asks for more when it has consumed it, and always knows the absolute byte offset.
// Used instead of mmap so the file's pages never count towards the process' resident memory.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>

namespace plumb::ply {

class BlockReader {
 public:
  /// Opens the file; throws FileError if it cannot.
  explicit BlockReader(const std::filesystem::path& path, std::size_t block_size = 4 << 20);
  ~BlockReader();
  BlockReader(const BlockReader&) = delete;
  BlockReader& operator=(const BlockReader&) = delete;

  const char* data() const { return buf_.get() + begin_; }
  std::size_t available() const { return end_ - begin_; }
  /// Absolute file offset of data().
  std::uint64_t offset() const { return base_ + begin_; }
  std::uint64_t fileSize() const { return file_size_; }
  void consume(std::size_t n) { begin_ += n; }
  /// Makes at least `n` bytes available (fewer only at end of file). Returns available().
  std::size_t fill(std::size_t n);
  bool atEnd() const { return available() == 0 && eof_; }
  /// Drops the buffer and continues reading at absolute `offset`.
  void seek(std::uint64_t offset);
  int fd() const { return fd_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::unique_ptr<char[]> buf_;
  std::size_t capacity_ = 0;
  std::size_t begin_ = 0, end_ = 0;
  std::uint64_t base_ = 0;  ///< file offset of buf_[0]
  std::uint64_t file_size_ = 0;
  bool eof_ = false;
};

}  // namespace plumb::ply
