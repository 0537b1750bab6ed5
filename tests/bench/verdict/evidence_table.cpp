#include "evidence_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace plumb::verdict {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double x = q * double(v.size() - 1);
  const std::size_t i = std::size_t(std::floor(x));
  if (i + 1 >= v.size()) return v.back();
  return v[i] + (x - double(i)) * (v[i + 1] - v[i]);
}

EvidenceGroup groupOf(const std::vector<PairRecord>& records, const std::string& suite,
                      const std::string& group,
                      const std::string& label) {
  EvidenceGroup g{label.empty() ? group : label, {}};
  for (const auto& r : records)
    if (r.suite == suite && r.group == group) g.records.push_back(&r);
  return g;
}

void printOutcomeCounts(const std::string& suite, const std::vector<EvidenceGroup>& groups) {
  std::printf("\n== %s: outcomes by verdict level\n", suite.c_str());
  std::printf("  %-34s %6s %7s %8s %8s %10s %8s %9s\n", "group", "cases", "usable", "check",
              "failed", "(ambig.)", "correct", "conf.wrong");
  for (const auto& g : groups) {
    int usable = 0, check = 0, failed = 0, ambiguous = 0, correct = 0, wrong = 0;
    for (const PairRecord* r : g.records) {
      usable += r->level == Level::Usable;
      check += r->level == Level::CheckVisually;
      failed += r->level == Level::FailedOrAmbiguous;
      ambiguous += r->level == Level::FailedOrAmbiguous && r->status == "ambiguous";
      correct += r->correct;
      wrong += r->confident_wrong;
    }
    std::printf("  %-34s %6zu %7d %8d %8d %10d %8d %9d\n", g.name.c_str(), g.records.size(),
                usable, check, failed, ambiguous, correct, wrong);
  }
  std::fflush(stdout);
}

namespace {

std::string stats(const EvidenceGroup& g, const std::string& key) {
  std::vector<double> v;
  for (const PairRecord* r : g.records) {
    const auto it = r->figures.find(key);
    if (it != r->figures.end() && std::isfinite(it->second)) v.push_back(it->second);
  }
  char buf[128];
  if (v.empty()) {
    std::snprintf(buf, sizeof buf, "%4s %9s %9s %9s %9s %9s", "0", "-", "-", "-", "-", "-");
  } else {
    std::snprintf(buf, sizeof buf, "%4zu %9.4g %9.4g %9.4g %9.4g %9.4g", v.size(), quantile(v, 0),
                  quantile(v, 0.1), quantile(v, 0.5), quantile(v, 0.9), quantile(v, 1));
  }
  return buf;
}

}  // namespace

void printFigureDistributions(const std::string& suite, const std::vector<EvidenceGroup>& groups) {
  std::set<std::string> keys;
  for (const auto& g : groups)
    for (const PairRecord* r : g.records)
      for (const auto& [k, v] : r->figures) keys.insert(k);
  std::printf("\n== %s: evidence figures (n min p10 median p90 max per group)\n", suite.c_str());
  std::printf("  %-36s", "figure");
  for (const auto& g : groups) std::printf(" | %-54.54s", g.name.c_str());
  std::printf("\n");
  for (const auto& k : keys) {
    std::printf("  %-36.36s", k.c_str());
    for (const auto& g : groups) std::printf(" | %-54s", stats(g, k).c_str());
    std::printf("\n");
  }
  std::fflush(stdout);
}

}  // namespace plumb::verdict
