#include "core/surface/local_support.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/geometry/kd_tree.hpp"
#include "core/geometry/sample_spacing.hpp"

namespace amls {

namespace {

// D - 1 unit vectors orthogonal to the unit vector n and to each other.
template <int D>
std::array<Vec<D>, D - 1> tangent_basis(const Vec<D>& n) {
  if constexpr (D == 2) {
    return {Vec<D>(-n[1], n[0])};
  } else {
    // The axis least aligned with n gives a well-conditioned cross product.
    int least = 0;
    n.cwiseAbs().minCoeff(&least);
    const Vec<D> first = n.cross(Vec<D>::Unit(least)).normalized();
    return {first, n.cross(first)};
  }
}

}  // namespace

template <int D>
std::vector<double> widened_support_radii(const std::vector<Vec<D>>& positions, double radius, double h,
                                          ThreadPool& pool) {
  const std::size_t n = positions.size();
  if (n <= static_cast<std::size_t>(kSpacingNeighbours)) return {};
  KdTree<D> tree;
  tree.build(positions);
  std::vector<double> radii(n);
  std::vector<unsigned char> wide(static_cast<std::size_t>(pool.threads()), 0);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int block) {
    std::vector<std::uint32_t> ids;
    std::vector<double> squared;
    bool widened = false;
    for (std::size_t i = begin; i < end; ++i) {
      // The point itself is among its k + 1 nearest (sample_spacing.hpp's rule).
      tree.nearest(positions[i], static_cast<std::size_t>(kSpacingNeighbours) + 1, ids, squared);
      const double own_spacing = std::sqrt(squared.back()) / kSpacingNeighbourDivisor;
      radii[i] = radius * std::clamp(own_spacing / (kRegularSpread * h), 1.0, kMostWidening);
      widened = widened || radii[i] > radius;
    }
    if (widened) wide[static_cast<std::size_t>(block)] = 1;
  });
  if (std::find(wide.begin(), wide.end(), 1) == wide.end()) radii.clear();
  return radii;
}

template <int D>
void append_widened_walk_positions(const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                                   const std::vector<double>& radii, double radius, double h,
                                   std::vector<Vec<D>>& out, ThreadPool& pool) {
  const double step = 2.0 * h;
  // Calls visit(offset) for every offset of point i's disc: every k in
  // [-steps, steps]^(D-1) whose position lies within the disc, widened by a
  // step so that the walks' blocks reach its rim.
  const auto for_each_offset = [&](std::size_t i, auto&& visit) {
    if (!(radii[i] > radius)) return;
    const double norm = normals[i].norm();
    if (!(norm > 0.0)) return;
    const std::array<Vec<D>, D - 1> basis = tangent_basis<D>(Vec<D>(normals[i] / norm));
    const double disc = kWalkDisc * radii[i];
    const int steps = static_cast<int>(std::ceil(disc / step));
    const double disc2 = (disc + step) * (disc + step);
    IVec<D - 1> k = IVec<D - 1>::Constant(-steps);
    for (;;) {
      Vec<D> offset = Vec<D>::Zero();
      for (int a = 0; a < D - 1; ++a) offset += (step * static_cast<double>(k[a])) * basis[static_cast<std::size_t>(a)];
      if (!k.isZero() && offset.squaredNorm() <= disc2) visit(offset);
      int a = 0;
      while (a < D - 1 && k[a] == steps) k[a++] = -steps;
      if (a == D - 1) break;
      ++k[a];
    }
  };
  // A disc can hold a thousand positions and every point can be widened (a
  // grid far finer than the input): counted first and written in place, on the
  // pool, so that no reallocation copies the list while Ctrl+C waits.
  std::vector<std::size_t> first(radii.size() + 1, 0);
  pool.parallel_for(radii.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) for_each_offset(i, [&](const Vec<D>&) { ++first[i + 1]; });
  });
  for (std::size_t i = 0; i < radii.size(); ++i) first[i + 1] += first[i];
  const std::size_t start = out.size();
  out.resize(start + first.back());
  pool.parallel_for(radii.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      std::size_t slot = start + first[i];
      for_each_offset(i, [&](const Vec<D>& offset) { out[slot++] = positions[i] + offset; });
    }
  });
}

template std::vector<double> widened_support_radii<2>(const std::vector<Vec<2>>&, double, double, ThreadPool&);
template std::vector<double> widened_support_radii<3>(const std::vector<Vec<3>>&, double, double, ThreadPool&);
template void append_widened_walk_positions<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&,
                                               const std::vector<double>&, double, double, std::vector<Vec<2>>&,
                                               ThreadPool&);
template void append_widened_walk_positions<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&,
                                               const std::vector<double>&, double, double, std::vector<Vec<3>>&,
                                               ThreadPool&);

}  // namespace amls
