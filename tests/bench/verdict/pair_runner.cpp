#include "pair_runner.hpp"

#include <nlohmann/json.hpp>

#include <chrono>

#include "report_figures.hpp"

namespace plumb::verdict {

PairOutcome registerMoved(const SideData& source, const RigidTransform& pose,
                          const SideData& target, const PipelineParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  PointCloud moved = source.cloud;
  moved.transform(pose);
  FeatureSet features = source.features;
  features.transform(pose);
  if (!target.model) features.segments.clear();
  RegistrationSide src, tgt;
  src.cloud = &moved;
  src.features = &features;
  if (target.model) {
    tgt.model = target.model.get();
    tgt.model_samples = &target.samples;
  } else {
    tgt.cloud = &target.cloud;
  }
  tgt.features = &target.features;
  PairOutcome out;
  out.report = registerData(src, tgt, params).report;
  out.json = qualityReportToJson(out.report);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

PairRecord recordOf(const std::string& suite, const std::string& pair, int seed,
                    const PairOutcome& outcome) {
  PairRecord r;
  r.suite = suite;
  r.pair = pair;
  r.seed = seed;
  r.level = reportLevel(outcome.json);
  r.status = outcome.report.status;
  r.success = outcome.report.success;
  r.figures = reportFigures(outcome.json);
  r.seconds = outcome.seconds;
  return r;
}

namespace {

std::optional<RigidTransform> matrixTransform(const nlohmann::json& m) {
  if (!m.is_array() || m.size() != 4) return std::nullopt;
  Eigen::Matrix4d x;
  for (int r = 0; r < 4; ++r) {
    if (!m[r].is_array() || m[r].size() != 4) return std::nullopt;
    for (int c = 0; c < 4; ++c) x(r, c) = m[r][c].get<double>();
  }
  try {
    return RigidTransform::fromMatrix(x, 1e-3);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::vector<RigidTransform> reportedPlacements(const PairOutcome& o) {
  std::vector<RigidTransform> out;
  const QualityReport& q = o.report;
  if (q.success) out.push_back(q.transform);
  out.push_back(q.global_transform);
  if (q.has_runner_up) out.push_back(q.runner_up_transform);
  const auto j = nlohmann::json::parse(o.json);
  if (j.contains("candidates") && j["candidates"].is_array())
    for (const auto& c : j["candidates"])
      if (c.is_object() && c.contains("transform"))
        if (auto t = matrixTransform(c["transform"])) out.push_back(*t);
  return out;
}

}  // namespace plumb::verdict
