#include "registration/network/competing_placements.hpp"

#include <algorithm>
#include <set>

namespace plumb {
namespace {

/// Links of one kind (sequence, anchor: links to the BIM) that `adj` dropped.
std::size_t droppedLinks(const std::vector<AdjustmentLink>& links, const NetworkAdjustment& adj,
                         bool AdjustmentLink::*kind) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < links.size(); ++k) n += adj.links[k].dropped && links[k].*kind;
  return n;
}

/// Stations both solutions place, whose poses differ beyond the drop thresholds.
void compareStations(const NetworkAdjustment& adopted, const NetworkAdjustment& alternative,
                     const PoseGraphParams& params, CompetingPlacement& out) {
  for (std::size_t i = 0; i < adopted.poses.size(); ++i) {
    if (!adopted.poses[i] || !alternative.poses[i]) continue;
    const double t = RigidTransform::translationError(*adopted.poses[i], *alternative.poses[i]);
    const double r = RigidTransform::rotationErrorDeg(*adopted.poses[i], *alternative.poses[i]);
    if (t <= params.drop_translation && r <= params.drop_rotation) continue;
    out.stations.push_back(i);
    out.max_translation = std::max(out.max_translation, t);
    out.max_rotation_deg = std::max(out.max_rotation_deg, r);
  }
}

/// What the adopted solution gave up: links to the BIM and sequence links it dropped.
struct GivenUp {
  std::size_t anchors = 0, sequence = 0;
};

CompetingPlacement alternativeFor(std::size_t link, std::size_t stations, const std::vector<AdjustmentLink>& links,
                                  std::size_t reference, const RigidTransform& reference_pose,
                                  const PoseGraphParams& params, const NetworkAdjustment& adopted,
                                  const GivenUp& adopted_gave_up) {
  const NetworkAdjustment alt = adjustNetwork(stations, links, reference, reference_pose, params, {link});
  CompetingPlacement c;
  c.link = link;
  c.corroborated = !alt.links[link].bridge;
  c.dropped = alt.dropped_order.size();
  c.dropped_sequence = droppedLinks(links, alt, &AdjustmentLink::sequence);
  c.dropped_anchors = droppedLinks(links, alt, &AdjustmentLink::anchor);
  compareStations(adopted, alt, params, c);
  c.poses = alt.poses;
  // The adopted solution wins outright when it gives up fewer links to the BIM, or as many and
  // fewer sequence links.
  const auto [anchors, sequence] = adopted_gave_up;
  const bool dominated = anchors < c.dropped_anchors || (anchors == c.dropped_anchors && sequence < c.dropped_sequence);
  c.competes = c.corroborated && !dominated && !c.stations.empty();
  return c;
}

}  // namespace

CompetingPlacements findCompetingPlacements(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                            std::size_t reference, const RigidTransform& reference_pose,
                                            const PoseGraphParams& params, const NetworkAdjustment& adopted) {
  CompetingPlacements out;
  std::set<std::size_t> ambiguous;
  const GivenUp gave_up{droppedLinks(links, adopted, &AdjustmentLink::anchor),
                        droppedLinks(links, adopted, &AdjustmentLink::sequence)};
  for (std::size_t link : adopted.dropped_order) {
    out.alternatives.push_back(
        alternativeFor(link, stations, links, reference, reference_pose, params, adopted, gave_up));
    const CompetingPlacement& c = out.alternatives.back();
    if (c.competes) ambiguous.insert(c.stations.begin(), c.stations.end());
  }
  out.ambiguous.assign(ambiguous.begin(), ambiguous.end());
  return out;
}

}  // namespace plumb
