#include "io/e57/e57_xml.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

#include "common/error.hpp"
#include "io/e57/e57_pages.hpp"

namespace plumb::e57 {

unsigned FieldSpec::bits() const {
  switch (type) {
    case FieldType::Float: return single ? 32u : 64u;
    case FieldType::Integer:
    case FieldType::ScaledInteger: {
      const auto range = static_cast<std::uint64_t>(maximum) - static_cast<std::uint64_t>(minimum);
      return static_cast<unsigned>(std::bit_width(range));  // ceil(log2(range + 1))
    }
  }
  return 64;
}

std::uint64_t ScanInfo::recordCost() const {
  std::uint64_t bits = 0;
  for (const FieldSpec& f : fields) bits += f.bits();
  return std::max<std::uint64_t>({bits, fields.size(), 1});
}

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::strchr(" \t\r\n", s.front())) s.remove_prefix(1);
  while (!s.empty() && std::strchr(" \t\r\n", s.back())) s.remove_suffix(1);
  return s;
}

class XmlParser {
 public:
  XmlParser(const std::filesystem::path& file) : file_(file) {}

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    FileLocation where;
    where.element = path;
    throw FileError(file_, message, where);
  }

  std::string type(const pugi::xml_node& n, const std::string& path) const {
    const char* t = n.attribute("type").value();
    if (!*t) fail(path, "element has no 'type' attribute");
    return t;
  }

  std::int64_t parseInt(std::string_view text, const std::string& path, const char* what) const {
    text = trim(text);
    if (text.empty()) return 0;
    if (text.front() == '+') text.remove_prefix(1);
    std::int64_t v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
      fail(path, std::string("invalid integer for ") + what + ": '" + std::string(text) + "'");
    return v;
  }

  double parseDouble(std::string_view text, const std::string& path, const char* what) const {
    text = trim(text);
    if (text.empty()) return 0.0;
    if (text.front() == '+') text.remove_prefix(1);
    double v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if ((ec != std::errc() && ec != std::errc::result_out_of_range) ||
        end != text.data() + text.size())
      fail(path, std::string("invalid number for ") + what + ": '" + std::string(text) + "'");
    return v;
  }

  std::uint64_t parseCount(const pugi::xml_node& n, const char* attr, const std::string& path) const {
    const pugi::xml_attribute a = n.attribute(attr);
    if (!a) fail(path, std::string("CompressedVector has no '") + attr + "' attribute");
    std::string_view text = trim(a.value());
    std::uint64_t v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
      fail(path, std::string("invalid ") + attr + " '" + std::string(text) + "'");
    return v;
  }

  /// Numeric value of an Integer, ScaledInteger or Float element.
  double number(const pugi::xml_node& n, const std::string& path) const {
    const std::string t = type(n, path);
    const char* text = n.text().get();
    if (t == "Float") return parseDouble(text, path, "Float value");
    if (t == "Integer") return static_cast<double>(parseInt(text, path, "Integer value"));
    if (t == "ScaledInteger") {
      const double scale = n.attribute("scale") ? parseDouble(n.attribute("scale").value(), path, "scale") : 1.0;
      const double offset = n.attribute("offset") ? parseDouble(n.attribute("offset").value(), path, "offset") : 0.0;
      return static_cast<double>(parseInt(text, path, "ScaledInteger value")) * scale + offset;
    }
    fail(path, "expected a number (Integer, ScaledInteger or Float), found type '" + t + "'");
  }

  std::optional<double> childNumber(const pugi::xml_node& parent, const char* name,
                                    const std::string& path) const {
    const pugi::xml_node c = parent.child(name);
    if (!c) return std::nullopt;
    return number(c, path + "/" + name);
  }

  /// Text of a String child: all its text and CDATA pieces joined ("]]>" splits CDATA).
  std::string childString(const pugi::xml_node& parent, const char* name) const {
    return childText(parent.child(name));
  }

  /// Text of a String node (text and CDATA pieces joined, trimmed).
  static std::string childText(const pugi::xml_node& node) {
    std::string out;
    for (pugi::xml_node t = node.first_child(); t; t = t.next_sibling())
      if (t.type() == pugi::node_pcdata || t.type() == pugi::node_cdata) out += t.value();
    return std::string(trim(out));
  }

  std::optional<Limits> limits(const pugi::xml_node& parent, const char* min_name,
                               const char* max_name, const std::string& path) const {
    auto lo = childNumber(parent, min_name, path);
    auto hi = childNumber(parent, max_name, path);
    if (!lo || !hi) return std::nullopt;
    return Limits{*lo, *hi};
  }

  void prototypeFields(const pugi::xml_node& node, const std::string& prefix, const std::string& path,
                       std::vector<FieldSpec>& out, int depth = 0) const {
    if (depth > 16) fail(path, "prototype Structures nested too deeply");
    for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling()) {
      if (c.type() != pugi::node_element) continue;
      const std::string name = c.name();
      const std::string cpath = path + "/" + name;
      const std::string t = type(c, cpath);
      if (t == "Structure") {
        prototypeFields(c, prefix + name + "/", cpath, out, depth + 1);
        continue;
      }
      FieldSpec f;
      f.name = prefix + name;
      f.path = cpath;
      if (t == "Float") {
        f.type = FieldType::Float;
        const std::string precision = c.attribute("precision").value();
        if (precision == "single") {
          f.single = true;
        } else if (!precision.empty() && precision != "double") {
          fail(cpath, "invalid Float precision '" + precision + "'");
        }
        if (c.attribute("minimum") && c.attribute("maximum")) {
          f.float_min = parseDouble(c.attribute("minimum").value(), cpath, "minimum");
          f.float_max = parseDouble(c.attribute("maximum").value(), cpath, "maximum");
          f.has_float_limits = true;
        }
      } else if (t == "Integer" || t == "ScaledInteger") {
        f.type = t == "Integer" ? FieldType::Integer : FieldType::ScaledInteger;
        if (c.attribute("minimum")) f.minimum = parseInt(c.attribute("minimum").value(), cpath, "minimum");
        if (c.attribute("maximum")) f.maximum = parseInt(c.attribute("maximum").value(), cpath, "maximum");
        if (f.minimum > f.maximum)
          fail(cpath, "minimum " + std::to_string(f.minimum) + " is greater than maximum " +
                          std::to_string(f.maximum));
        if (f.type == FieldType::ScaledInteger) {
          if (c.attribute("scale")) f.scale = parseDouble(c.attribute("scale").value(), cpath, "scale");
          if (c.attribute("offset")) f.offset = parseDouble(c.attribute("offset").value(), cpath, "offset");
          if (!std::isfinite(f.scale) || f.scale == 0.0 || !std::isfinite(f.offset))
            fail(cpath, "invalid ScaledInteger scale/offset");
        }
      } else {
        fail(cpath, "unsupported point field type '" + t + "' (only Integer, ScaledInteger and Float)");
      }
      out.push_back(std::move(f));
    }
  }

  ScanInfo scan(const pugi::xml_node& node, const std::string& path) const {
    ScanInfo s;
    s.path = path;
    if (type(node, path) != "Structure") fail(path, "data3D entry is not a Structure");
    s.guid = childString(node, "guid");
    for (pugi::xml_node g = node.child("originalGuids").first_child(); g; g = g.next_sibling())
      if (g.type() == pugi::node_element) s.original_guids.push_back(childText(g));
    s.name = childString(node, "name");
    s.description = childString(node, "description");
    for (const char* part : {"sensorVendor", "sensorModel", "sensorSerialNumber"}) {
      const std::string v = childString(node, part);
      if (!v.empty()) s.sensor += (s.sensor.empty() ? "" : " ") + v;
    }
    if (const pugi::xml_node pose = node.child("pose")) {
      const std::string ppath = path + "/pose";
      s.has_pose = true;
      if (const pugi::xml_node r = pose.child("rotation")) {
        const std::string rpath = ppath + "/rotation";
        Eigen::Quaterniond q(childNumber(r, "w", rpath).value_or(1.0), childNumber(r, "x", rpath).value_or(0.0),
                             childNumber(r, "y", rpath).value_or(0.0), childNumber(r, "z", rpath).value_or(0.0));
        const double norm = q.norm();
        if (!std::isfinite(norm) || norm < 1e-6)
          fail(rpath, "pose rotation is not a valid quaternion (norm " + std::to_string(norm) + ")");
        s.rotation = q.normalized();
      }
      if (const pugi::xml_node t = pose.child("translation")) {
        const std::string tpath = ppath + "/translation";
        s.translation = {childNumber(t, "x", tpath).value_or(0.0), childNumber(t, "y", tpath).value_or(0.0),
                         childNumber(t, "z", tpath).value_or(0.0)};
        if (!s.translation.allFinite()) fail(tpath, "pose translation is not finite");
      }
    }
    if (const pugi::xml_node l = node.child("intensityLimits"))
      s.intensity_limits = limits(l, "intensityMinimum", "intensityMaximum", path + "/intensityLimits");
    if (const pugi::xml_node l = node.child("colorLimits")) {
      const std::string lpath = path + "/colorLimits";
      auto r = limits(l, "colorRedMinimum", "colorRedMaximum", lpath);
      auto g = limits(l, "colorGreenMinimum", "colorGreenMaximum", lpath);
      auto b = limits(l, "colorBlueMinimum", "colorBlueMaximum", lpath);
      if (r && g && b) s.color_limits = std::array<Limits, 3>{*r, *g, *b};
    }
    if (const pugi::xml_node l = node.child("indexBounds")) {
      const std::string lpath = path + "/indexBounds";
      s.row_limits = limits(l, "rowMinimum", "rowMaximum", lpath);
      s.column_limits = limits(l, "columnMinimum", "columnMaximum", lpath);
    }
    const pugi::xml_node points = node.child("points");
    s.points_path = path + "/points";
    if (!points) fail(path, "scan has no 'points' element");
    if (type(points, s.points_path) != "CompressedVector")
      fail(s.points_path, "'points' is not a CompressedVector");
    s.points_offset = parseCount(points, "fileOffset", s.points_path);
    s.record_count = parseCount(points, "recordCount", s.points_path);
    const pugi::xml_node proto = points.child("prototype");
    if (!proto) fail(s.points_path, "CompressedVector has no 'prototype'");
    if (type(proto, s.points_path + "/prototype") != "Structure")
      fail(s.points_path + "/prototype", "prototype is not a Structure");
    prototypeFields(proto, "", s.points_path + "/prototype", s.fields);
    return s;
  }

 private:
  const std::filesystem::path& file_;
};

}  // namespace

FileInfo parseXml(const char* xml, std::size_t size, const std::filesystem::path& file,
                  std::uint64_t xml_logical_offset) {
  pugi::xml_document doc;
  const pugi::xml_parse_result res =
      doc.load_buffer(xml, size, pugi::parse_default | pugi::parse_ws_pcdata_single, pugi::encoding_utf8);
  if (!res) {
    const auto at = xml_logical_offset + static_cast<std::uint64_t>(std::max<std::ptrdiff_t>(res.offset, 0));
    throw FileError(file, std::string("malformed XML section: ") + res.description(),
                    atByte(logicalToPhysical(at), "XML section"));
  }
  XmlParser p(file);
  const pugi::xml_node root = doc.child("e57Root");
  if (!root) p.fail("/", "XML section has no e57Root element");
  p.type(root, "/e57Root");
  FileInfo info;
  info.guid = p.childString(root, "guid");
  info.library_version = p.childString(root, "e57LibraryVersion");
  info.coordinate_metadata = p.childString(root, "coordinateMetadata");
  if (const pugi::xml_node data3d = root.child("data3D")) {
    std::size_t k = 0;
    for (pugi::xml_node c = data3d.first_child(); c; c = c.next_sibling()) {
      if (c.type() != pugi::node_element) continue;
      info.scans.push_back(p.scan(c, "/e57Root/data3D/" + std::to_string(k++)));
    }
  }
  if (const pugi::xml_node images = root.child("images2D"))
    for (pugi::xml_node c = images.first_child(); c; c = c.next_sibling())
      if (c.type() == pugi::node_element) ++info.image_count;
  return info;
}

}  // namespace plumb::e57
