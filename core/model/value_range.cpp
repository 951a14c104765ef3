#include "core/model/value_range.hpp"

#include <charconv>
#include <cmath>

namespace orni {

bool ValueRange::bounded() const { return std::isfinite(lo) && std::isfinite(hi); }

std::string ValueRange::interval() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (!has_lo && !has_hi) return std::string();
  if (has_lo && !has_hi) return std::string(lo_open ? "> " : ">= ") + displayNumber(lo);
  if (!has_lo) return std::string(hi_open ? "< " : "<= ") + displayNumber(hi);
  return std::string(lo_open ? "(" : "[") + displayNumber(lo) + ", " + displayNumber(hi) +
         (hi_open ? ")" : "]");
}

std::string ValueRange::describe(const std::string& noun) const {
  const std::string i = interval();
  if (i.empty()) return noun;
  return noun + (i[0] == '(' || i[0] == '[' ? " in " : " ") + i;
}

std::string displayNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  // Whole numbers as integers ("100000", not "1e5"), up to where doubles stop being whole.
  constexpr double kExactWhole = 9007199254740992.0;  // 2^53
  if (std::floor(value) == value && std::abs(value) < kExactWhole) {
    char digits[32];
    const auto res = std::to_chars(digits, digits + sizeof(digits), static_cast<long long>(value));
    return std::string(digits, res.ptr);
  }
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof(buf), value);
  std::string s(buf, res.ptr);
  // to_chars writes exponents as "e-07" / "e+308": drop the '+' and the leading zeros.
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  std::string sign;
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  const std::size_t nz = exponent.find_first_not_of('0');
  exponent = nz == std::string::npos ? "0" : exponent.substr(nz);
  return mantissa + "e" + sign + exponent;
}

}  // namespace orni
