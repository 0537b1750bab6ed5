#pragma once
// Counter-based random numbers for simulated pulses: the draws of pulse i depend only on
// (seed, i), so results are identical whatever the thread count or scheduling.
#include <cmath>
#include <cstdint>

namespace plumb::sim {

inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

class PulseRandom {
 public:
  PulseRandom(std::uint64_t seed, std::uint64_t pulse) : state_(splitmix64(seed) ^ splitmix64(pulse * 0xD1B54A32D192ED03ull + 1)) {}
  /// Uniform in [0, 1).
  double uniform() {
    state_ = splitmix64(state_);
    return static_cast<double>(state_ >> 11) * (1.0 / 9007199254740992.0);
  }
  /// Standard normal (Box-Muller).
  double normal() {
    const double u1 = 1.0 - uniform(), u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  std::uint64_t state_;
};

}  // namespace plumb::sim
