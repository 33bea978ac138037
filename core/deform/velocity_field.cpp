#include "core/deform/velocity_field.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/math/sin_cos_pi.hpp"

namespace amls {

namespace {
constexpr double kPi = std::numbers::pi;
}

double SingleVortex::amplitude(double t) const { return 2.0 * std::cos(kPi * t / period_); }

FlowSample<2> SingleVortex::pattern(const Vec<2>& p) const {
  const auto [sx, cx] = sin_cos_pi(p.x());
  const auto [sy, cy] = sin_cos_pi(p.y());
  // Double angles from the single ones: sin 2a = 2 sin a cos a, cos 2a = 1 - 2 sin^2 a.
  const double s2x = 2 * sx * cx, c2x = 1 - 2 * sx * sx;
  const double s2y = 2 * sy * cy, c2y = 1 - 2 * sy * sy;
  FlowSample<2> f;
  f.velocity = Vec<2>(-sx * sx * sy * cy, sx * cx * sy * sy);
  f.jacobian << -0.5 * kPi * s2x * s2y, -kPi * sx * sx * c2y,  //
      kPi * c2x * sy * sy, 0.5 * kPi * s2x * s2y;
  return f;
}

double EnrightField::amplitude(double t) const { return std::cos(kPi * t / period_); }

FlowSample<3> EnrightField::pattern(const Vec<3>& p) const {
  const auto [sx, cx] = sin_cos_pi(p.x());
  const auto [sy, cy] = sin_cos_pi(p.y());
  const auto [sz, cz] = sin_cos_pi(p.z());
  const double s2x = 2 * sx * cx, s2y = 2 * sy * cy, s2z = 2 * sz * cz;
  const double c2x = 1 - 2 * sx * sx, c2y = 1 - 2 * sy * sy, c2z = 1 - 2 * sz * sz;
  FlowSample<3> f;
  f.velocity = Vec<3>(2 * sx * sx * s2y * s2z, -s2x * sy * sy * s2z, -s2x * s2y * sz * sz);
  // d/ds sin^2(pi s) = pi sin(2 pi s); d/ds sin(2 pi s) = 2 pi cos(2 pi s).
  f.jacobian << 2 * kPi * s2x * s2y * s2z, 4 * kPi * sx * sx * c2y * s2z, 4 * kPi * sx * sx * s2y * c2z,  //
      -2 * kPi * c2x * sy * sy * s2z, -kPi * s2x * s2y * s2z, -2 * kPi * s2x * sy * sy * c2z,                //
      -2 * kPi * c2x * s2y * sz * sz, -2 * kPi * s2x * c2y * sz * sz, -kPi * s2x * s2y * s2z;
  return f;
}

template <int D>
RigidRotation<D>::RigidRotation(const Vec<D>& center, double angular_velocity, const Vec<3>& axis)
    : center_(center) {
  if constexpr (D == 2) {
    generator_ << 0, -angular_velocity, angular_velocity, 0;
  } else {
    if (std::abs(axis.norm() - 1.0) > 1e-9) throw std::invalid_argument("rotation axis must be a unit vector");
    const Vec<3> w = angular_velocity * axis;
    generator_ << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  }
}

template <int D>
FlowSample<D> RigidRotation<D>::pattern(const Vec<D>& x) const {
  return {generator_ * (x - center_), generator_};
}

template class RigidRotation<2>;
template class RigidRotation<3>;

}  // namespace amls
