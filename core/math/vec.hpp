#pragma once
// Fixed-size vector types shared by the whole core. D is the dimension (2 or 3).
#include <Eigen/Core>
#include <cstdint>

namespace amls {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

template <int D>
using Mat = Eigen::Matrix<double, D, D>;

// Integer grid coordinates (vertex or cell indices) may be negative near the
// domain's border, so they are signed.
template <int D>
using IVec = Eigen::Matrix<std::int64_t, D, 1>;

}  // namespace amls
