#include "core/geometry/surface_scatter.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "core/geometry/kd_tree.hpp"
#include "core/geometry/sample_spacing.hpp"

namespace amls {

namespace {

template <int D>
struct Neighbours {
  Vec<D> centre = Vec<D>::Zero();
  // The principal axes, least spread first, and the spreads (covariance eigenvalues) along them.
  Eigen::SelfAdjointEigenSolver<Mat<D>> frame;
};

template <int D>
Neighbours<D> principal_axes(const std::vector<Vec<D>>& positions, const std::vector<std::uint32_t>& ids) {
  Neighbours<D> out;
  for (const std::uint32_t id : ids) out.centre += positions[id];
  out.centre /= static_cast<double>(ids.size());
  Mat<D> covariance = Mat<D>::Zero();
  for (const std::uint32_t id : ids) {
    const Vec<D> d = positions[id] - out.centre;
    covariance += d * d.transpose();
  }
  out.frame.compute(covariance);
  return out;
}

template <int D>
double thickness_of(const std::vector<Vec<D>>& positions, const std::vector<std::uint32_t>& ids) {
  const auto spreads = principal_axes<D>(positions, ids).frame.eigenvalues();
  return spreads[1] > 0.0 ? std::sqrt(std::max(spreads[0], 0.0) / spreads[1]) : 0.0;
}

// The RMS residual of the quadric height field over the principal plane:
// terms 1, u, and the products of two tangent coordinates (3D: 1, u, v, u^2,
// uv, v^2; 2D: 1, u, u^2).
template <int D>
double quadric_residual(const std::vector<Vec<D>>& positions, const std::vector<std::uint32_t>& ids) {
  constexpr int kTerms = 1 + (D - 1) + (D - 1) * D / 2;
  const Neighbours<D> axes = principal_axes<D>(positions, ids);
  Eigen::MatrixXd basis(ids.size(), kTerms);
  Eigen::VectorXd height(ids.size());
  for (std::size_t row = 0; row < ids.size(); ++row) {
    const Vec<D> local = axes.frame.eigenvectors().transpose() * (positions[ids[row]] - axes.centre);
    int column = 0;
    basis(row, column++) = 1.0;
    for (int a = 1; a < D; ++a) basis(row, column++) = local[a];
    for (int a = 1; a < D; ++a)
      for (int b = a; b < D; ++b) basis(row, column++) = local[a] * local[b];
    height(row) = local[0];
  }
  const Eigen::VectorXd coefficients = basis.colPivHouseholderQr().solve(height);
  return std::sqrt((basis * coefficients - height).squaredNorm() / static_cast<double>(ids.size()));
}

// The median of `measure` over the measured points' `count` nearest neighbours.
template <int D>
double median_over_neighbourhoods(
    const std::vector<Vec<D>>& positions, const KdTree<D>& tree, int count,
    const std::function<double(const std::vector<Vec<D>>&, const std::vector<std::uint32_t>&)>& measure) {
  const std::size_t n = positions.size();
  const std::size_t stride = (n + SurfaceScatter::kMostPoints - 1) / SurfaceScatter::kMostPoints;
  std::vector<double> values;
  values.reserve(n / stride + 1);
  std::vector<std::uint32_t> ids;
  std::vector<double> squared;
  for (std::size_t i = 0; i < n; i += stride) {
    tree.nearest(positions[i], static_cast<std::size_t>(count), ids, squared);
    values.push_back(measure(positions, ids));
  }
  return median_of(std::move(values));
}

}  // namespace

template <int D>
SurfaceScatter surface_scatter(const std::vector<Vec<D>>& positions) {
  SurfaceScatter out;
  if (positions.size() <= static_cast<std::size_t>(SurfaceScatter::kScatterNeighbours)) return out;
  KdTree<D> tree;
  tree.build(positions);
  out.thickness = median_over_neighbourhoods<D>(positions, tree, SurfaceScatter::kThicknessNeighbours, thickness_of<D>);
  if (out.noisy())
    out.scatter =
        median_over_neighbourhoods<D>(positions, tree, SurfaceScatter::kScatterNeighbours, quadric_residual<D>);
  return out;
}

template SurfaceScatter surface_scatter<2>(const std::vector<Vec<2>>&);
template SurfaceScatter surface_scatter<3>(const std::vector<Vec<3>>&);

}  // namespace amls
