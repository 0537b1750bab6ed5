#include "io/lod/lod_split.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "common/error.hpp"

namespace plumb {
namespace {

std::size_t levelStart(int level) { return ((std::size_t{1} << (3 * level)) - 1) / 7; }

std::string bucketName(const LodKey& k) {
  return "b" + std::to_string(k.depth) + "_" + std::to_string(k.xyz[0]) + "_" + std::to_string(k.xyz[1]) + "_" +
         std::to_string(k.xyz[2]) + ".bin";
}

void appendRecords(const std::filesystem::path& file, const std::vector<LodPoint>& points) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0600);
  if (fd < 0) throw FileError(file, std::string("cannot open a temporary bucket file: ") + std::strerror(errno));
  const char* data = reinterpret_cast<const char*>(points.data());
  std::size_t left = points.size() * sizeof(LodPoint);
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = errno;
      ::close(fd);
      throw FileError(file, std::string("cannot write a temporary bucket file: ") + std::strerror(err));
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  ::close(fd);
}

}  // namespace

LodSplit::LodSplit(const LodGrid& grid, const LodKey& top, int levels, std::size_t capacity,
                   std::filesystem::path dir, std::size_t buffer_points)
    : grid_(grid), top_(top), levels_(levels), capacity_(capacity), buffer_points_(buffer_points),
      dir_(std::move(dir)) {
  nodes_.resize(levelStart(levels_));
  buffers_.resize(std::size_t{1} << (3 * levels_));
  counts_.assign(buffers_.size(), 0);
}

std::size_t LodSplit::nodeIndex(const LodPoint& p, int level) const {
  const int shift = grid_.rootBits() - (top_.depth + level);
  std::size_t index = 0;
  for (int a = 0; a < 3; ++a) {
    const std::size_t local = (p.q[a] >> shift) - (std::size_t{top_.xyz[a]} << level);
    index |= local << (a * level);
  }
  return index;
}

void LodSplit::add(const LodPoint& p) {
  for (int level = 0; level < levels_; ++level) {
    auto& node = nodes_[levelStart(level) + nodeIndex(p, level)];
    if (!node) node = std::make_unique<LodNodeSample>();
    if (node->offer(grid_, top_.depth + level, p, capacity_)) return;
  }
  const std::size_t b = nodeIndex(p, levels_);
  buffers_[b].push_back(p);
  ++counts_[b];
  ++spilled_;
  if (buffers_[b].size() >= buffer_points_) flush(b);
}

void LodSplit::flush(std::size_t bucket) {
  if (buffers_[bucket].empty()) return;
  appendRecords(dir_ / ("split" + std::to_string(top_.depth) + "_" + std::to_string(bucket) + ".tmp"),
                buffers_[bucket]);
  buffers_[bucket].clear();
}

std::vector<LodBucket> LodSplit::finish(LodNodeOutput& out) {
  for (int level = 0; level < levels_; ++level) {
    const std::size_t side = std::size_t{1} << level;
    for (std::size_t i = 0; i < (side << (2 * level)); ++i) {
      auto& node = nodes_[levelStart(level) + i];
      if (!node) continue;
      const std::array<std::size_t, 3> local{i & (side - 1), (i >> level) & (side - 1), i >> (2 * level)};
      LodKey key{top_.depth + level, {}};
      for (int a = 0; a < 3; ++a) key.xyz[a] = static_cast<std::uint32_t>((std::size_t{top_.xyz[a]} << level) + local[a]);
      out.write(key, node->points);
      node.reset();
    }
  }
  std::vector<LodBucket> buckets;
  const std::size_t side = std::size_t{1} << levels_;
  for (std::size_t b = 0; b < buffers_.size(); ++b) {
    if (counts_[b] == 0) continue;
    flush(b);
    std::vector<LodPoint>().swap(buffers_[b]);
    LodBucket bucket;
    bucket.key.depth = top_.depth + levels_;
    const std::array<std::size_t, 3> local{b & (side - 1), (b >> levels_) & (side - 1), b >> (2 * levels_)};
    for (int a = 0; a < 3; ++a)
      bucket.key.xyz[a] = static_cast<std::uint32_t>((std::size_t{top_.xyz[a]} << levels_) + local[a]);
    bucket.file = dir_ / bucketName(bucket.key);
    std::filesystem::rename(dir_ / ("split" + std::to_string(top_.depth) + "_" + std::to_string(b) + ".tmp"),
                            bucket.file);
    bucket.count = counts_[b];
    buckets.push_back(std::move(bucket));
  }
  return buckets;
}

std::vector<LodPoint> readLodBucketBlock(const LodBucket& bucket, std::uint64_t first, std::size_t n) {
  const std::uint64_t count = std::min<std::uint64_t>(n, bucket.count - first);
  std::vector<LodPoint> points(count);
  const int fd = ::open(bucket.file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw FileError(bucket.file, std::string("cannot open a temporary bucket file: ") + std::strerror(errno));
  char* data = reinterpret_cast<char*>(points.data());
  std::uint64_t done = 0;
  const std::uint64_t want = count * sizeof(LodPoint);
  while (done < want) {
    const ssize_t r = ::pread(fd, data + done, want - done, static_cast<off_t>(first * sizeof(LodPoint) + done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    done += static_cast<std::uint64_t>(r);
  }
  ::close(fd);
  if (done != want)
    throw FileError(bucket.file, "temporary bucket file is shorter than the points written to it",
                    atByte(first * sizeof(LodPoint) + done));
  return points;
}

std::vector<LodPoint> readLodBucket(const LodBucket& bucket) {
  std::vector<LodPoint> points = readLodBucketBlock(bucket, 0, bucket.count);
  std::filesystem::remove(bucket.file);
  return points;
}

}  // namespace plumb
