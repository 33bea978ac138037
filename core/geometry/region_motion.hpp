#pragma once
// The motion of a region handle (Pauly et al. 2003, "Shape modeling with
// point-sampled geometry": a handle region moved as one piece): a rotation
// and a uniform scale about the region's centre, then a translation of the
// centre. It is given by its parameters, not by a matrix, so that a scene
// stores exactly what the editor applied and a replay rebuilds the same map.
#include <cmath>

#include <Eigen/Geometry>

#include "core/math/vec.hpp"

namespace amls {

// 2D: the angle; 3D: the rotation vector (the axis times the angle). Radians.
template <int D>
using RotationParameters = Eigen::Matrix<double, D == 2 ? 1 : 3, 1>;

template <int D>
struct RegionMotion {
  Vec<D> translation = Vec<D>::Zero();  // of the region's centre
  RotationParameters<D> rotation = RotationParameters<D>::Zero();
  double scale = 1.0;

  bool operator==(const RegionMotion&) const = default;
  bool is_identity() const { return *this == RegionMotion{}; }
  bool finite() const { return translation.allFinite() && rotation.allFinite() && std::isfinite(scale); }

  Mat<D> rotation_matrix() const {
    if constexpr (D == 2) {
      const double c = std::cos(rotation[0]), s = std::sin(rotation[0]);
      Mat<2> r;
      r << c, -s, s, c;
      return r;
    } else {
      const double angle = rotation.norm();
      if (angle == 0.0) return Mat<3>::Identity();
      return Eigen::AngleAxisd(angle, rotation / angle).toRotationMatrix();
    }
  }
  // x -> centre + translation + scale R (x - centre) is x -> linear x + offset.
  Mat<D> linear() const { return scale * rotation_matrix(); }
  Vec<D> offset(const Vec<D>& centre) const { return centre + translation - linear() * centre; }

  // The parameters move linearly: a rotation about a fixed axis turns at a
  // constant rate, as point handles move along straight lines. Exact at t = 0 and 1.
  static RegionMotion lerp(const RegionMotion& a, const RegionMotion& b, double t) {
    return {(1.0 - t) * a.translation + t * b.translation, (1.0 - t) * a.rotation + t * b.rotation,
            (1.0 - t) * a.scale + t * b.scale};
  }
};

}  // namespace amls
