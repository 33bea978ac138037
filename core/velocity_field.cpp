#include "core/velocity_field.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace amls {

namespace {
constexpr double kPi = std::numbers::pi;
}

Vec<2> SingleVortex::velocity(const Vec<2>& p, double t) const {
  const double amplitude = 2.0 * std::cos(kPi * t / period_);
  const double sx = std::sin(kPi * p.x()), cx = std::cos(kPi * p.x());
  const double sy = std::sin(kPi * p.y()), cy = std::cos(kPi * p.y());
  return amplitude * Vec<2>(-sx * sx * sy * cy, sx * cx * sy * sy);
}

Mat<2> SingleVortex::jacobian(const Vec<2>& p, double t) const {
  const double amplitude = 2.0 * std::cos(kPi * t / period_);
  const double s2x = std::sin(2 * kPi * p.x()), c2x = std::cos(2 * kPi * p.x());
  const double s2y = std::sin(2 * kPi * p.y()), c2y = std::cos(2 * kPi * p.y());
  const double sx = std::sin(kPi * p.x()), sy = std::sin(kPi * p.y());
  Mat<2> j;
  j << -0.5 * kPi * s2x * s2y, -kPi * sx * sx * c2y,  //
      kPi * c2x * sy * sy, 0.5 * kPi * s2x * s2y;
  return amplitude * j;
}

Vec<3> EnrightField::velocity(const Vec<3>& p, double t) const {
  const double g = std::cos(kPi * t / period_);
  const double sx = std::sin(kPi * p.x()), sy = std::sin(kPi * p.y()), sz = std::sin(kPi * p.z());
  const double s2x = std::sin(2 * kPi * p.x()), s2y = std::sin(2 * kPi * p.y()), s2z = std::sin(2 * kPi * p.z());
  return g * Vec<3>(2 * sx * sx * s2y * s2z, -s2x * sy * sy * s2z, -s2x * s2y * sz * sz);
}

Mat<3> EnrightField::jacobian(const Vec<3>& p, double t) const {
  const double g = std::cos(kPi * t / period_);
  const double sx = std::sin(kPi * p.x()), sy = std::sin(kPi * p.y()), sz = std::sin(kPi * p.z());
  const double s2x = std::sin(2 * kPi * p.x()), s2y = std::sin(2 * kPi * p.y()), s2z = std::sin(2 * kPi * p.z());
  const double c2x = std::cos(2 * kPi * p.x()), c2y = std::cos(2 * kPi * p.y()), c2z = std::cos(2 * kPi * p.z());
  // d/ds sin^2(pi s) = pi sin(2 pi s); d/ds sin(2 pi s) = 2 pi cos(2 pi s).
  Mat<3> j;
  j << 2 * kPi * s2x * s2y * s2z, 4 * kPi * sx * sx * c2y * s2z, 4 * kPi * sx * sx * s2y * c2z,  //
      -2 * kPi * c2x * sy * sy * s2z, -kPi * s2x * s2y * s2z, -2 * kPi * s2x * sy * sy * c2z,     //
      -2 * kPi * c2x * s2y * sz * sz, -2 * kPi * s2x * c2y * sz * sz, -kPi * s2x * s2y * s2z;
  return g * j;
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
Vec<D> RigidRotation<D>::velocity(const Vec<D>& x, double) const {
  return generator_ * (x - center_);
}

template <int D>
Mat<D> RigidRotation<D>::jacobian(const Vec<D>&, double) const {
  return generator_;
}

template class RigidRotation<2>;
template class RigidRotation<3>;

}  // namespace amls
