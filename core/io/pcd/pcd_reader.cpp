// readPcd: our header checks in this process, PCL's reader in the plumb-import helper process,
// the records converted straight from the helper's stream (pcd_io.hpp).
#include <algorithm>
#include <csignal>
#include <sstream>
#include <system_error>

#include "common/error.hpp"
#include "io/isolation/helper_failure.hpp"
#include "io/isolation/import_process.hpp"
#include "io/pcd/pcd_convert.hpp"
#include "io/pcd/pcd_header.hpp"
#include "io/pcd/pcd_io.hpp"
#include "io/pcd/pcd_stream.hpp"

namespace plumb {
namespace {

const helper_failure::Wording kWording{
    "reading this PCD file with PCL", "the PCD import (PCL)",
    "; Plumb itself is unaffected. The limit is " + std::to_string(static_cast<int>(kPcdBaseSeconds)) +
        " s + 1 s per " + std::to_string(static_cast<int>(kPcdBytesPerSecond / 1e6)) +
        " MB of file; raise it with PLUMB_IMPORT_TIMEOUT=SECONDS, or check that the file is not damaged",
    "; Plumb itself is unaffected", "split the cloud"};

helper_failure::Limits limitsFor(const std::filesystem::path& path) {
  const double size = static_cast<double>(std::filesystem::file_size(path));
  return helper_failure::environmentLimits(kPcdBaseSeconds + size / kPcdBytesPerSecond,
                                           helper_failure::defaultMemoryMib());
}

/// Bytes of the helper's stream: the records (< 2^52: checkPcdFile bounded both factors), plus
/// the layout (at most 8 bytes per header byte: a field named in n characters is encoded in
/// n + 13 bytes) and the framing; never more than the helper may hold.
std::size_t expectedStream(const PcdHeader& h, const helper_failure::Limits& limits) {
  const std::uint64_t bytes = h.points * h.recordSize() + 8 * h.data_offset + 4096;
  const std::uint64_t most = limits.memory_mib ? std::uint64_t{limits.memory_mib} << 20 : bytes;
  return static_cast<std::size_t>(std::min(bytes, most));
}

[[noreturn]] void crashed(const std::filesystem::path& path, const import_process::Outcome& o) {
  const std::string note = helper_failure::lastLine(o.error_tail);
  throw FileError(path, "PCL crashed (" + helper_failure::signalName(o.signal) + ") reading this file" +
                            (o.signal == SIGABRT && !note.empty() ? " (" + note + ")" : "") +
                            "; Plumb itself is unaffected. The file is probably damaged: write it again with "
                            "the program that made it, or convert it to PLY or E57");
}

import_process::Outcome runHelper(const std::filesystem::path& path, const PcdHeader& header,
                                  const helper_failure::Limits& limits, Progress* progress) {
  const auto helper = helper_failure::helperOrThrow(path, "read PCD files");
  try {
    return import_process::run(
        {helper, {"--pcd"}, path, limits.seconds, limits.memory_mib, expectedStream(header, limits)}, progress);
  } catch (const std::system_error& e) {  // no pipe, no process
    throw FileError(path, "cannot run the PCD import helper " + helper.string() + ": " + e.what());
  }
}

/// The helper's stream decoded, or the FileError it or the helper's end describe.
pcd_stream::Cloud decodeOutcome(const std::filesystem::path& path, const import_process::Outcome& o,
                                const helper_failure::Limits& limits) {
  return helper_failure::resultOrThrow(path, o, "the PCD import helper", pcd_stream::decode, [&] {
    helper_failure::raise(path, o, limits, kWording, [&](const import_process::Outcome& out) { crashed(path, out); });
  });
}

}  // namespace

Dataset readPcd(const std::filesystem::path& path, Progress* progress) {
  const PcdHeader header = checkPcdFile(path);
  reportProgress(progress, 0.05, "reading PCD");
  const auto limits = limitsFor(path);
  const import_process::Outcome outcome = runHelper(path, header, limits, progress);
  reportProgress(progress, 0.7, "converting PCD");
  const pcd_stream::Cloud cloud = decodeOutcome(path, outcome, limits);
  Dataset d = pcdToDataset(path, header.data, cloud.layout, cloud.points);
  reportProgress(progress, 1.0, "reading PCD");
  return d;
}

}  // namespace plumb
