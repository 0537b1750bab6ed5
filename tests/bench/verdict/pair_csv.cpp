#include <fstream>
#include <set>
#include <stdexcept>

#include "pair_record.hpp"

namespace plumb::verdict {

namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string optional(const std::optional<double>& v) {
  return v ? std::to_string(*v) : std::string();
}

}  // namespace

void writePairCsv(const std::string& path, const std::vector<PairRecord>& records) {
  std::set<std::string> keys;
  for (const auto& r : records)
    for (const auto& [k, v] : r.figures) keys.insert(k);
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << "suite,pair,group,seed,verdict_level,status,success,correct,confident_wrong,"
       "rotation_error_deg,translation_error_m,oracle_agreement,oracle_wall_agreement,seconds";
  for (const auto& k : keys) f << "," << quoted(k);
  f << "\n";
  for (const auto& r : records) {
    f << quoted(r.suite) << "," << quoted(r.pair) << "," << quoted(r.group) << "," << r.seed << ","
      << quoted(levelName(r.level)) << "," << quoted(r.status) << "," << r.success << ","
      << r.correct << "," << r.confident_wrong << "," << optional(r.rotation_error_deg) << ","
      << optional(r.translation_error_m) << "," << optional(r.oracle_agreement) << ","
      << optional(r.oracle_wall_agreement) << ","
      << r.seconds;
    for (const auto& k : keys) {
      const auto it = r.figures.find(k);
      f << "," << (it == r.figures.end() ? std::string() : std::to_string(it->second));
    }
    f << "\n";
  }
}

}  // namespace plumb::verdict
