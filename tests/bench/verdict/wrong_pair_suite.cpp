// Wrong-pair suite: one building's indoor scan onto another building's data. None may be
// usable; a pair whose target genuinely contains the source's rooms at a reported placement
// (placement_oracle.hpp) is reported apart from the clear mismatches.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include "acceptance_scenarios.hpp"
#include "pair_runner.hpp"
#include "placement_oracle.hpp"
#include "suites.hpp"

namespace plumb::verdict {

std::vector<WrongPair> allWrongPairs(SurveyCatalogue& data, const std::vector<std::string>& buildings,
                                     const std::vector<std::string>& mms_buildings) {
  std::vector<std::vector<WrongPair>> per_source;
  for (const auto& s : buildings) {
    if (data.building(s).stations.empty()) continue;
    per_source.emplace_back();
    for (const auto& t : buildings) {
      if (t == s || !data.building(t).model) continue;
      per_source.back().push_back({s, t, "model"});
      if (std::find(mms_buildings.begin(), mms_buildings.end(), t) != mms_buildings.end())
        per_source.back().push_back({s, t, "mms"});
      if (!data.building(t).stations.empty()) per_source.back().push_back({s, t, "indoor"});
    }
  }
  std::vector<WrongPair> out;
  for (std::size_t round = 0;; ++round) {
    const std::size_t before = out.size();
    for (const auto& list : per_source)
      if (round < list.size()) out.push_back(list[round]);
    if (out.size() == before) return out;
  }
}

namespace {

const SideData& targetOf(SurveyCatalogue& data, const WrongPair& p) {
  if (p.target_kind == "model") return data.modelTarget(p.target);
  if (p.target_kind == "mms") return data.mms(p.target);
  return data.indoor(p.target);
}

/// The agreement of the placement the report names that agrees best (genuine first, then
/// by wall agreement); a placement maps the moved source to the target, so the source
/// building's frame maps by placement * pose.
Agreement bestAgreement(SurveyCatalogue& data, const WrongPair& p, const RigidTransform& pose,
                        const PairOutcome& o) {
  Agreement best;
  for (const auto& t : reportedPlacements(o)) {
    const Agreement a = rangeAgreement(data.bareScene(p.source), data.bareScene(p.target),
                                       data.building(p.source).stations, t * pose);
    if (std::make_pair(a.genuine(), a.walls) > std::make_pair(best.genuine(), best.walls)) best = a;
  }
  return best;
}

/// "global 1.2 s, refinement 0.4 s": the pipeline's own timings.
std::string stageSeconds(const QualityReport& q) {
  std::string out;
  for (const auto& [k, v] : q.figures)
    if (k.rfind("seconds ", 0) == 0 && k != "seconds features") {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s%s %.1f s", out.empty() ? "" : ", ", k.c_str() + 8, v);
      out += buf;
    }
  return out;
}

}  // namespace

std::vector<PairRecord> runWrongPairSuite(SurveyCatalogue& data, const std::vector<WrongPair>& pairs,
                                          int poses, double budget_seconds, int& skipped,
                                          std::uint64_t seed_offset) {
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<PairRecord> out;
  skipped = 0;
  for (const auto& p : pairs) {
    if (budget_seconds > 0 && elapsed() > budget_seconds) {
      ++skipped;
      continue;
    }
    const SideData& source = data.indoor(p.source);
    const SideData& target = targetOf(data, p);
    const auto cases = test::randomPoses(poses, 7000 + std::hash<std::string>{}(p.name()) % 1000 + seed_offset);
    for (int i = 0; i < poses; ++i) {
      const PairOutcome o = registerMoved(source, cases[i], target, data.params());
      PairRecord r = recordOf("wrong-pair", p.name(), i, o);
      const Agreement a = bestAgreement(data, p, cases[i], o);
      r.oracle_agreement = a.all;
      r.oracle_wall_agreement = a.walls;
      const bool genuine = a.genuine();
      r.group = genuine ? "wrong: genuine match" : "wrong: clear mismatch";
      r.confident_wrong = r.level == Level::Usable;
      // A clear mismatch must end failed; a genuine match may be ambiguous (not usable).
      r.correct = genuine ? r.level != Level::Usable : r.level == Level::FailedOrAmbiguous;
      std::printf("  [wrong-pair] %-48s pose %d: %-19s %-12s oracle %.2f / walls %.2f  %.1f s "
                  "(%s)\n",
                  p.name().c_str(), i, levelName(r.level).c_str(), r.status.c_str(), a.all,
                  a.walls, r.seconds, stageSeconds(o.report).c_str());
      std::fflush(stdout);
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace plumb::verdict
