#pragma once
// Error-free transformations of doubles (internal to coverkit::geometry): where a decision or a
// value can be had exactly in doubles because no rounding happens, or because the rounding error
// is itself a double. Round-to-nearest mode only; no overflow.
#include <cmath>

namespace coverkit::detail {

/// Knuth's TwoSum: fl(a + b), with `err` its rounding error, so that a + b = result + err exactly.
inline double twoSum(double a, double b, double& err) {
  const double s = a + b, bv = s - a, av = s - bv;
  err = (a - av) + (b - bv);
  return s;
}

/// a + b in `s`, true when that is exact.
inline bool exactSum(double a, double b, double& s) {
  double err;
  s = twoSum(a, b, err);
  return err == 0;
}

/// a · b in `p`, true when that is exact: fma shows no rounding error, and the product is 0 of a zero
/// factor or at least `tiny` in magnitude (so that an error could not have underflowed to 0).
inline bool exactProduct(double a, double b, double& p, double tiny = 0x1p-400) {
  p = a * b;
  if (p == 0) return a == 0 || b == 0;
  return std::isfinite(p) && std::abs(p) >= tiny && std::fma(a, b, -p) == 0;
}

}  // namespace coverkit::detail
