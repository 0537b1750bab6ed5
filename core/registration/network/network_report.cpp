#include "registration/network/network_report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace plumb {
namespace {

nlohmann::json matrixJson(const RigidTransform& t) { return nlohmann::json::parse(transformToJson(t)); }
nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// The adjustment's outcome of links[k], if it was adjusted.
const LinkOutcome* outcomeOf(const NetworkResult& r, std::size_t k) {
  for (std::size_t i = 0; i < r.adjusted.size(); ++i)
    if (r.adjusted[i] == k) return &r.adjustment.links[i];
  return nullptr;
}

nlohmann::json linkJson(const NetworkResult& r, const std::vector<Station>& st, std::size_t k) {
  const Link& l = r.links[k];
  nlohmann::json j = {{"a", st[l.a].name}, {"b", st[l.b].name}, {"reason", l.reason},
                      {"similarity", l.similarity}, {"method", l.method},
                      {"verdict_level", verdictLevelName(l.level)}, {"verdict", l.verdict}, {"status", l.status},
                      {"warnings", l.warnings}, {"overlap", l.overlap}, {"point_rms_m", l.point_rms},
                      {"weakest_resistance", l.weakest_resistance}, {"sigma_translation_m", l.sigma_translation},
                      {"sigma_rotation_deg", l.sigma_rotation_deg}, {"accepted", l.accepted},
                      {"seconds", l.seconds}};
  if (l.registered) j["transform"] = matrixJson(l.transform);
  if (!l.decision.empty()) j["decision"] = l.decision;  // "accepted" / "rejected" (by the surveyor)
  j["alternatives"] = nlohmann::json::array();
  for (const auto& alt : l.alternatives)
    j["alternatives"].push_back({{"role", alt.role}, {"overlap", alt.overlap}, {"point_rms_m", alt.point_rms},
                                 {"rotation_from_chosen_deg", RigidTransform::rotationErrorDeg(alt.transform, l.transform)},
                                 {"transform", matrixJson(alt.transform)}});
  const LinkOutcome* o = outcomeOf(r, k);
  j["flagged"] = o && o->flagged;
  j["dropped"] = o && o->dropped;
  if (o && o->dropped_by_control) j["dropped_by"] = "control points";
  j["bridge"] = o && o->bridge;
  if (o) {
    j["residual_translation_m"] = o->residual.translation;
    j["residual_rotation_deg"] = o->residual.rotation_deg;
    j["residual_sigma"] = o->residual.normalised;
    j["triangles_closing"] = o->triangles.closing;
    j["triangles_failing"] = o->triangles.failing;
  }
  return j;
}

/// Why the georeferencing left station i unplaced (Georeference::unplaced).
std::string unplacedByControlWhy(const Georeference& g, std::size_t i) {
  for (const auto& f : g.check_failures)
    if (f.station == i) {
      std::ostringstream o;
      o << std::fixed << std::setprecision(3) << "check point " << f.point << " it sees lies " << f.misfit
        << " m from its coordinates at this placement: the placement is wrong (or the target misidentified)";
      return o.str();
    }
  return "the control points contradict the links that placed it, and it sees fewer than 3 of them";
}

nlohmann::json tallyJson(const FreeSpaceTally& t) {
  return {{"visible", t.visible}, {"contradicting", t.contradicting}, {"ratio", t.ratio()}};
}

/// What the free-space judge found for station i (free_space_judge.hpp), or null.
nlohmann::json freeSpaceJson(const FreeSpaceJudgement& f, std::size_t i) {
  for (const auto& s : f.stations) {
    if (s.station != i) continue;
    nlohmann::json placements = nlohmann::json::array();
    for (const auto& p : s.placements)
      placements.push_back({{"source", p.source}, {"tally", tallyJson(p.tally)}, {"judged", p.judged},
                            {"clean", p.clean}});
    nlohmann::json j = {{"settled", s.settled}, {"why", s.why}, {"round", s.round}, {"placements", placements}};
    if (s.decided) j["decided"] = s.placements[*s.decided].source;
    return j;
  }
  return nullptr;
}

nlohmann::json stationJson(const NetworkResult& r, const std::vector<Station>& st, std::size_t i) {
  nlohmann::json links = nlohmann::json::array();
  for (std::size_t k = 0; k < r.links.size(); ++k)
    if (r.links[k].a == i || r.links[k].b == i) links.push_back(k);
  const bool ambiguous = r.isAmbiguous(i);
  nlohmann::json j = {{"name", st[i].name}, {"file", st[i].file}, {"scan", st[i].scan_index},
                      {"placed", r.placed(i)}, {"ambiguous", ambiguous}, {"model", st[i].is_model},
                      {"links", links}};
  if (st[i].subsample_voxel > 0) j["subsample_voxel_m"] = st[i].subsample_voxel;
  if (st[i].mms_pass >= 0)  // seconds after the pass's first point time
    j["mms_window_s"] = {{"pass", st[i].mms_pass}, {"start", st[i].window_start}, {"end", st[i].window_end}};
  if (std::binary_search(r.locked.begin(), r.locked.end(), i)) j["locked"] = true;
  if (std::binary_search(r.placed_by_own_control.begin(), r.placed_by_own_control.end(), i))
    j["placed_by"] = "own control points";  // no kept link joins it to the reference
  if (r.georeference && std::binary_search(r.georeference->settled.begin(), r.georeference->settled.end(), i))
    j["settled_by_control"] = true;  // sees 3 control points itself, all within the drop translation
  if (r.georeference && std::binary_search(r.georeference->unplaced.begin(), r.georeference->unplaced.end(), i))
    j["unplaced_why"] = unplacedByControlWhy(*r.georeference, i);
  if (auto f = freeSpaceJson(r.free_space, i); !f.is_null()) j["free_space"] = std::move(f);
  if (ambiguous)
    j["ambiguous_why"] =
        std::binary_search(r.competing.ambiguous.begin(), r.competing.ambiguous.end(), i)
            ? "competing: loop-checked links place it in two ways"
        : std::binary_search(r.one_loop.begin(), r.one_loop.end(), i)
            ? "one loop: a dropped link contradicted the only path placing it, and one loop cannot tell which "
              "link was wrong"
        : std::binary_search(r.contested.begin(), r.contested.end(), i)
            ? "contested: one link no loop checks placed it, and the free space of the confirmed stations "
              "contests that placement"
            : "copies: the BIM fits it in several places and only links no loop checks chose one";
  else if (std::binary_search(r.unchecked.begin(), r.unchecked.end(), i))
    j["unchecked"] = true;  // placed by one link no loop checks (a bridge)
  if (const auto& p = r.adjustment.poses[i]) {  // an ambiguous station keeps the adopted pose, for inspection
    j["pose"] = matrixJson(*p);
    j["transform"] = matrixJson(*stationTransform(r, st, i));
    j["sigma_position_m"] = vec(r.adjustment.sigma_position[i]);
    j["sigma_rotation_deg"] = vec(r.adjustment.sigma_rotation_deg[i]);
  }
  return j;
}

struct MeanMax {
  double sum = 0, max = 0;
  int n = 0;
  void add(double v) { sum += v, max = std::max(max, v), ++n; }
  double mean() const { return n ? sum / n : 0.0; }
};

nlohmann::json names(const std::vector<Station>& st, const std::vector<std::size_t>& idx) {
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t i : idx) j.push_back(st[i].name);
  return j;
}

nlohmann::json loopsJson(const NetworkResult& r, const std::vector<Station>& st, MeanMax& t, MeanMax& rot) {
  nlohmann::json loops = nlohmann::json::array();
  for (const auto& loop : r.adjustment.loops) {
    t.add(loop.translation), rot.add(loop.rotation_deg);
    loops.push_back({{"link", r.adjusted[loop.edge]}, {"stations", names(st, loop.nodes)},
                     {"translation_m", loop.translation}, {"rotation_deg", loop.rotation_deg}});
  }
  return loops;
}

nlohmann::json competingJson(const NetworkResult& r, const std::vector<Station>& st) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& c : r.competing.alternatives)
    out.push_back({{"link", r.adjusted[c.link]}, {"corroborated", c.corroborated}, {"competes", c.competes},
                   {"links_dropped", c.dropped}, {"sequence_links_dropped", c.dropped_sequence},
                   {"model_links_dropped", c.dropped_anchors},
                   {"stations_moved", names(st, c.stations)}, {"max_translation_m", c.max_translation},
                   {"max_rotation_deg", c.max_rotation_deg}});
  return out;
}

nlohmann::json networkJson(const NetworkResult& r, const std::vector<Station>& st) {
  MeanMax lt, lr, res;
  nlohmann::json loops = loopsJson(r, st, lt, lr);
  std::size_t tried = 0, registered = 0, flagged = 0, bridges = 0;
  for (const auto& l : r.links)
    if (l.reason != kFinalRefinementReason) ++tried, registered += l.registered;  // pairs the pipeline registered
  std::vector<std::size_t> dropped;
  for (std::size_t i = 0; i < r.adjusted.size(); ++i) {
    const auto& o = r.adjustment.links[i];
    if (o.dropped) dropped.push_back(r.adjusted[i]);
    else res.add(o.residual.translation), flagged += o.flagged, bridges += o.bridge;
  }
  nlohmann::json parts = nlohmann::json::array();
  for (const auto& p : r.parts) parts.push_back(names(st, p));
  return {{"stations", st.size()}, {"pairs_all", r.all_pairs}, {"pairs_registered", tried},
          {"links_registered", registered}, {"links_accepted", r.adjusted.size()}, {"links_dropped", dropped},
          {"links_flagged", flagged}, {"links_unchecked", bridges}, {"rounds", r.rounds}, {"loop_closures", loops},
          {"loop_translation_mean_m", lt.mean()}, {"loop_translation_max_m", lt.max},
          {"loop_rotation_mean_deg", lr.mean()}, {"loop_rotation_max_deg", lr.max},
          {"residual_translation_mean_m", res.mean()}, {"residual_translation_max_m", res.max},
          {"unplaced", names(st, r.unplaced)}, {"ambiguous", names(st, r.ambiguous())},
          {"copies_unchecked", names(st, r.copies_unchecked)}, {"one_loop", names(st, r.one_loop)},
          {"unchecked", names(st, r.unchecked)}, {"contested", names(st, r.contested)},
          {"placed_by_own_control", names(st, r.placed_by_own_control)},
          {"settled_by_free_space", names(st, r.free_space.settled)}, {"seconds_free_space", r.free_space.seconds},
          {"competing", competingJson(r, st)}, {"parts", parts}, {"solves", r.adjustment.solves},
          {"converged", r.adjustment.converged}, {"covariance", r.adjustment.covariance_ok},
          {"solver", r.adjustment.message}, {"seconds_features", r.seconds_features},
          {"seconds_links", r.seconds_links}, {"seconds_adjustment", r.seconds_adjustment}};
}

/// The frame the stations come out in: the reference station's, or the control points'.
std::string referenceName(const NetworkResult& r, const std::vector<Station>& st) {
  return r.georeference && r.georeference->done ? "control points" : st[r.reference].name;
}

nlohmann::json checkFailuresJson(const Georeference& g, const std::vector<Station>& st) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& f : g.check_failures)
    out.push_back({{"point", f.point}, {"station", st[f.station].name}, {"misfit_m", f.misfit}});
  return out;
}

nlohmann::json georeferenceJson(const Georeference& g, const std::vector<Station>& st) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : g.points) {
    nlohmann::json j = {{"name", p.point}, {"role", p.check ? "check" : "control"}, {"observations", p.observations}};
    if (p.observations > 0)
      j.update({{"residual_ground_m", vec(p.ground)}, {"residual_grid_m", vec(p.grid)}, {"residual_m", p.ground.norm()}});
    points.push_back(j);
  }
  return {{"done", g.done}, {"message", g.message}, {"crs", g.grid.crs}, {"scale_factor", g.grid.scale_factor},
          {"origin_grid", vec(g.grid.origin)},
          {"coordinates", "ground frame moved to origin_grid: grid coordinates at that point, ground distances "
                          "about it (grid = origin + scale_factor x horizontal offset)"},
          {"control_used", g.control_used}, {"control_rms_m", g.control_rms}, {"check_max_m", g.check_max},
          {"links_dropped", g.links_dropped}, {"points", points}, {"check_failures", checkFailuresJson(g, st)}};
}

void georeferenceText(const nlohmann::json& g, std::ostringstream& o) {
  o << "georeference: " << g["message"].get<std::string>() << ", grid scale factor " << std::setprecision(8)
    << g["scale_factor"].get<double>() << "\n";
  for (const auto& p : g["points"]) {
    o << "  " << p["role"].get<std::string>() << " " << p["name"].get<std::string>() << ": ";
    if (p["observations"].get<std::size_t>() == 0) {
      o << "not seen by a placed station\n";
      continue;
    }
    const auto& d = p["residual_grid_m"];
    o << std::setprecision(1) << p["observations"] << " station(s), residual dE " << 1000 * d[0].get<double>()
      << " dN " << 1000 * d[1].get<double>() << " dH " << 1000 * d[2].get<double>() << " mm\n";
  }
  if (g["done"].get<bool>())
    o << std::setprecision(1) << "  control RMS " << 1000 * g["control_rms_m"].get<double>() << " mm, check max "
      << 1000 * g["check_max_m"].get<double>() << " mm\n";
  for (const auto& f : g["check_failures"])
    o << std::setprecision(3) << "  CHECK FAILED: " << f["point"].get<std::string>() << " seen by "
      << f["station"].get<std::string>() << " lies " << f["misfit_m"].get<double>()
      << " m from its coordinates: the station is not placed\n";
}

}  // namespace

int networkExitCode(const NetworkResult& r) {
  if (!r.complete()) return 2;
  for (const auto& o : r.adjustment.links)
    if (o.flagged && !o.dropped) return 3;
  return 0;
}

std::optional<RigidTransform> stationTransform(const NetworkResult& r, const std::vector<Station>& st, std::size_t i) {
  if (!r.adjustment.poses[i]) return std::nullopt;  // ambiguous stations keep it (the report shows it)
  return *r.adjustment.poses[i] * st[i].file_pose.inverse();
}

nlohmann::json networkReportToJson(const NetworkResult& r, const std::vector<Station>& st) {
  nlohmann::json j = {{"format", "plumb-network-report"}, {"version", 1}, {"complete", r.complete()},
                      {"exit_code", networkExitCode(r)}, {"reference", referenceName(r, st)}};
  j["stations"] = nlohmann::json::array();
  for (std::size_t i = 0; i < st.size(); ++i) j["stations"].push_back(stationJson(r, st, i));
  j["links"] = nlohmann::json::array();
  for (std::size_t k = 0; k < r.links.size(); ++k) j["links"].push_back(linkJson(r, st, k));
  j["network"] = networkJson(r, st);
  if (r.georeference) j["georeference"] = georeferenceJson(*r.georeference, st);
  if (r.final_refinement.done)
    j["final_refinement"] = {{"pairs_tried", r.final_refinement.pairs_tried},
                             {"pairs_used", r.final_refinement.pairs_used},
                             {"seconds", r.final_refinement.seconds}};
  return j;
}

std::string networkReportToText(const NetworkResult& r, const std::vector<Station>& st) {
  std::ostringstream o;
  o << std::fixed;
  const nlohmann::json j = networkReportToJson(r, st);
  for (const auto& l : j["links"]) {
    o << "link " << l["a"].get<std::string>() << " - " << l["b"].get<std::string>() << ": "
      << l["verdict_level"].get<std::string>() << " (" << l["method"].get<std::string>() << ")";
    if (!l["accepted"].get<bool>() && l["status"] != "success") o << " " << l["status"].get<std::string>();
    if (l["accepted"].get<bool>())
      o << std::setprecision(1) << ", overlap " << 100 * l["overlap"].get<double>() << "%, RMS "
        << 1000 * l["point_rms_m"].get<double>() << " mm, residual " << 1000 * l.value("residual_translation_m", 0.0)
        << " mm / " << std::setprecision(4) << l.value("residual_rotation_deg", 0.0) << " deg";
    if (l["dropped"].get<bool>())
      o << (l.contains("dropped_by") ? "  DROPPED (the control points contradict it)" : "  DROPPED (disagrees with the network)");
    else if (l["flagged"].get<bool>()) o << "  FLAGGED (disagrees with the network)";
    else if (l["bridge"].get<bool>()) o << "  (no loop checks it)";
    if (l.contains("decision"))
      o << (l["decision"] == kFreeSpaceDecision ? "  [taken as true: the free space of the placed stations chose it]"
                                                : "  [" + l["decision"].get<std::string>() + " by the surveyor]");
    o << "\n";
  }
  for (const auto& s : j["stations"]) {
    o << "station " << s["name"].get<std::string>() << ": ";
    if (s["ambiguous"].get<bool>()) {
      o << "AMBIGUOUS (" << s["ambiguous_why"].get<std::string>() << ")";
      if (s.contains("free_space")) o << "; not settled by the free space: " << s["free_space"]["why"].get<std::string>();
      o << "\n";
      continue;
    }
    if (!s["placed"].get<bool>()) {
      o << "NOT PLACED (" << s.value("unplaced_why", "no accepted link joins it to the reference") << ")\n";
      continue;
    }
    const auto& sp = s["sigma_position_m"];
    if (s.value("locked", false)) o << "locked, ";
    if (s.contains("placed_by")) o << "placed by its own control points (no link to the reference), ";
    if (s.value("settled_by_control", false)) o << "confirmed by the 3+ control points it sees, ";
    if (s.contains("free_space") && s["free_space"]["settled"].get<bool>())
      o << (s.value("unchecked", false) ? "one unchecked link placed it, " : "ambiguous by its links, ")
        << s["free_space"]["why"].get<std::string>() << ", ";
    else if (s.value("unchecked", false))
      o << "placed by one link no loop checks, not confirmed by the free space, ";
    o << std::setprecision(2) << "sigma " << 1000 * sp[0].get<double>() << ", " << 1000 * sp[1].get<double>() << ", "
      << 1000 * sp[2].get<double>() << " mm\n";
  }
  const auto& n = j["network"];
  o << std::setprecision(2) << "network: " << st.size() << " stations, reference " << referenceName(r, st) << ", "
    << n["pairs_registered"] << " of " << n["pairs_all"] << " pairs registered, " << n["links_accepted"]
    << " links accepted, " << n["links_dropped"].size() << " dropped; " << n["loop_closures"].size()
    << " loops, closure mean " << 1000 * n["loop_translation_mean_m"].get<double>() << " mm, max "
    << 1000 * n["loop_translation_max_m"].get<double>() << " mm\n";
  if (j.contains("georeference")) georeferenceText(j["georeference"], o);
  for (const auto& c : n["competing"]) {
    if (!c["competes"].get<bool>()) continue;
    const auto& l = j["links"][c["link"].get<std::size_t>()];
    o << "competing: with link " << l["a"].get<std::string>() << " - " << l["b"].get<std::string>()
      << " taken as true, loops confirm a second placement moving " << c["stations_moved"].size()
      << " station(s) by up to " << c["max_translation_m"].get<double>() << " m / "
      << c["max_rotation_deg"].get<double>() << " deg\n";
  }
  return o.str();
}

}  // namespace plumb
