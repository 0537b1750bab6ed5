#pragma once
// E57 writer. Each Scan becomes one data3D entry with its pose (normalised double quaternion +
// translation), a new GUID (the one the scan was read with kept in originalGuids), name, description (String values
// with bytes XML cannot carry replaced by U+FFFD), cartesianBounds (of the stored, quantized
// values), and a point prototype of: cartesianX/Y/Z as ScaledInteger with quantum `scaled_precision`
// (limits from the data, so bits = ceil(log2(range/precision + 1))) or as Float double;
// cartesianInvalidState (only when some position is not finite: those points are written as
// invalid); intensity (Integer when every value is a whole number, else Float single, with
// intensityLimits); colorRed/Green/Blue Integer 0..255 with colorLimits (and isColorInvalid
// from color_invalid); rowIndex/columnIndex
// with indexBounds (all six children, as E57RefImpl tools require); returnIndex (0-based)
// and returnCount; timeStamp (Float double); normals as the nor:normalX/Y/Z extension.
// Classification, the other LAS fields and custom scalar fields have no standard E57 field:
// they are written as extension fields in Plumb's namespace and read back by Plumb
// (e57_extension_fields.hpp); other readers skip them.
// The file is streamed (one packet and one page in memory), has no index packets and writes
// empty scans in the form both libE57Format 3.x and E57RefImpl tools read (docs/E57_FORMAT.md
// pitfall 8), and is replaced atomically.
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/progress.hpp"
#include "model/dataset.hpp"

namespace plumb {

struct E57WriteOptions {
  /// Position quantum in metres for ScaledInteger coordinates (default 0.1 mm). Valid range
  /// 1e-9 .. 1.
  double scaled_precision = 1e-4;
  /// Write positions as Float double instead of ScaledInteger.
  bool float_positions = false;
};

void writeE57(const std::filesystem::path& path, const Dataset& data,
              const E57WriteOptions& options = {}, Progress* progress = nullptr);

/// The same file written one scan at a time (writeE57 uses it): a scan's binary section is
/// written when the scan is given, the XML (every scan's pose, limits, prototype) at
/// finish(), so memory is the largest scan, never the campaign. The target is replaced only
/// by finish(); destroyed before, nothing is left (AtomicFileWriter).
class E57StreamWriter {
 public:
  E57StreamWriter(const std::filesystem::path& path, const E57WriteOptions& options = {});
  ~E57StreamWriter();
  E57StreamWriter(const E57StreamWriter&) = delete;
  E57StreamWriter& operator=(const E57StreamWriter&) = delete;
  /// Writes one scan (validated first); the caller may release it afterwards.
  void writeScan(const Scan& scan, Progress* progress = nullptr);
  /// The XML (a new file GUID: every written file is a new file, never the source's) and the
  /// header; commits.
  void finish(const std::string& coordinate_system);
  std::uint64_t points() const { return points_; }
  std::size_t scans() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::uint64_t points_ = 0;
};

}  // namespace plumb
