#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/deform/flow_deformation.hpp"
#include "core/geometry/shapes.hpp"
#include "core/math/sin_cos_pi.hpp"
#include "core/deform/velocity_field.hpp"

#include <Eigen/Geometry>

using namespace amls;

namespace {

// Central differences of the velocity, to check the analytic Jacobian.
template <int D>
Mat<D> numeric_jacobian(const VelocityField<D>& field, const Vec<D>& x, double t) {
  const double e = 1e-6;
  Mat<D> j;
  for (int a = 0; a < D; ++a) {
    const Vec<D> step = e * Vec<D>::Unit(a);
    j.col(a) = (field.sample(x + step, t).velocity - field.sample(x - step, t).velocity) / (2 * e);
  }
  return j;
}

template <int D>
void check_divergence_free_with_exact_jacobian(const VelocityField<D>& field) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = u(rng);
    const double t = 3.0 * u(rng);
    const FlowSample<D> f = field.sample(x, t);
    const Mat<D> numeric = numeric_jacobian(field, x, t);
    CHECK((f.jacobian - numeric).norm() < 1e-6);
    CHECK(std::abs(f.jacobian.trace()) < 1e-12);  // divergence = trace of the Jacobian
    CHECK(std::abs(numeric.trace()) < 1e-6);
  }
}

}  // namespace

TEST_CASE("the single-vortex field (sign restored) is divergence-free and its Jacobian is exact") {
  check_divergence_free_with_exact_jacobian<2>(SingleVortex(8.0));
}

TEST_CASE("the Enright field is divergence-free and its Jacobian is exact") {
  check_divergence_free_with_exact_jacobian<3>(EnrightField(3.0));
}

TEST_CASE("the single vortex reverses at t = 4 and brings points back at t = 8") {
  ThreadPool pool(1);
  PointSet<2> pts = sample_circle(Vec<2>(0.5, 0.75), 0.15, 64);
  const PointSet<2> start = pts;
  const FlowDeformation<2> flow(std::make_shared<SingleVortex>(8.0), 1);
  for (int k = 0; k < 800; ++k) flow.deform(pts, 0.01 * k, 0.01 * (k + 1), pool);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    CHECK((pts.positions[i] - start.positions[i]).norm() < 1e-6);
    CHECK((pts.normals[i] - start.normals[i]).norm() < 1e-5);
  }
}

TEST_CASE("a rigid rotation carries points and normals along exactly (up to RK4 error)") {
  ThreadPool pool(2);
  const Vec<3> center(0.5, 0.5, 0.5);
  PointSet<3> pts = sample_sphere(Vec<3>(0.6, 0.5, 0.5), 0.05, 100);
  const PointSet<3> start = pts;
  const double omega = std::numbers::pi / 2;  // a quarter turn per unit time about z
  const FlowDeformation<3> flow(std::make_shared<RigidRotation<3>>(center, omega, Vec<3>::UnitZ()), 4);
  for (int k = 0; k < 10; ++k) flow.deform(pts, 0.1 * k, 0.1 * (k + 1), pool);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(omega, Vec<3>::UnitZ()).toRotationMatrix();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    CHECK((pts.positions[i] - (center + r * (start.positions[i] - center))).norm() < 1e-7);
    CHECK((pts.normals[i] - r * start.normals[i]).norm() < 1e-7);
  }
}

TEST_CASE("sin_cos_pi agrees with long-double sin and cos of pi x to about an ulp") {
  const long double pi = 3.141592653589793238462643383279502884L;
  double worst = 0.0;
  // Steps of 1/10000 over [-4, 4] cross every quadrant boundary; the offset
  // keeps them off the boundaries, which the multiples of 1/4 then hit exactly.
  for (int i = -40000; i <= 40000; ++i) {
    for (const double x : {i * 1e-4 + 3.7e-6, (i % 17) * 0.25}) {
      const SinCos sc = sin_cos_pi(x);
      worst = std::max({worst, std::abs(sc.sin - static_cast<double>(sinl(pi * x))),
                        std::abs(sc.cos - static_cast<double>(cosl(pi * x)))});
    }
  }
  CHECK(worst <= 3e-16);
  CHECK(sin_cos_pi(1.0).sin == 0.0);
  CHECK(sin_cos_pi(-0.5).sin == -1.0);
  CHECK(std::isnan(sin_cos_pi(std::nan("")).sin));
}
