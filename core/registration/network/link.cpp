#include "registration/network/link.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace plumb {

void weighLink(Link& link, const LinkWeightParams& p) {
  const double held = std::clamp(link.weakest_resistance / p.full_resistance, 1e-3, 1.0);
  link.sigma_translation = std::max(p.min_sigma, p.rms_factor * link.point_rms) / std::sqrt(held);
  link.sigma_rotation_deg = link.sigma_translation / std::max(1.0, link.length_scale) * 180.0 / M_PI;
}

namespace {
RegistrationSide withoutFeatures(RegistrationSide side) {
  side.features = nullptr;
  return side;
}

/// The refined candidates other than the chosen one and those converging onto it or ruled out
/// by the free space.
std::vector<LinkAlternative> alternativesOf(const PipelineResult& r) {
  std::vector<LinkAlternative> out;
  for (const auto& c : r.report.candidates)
    if (c.refined && (c.role == "competing" || c.role == "worse"))
      out.push_back({c.transform, c.role, c.overlap, c.point_rms});
  return out;
}
}  // namespace

Link registerLink(const Station& a, const Station& b, const CandidatePair& pair, const NetworkParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  Link link;
  link.a = pair.a;
  link.b = pair.b;
  link.reason = pair.reason;
  link.similarity = pair.similarity;
  // A scan onto the BIM, never the BIM onto a scan: the pipeline's model target path (its
  // planes, openings, copy search) is the one calibrated (docs/VERDICT.md).
  // The station's features are detected again there, with the segments a model target needs
  // (its stored features have none), so the link is exactly plumb-cli register onto the model.
  const bool onto_model = b.is_model;
  const PipelineResult r = onto_model ? registerData(withoutFeatures(a.input.side()), b.input.side(), params.link)
                                      : registerData(b.input.side(), a.input.side(), params.link);
  link.level = r.report.level;
  link.verdict = r.report.verdict;
  link.status = r.report.status;
  link.method = r.method_used;
  link.warnings = r.report.warnings;
  link.registered = r.success();
  link.transform = onto_model ? r.transform().inverse() : r.transform();
  link.overlap = r.report.overlap_ratio;
  link.point_rms = r.report.point_rms;
  link.weakest_resistance = *std::min_element(r.report.direction_resistance.begin(), r.report.direction_resistance.end());
  link.length_scale = r.refinement ? r.refinement->length_scale : 0.0;
  link.accepted = link.registered && (link.level == VerdictLevel::Usable ||
                                      (link.level == VerdictLevel::CheckVisually && params.weights.accept_check_visually));
  if (!onto_model) link.alternatives = alternativesOf(r);
  weighLink(link, params.weights);
  link.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return link;
}

}  // namespace plumb
