#include "features/export/feature_export.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "features/planes/plane_fit.hpp"

namespace plumb {
namespace {

using nlohmann::json;

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

Eigen::Vector3d toVec(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    throw InputError("feature JSON: " + what + " must be an array of 3 numbers");
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

const json& member(const json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key))
    throw InputError("feature JSON: " + where + " has no '" + key + "'");
  return j.at(key);
}

}  // namespace

json featureSetToJson(const FeatureSet& fs, bool with_inliers) {
  json planes = json::array();
  for (const auto& p : fs.planes) {
    json rings = json::array();
    for (const auto& ring : p.rings) {
      json r = json::array();
      for (const auto& uv : ring) r.push_back(vec(p.to3d(uv)));
      rings.push_back(std::move(r));
    }
    planes.push_back({{"normal", vec(p.normal)},
                      {"offset", p.offset},
                      {"inlier_count", p.inlier_count},
                      {"area", p.area},
                      {"centroid", vec(p.centroid)},
                      {"rings", std::move(rings)}});
    if (with_inliers) planes.back()["inliers"] = p.inliers;
  }
  json openings = json::array();
  for (const auto& o : fs.openings) {
    json corners = json::array();
    for (const auto& c : o.corners) corners.push_back(vec(c));
    openings.push_back({{"corners", std::move(corners)},
                        {"facade", o.facade},
                        {"evidence_count", o.evidence_count}});
  }
  json segments = json::array();
  for (const auto& s : fs.segments)
    segments.push_back({{"a", vec(s.a)}, {"b", vec(s.b)}, {"support", s.support}});
  return {{"planes", std::move(planes)},
          {"facades", fs.facades},
          {"openings", std::move(openings)},
          {"segments", std::move(segments)}};
}

FeatureSet featureSetFromJson(const json& j) {
  if (!j.is_object()) throw InputError("feature JSON: the top level must be an object");
  FeatureSet fs;
  if (j.contains("planes")) {
    std::size_t k = 0;
    for (const auto& jp : j.at("planes")) {
      const std::string where = "planes[" + std::to_string(k++) + "]";
      PlanarPolygon p;
      p.normal = toVec(member(jp, "normal", where), where + ".normal").normalized();
      p.offset = member(jp, "offset", where).get<double>();
      p.inlier_count = jp.value("inlier_count", std::size_t(0));
      p.area = jp.value("area", 0.0);
      p.centroid = jp.contains("centroid") ? toVec(jp.at("centroid"), where + ".centroid")
                                           : Eigen::Vector3d(p.offset * p.normal);
      setPlaneFrame(p);
      if (jp.contains("rings"))
        for (const auto& jr : jp.at("rings")) {
          std::vector<Eigen::Vector2d> ring;
          for (const auto& jv : jr) ring.push_back(p.to2d(toVec(jv, where + ".rings")));
          p.rings.push_back(std::move(ring));
        }
      if (jp.contains("inliers")) p.inliers = jp.at("inliers").get<std::vector<std::uint32_t>>();
      fs.planes.push_back(std::move(p));
    }
  }
  if (j.contains("facades")) fs.facades = j.at("facades").get<std::vector<int>>();
  if (j.contains("openings")) {
    std::size_t k = 0;
    for (const auto& jo : j.at("openings")) {
      const std::string where = "openings[" + std::to_string(k++) + "]";
      Opening o;
      const auto& c = member(jo, "corners", where);
      if (!c.is_array() || c.size() != 4) throw InputError("feature JSON: " + where + ".corners must hold 4 points");
      for (int i = 0; i < 4; ++i) o.corners[i] = toVec(c[i], where + ".corners");
      o.facade = jo.value("facade", -1);
      o.evidence_count = jo.value("evidence_count", std::size_t(0));
      fs.openings.push_back(o);
    }
  }
  if (j.contains("segments")) {
    std::size_t k = 0;
    for (const auto& js : j.at("segments")) {
      const std::string where = "segments[" + std::to_string(k++) + "]";
      Segment3D s;
      s.a = toVec(member(js, "a", where), where + ".a");
      s.b = toVec(member(js, "b", where), where + ".b");
      s.support = js.value("support", 0.0);
      fs.segments.push_back(s);
    }
  }
  return fs;
}

void writeFeatureSetJson(const std::filesystem::path& path, const FeatureSet& features,
                         bool with_inliers) {
  const json j = featureSetToJson(features, with_inliers);
  const std::string text = with_inliers ? j.dump() : j.dump(1);
  writeFileAtomically(path, [&](std::ostream& out) { out << text << '\n'; });
}

void writeFeatureSetPly(const std::filesystem::path& path, const FeatureSet& fs) {
  struct V {
    Eigen::Vector3d p;
    Rgb8 c;
  };
  std::vector<V> verts;
  std::vector<std::array<std::size_t, 2>> edges;
  auto addLoop = [&](const std::vector<Eigen::Vector3d>& pts, Rgb8 c, bool closed) {
    const std::size_t base = verts.size();
    for (const auto& p : pts) verts.push_back({p, c});
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) edges.push_back({base + i, base + i + 1});
    if (closed && pts.size() > 2) edges.push_back({base + pts.size() - 1, base});
  };
  for (std::size_t k = 0; k < fs.planes.size(); ++k) {
    const auto& p = fs.planes[k];
    // A stable pseudo-random colour per plane.
    const std::uint32_t h = static_cast<std::uint32_t>(k * 2654435761u);
    const Rgb8 c{static_cast<std::uint8_t>(64 + (h >> 8) % 192), static_cast<std::uint8_t>(64 + (h >> 16) % 192),
                 static_cast<std::uint8_t>(64 + (h >> 24) % 192)};
    for (const auto& ring : p.rings) {
      std::vector<Eigen::Vector3d> pts;
      for (const auto& uv : ring) pts.push_back(p.to3d(uv));
      addLoop(pts, c, true);
    }
  }
  for (const auto& o : fs.openings)
    addLoop({o.corners.begin(), o.corners.end()}, Rgb8{255, 0, 0}, true);
  for (const auto& s : fs.segments) addLoop({s.a, s.b}, Rgb8{255, 220, 0}, false);
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "ply\nformat ascii 1.0\ncomment plumb features: plane rings, openings (red), "
           "segments (yellow)\n";
    out << "element vertex " << verts.size()
        << "\nproperty double x\nproperty double y\nproperty double z\n"
           "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    out << "element edge " << edges.size() << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    out.precision(10);
    for (const auto& v : verts)
      out << v.p.x() << ' ' << v.p.y() << ' ' << v.p.z() << ' ' << int(v.c[0]) << ' ' << int(v.c[1])
          << ' ' << int(v.c[2]) << '\n';
    for (const auto& e : edges) out << e[0] << ' ' << e[1] << '\n';
  });
}

void writeFeatureSet(const std::filesystem::path& path, const FeatureSet& features) {
  auto ext = path.extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".json") return writeFeatureSetJson(path, features);
  if (ext == ".ply") return writeFeatureSetPly(path, features);
  throw FileError(path, "unsupported feature file extension '" + ext + "' (use .json or .ply)");
}

FeatureSet readFeatureSetJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open feature file");
  json j;
  try {
    in >> j;
  } catch (const json::parse_error& e) {
    throw FileError(path, std::string("invalid JSON: ") + e.what(), atByte(e.byte));
  }
  try {
    return featureSetFromJson(j);
  } catch (const InputError& e) {
    throw FileError(path, e.what());
  } catch (const json::exception& e) {
    throw FileError(path, std::string("wrong value type: ") + e.what());
  }
}

}  // namespace plumb
