#pragma once
// Deformations given by velocity fields v(x, t) (paper, section 5): the single
// vortex (2D), Enright's field (3D) and rigid rotations. Each field also gives
// its Jacobian, so that carried normals can follow the flow.
#include <memory>

#include "core/math/vec.hpp"

namespace amls {

// The velocity at a point and its Jacobian J_ij = d v_i / d x_j, computed
// together because they share their (costly) trigonometry.
template <int D>
struct FlowSample {
  Vec<D> velocity;
  Mat<D> jacobian;
};

// Every field here is separable, v(x, t) = amplitude(t) * pattern(x), so that
// a deformation evaluates the time factor once per time level rather than once
// per point.
template <int D>
class VelocityField {
 public:
  virtual ~VelocityField() = default;
  virtual double amplitude(double t) const = 0;
  virtual FlowSample<D> pattern(const Vec<D>& x) const = 0;

  FlowSample<D> sample(const Vec<D>& x, double t) const {
    FlowSample<D> f = pattern(x);
    const double a = amplitude(t);
    f.velocity *= a;
    f.jacobian *= a;
    return f;
  }
};

// The single vortex of eq. (12) with the sign lost in print restored, so that it
// is divergence-free: u = -T(t) sin^2(pi x) sin(pi y) cos(pi y),
// v = T(t) sin(pi x) cos(pi x) sin^2(pi y), T(t) = 2 cos(pi t / period).
// Over [0, period] the flow returns every point to where it started.
class SingleVortex final : public VelocityField<2> {
 public:
  explicit SingleVortex(double period = 8.0) : period_(period) {}
  double amplitude(double t) const override;
  FlowSample<2> pattern(const Vec<2>& x) const override;

 private:
  double period_;
};

// Enright et al.'s 3D test field: u = 2 sin^2(pi x) sin(2 pi y) sin(2 pi z) g,
// v = -sin(2 pi x) sin^2(pi y) sin(2 pi z) g, w = -sin(2 pi x) sin(2 pi y) sin^2(pi z) g,
// g = cos(pi t / period).
class EnrightField final : public VelocityField<3> {
 public:
  explicit EnrightField(double period = 3.0) : period_(period) {}
  double amplitude(double t) const override;
  FlowSample<3> pattern(const Vec<3>& x) const override;

 private:
  double period_;
};

// Rotation about `center` at `angular_velocity` radians per unit time (about
// `axis` in 3D, which must be a unit vector).
template <int D>
class RigidRotation final : public VelocityField<D> {
 public:
  RigidRotation(const Vec<D>& center, double angular_velocity, const Vec<3>& axis = Vec<3>::UnitZ());
  double amplitude(double) const override { return 1.0; }
  FlowSample<D> pattern(const Vec<D>& x) const override;

 private:
  Vec<D> center_;
  Mat<D> generator_;  // v = generator (x - center)
};

extern template class RigidRotation<2>;
extern template class RigidRotation<3>;

}  // namespace amls
