#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <random>

#include "core/surface/gradient_fit.hpp"
#include "core/math/weight.hpp"

using namespace amls;

namespace {

struct Sample {
  Vec<3> d;  // position relative to x
  Vec<3> n;
  double w;
};

// The finite-K problem of eq. (7) solved directly: unknowns (c, b, a) of
// f(d) = c + b.d + a |d|^2.
Eigen::Matrix<double, 5, 1> solve_finite_k(const std::vector<Sample>& s, double k) {
  Eigen::Matrix<double, 5, 5> m = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> rhs = Eigen::Matrix<double, 5, 1>::Zero();
  for (const Sample& e : s) {
    Eigen::Matrix<double, 5, 1> value_row;
    value_row << 1, e.d, e.d.squaredNorm();
    m += e.w * value_row * value_row.transpose();
    for (int axis = 0; axis < 3; ++axis) {  // d f / d x_axis = b_axis + 2 a d_axis
      Eigen::Matrix<double, 5, 1> g = Eigen::Matrix<double, 5, 1>::Zero();
      g[1 + axis] = 1;
      g[4] = 2 * e.d[axis];
      m += k * e.w * g * g.transpose();
      rhs += k * e.w * e.n[axis] * g;
    }
  }
  return m.fullPivLu().solve(rhs);
}

}  // namespace

TEST_CASE("finite-K gradient-constrained fits converge to the closed form as K grows") {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Sample> samples;
  GradientFit<3> fit;
  for (int i = 0; i < 40; ++i) {
    const Vec<3> d(0.03 * u(rng), 0.03 * u(rng), 0.01 * u(rng));
    const Vec<3> n = Vec<3>(0.2 * u(rng), 0.2 * u(rng), 1.0).normalized();
    const double w = weight_of_squared_ratio(d.squaredNorm() / (0.04 * 0.04));
    samples.push_back({d, n, w});
    fit.add(d, n, w);
  }
  const Evaluation<3> limit = fit.solve(0.0);
  REQUIRE(limit.defined);
  double previous_error = 1e300;
  for (double k : {1e0, 1e2, 1e4, 1e6}) {
    const auto c = solve_finite_k(samples, k);
    const double error = std::abs(c[0] - limit.value) + (c.segment<3>(1) - limit.gradient).norm();
    CHECK(error < previous_error);
    previous_error = error;
  }
  CHECK(previous_error < 1e-6);
}

TEST_CASE("the gradient-constrained fit reproduces a circle: F is (|x-c|^2 - r^2) / 2r") {
  const Vec<2> center(0.5, 0.75);
  const double r = 0.15;
  for (const Vec<2>& x : {Vec<2>(0.5, 0.9), Vec<2>(0.62, 0.8), Vec<2>(0.5, 0.6 + 0.01)}) {
    GradientFit<2> fit;
    for (int i = 0; i < 400; ++i) {
      const double a = 2 * M_PI * i / 400.0;
      const Vec<2> n(std::cos(a), std::sin(a));
      const Vec<2> d = center + r * n - x;
      fit.add(d, n, weight_of_squared_ratio(d.squaredNorm() / (0.05 * 0.05)));
    }
    const Evaluation<2> e = fit.solve(0.2);
    REQUIRE(e.defined);
    CHECK(e.value == doctest::Approx(((x - center).squaredNorm() - r * r) / (2 * r)).epsilon(1e-10));
    CHECK((e.gradient - (x - center) / r).norm() < 1e-10);
  }
}

TEST_CASE("F is undefined where too little weight reaches x") {
  GradientFit<2> fit;
  fit.add(Vec<2>(0.1, 0), Vec<2>(0, 1), 0.05);
  fit.add(Vec<2>(-0.1, 0), Vec<2>(0, 1), 0.05);
  CHECK_FALSE(fit.solve(0.2).defined);
  CHECK(fit.solve(0.05).defined);
}
