#include "quality/visibility_verdict.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace plumb {

namespace {

std::string percent(double ratio) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(1) << 100.0 * ratio << "%";
  return o.str();
}

/// The direction whose contradiction ratio the verdict uses.
const VisibilityEvidence& worstDirection(const VisibilitySummary& s, const VisibilityParams& p) {
  const auto& a = s.source_in_target;
  const auto& b = s.target_in_source;
  if (!b.conclusive(p)) return a;
  if (!a.conclusive(p)) return b;
  return b.contradiction_ratio > a.contradiction_ratio ? b : a;
}

/// "N% of the ... lie in space ... saw through (c of v visible points)".
std::string describeContradiction(const VisibilitySummary& s, const VisibilityEvidence& e,
                                  const VisibilityParams& p) {
  std::ostringstream o;
  o << percent(e.contradiction_ratio);
  if (s.model_target)
    o << " of the scan's rays that meet the model cross a wall, slab or roof of it more than "
         "the margin (" << p.min_margin << " m + " << 100.0 * p.range_margin
      << "% of the range, more at grazing incidence) before their measured point";
  else if (&e == &s.source_in_target)
    o << " of the source points the target's scanners could see lie in space those scanners "
         "saw through";
  else
    o << " of the target points the source's scanners could see lie in space those scanners "
         "saw through";
  o << " (" << e.contradicting << " of " << e.visible << ")";
  return o.str();
}

/// The direction whose unexplained structure the verdict uses.
const VisibilityEvidence& worstStructure(const VisibilitySummary& s, const VisibilityParams& p) {
  const auto& a = s.source_in_target;
  const auto& b = s.target_in_source;
  const bool use_b = b.conclusive(p) && b.structure.conclusive(p);
  const bool use_a = a.conclusive(p) && a.structure.conclusive(p);
  if (!use_b) return a;
  if (!use_a) return b;
  return b.structure.unexplained_area_ratio > a.structure.unexplained_area_ratio ? b : a;
}

/// "N% of the ... large planes ... (u of j m^2 in k of n planes)".
std::string describeStructure(const VisibilitySummary& s, const VisibilityEvidence& e) {
  const StructureEvidence& st = e.structure;
  std::ostringstream o;
  const bool source = &e == &s.source_in_target;
  o << percent(st.unexplained_area_ratio) << " of the " << (source ? "source" : "target")
    << "'s large planes (walls, floors, ceilings) that the "
    << (s.model_target ? "model" : source ? "target's scanners" : "source's scanners")
    << " could judge are unexplained: "
    << (s.model_target ? "crossed by the model's walls or standing where the model is empty"
                       : "mostly in space those scanners saw through")
    << " (" << std::lround(st.unexplained_area) << " of " << std::lround(st.judged_area)
    << " m2, " << st.unexplained_planes << " of " << st.judged_planes << " planes)";
  return o.str();
}

/// The sentence naming the evidence the verdict rests on.
std::string evidenceSentence(const VisibilitySummary& s, const FitFigures& fit) {
  std::ostringstream o;
  if (!s.computed) return "";
  if (!s.conclusive()) {
    const auto& e = s.source_in_target;
    o << " No free-space evidence ("
      << (e.available ? "too few points visible to the other side's scanners" : e.missing_reason)
      << "): this verdict rests on features and point residuals only, which cannot tell a wrong "
         "building from the right one.";
    return o.str();
  }
  o << " Free space agrees: " << percent(s.contradiction_ratio)
    << " of the visible points contradict the other side's free space";
  if (s.expected_overlap >= 0)
    o << "; visibility predicts " << percent(s.expected_overlap) << " of the source visible to "
      << (s.model_target ? "the model" : "the target's scanners");
  if (fit.refined) o << " (refinement matched " << percent(fit.overlap) << ")";
  if (s.unexplained_structure >= 0)
    o << "; " << percent(s.unexplained_structure)
      << " of the large planes it could judge are unexplained";
  o << ".";
  return o.str();
}

}  // namespace

FreeSpaceFinding judgeFreeSpace(const VisibilitySummary& s, const VisibilityParams& p,
                                const FitFigures& fit) {
  FreeSpaceFinding f;
  if (!s.computed) return f;
  if (s.conclusive() && s.contradiction_ratio > p.fail_ratio) {
    f.contradicted = true;
    f.failure = "Registration FAILED (contradicted): " +
                describeContradiction(s, worstDirection(s, p), p) +
                ", above the failure level of " + percent(p.fail_ratio) +
                ": the scanners would have seen through the other data. This is another "
                "building or a wrong placement, however well the surfaces match (point RMS " +
                std::to_string(static_cast<int>(std::lround(1000.0 * fit.point_rms))) +
                " mm). No transform is given; check that the two datasets show the same place.";
    return f;
  }
  if (s.unexplained_structure > p.structure_fail_ratio) {
    f.contradicted = true;
    f.failure = "Registration FAILED (contradicted): " +
                describeStructure(s, worstStructure(s, p)) + ", above the failure level of " +
                percent(p.structure_fail_ratio) +
                ": whole walls of one side have no counterpart in the other. This is another "
                "building or a wrong placement, however well the other surfaces match (point "
                "RMS " + std::to_string(static_cast<int>(std::lround(1000.0 * fit.point_rms))) +
                " mm). No transform is given; check that the two datasets show the same place.";
    return f;
  }
  if (s.unexplained_structure > p.structure_warn_ratio)
    f.warnings.push_back("structure: " + describeStructure(s, worstStructure(s, p)) +
                         ", above the warning level of " + percent(p.structure_warn_ratio) +
                         ": changed or moved walls, or a partly wrong placement; check visually");
  if (s.conclusive() && s.contradiction_ratio > p.warn_ratio)
    f.warnings.push_back("free space: " + describeContradiction(s, worstDirection(s, p), p) +
                         ", above the warning level of " + percent(p.warn_ratio) +
                         ": moving objects, glass, changes, or a partly wrong placement; check "
                         "visually");
  f.evidence = evidenceSentence(s, fit);
  return f;
}

namespace {

nlohmann::json structureJson(const StructureEvidence& e) {
  return nlohmann::json{{"available", e.available},
                        {"missing_reason", e.missing_reason},
                        {"large_planes", e.large_planes},
                        {"judged_planes", e.judged_planes},
                        {"unexplained_planes", e.unexplained_planes},
                        {"judged_area_m2", e.judged_area},
                        {"unexplained_area_m2", e.unexplained_area},
                        {"unexplained_area_ratio", e.unexplained_area_ratio},
                        {"point_ratio", e.point_ratio},
                        {"worst_plane_fraction", e.worst_plane_fraction},
                        {"worst_plane_area_m2", e.worst_plane_area}};
}

}  // namespace

void addVisibilityJson(nlohmann::json& j, const VisibilitySummary& s) {
  auto one = [](const VisibilityEvidence& e) {
    return nlohmann::json{{"available", e.available},
                          {"structure", structureJson(e.structure)},
                          {"missing_reason", e.missing_reason},
                          {"what", e.what},
                          {"stations", e.stations},
                          {"tested", e.tested},
                          {"visible", e.visible},
                          {"consistent", e.consistent},
                          {"contradicting", e.contradicting},
                          {"contradiction_ratio", e.contradiction_ratio},
                          {"agreement_ratio", e.agreement_ratio},
                          {"expected_overlap", e.expected_overlap},
                          {"seconds", e.seconds}};
  };
  j["visibility"] = {{"computed", s.computed},
                     {"model_target", s.model_target},
                     {"contradiction_ratio", s.conclusive() ? nlohmann::json(s.contradiction_ratio)
                                                            : nlohmann::json(nullptr)},
                     {"expected_overlap", s.expected_overlap >= 0
                                              ? nlohmann::json(s.expected_overlap)
                                              : nlohmann::json(nullptr)},
                     {"unexplained_structure", s.unexplained_structure >= 0
                                                   ? nlohmann::json(s.unexplained_structure)
                                                   : nlohmann::json(nullptr)},
                     {"source_in_target", one(s.source_in_target)},
                     {"target_in_source", one(s.target_in_source)}};
}

std::string visibilityToText(const VisibilitySummary& s) {
  if (!s.computed) return "";
  std::ostringstream o;
  for (const VisibilityEvidence* e : {&s.source_in_target, &s.target_in_source}) {
    if (e->what.empty()) continue;
    o << "free space, " << e->what << ": ";
    if (!e->available) {
      o << "no evidence (" << e->missing_reason << ")\n";
      continue;
    }
    o << e->contradicting << " contradicting, " << e->consistent << " consistent of "
      << e->tested << " tested (" << percent(e->contradiction_ratio) << " of the visible; "
      << "expected overlap " << percent(e->expected_overlap) << ", " << e->stations
      << " stations, " << std::setprecision(3) << e->seconds << " s)\n";
    const StructureEvidence& st = e->structure;
    if (st.available)
      o << "  its large planes: " << st.unexplained_planes << " of " << st.judged_planes
        << " judged unexplained (" << std::setprecision(3) << st.unexplained_area << " of "
        << st.judged_area << " m2, " << percent(st.unexplained_area_ratio) << ")\n";
  }
  return o.str();
}

}  // namespace plumb
