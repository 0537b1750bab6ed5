#include "io/e57/e57_writer.hpp"

#include <algorithm>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/e57/e57_header.hpp"
#include "io/e57/e57_packet_writer.hpp"
#include "io/e57/e57_page_writer.hpp"
#include "io/e57/e57_scan_fields.hpp"
#include "io/e57/e57_xml_writer.hpp"

namespace plumb {

void writeE57(const std::filesystem::path& path, const Dataset& data, const E57WriteOptions& options,
              Progress* progress) {
  if (!(options.scaled_precision >= 1e-9 && options.scaled_precision <= 1.0))
    throw InputError("E57 scaled precision must be within 1e-9 .. 1 m");
  AtomicFileWriter file(path);
  e57::PagedWriter out(file.stream(), path);
  out.retain(0, e57::kHeaderSize);
  out.writeZeros(e57::kHeaderSize);  // patched at the end (pitfall 3)

  const std::size_t total = std::max<std::size_t>(1, data.pointCount());
  std::size_t done = 0;
  std::vector<e57::WrittenScan> written;
  for (const Scan& scan : data.scans) {
    scan.cloud.validate(true);
    e57::WrittenScan w;
    w.scan = &scan;
    w.guid = scan.guid.empty() ? e57::newGuid() : scan.guid;
    const auto fields = e57::describeScan(scan.cloud, options, w);
    if (progress) {
      Progress sub = progress->sub(static_cast<double>(done) / total,
                                   static_cast<double>(done + scan.cloud.size()) / total);
      w.section_offset = e57::writeCompressedVector(out, fields, w.records, &sub);
    } else {
      w.section_offset = e57::writeCompressedVector(out, fields, w.records, nullptr);
    }
    done += scan.cloud.size();
    written.push_back(std::move(w));
  }
  std::string file_guid;
  for (const auto& [key, value] : data.metadata)
    if (key == "file GUID") file_guid = value;
  const std::string xml =
      e57::buildXml(file_guid.empty() ? e57::newGuid() : file_guid, data.coordinate_system, written);
  e57::FileHeader header;
  header.xml_physical_offset = out.physicalPosition();
  header.xml_logical_length = xml.size();
  out.write(xml.data(), xml.size());
  header.physical_length = out.finish();
  const auto bytes = e57::encodeHeader(header);
  out.patch(0, bytes.data(), bytes.size());
  file.commit();
  reportProgress(progress, 1.0, "writing E57");
}

}  // namespace plumb
