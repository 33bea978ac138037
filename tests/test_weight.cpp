#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "core/math/weight.hpp"

using namespace amls;

// weight_of_squared_ratio() avoids std::max for speed; it must still give
// psi = max(0, 1 - s^2)^4 bit for bit, on and beyond the support's edge.
TEST_CASE("the weight is max(0, 1 - s^2)^4 bit for bit, zero from s = 1 on") {
  std::vector<double> s2s = {-1.0, -0.0, 0.0, 1e-300, 0.5, 1.0 - 1e-16, 1.0, 1.0 + 1e-16, 2.0, 1e300,
                             std::numeric_limits<double>::infinity(), std::nan("")};
  for (int i = 0; i <= 1000; ++i) s2s.push_back(i * 1.37e-3);
  for (const double value : s2s) {
    // Through a volatile: GCC folds maxsd of a constant NaN to NaN where the
    // instruction gives 0, and callers pass run-time values.
    volatile double opaque = value;
    const double s2 = opaque;
    CAPTURE(s2);
    const double a = std::max(0.0, 1.0 - s2);
    const double expected = (a * a) * (a * a);
    const double w = weight_of_squared_ratio(s2);
    CHECK(std::memcmp(&w, &expected, sizeof w) == 0);
    if (!(s2 < 1.0)) CHECK(w == 0.0);  // NaN too, as std::max gives it
  }
  CHECK(weight_of_squared_ratio(0.0) == 1.0);
}

TEST_CASE("the packed weights are the single weights bit for bit") {
  const double s2s[8] = {-0.0, 0.25, 1.0 - 1e-16, 1.0, 3.0, std::numeric_limits<double>::infinity(), std::nan(""), 0.7};
  volatile double opaque[8];
  for (int i = 0; i < 8; ++i) opaque[i] = s2s[i];
  double s2[8], w[8];
  for (int i = 0; i < 8; ++i) s2[i] = opaque[i];
  weights_of_squared_ratios(s2, w);
  for (int i = 0; i < 8; ++i) {
    CAPTURE(s2[i]);
    const double expected = weight_of_squared_ratio(s2[i]);
    CHECK(std::memcmp(&w[i], &expected, sizeof expected) == 0);
  }
}
