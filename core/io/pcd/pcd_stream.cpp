#include "io/pcd/pcd_stream.hpp"

#include <stdexcept>

namespace plumb::pcd_stream {
namespace {

using helper_stream::Reader;
using helper_stream::Writer;

constexpr helper_stream::RecordType kType{"PLUMBPCD", 1};
/// Smallest encoded field: empty name (4) + offset (4) + datatype (1) + count (4).
constexpr std::size_t kMinFieldBytes = 13;

PcdLayout readLayout(Reader& r) {
  PcdLayout l;
  l.width = r.pod<std::uint32_t>();
  l.height = r.pod<std::uint32_t>();
  l.point_step = r.pod<std::uint32_t>();
  l.fields.resize(r.count(r.pod<std::uint32_t>(), kMinFieldBytes));
  for (auto& f : l.fields) {
    f.name = r.str();
    f.offset = r.pod<std::uint32_t>();
    f.datatype = r.pod<std::uint8_t>();
    f.count = r.pod<std::uint32_t>();
  }
  for (double& v : l.viewpoint) v = r.pod<double>();
  return l;
}

Cloud readCloud(Reader& r) {
  Cloud c{readLayout(r), {}};
  const std::string_view bytes = r.view(r.count(r.pod<std::uint64_t>(), 1));
  if (const std::string problem = layoutProblem(c.layout, bytes.size()); !problem.empty())
    throw std::runtime_error(problem);
  c.points = {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()};
  return c;
}

}  // namespace

bool writeCloud(int fd, const PcdLayout& layout, std::span<const std::uint8_t> points) {
  Writer w(fd);
  w.begin(kType, helper_stream::kResult);
  w.pod(layout.width);
  w.pod(layout.height);
  w.pod(layout.point_step);
  w.pod(static_cast<std::uint32_t>(layout.fields.size()));
  for (const auto& f : layout.fields) {
    w.str(f.name);
    w.pod(f.offset);
    w.pod(f.datatype);
    w.pod(f.count);
  }
  for (double v : layout.viewpoint) w.pod(v);
  w.pod(static_cast<std::uint64_t>(points.size()));
  w.bytes(points.data(), points.size());
  return w.finish();
}

bool writeFailure(int fd, const helper_stream::Failure& failure) {
  return helper_stream::writeFailure(fd, kType, failure);
}

std::variant<Cloud, helper_stream::Failure> decode(std::string_view bytes) {
  return helper_stream::decode(bytes, kType, readCloud);
}

}  // namespace plumb::pcd_stream
