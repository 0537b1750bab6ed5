#include "io/lod/lod_cache.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <limits>

#include "common/error.hpp"

namespace plumb {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kMaxIndexBytes = std::uint64_t{1} << 30;

/// Reads `n` bytes at `offset`; false on a short read.
bool readAt(int fd, char* data, std::uint64_t n, std::uint64_t offset) {
  std::uint64_t done = 0;
  while (done < n) {
    const ssize_t r = ::pread(fd, data + done, n - done, static_cast<off_t>(offset + done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    done += static_cast<std::uint64_t>(r);
  }
  return true;
}

std::string readIndexFile(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw FileError(file, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  std::string bytes;
  const bool sized = ::fstat(fd, &st) == 0 && static_cast<std::uint64_t>(st.st_size) <= kMaxIndexBytes;
  if (sized) bytes.resize(static_cast<std::size_t>(st.st_size));
  const bool ok = sized && readAt(fd, bytes.data(), bytes.size(), 0);
  ::close(fd);
  if (!ok) throw FileError(file, "cannot read the level-of-detail index (or larger than 1 GiB)");
  return bytes;
}

std::string describeChange(const LodSourceStamp& was, const LodSourceStamp& now) {
  if (was.path != now.path) return "built for " + was.path;
  if (was.size != now.size)
    return "size changed from " + std::to_string(was.size) + " to " + std::to_string(now.size) + " bytes";
  return "modification time changed";
}

/// Opens points.plod and checks its size and header against the index.
int openPoints(const fs::path& file, const LodIndex& index) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw FileError(file, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  const std::string expected = lodPointsHeader();
  std::string header(expected.size(), '\0');
  const bool stat_ok = ::fstat(fd, &st) == 0;
  if (!stat_ok || static_cast<std::uint64_t>(st.st_size) != index.points_file_bytes) {
    ::close(fd);
    throw FileError(file, "damaged level-of-detail points: " + std::to_string(stat_ok ? st.st_size : 0) +
                              " bytes, the index says " + std::to_string(index.points_file_bytes));
  }
  if (!readAt(fd, header.data(), header.size(), 0) || header != expected) {
    ::close(fd);
    throw FileError(file, "damaged level-of-detail points: bad signature or version", atByte(0));
  }
  return fd;
}

LodCacheOpenResult notValid(LodCacheState state, std::string reason) {
  LodCacheOpenResult r;
  r.state = state;
  r.reason = std::move(reason);
  return r;
}

}  // namespace

LodCache::LodCache(fs::path directory, LodIndex index, int points_fd)
    : directory_(std::move(directory)), index_(std::move(index)), fd_(points_fd) {}

LodCache::~LodCache() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t LodCache::bytesOnDisk() const {
  std::error_code ec;
  const auto index_bytes = fs::file_size(directory_ / kLodIndexFile, ec);
  return index_.points_file_bytes + (ec ? 0 : index_bytes);
}

LodCacheOpenResult openLodCache(const fs::path& source, const fs::path& cache_root) {
  const fs::path dir = lodCacheDirectory(source, cache_root);
  const fs::path index_file = dir / kLodIndexFile;
  std::error_code ec;
  if (!fs::exists(index_file, ec)) return notValid(LodCacheState::missing, index_file.string() + ": no cache");
  LodIndex index;
  try {
    index = decodeLodIndex(readIndexFile(index_file), index_file);
  } catch (const FileError& e) {
    const bool version = e.message().rfind("format version", 0) == 0;
    return notValid(version ? LodCacheState::version : LodCacheState::damaged, e.what());
  }
  try {
    const LodSourceStamp now = lodSourceStamp(source);
    if (!(now == index.source))
      return notValid(LodCacheState::source_changed, source.string() + ": " + describeChange(index.source, now));
  } catch (const FileError& e) {
    return notValid(LodCacheState::source_changed, e.what());
  }
  try {
    const int fd = openPoints(dir / kLodPointsFile, index);
    LodCacheOpenResult r;
    r.state = LodCacheState::valid;
    r.cache = std::make_shared<const LodCache>(dir, std::move(index), fd);
    return r;
  } catch (const FileError& e) {
    return notValid(LodCacheState::damaged, e.what());
  }
}

}  // namespace plumb
