#include "io/e57/e57_extension_fields.hpp"

#include "io/e57/e57_out_fields.hpp"
#include "io/e57/e57_point_fields.hpp"

#include <cctype>
#include <set>

namespace plumb::e57 {
namespace {

template <class C>
OutField floatColumn(const std::string& local, const C& column) {
  OutField f{floatSpec(kPlumbPrefix + local, true), {}, {}};
  f.floats = [&column](std::size_t begin, std::size_t count, double* out) {
    for (std::size_t i = 0; i < count; ++i) out[i] = column[begin + i];
  };
  return f;
}

}  // namespace

std::string xmlLocalName(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    out += (std::isalnum(u) && u < 0x80) || c == '_' || c == '-' || c == '.' ? c : '_';
  }
  if (out.empty() || !(std::isalpha(static_cast<unsigned char>(out[0])) || out[0] == '_')) out = "_" + out;
  return out;
}

void appendExtensionFields(const PointCloud& cloud, std::vector<OutField>& fields) {
  auto present = [n = cloud.size()](const auto& column) { return n > 0 && column.size() == n; };
  auto integerColumn = [](const char* local, const auto& column) {
    return integerColumnField(kPlumbPrefix + std::string(local), column);
  };
  std::set<std::string> used;
  auto add = [&](OutField f) {
    used.insert(f.spec.name);
    fields.push_back(std::move(f));
  };
  if (present(cloud.classification)) add(integerColumn("classification", cloud.classification));
  if (present(cloud.classification_flags)) add(integerColumn("classificationFlags", cloud.classification_flags));
  if (present(cloud.scanner_channel)) add(integerColumn("scannerChannel", cloud.scanner_channel));
  if (present(cloud.scan_flags)) add(integerColumn("scanFlags", cloud.scan_flags));
  if (present(cloud.user_data)) add(integerColumn("userData", cloud.user_data));
  if (present(cloud.point_source_id)) add(integerColumn("pointSourceId", cloud.point_source_id));
  if (present(cloud.scan_angle)) add(floatColumn("scanAngle", cloud.scan_angle));
  for (const auto& sf : cloud.scalar_fields) {
    if (!present(sf.values)) continue;
    // A name already written, or one the reader would take for another role ("normalX",
    // "scanAngle"...), gets a numbered suffix.
    const std::string base = xmlLocalName(sf.name);
    std::string local = base;
    for (int k = 2; used.count(kPlumbPrefix + local) || detail::roleOf(kPlumbPrefix + local) >= 0; ++k)
      local = base + "_" + std::to_string(k);
    add(floatColumn(local, sf.values));
  }
}

}  // namespace plumb::e57
