#include "station_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>

namespace plumb::bimst {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void countOutcome(const RunRecord& r, RowStats& s) {
  ++s.runs;
  s.successes += isSuccess(r.outcome);
  s.ambiguous_repeat += r.outcome == Outcome::AmbiguousRepeat;
  s.failed += r.outcome == Outcome::Failed;
  s.wrong += r.outcome == Outcome::Wrong;
  s.check_visually += r.level == "check-visually";
}

/// Records grouped by key(record), in the order the keys first appear.
std::vector<std::pair<std::string, std::vector<RunRecord>>> groupBy(
    const std::vector<RunRecord>& records, const std::function<std::string(const RunRecord&)>& key) {
  std::vector<std::pair<std::string, std::vector<RunRecord>>> out;
  std::map<std::string, std::size_t> index;
  for (const auto& r : records) {
    const std::string k = key(r);
    auto it = index.find(k);
    if (it == index.end()) {
      it = index.emplace(k, out.size()).first;
      out.push_back({k, {}});
    }
    out[it->second].second.push_back(r);
  }
  return out;
}

void printRow(const RowStats& s) {
  std::printf("  %-36s %5d %5d %6.1f%% %6d %6d %6d %6d %9.4f %8.2f %7.1f  %s\n", s.label.c_str(), s.runs,
              s.successes, s.runs ? 100.0 * s.successes / s.runs : 0.0, s.ambiguous_repeat, s.check_visually,
              s.failed, s.wrong, s.median_rotation_deg, 1000.0 * s.median_translation_m, s.median_seconds,
              s.meets ? "meets" : "BELOW BAR");
}

void printHeader(const char* title) {
  std::printf("\n== %s\n  %-36s %5s %5s %7s %6s %6s %6s %6s %9s %8s %7s  %s\n", title, "row", "runs", "succ",
              "succ%", "amb.r", "check", "failed", "WRONG", "med.deg", "med.mm", "med.s", "bar");
}

std::vector<RowStats> printGrouped(const char* title, const std::vector<RunRecord>& records,
                                   const std::function<std::string(const RunRecord&)>& key,
                                   const BarParams& bar) {
  printHeader(title);
  std::vector<RowStats> rows;
  for (const auto& [label, group] : groupBy(records, key)) rows.push_back(summarize(label, group, bar));
  for (const auto& row : rows) printRow(row);
  if (!records.empty()) printRow(summarize("all", records, bar));
  return rows;
}

void printFailures(const std::vector<RunRecord>& records) {
  std::printf("\n== runs that are not a success (outcome, verdict level, status)\n");
  int n = 0;
  for (const auto& r : records) {
    if (isSuccess(r.outcome)) continue;
    ++n;
    std::printf("  %-28s %-8s (%6.1f, %6.1f, %5.1f) %-3s pose %2d: %-8s %-14s %-30s rot %.4f deg trans %.1f mm "
                "listed %d\n",
                r.model.c_str(), typeName(r.type), r.station.x(), r.station.y(), r.station.z(), setName(r.set),
                r.pose, outcomeName(r.outcome), r.level.c_str(), r.status.c_str(), r.rotation_deg,
                1000.0 * r.translation_m, int(r.truth_listed));
  }
  if (n == 0) std::printf("  none\n");
}

}  // namespace

RowStats summarize(const std::string& label, const std::vector<RunRecord>& records, const BarParams& bar) {
  RowStats s;
  s.label = label;
  std::vector<double> rot, trans, secs;
  for (const auto& r : records) {
    countOutcome(r, s);
    secs.push_back(r.seconds);
    if (!r.reported_success) continue;
    rot.push_back(r.rotation_deg);
    trans.push_back(r.translation_m);
  }
  s.median_rotation_deg = median(rot);
  s.median_translation_m = median(trans);
  s.median_seconds = median(secs);
  // A row whose successes are all "ambiguous, repeated room" returned no transform: no median.
  const bool medians_ok = rot.empty() || (s.median_rotation_deg <= bar.max_median_rotation_deg &&
                                          s.median_translation_m <= bar.max_median_translation_m);
  s.meets = s.runs > 0 && s.successes >= bar.min_success * s.runs && s.wrong == 0 && medians_ok;
  return s;
}

std::vector<RowStats> printTables(const std::vector<RunRecord>& records, const BarParams& bar) {
  const auto rows = printGrouped("per station type and pose set", records, [](const RunRecord& r) {
    return std::string(typeName(r.type)) + " / " + setName(r.set);
  }, bar);
  printGrouped("per model and pose set", records, [](const RunRecord& r) {
    return r.model + " / " + setName(r.set);
  }, bar);
  printFailures(records);
  std::printf("\n  bar: success >= %.0f%% (rotation < 0.05 deg and translation < 1 cm, or ambiguous with the "
              "truth listed where the model repeats the room), median <= %.3f deg and <= %.1f mm, no WRONG "
              "(reported success outside the tolerance)\n",
              100.0 * bar.min_success, bar.max_median_rotation_deg, 1000.0 * bar.max_median_translation_m);
  std::fflush(stdout);
  return rows;
}

void writeRunCsv(const std::string& path, const std::vector<RunRecord>& records) {
  std::ofstream f(path);
  f << "model,type,x,y,z,set,pose,points,outcome,level,status,method,rotation_deg,translation_m,truth_listed,"
       "genuine_repeat,self_symmetric,seconds\n";
  for (const auto& r : records)
    f << r.model << ',' << typeName(r.type) << ',' << r.station.x() << ',' << r.station.y() << ','
      << r.station.z() << ',' << setName(r.set) << ',' << r.pose << ',' << r.points << ','
      << outcomeName(r.outcome) << ',' << r.level << ",\"" << r.status << "\"," << r.method << ','
      << r.rotation_deg << ',' << r.translation_m << ',' << r.truth_listed << ',' << r.genuine_repeat << ','
      << r.self_symmetric << ',' << r.seconds << '\n';
}

}  // namespace plumb::bimst
