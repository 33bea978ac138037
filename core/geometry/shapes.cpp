#include "core/geometry/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace amls {

namespace {

constexpr double kPi = std::numbers::pi;

void require_spacing(double spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("sample spacing must be a positive finite number, got " + std::to_string(spacing));
}

// Cells of about `spacing` over a length (at least one).
std::size_t cells_over(double length, double spacing) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / spacing - 1e-9)));
}

// The Fibonacci lattice direction k of n.
Vec<3> fibonacci_direction(std::size_t k, std::size_t n) {
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  const double z = 1.0 - (2.0 * static_cast<double>(k) + 1.0) / static_cast<double>(n);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = golden_angle * static_cast<double>(k);
  return Vec<3>(r * std::cos(phi), r * std::sin(phi), z);
}

}  // namespace

PointSet<2> sample_circle(const Vec<2>& center, double radius, std::size_t count) {
  if (!(radius > 0.0)) throw std::invalid_argument("circle radius must be positive");
  PointSet<2> set;
  set.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double angle = 2.0 * kPi * static_cast<double>(i) / static_cast<double>(count);
    const Vec<2> n(std::cos(angle), std::sin(angle));
    set.add(center + radius * n, n);
  }
  return set;
}

PointSet<3> sample_sphere(const Vec<3>& center, double radius, std::size_t count) {
  if (!(radius > 0.0)) throw std::invalid_argument("sphere radius must be positive");
  PointSet<3> set;
  set.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Vec<3> n = fibonacci_direction(i, count);
    set.add(center + radius * n, n);
  }
  return set;
}

std::size_t circle_points_for_spacing(double radius, double spacing) {
  require_spacing(spacing);
  return std::max<std::size_t>(3, static_cast<std::size_t>(std::llround(2.0 * kPi * radius / spacing)));
}

std::size_t sphere_points_for_spacing(double radius, double spacing) {
  require_spacing(spacing);
  // A hexagonal lattice of spacing s has one point per sqrt(3)/2 s^2 of area.
  const double area = 4.0 * kPi * radius * radius;
  return std::max<std::size_t>(4, static_cast<std::size_t>(std::llround(area / (0.5 * std::sqrt(3.0) * spacing * spacing))));
}

PointSet<2> sample_ellipse(const Vec<2>& center, const Vec<2>& semi_axes, double spacing) {
  require_spacing(spacing);
  if (!(semi_axes.minCoeff() > 0.0) || !semi_axes.allFinite())
    throw std::invalid_argument("ellipse semi-axes must be positive");
  const double a = semi_axes.x(), b = semi_axes.y();
  // Arc length as a function of the parameter, tabulated finely enough that its
  // inverse by linear interpolation is far below the spacing.
  const std::size_t table = 64 * circle_points_for_spacing(std::max(a, b), spacing);
  std::vector<double> length(table + 1, 0.0);
  auto point = [&](double t) { return Vec<2>(a * std::cos(t), b * std::sin(t)); };
  for (std::size_t k = 1; k <= table; ++k) {
    const double t0 = 2.0 * kPi * static_cast<double>(k - 1) / static_cast<double>(table);
    const double t1 = 2.0 * kPi * static_cast<double>(k) / static_cast<double>(table);
    length[k] = length[k - 1] + (point(t1) - point(t0)).norm();
  }
  const double perimeter = length.back();
  const std::size_t count = std::max<std::size_t>(3, static_cast<std::size_t>(std::llround(perimeter / spacing)));
  PointSet<2> set;
  set.reserve(count);
  std::size_t k = 1;
  for (std::size_t i = 0; i < count; ++i) {
    const double s = perimeter * static_cast<double>(i) / static_cast<double>(count);
    while (k < table && length[k] < s) ++k;
    const double f = (s - length[k - 1]) / (length[k] - length[k - 1]);
    const double t = 2.0 * kPi * (static_cast<double>(k - 1) + f) / static_cast<double>(table);
    const Vec<2> n = Vec<2>(std::cos(t) / a, std::sin(t) / b).normalized();
    set.add(center + point(t), n);
  }
  return set;
}

PointSet<3> sample_torus(const Vec<3>& center, double major_radius, double minor_radius, double spacing) {
  require_spacing(spacing);
  if (!(minor_radius > 0.0) || !(major_radius > minor_radius) || !std::isfinite(major_radius))
    throw std::invalid_argument("torus radii must satisfy major > minor > 0");
  const std::size_t rings = circle_points_for_spacing(minor_radius, spacing);
  PointSet<3> set;
  for (std::size_t j = 0; j < rings; ++j) {
    const double v = 2.0 * kPi * static_cast<double>(j) / static_cast<double>(rings);
    const double ring_radius = major_radius + minor_radius * std::cos(v);
    const std::size_t count = circle_points_for_spacing(ring_radius, spacing);
    const double offset = j % 2 == 0 ? 0.0 : 0.5;  // staggered rows
    for (std::size_t i = 0; i < count; ++i) {
      const double u = 2.0 * kPi * (static_cast<double>(i) + offset) / static_cast<double>(count);
      const Vec<3> n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
      set.add(center + Vec<3>(ring_radius * std::cos(u), ring_radius * std::sin(u), minor_radius * std::sin(v)), n);
    }
  }
  return set;
}

namespace {

template <int D>
Vec<D> inner_half_extents(const Vec<D>& half_extents, double radius, double spacing) {
  require_spacing(spacing);
  if (!(half_extents.minCoeff() > 0.0) || !half_extents.allFinite())
    throw std::invalid_argument("rounded box half extents must be positive");
  if (!(radius >= 0.0) || radius > half_extents.minCoeff())
    throw std::invalid_argument("rounded box corner radius must lie in [0, smallest half extent], got " +
                                std::to_string(radius));
  return half_extents.array() - radius;
}

// Cell centres of [-half, half] in cells of about `spacing`; none if half is 0.
std::vector<double> cell_centres(double half, double spacing) {
  std::vector<double> out;
  if (!(half > 0.0)) return out;
  const std::size_t n = cells_over(2.0 * half, spacing);
  for (std::size_t i = 0; i < n; ++i) out.push_back(-half + 2.0 * half * (static_cast<double>(i) + 0.5) / static_cast<double>(n));
  return out;
}

// Cell-centred angles over a quarter turn.
std::vector<double> quarter_angles(double radius, double spacing) {
  std::vector<double> out;
  if (!(radius > 0.0)) return out;
  const std::size_t n = cells_over(0.5 * kPi * radius, spacing);
  for (std::size_t i = 0; i < n; ++i) out.push_back(0.5 * kPi * (static_cast<double>(i) + 0.5) / static_cast<double>(n));
  return out;
}

}  // namespace

PointSet<2> sample_rounded_box(const Vec<2>& center, const Vec<2>& half_extents, double radius, double spacing) {
  const Vec<2> inner = inner_half_extents<2>(half_extents, radius, spacing);
  PointSet<2> set;
  for (int a = 0; a < 2; ++a) {
    const int b = 1 - a;
    for (double sign : {-1.0, 1.0}) {
      // The flat side normal to axis a.
      for (double x : cell_centres(inner[b], spacing)) {
        Vec<2> p, n = Vec<2>::Zero();
        p[a] = sign * half_extents[a];
        p[b] = x;
        n[a] = sign;
        set.add(center + p, n);
      }
    }
  }
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0})
      for (double t : quarter_angles(radius, spacing)) {
        const Vec<2> n(sx * std::cos(t), sy * std::sin(t));
        set.add(center + Vec<2>(sx * inner.x(), sy * inner.y()) + radius * n, n);
      }
  return set;
}

PointSet<3> sample_rounded_box(const Vec<3>& center, const Vec<3>& half_extents, double radius, double spacing) {
  const Vec<3> inner = inner_half_extents<3>(half_extents, radius, spacing);
  PointSet<3> set;
  const double signs[2] = {-1.0, 1.0};
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    // Flat faces normal to axis a.
    for (double sign : signs)
      for (double x : cell_centres(inner[b], spacing))
        for (double y : cell_centres(inner[c], spacing)) {
          Vec<3> p, n = Vec<3>::Zero();
          p[a] = sign * half_extents[a];
          p[b] = x;
          p[c] = y;
          n[a] = sign;
          set.add(center + p, n);
        }
    // Rounded edges along axis a.
    for (double sb : signs)
      for (double sc : signs)
        for (double x : cell_centres(inner[a], spacing))
          for (double t : quarter_angles(radius, spacing)) {
            Vec<3> n = Vec<3>::Zero(), axis = Vec<3>::Zero();
            n[b] = sb * std::cos(t);
            n[c] = sc * std::sin(t);
            axis[a] = x;
            axis[b] = sb * inner[b];
            axis[c] = sc * inner[c];
            set.add(center + axis + radius * n, n);
          }
  }
  // Corners: the octants of a Fibonacci sphere of the corner radius.
  if (radius > 0.0) {
    const std::size_t n = sphere_points_for_spacing(radius, spacing);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec<3> d = fibonacci_direction(k, n);
      if ((d.array() == 0.0).any()) continue;
      const Vec<3> sign = d.array().sign();
      set.add(center + Vec<3>(sign.cwiseProduct(inner)) + radius * d, d);
    }
  }
  return set;
}

}  // namespace amls
