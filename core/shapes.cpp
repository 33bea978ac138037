#include "core/shapes.hpp"

#include <cmath>
#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace amls {

PointSet<2> sample_circle(const Vec<2>& center, double radius, std::size_t count) {
  if (!(radius > 0.0)) throw std::invalid_argument("circle radius must be positive");
  PointSet<2> set;
  set.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(count);
    const Vec<2> n(std::cos(angle), std::sin(angle));
    set.add(center + radius * n, n);
  }
  return set;
}

PointSet<3> sample_sphere(const Vec<3>& center, double radius, std::size_t count) {
  if (!(radius > 0.0)) throw std::invalid_argument("sphere radius must be positive");
  PointSet<3> set;
  set.reserve(count);
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(count);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * static_cast<double>(i);
    const Vec<3> n(r * std::cos(phi), r * std::sin(phi), z);
    set.add(center + radius * n, n);
  }
  return set;
}

}  // namespace amls
