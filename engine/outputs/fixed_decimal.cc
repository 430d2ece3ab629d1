// SPDX-License-Identifier: MIT
#include "engine/outputs/fixed_decimal.h"

#include <charconv>
#include <cmath>

namespace rpt::engine {
namespace {

// `digits` with a point before its last kDecimals digits ("0.0012" for 12 and 4) at `p`; returns
// the end.
template <int kDecimals>
char* WriteDigits(unsigned long long digits, char* p) {
  constexpr unsigned long long kPower = [] {
    unsigned long long power = 1;
    for (int i = 0; i < kDecimals; ++i) power *= 10;
    return power;
  }();
  p = std::to_chars(p, p + 24, digits / kPower).ptr;
  *p++ = '.';
  unsigned long long rest = digits % kPower;
  for (int i = kDecimals - 1; i >= 0; --i) {
    p[i] = static_cast<char>('0' + rest % 10);
    rest /= 10;
  }
  return p + kDecimals;
}

}  // namespace

void AppendFixedDecimal(double value, int decimals, std::string* out) {
  static constexpr double kScale[7] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6};
  char text[64];
  if (decimals >= 0 && decimals <= 6) {
    // The product value * 10^decimals rounded once (10^decimals is exact). Below 2^32 every
    // rounding tie k + 0.5 is a double, and rounding is monotonic and keeps doubles: a product on
    // one side of a tie stays on that side or lands on it. So where the rounded product is not a
    // tie it rounds to the same integer as the exact one; on a tie (and for large values)
    // std::to_chars decides.
    const double magnitude = std::fabs(value * kScale[decimals]);
    if (magnitude < 4294967296.0) {
      const auto whole = static_cast<unsigned long long>(magnitude);   // the floor: not negative
      const double fraction = magnitude - static_cast<double>(whole);  // exact: both below 2^32
      if (fraction != 0.5) {
        const unsigned long long digits = whole + (fraction > 0.5 ? 1 : 0);
        char* p = text;
        if (std::signbit(value)) *p++ = '-';
        switch (decimals) {  // constant divisors: multiplications, not divisions
          case 0:
            p = std::to_chars(p, text + sizeof(text), digits).ptr;
            break;
          case 1:
            p = WriteDigits<1>(digits, p);
            break;
          case 2:
            p = WriteDigits<2>(digits, p);
            break;
          case 3:
            p = WriteDigits<3>(digits, p);
            break;
          case 4:
            p = WriteDigits<4>(digits, p);
            break;
          case 5:
            p = WriteDigits<5>(digits, p);
            break;
          default:
            p = WriteDigits<6>(digits, p);
            break;
        }
        out->append(text, p);
        return;
      }
    }
  }
  char wide[400];  // the largest double has 309 digits before the point
  const auto [end, error] = std::to_chars(wide, wide + sizeof(wide), value, std::chars_format::fixed, decimals);
  out->append(wide, error == std::errc() ? end : wide);
}

}  // namespace rpt::engine
