#include "io/mesh/ifc_georef.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "io/mesh/step_entities.hpp"

namespace plumb::ifc_georef {
namespace {

constexpr double kThresholdMetres = 100.0;
constexpr std::uint64_t kLargestId = std::uint64_t{1} << 62;  ///< real files stay below 10^9

/// The entities the plan reads, by id, and where the DATA section ends.
struct Index {
  std::unordered_map<std::uint64_t, step::Entity> by_id;
  std::vector<std::uint64_t> top_level;  ///< IfcLocalPlacement with PlacementRelTo $
  std::uint64_t site = 0, project = 0, max_id = 0;
  std::size_t last_end = 0;
  /// Every entity of the text was seen (step::forEachEntity), and no two of those read here
  /// share an id.
  bool whole = true;
};

/// Stores `e`; another entity with its id makes the index not whole.
void keep(Index& ix, const step::Entity& e) {
  const auto [at, added] = ix.by_id.emplace(e.id, e);
  if (!added && at->second.begin != e.begin) ix.whole = false;
}

bool isHeadEntity(std::string_view type) {
  static const char* const types[] = {"IFCLOCALPLACEMENT", "IFCSITE", "IFCPROJECT", "IFCUNITASSIGNMENT",
                                      "IFCSIUNIT", "IFCGEOMETRICREPRESENTATIONCONTEXT"};
  return std::any_of(std::begin(types), std::end(types), [&](const char* t) { return type == t; });
}

/// Adds the entities whose ids are in `wanted` (one more pass over the text).
void collectWanted(std::string_view text, const std::unordered_set<std::uint64_t>& wanted, Index& ix) {
  if (wanted.empty()) return;
  step::forEachEntity(text, [&](const step::Entity& e) {
    if (wanted.count(e.id)) keep(ix, e);
  });
}

/// The ids that the arguments `which` of the entities `ids` refer to.
std::unordered_set<std::uint64_t> referenced(const Index& ix, const std::vector<std::uint64_t>& ids,
                                             std::initializer_list<std::size_t> which) {
  std::unordered_set<std::uint64_t> out;
  for (const auto id : ids) {
    const auto it = ix.by_id.find(id);
    if (it == ix.by_id.end()) continue;
    const auto args = step::splitArguments(it->second.args);
    for (const auto i : which)
      if (i < args.size() && step::reference(args[i])) out.insert(step::reference(args[i]));
  }
  return out;
}

/// Three passes, so that memory stays small on big files: the few head entities (placements
/// at the top, site, project, units, contexts), then their axis placements, then the points
/// and directions of those.
Index buildIndex(std::string_view text) {
  Index ix;
  const bool scanned = step::forEachEntity(text, [&](const step::Entity& e) {
    ix.max_id = std::max(ix.max_id, e.id);
    ix.last_end = e.end;
    if (!isHeadEntity(e.type)) return;
    const bool top = e.type == "IFCLOCALPLACEMENT" && step::splitArguments(e.args)[0] == "$";
    if (e.type == "IFCLOCALPLACEMENT" && !top) return;
    keep(ix, e);
    if (top) ix.top_level.push_back(e.id);
    if (e.type == "IFCSITE" && !ix.site) ix.site = e.id;
    if (e.type == "IFCPROJECT" && !ix.project) ix.project = e.id;
  });
  ix.whole = ix.whole && scanned;
  std::vector<std::uint64_t> contexts;
  for (const auto& [id, e] : ix.by_id)
    if (e.type == "IFCGEOMETRICREPRESENTATIONCONTEXT") contexts.push_back(id);
  auto placements = referenced(ix, ix.top_level, {1});
  for (const auto id : referenced(ix, contexts, {4})) placements.insert(id);
  collectWanted(text, placements, ix);
  const std::vector<std::uint64_t> placement_ids(placements.begin(), placements.end());
  collectWanted(text, referenced(ix, placement_ids, {0, 1, 2}), ix);
  return ix;
}

const step::Entity* find(const Index& ix, std::string_view ref, std::string_view type) {
  const auto it = ix.by_id.find(step::reference(ref));
  return it != ix.by_id.end() && it->second.type == type ? &it->second : nullptr;
}

std::string_view arg(const step::Entity& e, std::size_t i) {
  const auto a = step::splitArguments(e.args);
  return i < a.size() ? a[i] : std::string_view("$");
}

/// "(1.,2.,3.)" -> numbers; missing coordinates are 0; nullopt when one is not a finite number.
std::optional<Eigen::Vector3d> triple(std::string_view list) {
  if (list.size() < 2 || list.front() != '(' || list.back() != ')') return std::nullopt;
  const auto parts = step::splitArguments(list.substr(1, list.size() - 2));
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < parts.size() && i < 3; ++i) {
    const std::string s(parts[i]);
    char* end = nullptr;
    v[static_cast<int>(i)] = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || !std::isfinite(v[static_cast<int>(i)])) return std::nullopt;
  }
  return v;
}

std::optional<Eigen::Vector3d> point(const Index& ix, std::string_view ref, std::string_view type) {
  const step::Entity* e = find(ix, ref, type);
  return e ? triple(arg(*e, 0)) : std::nullopt;
}

/// An IfcAxis2Placement3D: location and rotation (axis = Z, ref direction = X).
struct Placement {
  const step::Entity* entity = nullptr;
  Eigen::Vector3d location = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

std::optional<Placement> placement(const Index& ix, std::string_view ref) {
  Placement p;
  p.entity = find(ix, ref, "IFCAXIS2PLACEMENT3D");
  if (!p.entity) return std::nullopt;
  const auto loc = point(ix, arg(*p.entity, 0), "IFCCARTESIANPOINT");
  if (!loc) return std::nullopt;
  p.location = *loc;
  const Eigen::Vector3d z = point(ix, arg(*p.entity, 1), "IFCDIRECTION").value_or(Eigen::Vector3d::UnitZ()).normalized();
  Eigen::Vector3d x = point(ix, arg(*p.entity, 2), "IFCDIRECTION").value_or(Eigen::Vector3d::UnitX());
  x = (x - x.dot(z) * z).normalized();
  p.rotation << x, z.cross(x), z;
  return p;
}

/// assimp's length scale: the last IfcSIUnit LENGTHUNIT of the project's units, by prefix.
double lengthScale(const Index& ix, const step::Entity& project) {
  static const std::map<std::string_view, double> prefixes = {
      {"$", 1.0},     {".KILO.", 1e3},  {".HECTO.", 1e2}, {".DECA.", 1e1},  {".DECI.", 1e-1},
      {".CENTI.", 1e-2}, {".MILLI.", 1e-3}, {".MICRO.", 1e-6}};
  double scale = 1.0;
  const step::Entity* units = find(ix, arg(project, 8), "IFCUNITASSIGNMENT");
  if (!units) return scale;
  step::forEachReference(arg(*units, 0), [&](std::uint64_t id) {
    const auto it = ix.by_id.find(id);
    if (it == ix.by_id.end() || it->second.type != "IFCSIUNIT" || arg(it->second, 1) != ".LENGTHUNIT.") return;
    const auto p = prefixes.find(arg(it->second, 2));
    if (p != prefixes.end()) scale = p->second;
  });
  return scale;
}

/// The context assimp takes its world coordinate system from.
const step::Entity* worldContext(const Index& ix, const step::Entity& project) {
  const step::Entity* chosen = nullptr;
  step::forEachReference(arg(project, 7), [&](std::uint64_t id) {
    if (chosen && arg(*chosen, 1) == "'Model'") return;
    const auto it = ix.by_id.find(id);
    if (it != ix.by_id.end() && it->second.type == "IFCGEOMETRICREPRESENTATIONCONTEXT") chosen = &it->second;
  });
  return chosen;
}

std::string stepReal(double v) {
  char buf[64];
  std::string s(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  const auto e = s.find('e');
  if (s.find('.') == std::string::npos) s.insert(e == std::string::npos ? s.size() : e, ".");
  std::replace(s.begin(), s.end(), 'e', 'E');
  return s;
}

/// Builds the rewritten file: entity replacements plus new entities at the end of DATA.
struct Rewrite {
  std::uint64_t next_id;
  std::map<std::size_t, std::pair<std::size_t, std::string>> replaced;  ///< begin -> (end, text)
  std::string appended;

  std::uint64_t add(const std::string& type_and_args) {
    appended += "#" + std::to_string(next_id) + "=" + type_and_args + ";\n";
    return next_id++;
  }
  /// `e` with its arguments replaced, keeping its line count.
  void replaceArgs(const step::Entity& e, std::string_view text, const std::vector<std::string_view>& args) {
    std::string s = "#" + std::to_string(e.id) + "=" + std::string(e.type) + "(";
    for (std::size_t i = 0; i < args.size(); ++i) s += (i ? "," : "") + std::string(args[i]);
    s += ");" + std::string(static_cast<std::size_t>(std::count(text.begin() + e.begin, text.begin() + e.end, '\n')), '\n');
    replaced[e.begin] = {e.end, s};
  }
  /// A copy of placement `p` at `location`; returns its id.
  std::uint64_t movedPlacement(const Placement& p, const Eigen::Vector3d& location) {
    const auto pt = add("IFCCARTESIANPOINT((" + stepReal(location.x()) + "," + stepReal(location.y()) + "," +
                        stepReal(location.z()) + "))");
    auto args = step::splitArguments(p.entity->args);
    args.resize(3, "$");
    return add("IFCAXIS2PLACEMENT3D(#" + std::to_string(pt) + "," + std::string(args[1]) + "," + std::string(args[2]) + ")");
  }
  /// The text with the replacements, and the new entities after the last one (`last_end`: not
  /// before the ENDSEC, which might be inside a comment).
  std::string apply(std::string_view text, std::size_t last_end) const {
    std::string out;
    out.reserve(text.size() + appended.size());
    std::size_t at = 0;
    for (const auto& [begin, r] : replaced) {
      out.append(text.substr(at, begin - at));
      out += r.second;
      at = r.first;
    }
    out.append(text.substr(at, last_end - at));
    out += "\n" + appended;
    out.append(text.substr(last_end));
    return out;
  }
};

/// Moves every top-level placement by -t; false if one is not an understood IfcAxis2Placement3D.
bool moveTopLevel(const Index& ix, std::string_view text, const Eigen::Vector3d& t, Rewrite& rw) {
  for (const auto id : ix.top_level) {
    const step::Entity& local = ix.by_id.at(id);
    auto args = step::splitArguments(local.args);
    const auto p = args.size() == 2 ? placement(ix, args[1]) : std::nullopt;
    if (!p || !(p->location - t).allFinite()) return false;
    const std::string ref = "#" + std::to_string(rw.movedPlacement(*p, p->location - t));
    args[1] = ref;
    rw.replaceArgs(local, text, args);
  }
  return true;
}

}  // namespace

double lengthUnit(std::string_view text) {
  const Index ix = buildIndex(text);
  const auto project = ix.by_id.find(ix.project);
  return project == ix.by_id.end() ? 1.0 : lengthScale(ix, project->second);
}

std::optional<Shift> plan(std::string_view text) {
  const Index ix = buildIndex(text);
  const auto project = ix.by_id.find(ix.project);
  // A damaged text (a string or comment left open, an instance not of the #id=TYPE(...) shape)
  // may hide entities whose ids the new ones would take, and two entities with one id leave
  // it unclear which the plan should read; ids near 2^64 would wrap.
  if (!ix.whole || ix.max_id >= kLargestId || project == ix.by_id.end()) return std::nullopt;
  const step::Entity* context = worldContext(ix, project->second);
  const auto wcs = context ? placement(ix, arg(*context, 4)) : std::nullopt;
  if (context && !wcs) return std::nullopt;  // an IfcAxis2Placement2D world system, say
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  if (const step::Entity* site = ix.site ? &ix.by_id.at(ix.site) : nullptr) {
    const auto local = find(ix, arg(*site, 5), "IFCLOCALPLACEMENT");
    if (local && arg(*local, 0) == "$") {
      const auto p = placement(ix, arg(*local, 1));
      if (p) t = p->location;
    }
  }
  const Eigen::Vector3d w = wcs ? wcs->location : Eigen::Vector3d::Zero();
  const Eigen::Matrix3d r = wcs ? wcs->rotation : Eigen::Matrix3d::Identity();
  Shift shift;
  shift.metres = lengthScale(ix, project->second) * (r * t + w);
  if (!shift.metres.allFinite() || shift.metres.cwiseAbs().maxCoeff() < kThresholdMetres) return std::nullopt;
  Rewrite rw{ix.max_id + 1, {}, {}};
  if (!t.isZero() && !moveTopLevel(ix, text, t, rw)) return std::nullopt;
  if (!w.isZero()) {
    auto args = step::splitArguments(context->args);
    const std::string ref = "#" + std::to_string(rw.movedPlacement(*wcs, Eigen::Vector3d::Zero()));
    args[4] = ref;
    rw.replaceArgs(*context, text, args);
  }
  if (text.find("ENDSEC", ix.last_end) == std::string_view::npos) return std::nullopt;
  shift.text = rw.apply(text, ix.last_end);
  return shift;
}

}  // namespace plumb::ifc_georef
