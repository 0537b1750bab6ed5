// libFuzzer target for the PCD reader (tests/fuzz/CMakeLists.txt explains the convention).
// readPcd runs PCL in the plumb-import helper, where libFuzzer cannot see, so this target runs
// both halves in its own process:
//   1. the in-process read: our header and size checks, PCL's PCDReader (not instrumented:
//      fuzz_pcd.cmake links the installed PCL; its heap corruption shows up later as an ASan
//      report on our side) and the conversion (readPcdInProcess);
//   2. the stream: what PCL read, encoded as plumb-import --pcd sends it (pcd_stream), decoded
//      and converted as readPcd does; it must give the same points as 1;
//   3. the decoder on the raw input bytes, as if the helper had sent them (a damaged stream
//      must be a std::runtime_error, never undefined behaviour);
//   4. the streaming reader (streamPcd: binary records and our own LZF decoder, 4096-point
//      chunks): it must stream or raise FileError, and when PCL read the file, stream the
//      same number of points.
// Any input must either read or raise plumb::FileError. PLUMB_FUZZ_PCD_HEADER_ONLY=1 fuzzes
// only our checks (checkPcdHeader). Runs so far: tests/unit/pcd/regressions/README.md.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "fuzz_input_file.hpp"
#include "io/pcd/helper/pcd_pcl_reader.hpp"
#include "io/pcd/pcd_convert.hpp"
#include "io/pcd/pcd_io.hpp"
#include "io/pcd/pcd_stream.hpp"

namespace {

struct CountPoints final : plumb::ChunkSink {
  std::uint64_t points = 0;
  void chunk(const plumb::PointCloud& c) override { points += c.size(); }
};

/// 4: the points streamPcd hands out; -1 when it does not stream the file, -2 on FileError.
std::int64_t streamedPoints(const std::filesystem::path& path) {
  try {
    plumb::StreamOptions o;
    o.chunk_points = 4096;
    CountPoints sink;
    return plumb::streamPcd(path, o, sink) ? static_cast<std::int64_t>(sink.points) : -1;
  } catch (const plumb::FileError&) {
    return -2;
  }
}

/// 1 and 2: the in-process read, and the same records through the stream.
plumb::Dataset readBothWays(const std::filesystem::path& path, std::int64_t chunks) {
  const plumb::PcdHeader header = plumb::checkPcdFile(path);
  const plumb::PclPcd pcd = plumb::readWithPcl(path, header);
  plumb::Dataset direct = plumb::pcdToDataset(path, header.data, pcd.layout, pcd.points);
  const std::string bytes =
      plumb::fuzz::writtenBytes([&](int fd) { return plumb::pcd_stream::writeCloud(fd, pcd.layout, pcd.points); });
  const auto decoded = plumb::pcd_stream::decode(bytes);
  const auto& cloud = std::get<plumb::pcd_stream::Cloud>(decoded);
  const plumb::Dataset streamed = plumb::pcdToDataset(path, header.data, cloud.layout, cloud.points);
  if (streamed.pointCount() != direct.pointCount() || streamed.metadata != direct.metadata) std::abort();
  // 4, when PCL read the file: the stream must give as many points (-1: not streamed).
  if (chunks != -1 && chunks != static_cast<std::int64_t>(direct.pointCount())) std::abort();
  return direct;
}

/// 3: the input as a helper stream.
void decodeRaw(const std::uint8_t* data, std::size_t size) {
  try {
    const auto out = plumb::pcd_stream::decode({reinterpret_cast<const char*>(data), size});
    if (const auto* cloud = std::get_if<plumb::pcd_stream::Cloud>(&out))
      plumb::pcdToDataset("stream", "binary", cloud->layout, cloud->points);
  } catch (const std::runtime_error&) {  // FileError (no x y z) is one too
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool header_only = std::getenv("PLUMB_FUZZ_PCD_HEADER_ONLY") != nullptr;
  decodeRaw(data, size);
  return plumb::fuzz::readDatasetInput(data, size, ".pcd", [](const auto& path) {
    if (!header_only) {
      const std::int64_t chunks = streamedPoints(path);  // first: whatever PCL says of the file
      return readBothWays(path, chunks);
    }
    plumb::checkPcdHeader(path);
    return plumb::Dataset();
  });
}
