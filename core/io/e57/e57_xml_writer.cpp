#include "io/e57/e57_xml_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <random>

namespace plumb::e57 {
namespace {

std::string num(double v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  return std::string(buf, end);
}

/// Length of the valid UTF-8 sequence at s[i] that XML 1.0 allows as a character, else 0:
/// no C0 control but tab/newline/return, no overlong form, surrogate, U+FFFE/U+FFFF or
/// code point beyond U+10FFFF.
std::size_t xmlCharLength(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned c = byte(i);
  if (c < 0x80) return (c >= 0x20 || c == '\t' || c == '\n' || c == '\r') ? 1 : 0;
  const std::size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 0;
  if (len == 0 || i + len > s.size()) return 0;
  unsigned cp = c & (0x7F >> len);
  for (std::size_t k = 1; k < len; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  const unsigned min_cp[] = {0, 0, 0x80, 0x800, 0x10000};
  const bool ok = cp >= min_cp[len] && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF) &&
                  cp != 0xFFFE && cp != 0xFFFF;
  return ok ? len : 0;
}

/// `s` with every byte XML cannot carry (control characters, invalid UTF-8) replaced by
/// U+FFFD, so the XML section stays well-formed whatever a scan name holds.
std::string xmlText(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t len = xmlCharLength(s, i);
    if (len == 0) {
      out += "\xEF\xBF\xBD";
      ++i;
    } else {
      out.append(s, i, len);
      i += len;
    }
  }
  return out;
}

std::string cdata(const std::string& raw) {
  const std::string s = xmlText(raw);
  std::string out = "<![CDATA[";
  std::size_t start = 0;
  for (std::size_t p; (p = s.find("]]>", start)) != std::string::npos; start = p + 2)
    out += s.substr(start, p + 2 - start) + "]]><![CDATA[";
  out += s.substr(start) + "]]>";
  return out;
}

struct Xml {
  std::string s;
  int depth = 1;
  void line(const std::string& text) { s.append(2 * depth, ' ').append(text).append("\n"); }
  void open(const std::string& name, const std::string& attrs) { line("<" + name + " " + attrs + ">"), ++depth; }
  void close(const std::string& name) { --depth, line("</" + name + ">"); }
  void str(const char* name, const std::string& v) {
    line(std::string("<") + name + " type=\"String\">" + cdata(v) + "</" + name + ">");
  }
  void flt(const char* name, double v) {
    line(std::string("<") + name + " type=\"Float\">" + num(v) + "</" + name + ">");
  }
  void integer(const char* name, std::int64_t v) {
    line(std::string("<") + name + " type=\"Integer\">" + std::to_string(v) + "</" + name + ">");
  }
};

void prototypeField(Xml& x, const FieldSpec& f) {
  switch (f.type) {
    case FieldType::Float:
      x.line("<" + f.name + " type=\"Float\"" + (f.single ? " precision=\"single\"" : "") + "/>");
      break;
    case FieldType::Integer:
      // The element value must lie within [minimum, maximum] (libE57Format checks it).
      x.line("<" + f.name + " type=\"Integer\" minimum=\"" + std::to_string(f.minimum) + "\" maximum=\"" +
             std::to_string(f.maximum) + "\">" + std::to_string(f.minimum) + "</" + f.name + ">");
      break;
    case FieldType::ScaledInteger:
      x.line("<" + f.name + " type=\"ScaledInteger\" minimum=\"" + std::to_string(f.minimum) +
             "\" maximum=\"" + std::to_string(f.maximum) + "\" scale=\"" + num(f.scale) + "\" offset=\"" +
             num(f.offset) + "\">" + std::to_string(f.minimum) + "</" + f.name + ">");
      break;
  }
}

/// pose: rotation as a normalised double quaternion with w >= 0, and translation.
void poseXml(Xml& x, const Scan& scan) {
  Eigen::Quaterniond q = scan.pose.quaternion().normalized();  // normalised doubles (pitfall 6)
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d& t = scan.pose.translation();
  x.open("pose", "type=\"Structure\"");
  x.open("rotation", "type=\"Structure\"");
  x.flt("w", q.w()), x.flt("x", q.x()), x.flt("y", q.y()), x.flt("z", q.z());
  x.close("rotation");
  x.open("translation", "type=\"Structure\"");
  x.flt("x", t.x()), x.flt("y", t.y()), x.flt("z", t.z());
  x.close("translation");
  x.close("pose");
}

/// cartesianBounds, indexBounds, intensityLimits and colorLimits, for those the scan has.
void limitsXml(Xml& x, const WrittenScan& w) {
  if (w.bounds) {  // all six, as Float (E57RefImpl reads them as FloatNode)
    x.open("cartesianBounds", "type=\"Structure\"");
    x.flt("xMinimum", w.bounds->min.x()), x.flt("xMaximum", w.bounds->max.x());
    x.flt("yMinimum", w.bounds->min.y()), x.flt("yMaximum", w.bounds->max.y());
    x.flt("zMinimum", w.bounds->min.z()), x.flt("zMaximum", w.bounds->max.z());
    x.close("cartesianBounds");
  }
  if (w.rows || w.returns) {  // all six children, Integer (pitfall in §6)
    const auto rows = w.rows.value_or(std::pair<std::int64_t, std::int64_t>{0, 0});
    const auto cols = w.columns.value_or(std::pair<std::int64_t, std::int64_t>{0, 0});
    const auto rets = w.returns.value_or(std::pair<std::int64_t, std::int64_t>{0, 0});
    x.open("indexBounds", "type=\"Structure\"");
    x.integer("rowMinimum", rows.first), x.integer("rowMaximum", rows.second);
    x.integer("columnMinimum", cols.first), x.integer("columnMaximum", cols.second);
    x.integer("returnMinimum", rets.first), x.integer("returnMaximum", rets.second);
    x.close("indexBounds");
  }
  if (w.intensity) {
    x.open("intensityLimits", "type=\"Structure\"");
    if (w.intensity_integer) {
      x.integer("intensityMinimum", static_cast<std::int64_t>(w.intensity->first));
      x.integer("intensityMaximum", static_cast<std::int64_t>(w.intensity->second));
    } else {
      x.flt("intensityMinimum", w.intensity->first);
      x.flt("intensityMaximum", w.intensity->second);
    }
    x.close("intensityLimits");
  }
  if (w.colors) {
    x.open("colorLimits", "type=\"Structure\"");
    for (const char* c : {"Red", "Green", "Blue"}) {
      x.integer((std::string("color") + c + "Minimum").c_str(), 0);
      x.integer((std::string("color") + c + "Maximum").c_str(), 255);
    }
    x.close("colorLimits");
  }
}

/// One data3D vectorChild: identification, pose, limits and the points' CompressedVector.
void scanXml(Xml& x, const WrittenScan& w) {
  const Scan& scan = w.scan;
  x.open("vectorChild", "type=\"Structure\"");
  x.str("guid", w.guid);
  if (!w.original_guids.empty()) {
    x.open("originalGuids", "type=\"Vector\" allowHeterogeneousChildren=\"0\"");
    for (const std::string& g : w.original_guids) x.str("vectorChild", g);
    x.close("originalGuids");
  }
  x.str("name", scan.name);
  if (!scan.description.empty()) x.str("description", scan.description);
  if (scan.has_pose || !scan.pose.isIdentity()) poseXml(x, scan);
  limitsXml(x, w);
  x.open("points", "type=\"CompressedVector\" fileOffset=\"" + std::to_string(w.section_offset) +
                       "\" recordCount=\"" + std::to_string(w.records) + "\"");
  x.open("prototype", "type=\"Structure\"");
  for (const FieldSpec& f : w.prototype) prototypeField(x, f);
  x.close("prototype");
  x.line("<codecs type=\"Vector\" allowHeterogeneousChildren=\"1\"/>");
  x.close("points");
  x.close("vectorChild");
}

}  // namespace

std::string newGuid() {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  const std::uint64_t a = rng(), b = rng();
  char buf[48];
  std::snprintf(buf, sizeof buf, "{%08X-%04X-%04X-%04X-%012llX}", static_cast<unsigned>(a >> 32),
                static_cast<unsigned>((a >> 16) & 0xFFFF), static_cast<unsigned>((a & 0x0FFF) | 0x4000),
                static_cast<unsigned>(((b >> 48) & 0x3FFF) | 0x8000),
                static_cast<unsigned long long>(b & 0xFFFFFFFFFFFFull));
  return buf;
}

std::string buildXml(const std::string& file_guid, const std::string& coordinate_system,
                     const std::vector<WrittenScan>& scans) {
  Xml x;
  x.s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<e57Root type=\"Structure\" xmlns=\"http://www.astm.org/COMMIT/E57/2010-e57-v1.0\" "
        "xmlns:nor=\"http://www.libe57.org/E57_NOR_surface_normals.txt\" "
        "xmlns:plumb=\"https://plumb.invalid/E57_extensions\">\n";
  x.str("formatName", "ASTM E57 3D Imaging Data File");
  x.str("guid", file_guid);
  x.integer("versionMajor", 1);
  x.integer("versionMinor", 0);
  x.str("e57LibraryVersion", "Plumb E57 writer 1.0");
  if (!coordinate_system.empty()) x.str("coordinateMetadata", coordinate_system);
  x.open("data3D", "type=\"Vector\" allowHeterogeneousChildren=\"1\"");
  for (const WrittenScan& w : scans) scanXml(x, w);
  x.close("data3D");
  x.line("<images2D type=\"Vector\" allowHeterogeneousChildren=\"1\"/>");
  x.s += "</e57Root>\n";
  while (x.s.size() % 4) x.s += ' ';
  return x.s;
}

}  // namespace plumb::e57
