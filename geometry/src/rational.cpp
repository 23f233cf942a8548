#include <coverkit/geometry/error.h>
#include <coverkit/geometry/rational.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace coverkit {

Rational parseRational(std::string_view text, const std::string& file, const std::string& place) {
  auto bad = [&](const std::string& why) -> InputError {
    return InputError(file, place, "'" + std::string(text) + "' is not a number: " + why);
  };
  std::string s(text);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  s = s.substr(i);
  if (s.empty()) throw bad("empty");
  if (auto slash = s.find('/'); slash != std::string::npos) {
    Rational n = parseRational(s.substr(0, slash), file, place);
    Rational d = parseRational(s.substr(slash + 1), file, place);
    if (d == 0) throw bad("zero denominator");
    return Rational(n / d);
  }
  std::size_t p = 0;
  bool neg = false;
  if (s[p] == '+' || s[p] == '-') neg = s[p++] == '-';
  std::string digits;
  long exp10 = 0;
  bool any = false, dot = false;
  for (; p < s.size(); ++p) {
    char c = s[p];
    if (std::isdigit(static_cast<unsigned char>(c))) {
      digits += c;
      any = true;
      if (dot) --exp10;
    } else if (c == '.' && !dot) {
      dot = true;
    } else {
      break;
    }
  }
  if (!any) throw bad(s == "nan" || s == "NaN" || s.find("inf") != std::string::npos ? "not finite" : "no digits");
  if (p < s.size()) {
    if (s[p] != 'e' && s[p] != 'E') throw bad("unexpected character");
    ++p;
    std::string e = s.substr(p);
    if (e.empty()) throw bad("empty exponent");
    char* end = nullptr;
    long ev = std::strtol(e.c_str(), &end, 10);
    if (*end != '\0' || std::labs(ev) > 4000) throw bad("bad exponent");
    exp10 += ev;
  }
  mpz_class num(digits, 10);
  mpz_class pow;
  mpz_ui_pow_ui(pow.get_mpz_t(), 10, static_cast<unsigned long>(std::labs(exp10)));
  Rational q = exp10 >= 0 ? Rational(num * pow) : Rational(num, pow);
  q.canonicalize();
  return neg ? Rational(-q) : q;
}

Rational exactFromDouble(double v) {
  if (!std::isfinite(v)) throw InputError("", "", "non-finite coordinate");
  return Rational(v);  // mpq_set_d is exact
}

std::string formatDouble(double v) {
  char buf[400];
  for (int prec = 1; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  const double a = std::fabs(v);
  if (std::strchr(buf, 'e') && a >= 1e-4 && a < 1e16) {  // plain notation in the everyday range
    for (int k = 0; k <= 20; ++k) {
      std::snprintf(buf, sizeof buf, "%.*f", k, v);
      if (std::strtod(buf, nullptr) == v) break;
    }
  }
  return buf;
}

Rational decimalFromDouble(double v) {
  if (!std::isfinite(v)) throw InputError("", "", "non-finite number");
  return parseRational(formatDouble(v));
}

double toDouble(const Rational& q) {
  // a dyadic number of at most 53 significant bits is a double: mpq_get_d gives it exactly
  const mpz_srcptr num = q.get_num_mpz_t(), den = q.get_den_mpz_t();
  if (mpz_popcount(den) == 1 && mpz_sizeinbase(num, 2) <= 53 && mpz_sizeinbase(den, 2) < 1000) return q.get_d();
  // mpq_get_d truncates; correct to nearest by comparing the neighbours exactly.
  double d = q.get_d();
  if (!std::isfinite(d)) return d;   // beyond the doubles (GMP gives ±inf): no neighbours to compare
  double up = std::nextafter(d, HUGE_VAL), dn = std::nextafter(d, -HUGE_VAL);
  Rational e = abs(Rational(d) - q);
  double best = d;
  if (std::isfinite(up) && abs(Rational(up) - q) < e) { best = up; e = abs(Rational(up) - q); }
  if (std::isfinite(dn) && abs(Rational(dn) - q) < e) best = dn;
  return best;
}

double roundToward(const Rational& q, const Rational& toward) {
  double d = toDouble(q);
  Rational dq(d);
  if (toward > q) {
    while (dq < q) { d = std::nextafter(d, HUGE_VAL); dq = Rational(d); }
  } else if (toward < q) {
    while (dq > q) { d = std::nextafter(d, -HUGE_VAL); dq = Rational(d); }
  }
  return d;
}

}  // namespace coverkit
