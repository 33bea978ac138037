#include <doctest/doctest.h>

#include <Eigen/Core>

#include "core/math/small_cholesky.hpp"

using namespace amls;

namespace {

template <int M>
Eigen::Matrix<double, M, M> random_spd_matrix() {
  const Eigen::Matrix<double, M, M> b = Eigen::Matrix<double, M, M>::Random();
  return b * b.transpose() + 0.1 * Eigen::Matrix<double, M, M>::Identity();
}

// Puts matrix a's lower triangle into lane l.
template <int M, int Pairs>
void put_lane(typename LaneLdlt<M, Pairs>::Packed& lower, int l, const Eigen::Matrix<double, M, M>& a) {
  for (int j = 0; j < M; ++j)
    for (int i = j; i < M; ++i) set_lane(lower[packed_index<M>(i, j)], l, a(i, j));
}

// Solves with a random positive definite matrix in every lane at once, and
// checks each lane against the residual and against the same matrix solved
// in the first lane of a single pair.
template <int M, int Pairs>
void check_lanes_of_random_spd_matrices(unsigned seed) {
  std::srand(seed);
  constexpr int kLanes = Pairs * kLanesPerPair;
  typename LaneLdlt<M, Pairs>::Packed lower;
  LaneVector<M, Pairs> x;
  std::array<Eigen::Matrix<double, M, M>, kLanes> a;
  std::array<Eigen::Matrix<double, M, 1>, kLanes> rhs;
  for (int l = 0; l < kLanes; ++l) {
    a[l] = random_spd_matrix<M>();
    rhs[l] = Eigen::Matrix<double, M, 1>::Random();
    put_lane<M, Pairs>(lower, l, a[l]);
    for (int i = 0; i < M; ++i) set_lane(x[i], l, rhs[l][i]);
  }
  LaneLdlt<M, Pairs> ldlt;
  const LaneMasks<Pairs> positive = ldlt.factor(lower, {});
  ldlt.solve(x);
  for (int l = 0; l < kLanes; ++l) {
    CAPTURE(l);
    REQUIRE(in_lane(positive, l));
    const Eigen::Matrix<double, M, 1> solution = lane_vector<M, Pairs>(x, l);
    CHECK((a[l] * solution - rhs[l]).cwiseAbs().maxCoeff() < 1e-10);
    // Alone, the lane's numbers go through the same operations.
    typename LaneLdlt<M, 1>::Packed alone_lower{};
    put_lane<M, 1>(alone_lower, 0, a[l]);
    LaneVector<M, 1> alone{};
    for (int i = 0; i < M; ++i) set_lane(alone[i], 0, rhs[l][i]);
    LaneLdlt<M, 1> alone_ldlt;
    const LaneMasks<1> alone_positive = alone_ldlt.factor(alone_lower, {});
    REQUIRE(in_lane(alone_positive, 0));
    alone_ldlt.solve(alone);
    CHECK(lane_vector<M, 1>(alone, 0) == solution);
  }
}

}  // namespace

TEST_CASE("LaneLdlt solves symmetric positive definite systems lane by lane, as each would be alone") {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    check_lanes_of_random_spd_matrices<4, 2>(seed);
    check_lanes_of_random_spd_matrices<5, 2>(seed);
    check_lanes_of_random_spd_matrices<4, 1>(seed);
  }
}

TEST_CASE("LaneLdlt flags the lanes whose matrix is not positive definite, and a shift can make it so") {
  using Ldlt = LaneLdlt<4, 2>;
  Ldlt::Packed lower;
  Eigen::Matrix4d indefinite = Eigen::Matrix4d::Identity();
  indefinite(2, 2) = -1.0;
  Eigen::Matrix4d singular = Eigen::Matrix4d::Zero();
  singular(0, 0) = 1.0;
  Eigen::Matrix4d not_a_number = Eigen::Matrix4d::Identity();
  not_a_number(1, 1) = std::numeric_limits<double>::quiet_NaN();
  put_lane<4, 2>(lower, 0, indefinite);
  put_lane<4, 2>(lower, 1, Eigen::Matrix4d::Identity());
  put_lane<4, 2>(lower, 2, singular);
  put_lane<4, 2>(lower, 3, not_a_number);
  Ldlt ldlt;
  LaneMasks<2> positive = ldlt.factor(lower, {});
  CHECK_FALSE(in_lane(positive, 0));
  CHECK(in_lane(positive, 1));
  CHECK_FALSE(in_lane(positive, 2));
  CHECK_FALSE(in_lane(positive, 3));
  Lanes<2> shift{};
  set_lane(shift, 2, 1e-3);
  positive = ldlt.factor(lower, shift);
  CHECK_FALSE(in_lane(positive, 0));
  CHECK(in_lane(positive, 1));
  CHECK(in_lane(positive, 2));
  // The shifted singular matrix is diag(1 + 1e-3, 1e-3, 1e-3, 1e-3).
  LaneVector<4, 2> x{};
  for (int i = 0; i < 4; ++i) set_lane(x[i], 2, 1.0);
  ldlt.solve(x);
  CHECK(lane_of(x[0], 2) == doctest::Approx(1.0 / 1.001));
  CHECK(lane_of(x[3], 2) == doctest::Approx(1e3));
}
