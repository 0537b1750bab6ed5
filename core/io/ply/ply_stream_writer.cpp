#include "io/ply/ply_stream_writer.hpp"

#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/ply/ply_point_columns.hpp"

namespace plumb {
namespace {

constexpr std::size_t kCountWidth = 20;    // digits of 2^64
constexpr std::size_t kCommentWidth = 40;  // "plumb-grid ROWS COLUMNS" with int32 values

// What a column is in the header: its name and type.
std::vector<std::pair<std::string, ply::Type>> signature(const std::vector<ply::OutColumn>& cols) {
  std::vector<std::pair<std::string, ply::Type>> out;
  for (const auto& c : cols) out.emplace_back(c.name, c.type);
  return out;
}

std::string padded(std::string s, std::size_t width) {
  s.resize(width, ' ');
  return s;
}

}  // namespace

struct PlyStreamWriter::State {
  AtomicFileWriter writer;
  PlyWriteOptions options;
  bool double_xyz = false;
  std::vector<std::pair<std::string, ply::Type>> columns;
  std::streamoff count_at = 0, comment_at = 0;
  std::uint64_t points = 0;
  explicit State(const std::filesystem::path& p) : writer(p) {}
};

PlyStreamWriter::PlyStreamWriter(const std::filesystem::path& path, const PointCloud& sample,
                                 bool double_xyz, const PlyWriteOptions& options)
    : s_(std::make_unique<State>(path)) {
  s_->options = options;
  s_->double_xyz = double_xyz;
  const auto cols = ply::pointColumns(sample, double_xyz);
  s_->columns = signature(cols);
  std::ostringstream header;
  ply::writeHeader(header, options.encoding, {std::string(kCommentWidth, ' ')}, "vertex",
                   std::string(kCountWidth, ' '), cols);
  header << "end_header\n";
  const std::string text = header.str();
  s_->count_at = static_cast<std::streamoff>(text.find("element vertex ") + 15);
  s_->comment_at = static_cast<std::streamoff>(text.find("comment " + std::string(kCommentWidth, ' ')) + 8);
  s_->writer.stream() << text;
}

PlyStreamWriter::~PlyStreamWriter() = default;

void PlyStreamWriter::write(const PointCloud& points, Progress* progress) {
  points.validate(true);
  const auto cols = ply::pointColumns(points, s_->double_xyz);
  if (signature(cols) != s_->columns)
    throw InputError("PLY stream: a chunk of " + std::to_string(points.size()) +
                     " points does not have the columns of the first one");
  ply::writeRecords(s_->writer.stream(), s_->options.encoding, cols, points.size(), progress);
  s_->points += points.size();
}

void PlyStreamWriter::finish(std::int32_t grid_rows, std::int32_t grid_columns) {
  std::ostream& out = s_->writer.stream();
  out.seekp(s_->count_at);
  out << padded(std::to_string(s_->points), kCountWidth);
  if (grid_rows > 0 && grid_columns > 0) {
    out.seekp(s_->comment_at);
    out << padded(ply::gridComment(grid_rows, grid_columns), kCommentWidth);
  }
  s_->writer.commit();
}

std::uint64_t PlyStreamWriter::points() const { return s_->points; }

}  // namespace plumb
