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

// Reads the header and the XML section, describes the file in `data` (no scans yet) and
// checks the scans' record counts against the file size.
e57::FileInfo readOutline(const e57::ByteSource& source, e57::PagedReader& file,
                          const std::filesystem::path& name, Dataset& data) {
  const e57::FileHeader header = e57::readHeader(source, file);
  const std::uint64_t xml_logical = e57::physicalToLogical(header.xml_physical_offset);
  std::string xml(static_cast<std::size_t>(header.xml_logical_length), '\0');
  file.readLogical(xml_logical, xml.size(), reinterpret_cast<std::uint8_t*>(xml.data()), "XML section");
  e57::FileInfo info = e57::parseXml(xml.data(), xml.size(), name, xml_logical);

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
  return info;
}

// Calls read(k, scan info, progress) for every scan with coordinates, in order; the others
// get a "warning" in the metadata (the file fails when no scan has coordinates).
template <class Read>
void forEachReadableScan(e57::PagedReader& file, const e57::FileInfo& info, Dataset& data,
                         Progress* progress, Read&& read) {
  std::uint64_t total = 0, done = 0;
  for (const auto& s : info.scans) total += s.record_count;
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
      read(k, s, &sub);
    } else {
      read(k, s, nullptr);
    }
    done += s.record_count;
  }
  if (skipped > 0 && skipped == info.scans.size())
    file.fail("no scan has coordinates (cartesianX/Y/Z or sphericalRange/Azimuth/Elevation)",
              FileLocation{std::nullopt, std::nullopt, info.scans[0].points_path + "/prototype"});
}

Dataset readFromSource(const e57::ByteSource& source, const std::filesystem::path& name,
                       const E57ReadOptions& options, Progress* progress) {
  e57::PagedReader file(source, name);
  Dataset data;
  const e57::FileInfo info = readOutline(source, file, name, data);
  forEachReadableScan(file, info, data, progress, [&](std::size_t k, const e57::ScanInfo& s, Progress* p) {
    data.scans.push_back(e57::readScan(file, s, k, options, p, data.metadata));
  });
  reportProgress(progress, 1.0, "reading E57");
  return data;
}

// The outline a sink gets first: every scan with coordinates, without points.
StreamOutline streamOutline(e57::PagedReader& file, const e57::FileInfo& info, const Dataset& data,
                            const E57ReadOptions& options) {
  StreamOutline outline;
  outline.dataset = data;
  for (std::size_t k = 0; k < info.scans.size(); ++k) {
    if (!e57::hasCoordinates(info.scans[k])) continue;
    outline.scans.push_back(e57::streamScanHeader(file, info.scans[k], k, outline.scans.size(), options,
                                                  outline.dataset.metadata));
    outline.dataset.scans.push_back(outline.scans.back().scan);
  }
  return outline;
}

void streamFromSource(const e57::ByteSource& source, const std::filesystem::path& name,
                      const StreamOptions& options, ChunkSink& sink, Progress* progress) {
  e57::PagedReader file(source, name);
  Dataset data;
  const e57::FileInfo info = readOutline(source, file, name, data);
  E57ReadOptions o;
  o.keep_direction_only = options.keep_direction_only;
  StreamOutline outline = streamOutline(file, info, data, o);
  sink.begin(outline);
  std::size_t position = 0;
  forEachReadableScan(file, info, outline.dataset, progress,
                      [&](std::size_t k, const e57::ScanInfo& s, Progress* p) {
    sink.beginScan(outline.scans[position]);
    sink.endScan(e57::streamScan(file, s, k, position, o, chunkCapacity(options), sink, p,
                                 outline.dataset.metadata));
    ++position;
  });
  reportProgress(progress, 1.0, "reading E57");
  sink.end(outline);
}

}  // namespace

Dataset readE57(const std::filesystem::path& path, const E57ReadOptions& options, Progress* progress) {
  const auto source = e57::openFileSource(path);
  return readFromSource(*source, path, options, progress);
}

void streamE57(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
               Progress* progress) {
  const auto source = e57::openFileSource(path);
  streamFromSource(*source, path, options, sink, progress);
}

Dataset readE57FromMemory(const void* data, std::size_t size, const std::filesystem::path& name,
                          const E57ReadOptions& options, Progress* progress) {
  const auto source = e57::memorySource(data, size);
  return readFromSource(*source, name, options, progress);
}

}  // namespace plumb
