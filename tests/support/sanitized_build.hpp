#pragma once
// Tests built in the AddressSanitizer + UBSan tree (tests/sanitize) run 2-5 times slower.
// Tests that repeat one scenario over many random cases run a few of them there: the
// sanitizers look for memory and undefined-behaviour errors on each code path, which the
// first cases already take; the statistics are asserted by the normal build.

namespace plumb::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

/// `normal` repetitions in the normal build, `sanitized` in the sanitizer tree.
constexpr int repetitions(int normal, int sanitized) { return kSanitizedBuild ? sanitized : normal; }

}  // namespace plumb::test
