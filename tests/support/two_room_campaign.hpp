#pragma once
// The five-station campaign of the network tests (CLI and GUI): two furnished rooms of 4 x 5
// and 4.5 x 5 m, a station in each room centre, the doorway and one corner of each room, shot
// as a walk, each independently perturbed by any yaw and up to 20 m; written to DIR/sim by
// plumb-cli simulate. `more`: further simulate options (control points...).
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"

namespace plumb::test {

inline CliResult simulateTwoRoomCampaign(const std::filesystem::path& dir, std::uint64_t seed,
                                         const std::string& more = {}) {
  std::ofstream(dir / "rooms.json") << R"({"name": "two-furnished-rooms", "column_widths": [4.0, 4.5],
                                          "row_depths": [5.0], "furniture_per_room": 1})";
  return plumbCli(dir, "simulate --building rooms.json --tls-rooms --tls-doors --tls 1.2,1.2,1.75 "
                       "--tls 7.2,3.9,1.75 --tls-walk --perturb-stations 180,20 --seed " +
                           std::to_string(seed) + " " + more + " -o sim");
}

}  // namespace plumb::test
