#include <doctest/doctest.h>

#include <Eigen/Core>

#include "core/small_cholesky.hpp"

namespace {

template <int N>
void check_inverse_of_random_spd_matrix(unsigned seed) {
  std::srand(seed);
  const Eigen::Matrix<double, N, N> b = Eigen::Matrix<double, N, N>::Random();
  const Eigen::Matrix<double, N, N> a = b * b.transpose() + 0.1 * Eigen::Matrix<double, N, N>::Identity();
  // Only the lower triangle is read: garbage above it must not matter.
  Eigen::Matrix<double, N, N> lower = a;
  lower.template triangularView<Eigen::StrictlyUpper>().setConstant(1e9);
  Eigen::Matrix<double, N, N> inverse;
  REQUIRE(amls::invert_positive_definite<N>(lower, inverse));
  CHECK((a * inverse - Eigen::Matrix<double, N, N>::Identity()).cwiseAbs().maxCoeff() < 1e-10);
  CHECK((inverse - inverse.transpose()).cwiseAbs().maxCoeff() == 0.0);
}

}  // namespace

TEST_CASE("invert_positive_definite inverts symmetric positive definite matrices from their lower triangle") {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    check_inverse_of_random_spd_matrix<4>(seed);
    check_inverse_of_random_spd_matrix<5>(seed);
  }
}

TEST_CASE("invert_positive_definite refuses matrices that are not positive definite") {
  Eigen::Matrix4d inverse;
  Eigen::Matrix4d indefinite = Eigen::Matrix4d::Identity();
  indefinite(2, 2) = -1.0;
  CHECK_FALSE(amls::invert_positive_definite<4>(indefinite, inverse));
  Eigen::Matrix4d singular = Eigen::Matrix4d::Zero();
  singular(0, 0) = 1.0;
  CHECK_FALSE(amls::invert_positive_definite<4>(singular, inverse));
}
