#include <charconv>
#include <cstdio>
#include <string>

#include "common/atomic_file.hpp"
#include "common/header_token.hpp"
#include "io/text/text_io.hpp"

namespace plumb {
namespace {

void appendFloat(std::string& out, float v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

/// Shortest fixed-point text that reads back as exactly `v` (a value read from text is
/// written as it was read; georeferenced coordinates keep every digit they carry).
void appendDouble(std::string& out, double v) {
  char buf[400];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  out.append(buf, r.ptr);
}

}  // namespace

void writeText(const std::filesystem::path& path, const PointCloud& cloud,
               const TextWriteOptions& options, Progress* progress) {
  cloud.validate(true);
  std::string ext = path.extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const bool csv = ext == ".csv";
  const char delim = options.delimiter ? options.delimiter : (csv ? ',' : ' ');
  const std::size_t n = cloud.size();
  const bool exact_floats = cloud.offset.isZero() && !cloud.hasPositionResiduals();
  AtomicFileWriter writer(path);
  std::ostream& out = writer.stream();
  if (options.header) {
    std::string h = csv ? "" : "// ";
    std::vector<std::string> names{"x", "y", "z"};
    if (cloud.hasColors()) names.insert(names.end(), {"red", "green", "blue"});
    if (cloud.hasIntensity()) names.push_back("intensity");
    if (cloud.hasNormals()) names.insert(names.end(), {"nx", "ny", "nz"});
    // One token per column whatever the field is called ("my field" -> "my_field").
    std::vector<std::string> fields;
    for (const auto& f : cloud.scalar_fields)
      if (f.values.size() == n) fields.push_back(f.name);
    const auto tokens = headerTokens(fields, names, ",;\"");
    names.insert(names.end(), tokens.begin(), tokens.end());
    for (std::size_t k = 0; k < names.size(); ++k) h += (k ? std::string(1, delim) : "") + names[k];
    out << h << "\n";
  }
  std::string line;
  for (std::size_t i = 0; i < n; ++i) {
    line.clear();
    const Eigen::Vector3d w = exact_floats ? Eigen::Vector3d::Zero() : cloud.world(i);
    for (int a = 0; a < 3; ++a) {
      if (a) line.push_back(delim);
      if (exact_floats) appendFloat(line, cloud.positions[i][a]);
      else appendDouble(line, w[a]);
    }
    if (cloud.hasColors())
      for (int a = 0; a < 3; ++a) line += delim + std::to_string(cloud.colors[i][a]);
    if (cloud.hasIntensity()) {
      line.push_back(delim);
      appendFloat(line, cloud.intensity[i]);
    }
    if (cloud.hasNormals())
      for (int a = 0; a < 3; ++a) {
        line.push_back(delim);
        appendFloat(line, cloud.normals[i][a]);
      }
    for (const auto& f : cloud.scalar_fields)
      if (f.values.size() == n) {
        line.push_back(delim);
        appendFloat(line, f.values[i]);
      }
    line.push_back('\n');
    out.write(line.data(), static_cast<std::streamsize>(line.size()));
    if ((i & 0xFFFF) == 0) {
      checkCanceled(progress);
      reportProgress(progress, static_cast<double>(i) / static_cast<double>(n), "writing text");
    }
  }
  writer.commit();
  reportProgress(progress, 1.0, "writing text");
}

}  // namespace plumb
