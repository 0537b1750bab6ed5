#pragma once
// Converting a double outside float's range to float is undefined behaviour (the fuzzers find
// it in every reader whose files may carry 1e300). Every file value narrowed to float goes
// through toFloat.

#include <limits>

namespace plumb {

/// v as a float; values beyond float's range become +-infinity (then rejected as non-finite
/// like any other), NaN stays NaN.
inline float toFloat(double v) {
  constexpr double kMax = static_cast<double>(std::numeric_limits<float>::max());
  if (v > kMax) return std::numeric_limits<float>::infinity();
  if (v < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);
}

/// v clamped to float's finite range (NaN stays NaN): for values that must stay finite.
inline double inFloatRange(double v) {
  constexpr double kMax = static_cast<double>(std::numeric_limits<float>::max());
  return v < -kMax ? -kMax : (v > kMax ? kMax : v);
}

}  // namespace plumb
