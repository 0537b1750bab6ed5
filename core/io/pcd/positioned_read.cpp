#include "io/pcd/positioned_read.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "common/error.hpp"

namespace plumb {

void readFileAt(int fd, const std::filesystem::path& path, std::uint64_t offset, std::uint8_t* out,
                std::uint64_t n, const char* element) {
  while (n > 0) {
    const ssize_t got = ::pread(fd, out, n, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0)
      throw FileError(path, got < 0 ? std::string("read error: ") + std::strerror(errno) : "truncated data",
                      atByte(offset, element));
    out += got;
    offset += static_cast<std::uint64_t>(got);
    n -= static_cast<std::uint64_t>(got);
  }
}

}  // namespace plumb
