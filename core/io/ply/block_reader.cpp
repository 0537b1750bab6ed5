#include "io/ply/block_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "common/error.hpp"

namespace plumb::ply {

BlockReader::BlockReader(const std::filesystem::path& path, std::size_t block_size)
    : path_(path), buf_(new char[block_size]), capacity_(block_size) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw FileError(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd_, &st) == 0) file_size_ = static_cast<std::uint64_t>(st.st_size);
  if (S_ISDIR(st.st_mode)) {
    ::close(fd_);
    throw FileError(path, "is a directory, not a file");
  }
  ::posix_fadvise(fd_, 0, 0, POSIX_FADV_SEQUENTIAL);
}

BlockReader::~BlockReader() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t BlockReader::fill(std::size_t n) {
  if (available() >= n || eof_) return available();
  if (n > capacity_) {  // grow (only for pathological records / header lines)
    std::size_t cap = capacity_;
    while (cap < n) cap *= 2;
    std::unique_ptr<char[]> bigger(new char[cap]);
    std::memcpy(bigger.get(), data(), available());
    buf_ = std::move(bigger);
    capacity_ = cap;
  } else if (begin_ > 0) {
    std::memmove(buf_.get(), data(), available());
  }
  base_ += begin_;
  end_ -= begin_;
  begin_ = 0;
  while (end_ < n && !eof_) {
    const ssize_t got = ::read(fd_, buf_.get() + end_, capacity_ - end_);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw FileError(path_, std::string("read error: ") + std::strerror(errno),
                      atByte(base_ + end_));
    }
    if (got == 0) eof_ = true;
    end_ += static_cast<std::size_t>(got);
  }
  return available();
}

void BlockReader::seek(std::uint64_t offset) {
  if (::lseek(fd_, static_cast<off_t>(offset), SEEK_SET) < 0)
    throw FileError(path_, std::string("seek failed: ") + std::strerror(errno), atByte(offset));
  base_ = offset;
  begin_ = end_ = 0;
  eof_ = false;
}

}  // namespace plumb::ply
