#pragma once
// Builds the XML section of a written E57 file (docs/E57_FORMAT.md §5-6).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/e57/e57_packet_writer.hpp"
#include "model/dataset.hpp"

namespace plumb::e57 {

/// What the writer knows about one written scan.
struct WrittenScan {
  Scan scan;  ///< name, description, pose (no points: the writer may stream scan after scan)
  std::string guid;                         ///< new for every written scan
  std::vector<std::string> original_guids;  ///< the GUID the scan was read with (or its originals)
  std::uint64_t section_offset = 0;  ///< physical
  std::uint64_t records = 0;
  std::vector<FieldSpec> prototype;
  std::optional<Bounds> bounds;  ///< scan frame
  std::optional<std::pair<std::int64_t, std::int64_t>> rows, columns, returns;
  std::optional<std::pair<double, double>> intensity;
  bool intensity_integer = false;
  bool colors = false;
};

std::string buildXml(const std::string& file_guid, const std::string& coordinate_system,
                     const std::vector<WrittenScan>& scans);

/// "{XXXXXXXX-XXXX-XXXX-XXXX-XXXXXXXXXXXX}" from a random source.
std::string newGuid();

}  // namespace plumb::e57
