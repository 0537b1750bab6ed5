#pragma once
// Link registration as batch jobs (issue 15, docs/NETWORK.md "Batch link jobs"): `network
// --plan DIR` writes each station alone in its own frame (DIR/stations/), one `plumb-cli
// register` command line per planned link (DIR/jobs.txt, absolute paths: run them with GNU
// parallel, a Slurm job array or Kubernetes Jobs) and DIR/plan.json; `network --links-from
// DIR` reads the jobs' reports back as links for the adjustment and, when they leave the
// network split, writes the next round of jobs (appendLinkRound).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "model/dataset.hpp"
#include "registration/bounded/bounded_datasets.hpp"
#include "registration/network/link.hpp"

namespace plumb::cli {

/// A station's name as a file name stem: path separators, ':' and '#' become '_' (names are
/// unique in a network, so are these stems).
std::string stationFileStem(const std::string& name);

struct LinkPlan {
  std::filesystem::path dir;
  std::vector<std::string> settings;  ///< --set GROUP.KEY=VALUE of the link pipeline, passed on
  std::uint64_t seed = 1;
  std::string model;  ///< the BIM's file (the last station), empty without one
};

/// Writes DIR/stations/*.e57 (moving the scans out of `datasets`, in station order: a file above
/// the memory budget gives its stations' subsamples, what the network's links register), DIR/links/,
/// DIR/jobs.txt and DIR/plan.json for `pairs`; returns the jobs file. Written atomically.
std::filesystem::path writeLinkPlan(const LinkPlan& plan, const std::vector<Station>& stations,
                                    std::vector<BoundedDataset>& datasets, const std::vector<CandidatePair>& pairs);

/// Appends `pairs` (an expansion round: the planned links left the network split) to
/// DIR/plan.json as round R and writes their jobs to DIR/jobs-R.txt, which it returns; the
/// station files of the first plan are reused.
std::filesystem::path appendLinkRound(const std::filesystem::path& dir, const std::vector<Station>& stations,
                                      const std::vector<CandidatePair>& pairs);

/// The links of DIR/plan.json from the jobs' reports. Throws InputError when the plan's
/// stations are not `stations` (same names, same order), FileError naming a report that is
/// missing (its job did not run or failed on its input) or not a register report.
std::vector<Link> readLinkReports(const std::filesystem::path& dir, const std::vector<Station>& stations,
                                  const NetworkParams& params);

}  // namespace plumb::cli
