#pragma once
// A link of the network: one station pair registered with the pipeline (registerData, source =
// station b, target = station a, each in its own frame), its quality figures and verdict, and
// the standard deviations that weigh it in the adjustment (docs/NETWORK.md "Links").
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

#include "quality/verdict_level.hpp"
#include "registration/network/network_params.hpp"
#include "registration/network/pair_selection.hpp"
#include "registration/network/robust_adjustment.hpp"
#include "registration/network/station.hpp"

namespace plumb {

/// Another placement the link's pipeline refined and judged (its PlacementCandidate with role
/// "competing" or "worse"), listed in the report: what the pair could also have been.
struct LinkAlternative {
  RigidTransform transform;  ///< b's frame -> a's frame
  std::string role;
  double overlap = 0.0;
  double point_rms = 0.0;  ///< m
};

struct Link {
  std::size_t a = 0, b = 0;
  std::string reason;        ///< why the pair was tried (CandidatePair::reason)
  double similarity = 0.0;   ///< layout similarity
  /// b's frame -> a's frame: meaningful when registered, and for a link that failed as
  /// ambiguous, its chosen placement as refined (the competing ones are `alternatives`).
  RigidTransform transform;
  bool registered = false;   ///< the pipeline gave a transform (usable or check visually)
  bool accepted = false;     ///< used in the adjustment (registered, and verdict accepted)
  VerdictLevel level = VerdictLevel::Failed;
  std::string verdict, method;
  std::string status;  ///< the pipeline's status ("success", "ambiguous", "too few features", ...)
  std::vector<std::string> warnings;
  double overlap = 0.0;             ///< fraction of b's points matched
  double point_rms = 0.0;           ///< m
  double weakest_resistance = 0.0;  ///< slide resistance of the weakest direction
  double length_scale = 0.0;        ///< m, RMS radius of the matched points
  double sigma_translation = 0.0;   ///< m, weight in the adjustment
  double sigma_rotation_deg = 0.0;  ///< deg
  double seconds = 0.0;
  std::vector<LinkAlternative> alternatives;  ///< empty for links to the BIM (the model report lists those)
  /// Links to the BIM: every refined placement the pipeline compared, the chosen one first
  /// (station frame -> model frame); an ambiguous link's copies are the free-space judge's
  /// hypotheses (free_space_judge.hpp).
  std::vector<RigidTransform> model_candidates;
  /// The surveyor's decision (NetworkDecisions): "" none, "accepted" (taken as true, never
  /// dropped) or "rejected" (left out of the adjustment); or kFreeSpaceDecision (taken as true
  /// because the free space of the placed stations chose it).
  std::string decision;
};

/// Link::decision of a link the free-space judge took as true (free_space_judge.hpp).
inline constexpr const char* kFreeSpaceDecision = "free space";

/// Registers station b onto station a with params.link and weighs the result (when b is the
/// model, a onto the model, the transform inverted).
Link registerLink(const Station& a, const Station& b, const CandidatePair& pair, const NetworkParams& params);

/// The link of `pair` from the JSON report of `plumb-cli register` run as a batch job
/// (network --plan / --links-from, docs/NETWORK.md "Batch link jobs"): the same figures as
/// registerLink takes from the pipeline. `onto_model`: the job registered station a onto the
/// model (the transform is inverted). Throws InputError naming what the report lacks.
Link linkFromReport(const nlohmann::json& report, const CandidatePair& pair, bool onto_model,
                    const NetworkParams& params);

/// The link as the adjustment takes it: its transform and sigmas, whether it is a sequence link
/// and whether it joins a station to the model (an anchor).
AdjustmentLink adjustmentLink(const Link& link, const std::vector<Station>& stations);

/// sigma_t = max(min_sigma, rms_factor * point_rms) / sqrt(min(1, weakest / full_resistance));
/// sigma_r = sigma_t / length_scale (radians; length_scale at least 1 m).
void weighLink(Link& link, const LinkWeightParams& params);

}  // namespace plumb
