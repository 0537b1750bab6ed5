#pragma once
// The one random seed of a run (issue 18). Every step that draws at random takes the seed as a
// function argument; the registration pipeline passes PipelineParams::seed down to each of
// them, so no parameter group carries a seed of its own.
#include <cstdint>

namespace plumb {

/// Default seed of the registration pipeline and of `plumb-cli features`.
inline constexpr std::uint64_t kDefaultSeed = 1;
/// Largest accepted seed. Below 2^53, so a seed survives JSON numbers and the double values of
/// ParamSchema exactly.
inline constexpr double kMaxSeed = 9.0e15;

}  // namespace plumb
