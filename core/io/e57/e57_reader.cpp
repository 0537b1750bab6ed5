#include "io/e57/e57_reader.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "io/e57/e57_header.hpp"
#include "io/e57/e57_pages.hpp"
#include "io/e57/e57_scan_reader.hpp"
#include "io/e57/e57_xml.hpp"

namespace plumb {
namespace {

Dataset readFromSource(const e57::ByteSource& source, const std::filesystem::path& name,
                       const E57ReadOptions& options, Progress* progress) {
  e57::PagedReader file(source, name);
  const e57::FileHeader header = e57::readHeader(source, file);
  const std::uint64_t xml_logical = e57::physicalToLogical(header.xml_physical_offset);
  std::string xml(static_cast<std::size_t>(header.xml_logical_length), '\0');
  file.readLogical(xml_logical, xml.size(), reinterpret_cast<std::uint8_t*>(xml.data()), "XML section");
  const e57::FileInfo info = e57::parseXml(xml.data(), xml.size(), name, xml_logical);
  xml.clear();
  xml.shrink_to_fit();

  Dataset data;
  data.source = name;
  data.format = "e57";
  data.coordinate_system = info.coordinate_metadata;
  data.metadata.emplace_back("E57 version", std::to_string(header.major) + "." + std::to_string(header.minor));
  if (!info.library_version.empty()) data.metadata.emplace_back("writer", info.library_version);
  if (!info.guid.empty()) data.metadata.emplace_back("file GUID", info.guid);
  data.metadata.emplace_back("scans", std::to_string(info.scans.size()));
  if (info.image_count) data.metadata.emplace_back("images2D (skipped)", std::to_string(info.image_count));

  // Sections hold at least one bit per record and field (ScanInfo::recordCost); scans sharing
  // or overlapping sections in a corrupted file must not multiply the memory a small file can
  // demand.
  std::uint64_t total = 0;
  unsigned __int128 total_bits = 0;
  for (const auto& s : info.scans) {
    total += s.record_count;
    total_bits += static_cast<unsigned __int128>(s.record_count) * s.recordCost();
    if (total_bits > static_cast<unsigned __int128>(file.logicalSize()) * 8)
      file.fail("recordCount " + std::to_string(s.record_count) + ": the scans up to this one claim " +
                    std::to_string(total) + " records, more than the file can hold",
                FileLocation{std::nullopt, std::nullopt, s.points_path});
  }
  std::uint64_t done = 0;
  std::size_t skipped = 0;
  for (std::size_t k = 0; k < info.scans.size(); ++k) {
    checkCanceled(progress);
    const auto& s = info.scans[k];
    if (!e57::hasCoordinates(s)) {  // the other scans are still read
      ++skipped;
      data.metadata.emplace_back("warning", "scan " + std::to_string(k) + " ('" + s.name + "', " +
                                                s.points_path + ") skipped: its prototype has neither "
                                                "cartesianX/Y/Z nor sphericalRange/Azimuth/Elevation");
      continue;
    }
    if (progress && total > 0) {
      Progress sub = progress->sub(static_cast<double>(done) / total,
                                   static_cast<double>(done + s.record_count) / total);
      data.scans.push_back(e57::readScan(file, s, k, options, &sub, data.metadata));
    } else {
      data.scans.push_back(e57::readScan(file, s, k, options, nullptr, data.metadata));
    }
    done += s.record_count;
  }
  if (skipped > 0 && skipped == info.scans.size())
    file.fail("no scan has coordinates (cartesianX/Y/Z or sphericalRange/Azimuth/Elevation)",
              FileLocation{std::nullopt, std::nullopt, info.scans[0].points_path + "/prototype"});
  reportProgress(progress, 1.0, "reading E57");
  return data;
}

}  // namespace

Dataset readE57(const std::filesystem::path& path, const E57ReadOptions& options, Progress* progress) {
  const auto source = e57::openFileSource(path);
  return readFromSource(*source, path, options, progress);
}

Dataset readE57FromMemory(const void* data, std::size_t size, const std::filesystem::path& name,
                          const E57ReadOptions& options, Progress* progress) {
  const auto source = e57::memorySource(data, size);
  return readFromSource(*source, name, options, progress);
}

}  // namespace plumb
