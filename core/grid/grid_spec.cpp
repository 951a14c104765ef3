#include "core/grid/grid_spec.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace orni {

namespace {

/// The whole of `text` as a double (from_chars: no locale, no leading '+', no spaces).
bool parseDouble(std::string_view text, double* out) {
  if (text.empty()) return false;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), *out);
  return res.ec == std::errc() && res.ptr == text.data() + text.size() && std::isfinite(*out);
}

bool parseCount(std::string_view text, int* out) {
  if (text.empty()) return false;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), *out);
  return res.ec == std::errc() && res.ptr == text.data() + text.size();
}

std::string shortest(double v) {
  if (v == 0.0) return "0";
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

}  // namespace

bool GridSpec::IsValid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (!std::isfinite(first) || !std::isfinite(last)) return fail("A and B must be finite");
  if (count < 1 || count > kMaxGridCount)
    return fail("N must be in [1, " + std::to_string(kMaxGridCount) + "]");
  if (count == 1 && first != last) return fail("N = 1 needs A == B");
  return true;
}

bool tryParseGridSpec(std::string_view text, GridSpec* out, std::string* reason) {
  auto fail = [reason](const std::string& m) {
    if (reason) *reason = m;
    return false;
  };
  const std::size_t c1 = text.find(':');
  const std::size_t c2 = c1 == std::string_view::npos ? c1 : text.find(':', c1 + 1);
  if (c2 == std::string_view::npos || text.find(':', c2 + 1) != std::string_view::npos)
    return fail("three fields separated by ':' are needed");
  GridSpec spec;
  if (!parseDouble(text.substr(0, c1), &spec.first)) return fail("A is not a finite number");
  if (!parseDouble(text.substr(c1 + 1, c2 - c1 - 1), &spec.last))
    return fail("B is not a finite number");
  if (!parseCount(text.substr(c2 + 1), &spec.count)) return fail("N is not a whole number");
  std::string why;
  if (!spec.IsValid(&why)) return fail(why);
  *out = spec;
  return true;
}

GridSpec parseGridSpec(std::string_view text) {
  GridSpec spec;
  std::string reason;
  if (!tryParseGridSpec(text, &spec, &reason))
    throw std::invalid_argument(std::string("expected A:B:N (") + kGridSpecMeaning + "), got '" +
                                std::string(text) + "' (" + reason + ")");
  return spec;
}

std::vector<double> gridValues(const GridSpec& spec) {
  std::string why;
  if (!spec.IsValid(&why)) throw std::invalid_argument("grid spec: " + why);
  std::vector<double> v(static_cast<std::size_t>(spec.count));
  if (spec.count == 1) {
    v[0] = spec.first;
    return v;
  }
  const double n1 = spec.count - 1;
  for (int i = 1; i + 1 < spec.count; ++i)
    v[static_cast<std::size_t>(i)] = (spec.first * (n1 - i) + spec.last * i) / n1;
  v.front() = spec.first;  // the ends exactly, whatever the rounding of the formula
  v.back() = spec.last;
  return v;
}

std::string toString(const GridSpec& spec) {
  return shortest(spec.first) + ":" + shortest(spec.last) + ":" + std::to_string(spec.count);
}

}  // namespace orni
