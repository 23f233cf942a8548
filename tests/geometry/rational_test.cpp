#include <coverkit/geometry/error.h>
#include <coverkit/geometry/rational.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace coverkit;

TEST(Rational, DecimalsAreExact) {
  EXPECT_EQ(parseRational("0.05"), Rational(1, 20));
  EXPECT_EQ(parseRational("-12.5"), Rational(-25, 2));
  EXPECT_EQ(parseRational("1e-3"), Rational(1, 1000));
  EXPECT_EQ(parseRational("2.5E2"), Rational(250));
  EXPECT_EQ(parseRational("3/40"), Rational(3, 40));
  EXPECT_EQ(decimalFromDouble(0.2), Rational(1, 5));
  EXPECT_EQ(ratio(4, 20), Rational(1, 5));
  EXPECT_EQ(formatDouble(20), "20");
  EXPECT_EQ(formatDouble(0.1), "0.1");
  EXPECT_NE(exactFromDouble(0.2), Rational(1, 5));  // the double is not 1/5
}

TEST(Rational, JunkIsRejectedWithThePlace) {
  for (const char* bad : {"", "abc", "1.2.3", "nan", "inf", "1e", "--1", "1/0"}) {
    try {
      parseRational(bad, "f.yaml", "resolution");
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "f.yaml");
      EXPECT_EQ(e.place(), "resolution");
    }
  }
}

TEST(Rational, RoundTowardNeverCrossesAway) {
  for (int k = 1; k < 200; ++k) {
    const Rational q(k, 7 * 20);
    const double up = roundToward(q, q + 1), dn = roundToward(q, q - 1);
    EXPECT_GE(Rational(up), q);
    EXPECT_LE(Rational(dn), q);
    if (up != dn) EXPECT_EQ(std::nextafter(dn, 1e9), up);  // adjacent doubles, or q itself
  }
}

// A rational beyond the doubles' range becomes ±infinity (it used to abort inside GMP while
// comparing with the neighbours of infinity); the largest double stays itself.
TEST(Rational, ToDoubleBeyondTheRangeIsInfinite) {
  EXPECT_EQ(toDouble(parseRational("1e999")), HUGE_VAL);
  EXPECT_EQ(toDouble(parseRational("-1e999")), -HUGE_VAL);
  EXPECT_EQ(toDouble(Rational(std::numeric_limits<double>::max())), std::numeric_limits<double>::max());
}
