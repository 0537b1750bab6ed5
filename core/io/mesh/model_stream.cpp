#include "io/mesh/model_stream.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace plumb::model_stream {
namespace {

constexpr char kMagic[8] = {'P', 'L', 'U', 'M', 'B', 'M', 'D', 'L'};
constexpr char kEnd[4] = {'E', 'N', 'D', '!'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uint8_t kModel = 1, kFailure = 2;

class FdWriter {
 public:
  explicit FdWriter(int fd) : fd_(fd) { buffer_.reserve(kChunk); }
  void bytes(const void* p, std::size_t n) {
    if (n == 0) return;  // an empty table: p may be null
    const auto* c = static_cast<const char*>(p);
    while (n > 0 && ok_) {
      const std::size_t k = std::min(n, kChunk - buffer_.size());
      buffer_.append(c, k);
      c += k;
      n -= k;
      if (buffer_.size() == kChunk) flush();
    }
  }
  template <class T>
  void pod(const T& v) { bytes(&v, sizeof v); }
  void str(const std::string& s) {
    pod(static_cast<std::uint32_t>(s.size()));
    bytes(s.data(), s.size());
  }
  template <class T>
  void table(const std::vector<T>& v) {
    pod(static_cast<std::uint64_t>(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  bool finish() {
    bytes(kEnd, sizeof kEnd);
    flush();
    return ok_;
  }

 private:
  static constexpr std::size_t kChunk = 1 << 20;
  void flush() {
    std::size_t done = 0;
    while (ok_ && done < buffer_.size()) {
      const ssize_t w = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) ok_ = false;
      else done += static_cast<std::size_t>(w);
    }
    buffer_.clear();
  }
  int fd_;
  bool ok_ = true;
  std::string buffer_;
};

void header(FdWriter& w, std::uint8_t kind) {
  w.bytes(kMagic, sizeof kMagic);
  w.pod(kVersion);
  w.pod(kind);
}

class Reader {
 public:
  explicit Reader(std::string_view b) : b_(b) {}
  void bytes(void* p, std::size_t n) {
    if (n == 0) return;  // an empty table: p may be null
    if (n > b_.size() - at_) throw std::runtime_error("the stream ends early");
    std::memcpy(p, b_.data() + at_, n);
    at_ += n;
  }
  template <class T>
  T pod() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
  std::string str() {
    std::string s(count(pod<std::uint32_t>(), 1), '\0');
    bytes(s.data(), s.size());
    return s;
  }
  template <class T>
  void table(std::vector<T>& v) {
    v.resize(count(pod<std::uint64_t>(), sizeof(T)));
    bytes(v.data(), v.size() * sizeof(T));
  }
  /// n items of `size` bytes must fit in what is left.
  std::size_t count(std::uint64_t n, std::size_t size) const {
    if (n > (b_.size() - at_) / size) throw std::runtime_error("a count exceeds the stream");
    return static_cast<std::size_t>(n);
  }
  bool atEnd() const { return at_ == b_.size(); }

 private:
  std::string_view b_;
  std::size_t at_ = 0;
};

void checkIndices(const BimModel& m) {
  for (const auto& t : m.mesh.triangles)
    for (auto v : t)
      if (v >= m.mesh.vertices.size()) throw std::runtime_error("a triangle names a missing vertex");
  if (m.triangle_element.size() != m.mesh.triangles.size())
    throw std::runtime_error("triangle elements do not match the triangles");
  for (auto e : m.triangle_element)
    if (e >= m.elements.size()) throw std::runtime_error("a triangle names a missing element");
  const auto n = m.mesh.vertices.size();
  if ((!m.mesh.vertex_normals.empty() && m.mesh.vertex_normals.size() != n) ||
      (!m.mesh.vertex_colors.empty() && m.mesh.vertex_colors.size() != n))
    throw std::runtime_error("normals or colours do not match the vertices");
}

BimModel readModel(Reader& r) {
  BimModel m;
  m.format = r.str();
  r.table(m.mesh.vertices);
  r.table(m.mesh.triangles);
  r.table(m.triangle_element);
  m.elements.resize(r.count(r.pod<std::uint64_t>(), 12));
  for (auto& e : m.elements) {
    e.type = r.str();
    e.name = r.str();
    e.guid = r.str();
  }
  r.table(m.mesh.vertex_normals);
  r.table(m.mesh.vertex_colors);
  checkIndices(m);
  return m;
}

ImportFailure readFailure(Reader& r) {
  ImportFailure f;
  f.message = r.str();
  const auto has_line = r.pod<std::uint8_t>();
  const auto line = r.pod<std::uint64_t>();
  if (has_line) f.where.line = line;
  f.where.element = r.str();
  return f;
}

}  // namespace

static_assert(sizeof(Eigen::Vector3d) == 24 && sizeof(Eigen::Vector3f) == 12 && sizeof(Rgb8) == 3,
              "the stream copies these as packed arrays");

bool writeModel(int fd, const BimModel& model) {
  FdWriter w(fd);
  header(w, kModel);
  w.str(model.format);
  w.table(model.mesh.vertices);
  w.table(model.mesh.triangles);
  w.table(model.triangle_element);
  w.pod(static_cast<std::uint64_t>(model.elements.size()));
  for (const auto& e : model.elements) {
    w.str(e.type);
    w.str(e.name);
    w.str(e.guid);
  }
  w.table(model.mesh.vertex_normals);
  w.table(model.mesh.vertex_colors);
  return w.finish();
}

bool writeFailure(int fd, const ImportFailure& failure) {
  FdWriter w(fd);
  header(w, kFailure);
  w.str(failure.message);
  w.pod(static_cast<std::uint8_t>(failure.where.line.has_value()));
  w.pod(static_cast<std::uint64_t>(failure.where.line.value_or(0)));
  w.str(failure.where.element);
  return w.finish();
}

std::variant<BimModel, ImportFailure> decode(std::string_view bytes) {
  Reader r(bytes);
  char magic[sizeof kMagic];
  r.bytes(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw std::runtime_error("it does not start with PLUMBMDL");
  if (r.pod<std::uint32_t>() != kVersion) throw std::runtime_error("its version is not this build's");
  const auto kind = r.pod<std::uint8_t>();
  if (kind != kModel && kind != kFailure) throw std::runtime_error("unknown record kind");
  std::variant<BimModel, ImportFailure> out;
  if (kind == kModel) out = readModel(r);
  else out = readFailure(r);
  char end[sizeof kEnd];
  r.bytes(end, sizeof end);
  if (std::memcmp(end, kEnd, sizeof kEnd) != 0 || !r.atEnd()) throw std::runtime_error("it does not end with END!");
  return out;
}

}  // namespace plumb::model_stream
