#pragma once
// Exact rationals for every coordinate that decides safety or topology.
// Decimal input is read exactly ("0.05" is 1/20); doubles written by coverkit are read back as the
// exact binary value they hold. GMP's C++ class is used directly: it is CGAL-free and CGAL's kernels
// accept it as a number type inside geometry/src.
#include <gmpxx.h>

#include <string>
#include <string_view>

namespace coverkit {

using Rational = mpq_class;

/// Parses a decimal ("-12.5", "1e-3", "3/40") exactly. Throws InputError(file, place, ...) on junk,
/// NaN or infinity.
Rational parseRational(std::string_view text, const std::string& file = {}, const std::string& place = {});
/// The exact value of a finite double (no rounding at all).
Rational exactFromDouble(double v);
/// The shortest decimal that round-trips to v, read exactly: 0.2 (the double) becomes 1/5.
/// Used for numbers that came from decimal text through a double-only parser (JSON).
Rational decimalFromDouble(double v);
/// n/d in canonical form (GMP compares only canonical rationals correctly).
inline Rational ratio(long n, long d) {
  Rational q(n, d);
  q.canonicalize();
  return q;
}
/// Nearest double.
double toDouble(const Rational& q);
/// The double next to q in the direction of `toward` that lies on the same side of q as `toward`
/// or on q itself: rounding that never crosses q away from `toward`.
double roundToward(const Rational& q, const Rational& toward);
/// Shortest round-trip text of a double ("0.1", "3", "1e-07").
std::string formatDouble(double v);

}  // namespace coverkit
