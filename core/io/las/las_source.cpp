#include "io/las/las_source.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "common/error.hpp"

namespace plumb::las {

void MemorySource::read(std::uint64_t offset, std::uint8_t* dst, std::size_t n) const {
  if (offset > bytes_.size() || n > bytes_.size() - offset)
    throw FileError(name_, "unexpected end of data reading " + std::to_string(n) + " bytes",
                    atByte(offset));
  if (n) std::memcpy(dst, bytes_.data() + offset, n);
}

FileSource::FileSource(std::filesystem::path path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw FileError(path_, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    throw FileError(path_, "not a regular file");
  }
  size_ = static_cast<std::uint64_t>(st.st_size);
#ifdef POSIX_FADV_SEQUENTIAL
  ::posix_fadvise(fd_, 0, 0, POSIX_FADV_SEQUENTIAL);
#endif
}

FileSource::~FileSource() {
  if (fd_ >= 0) ::close(fd_);
}

void FileSource::read(std::uint64_t offset, std::uint8_t* dst, std::size_t n) const {
  if (offset > size_ || n > size_ - offset)
    throw FileError(path_, "unexpected end of file reading " + std::to_string(n) + " bytes",
                    atByte(offset));
  std::size_t done = 0;
  while (done < n) {
    const ssize_t r = ::pread(fd_, dst + done, n - done, static_cast<off_t>(offset + done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0)
      throw FileError(path_,
                      r == 0 ? std::string("file shrank while reading")
                             : std::string("read error: ") + std::strerror(errno),
                      atByte(offset + done));
    done += static_cast<std::size_t>(r);
  }
}

}  // namespace plumb::las
