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

struct E57StreamWriter::State {
  State(const std::filesystem::path& path, const E57WriteOptions& o) : file(path), out(file.stream(), path), options(o) {}
  AtomicFileWriter file;
  e57::PagedWriter out;
  E57WriteOptions options;
  std::vector<e57::WrittenScan> written;
};

E57StreamWriter::E57StreamWriter(const std::filesystem::path& path, const E57WriteOptions& options) {
  if (!(options.scaled_precision >= 1e-9 && options.scaled_precision <= 1.0))
    throw InputError("E57 scaled precision must be within 1e-9 .. 1 m");
  state_ = std::make_unique<State>(path, options);
  state_->out.retain(0, e57::kHeaderSize);
  state_->out.writeZeros(e57::kHeaderSize);  // patched at the end (pitfall 3)
}

E57StreamWriter::~E57StreamWriter() = default;

std::size_t E57StreamWriter::scans() const { return state_->written.size(); }

void E57StreamWriter::writeScan(const Scan& scan, Progress* progress) {
  scan.cloud.validate(true);
  e57::WrittenScan w;
  w.scan.name = scan.name;
  w.scan.description = scan.description;
  w.scan.pose = scan.pose;
  w.scan.has_pose = scan.has_pose;
  // A written scan is a new version of the data (E57: "guid" identifies the current version):
  // a new GUID, and the one it was read with kept in originalGuids for traceability.
  w.guid = e57::newGuid();
  w.original_guids = scan.guid.empty() ? scan.original_guids : std::vector<std::string>{scan.guid};
  const auto fields = e57::describeScan(scan.cloud, state_->options, w);
  w.section_offset = e57::writeCompressedVector(state_->out, fields, w.records, progress);
  points_ += scan.cloud.size();
  state_->written.push_back(std::move(w));
}

void E57StreamWriter::finish(const std::string& coordinate_system) {
  const std::string xml = e57::buildXml(e57::newGuid(), coordinate_system, state_->written);
  e57::FileHeader header;
  header.xml_physical_offset = state_->out.physicalPosition();
  header.xml_logical_length = xml.size();
  state_->out.write(xml.data(), xml.size());
  header.physical_length = state_->out.finish();
  const auto bytes = e57::encodeHeader(header);
  state_->out.patch(0, bytes.data(), bytes.size());
  state_->file.commit();
}

void writeE57(const std::filesystem::path& path, const Dataset& data, const E57WriteOptions& options,
              Progress* progress) {
  E57StreamWriter writer(path, options);
  const std::size_t total = std::max<std::size_t>(1, data.pointCount());
  std::size_t done = 0;
  for (const Scan& scan : data.scans) {
    if (progress) {
      Progress sub = progress->sub(static_cast<double>(done) / total,
                                   static_cast<double>(done + scan.cloud.size()) / total);
      writer.writeScan(scan, &sub);
    } else {
      writer.writeScan(scan, nullptr);
    }
    done += scan.cloud.size();
  }
  writer.finish(data.coordinate_system);
  reportProgress(progress, 1.0, "writing E57");
}

}  // namespace plumb
