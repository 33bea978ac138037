#include "core/deform/strain_lattice.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/geometry/grid.hpp"

namespace amls {

namespace {

// The dense tables cost a few bytes per lattice cell: beyond this many cells
// per point (plus a floor for small sets) the points are too scattered for a
// lattice to pay.
constexpr double kMaxCellsPerPoint = 4.0;
constexpr double kMinCells = 4096.0;

// Row-major (axis 0 fastest) index of v in a box of `size` per axis.
template <int D>
std::size_t index_in(const IVec<D>& v, const IVec<D>& size) {
  std::size_t index = 0;
  for (int a = D - 1; a >= 0; --a) index = index * static_cast<std::size_t>(size[a]) + static_cast<std::size_t>(v[a]);
  return index;
}

// The mean Jacobian over a cube of side `spacing` from its corners' images.
template <int D>
Mat<D> cube_jacobian(const std::array<Vec<D>, 1 << D>& images, double spacing) {
  Mat<D> jacobian = Mat<D>::Zero();
  for (int v = 0; v < (1 << D); ++v)
    for (int a = 0; a < D; ++a)
      if ((v >> a) & 1)
        jacobian.col(a) += images[static_cast<std::size_t>(v)] - images[static_cast<std::size_t>(v & ~(1 << a))];
  return jacobian / (spacing * static_cast<double>(1 << (D - 1)));
}

template <int D>
float strain_of(const Mat<D>& jacobian) {
  return static_cast<float>(0.5 * (jacobian.transpose() * jacobian - Mat<D>::Identity()).norm());
}

}  // namespace

template <int D>
float cube_strain(const std::array<Vec<D>, 1 << D>& images, double spacing) {
  return strain_of<D>(cube_jacobian<D>(images, spacing));
}

template <int D>
float step_cube_strain(const std::array<Vec<D>, 1 << D>& before, const std::array<Vec<D>, 1 << D>& after,
                       double spacing) {
  const Mat<D> from = cube_jacobian<D>(before, spacing);
  const double det = from.determinant();
  if (!(det > 0.0) || !std::isfinite(det)) return std::numeric_limits<float>::infinity();
  return strain_of<D>(Mat<D>(cube_jacobian<D>(after, spacing) * from.inverse()));
}

template <int D>
StrainLatticeStats add_step_strain(const Deformation<D>& deformation, double t0, double t1,
                                   const std::vector<Vec<D>>& positions, double spacing, std::vector<float>& strain,
                                   ThreadPool& pool) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("strain lattice: the spacing must be a positive number, got " +
                                std::to_string(spacing));
  const std::size_t n = positions.size();
  strain.resize(n, 0.0F);
  StrainLatticeStats stats;
  if (n == 0) return stats;

  // The points' box, in cells.
  Vec<D> lo = positions.front(), hi = lo;
  for (const Vec<D>& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // The cells start one below the points' box, as the MLS lattice's do (its
  // nodes need a halo there): for an MLS map both measure the same cells.
  lo.array() -= spacing;
  IVec<D> cells;
  double total_cells = 1.0;
  for (int a = 0; a < D; ++a) {
    const double across = std::floor((hi[a] - lo[a]) / spacing) + 1.0;
    total_cells *= across;
    cells[a] = std::isfinite(across) ? static_cast<std::int64_t>(std::min(across, 1e9)) : 1;
  }
  if (!std::isfinite(total_cells) || total_cells > kMaxCellsPerPoint * static_cast<double>(n) + kMinCells) {
    stats.fell_back = true;
    std::fill(strain.begin(), strain.end(), std::numeric_limits<float>::infinity());
    return stats;
  }
  const IVec<D> node_size = cells.array() + 1;

  // Each point's cell, and the cells holding points.
  std::vector<std::uint32_t> point_cell(n);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      IVec<D> c;
      for (int a = 0; a < D; ++a)
        c[a] = std::clamp(static_cast<std::int64_t>(std::floor((positions[i][a] - lo[a]) / spacing)), std::int64_t{0},
                          cells[a] - 1);
      point_cell[i] = static_cast<std::uint32_t>(index_in<D>(c, cells));
    }
  });
  std::vector<std::uint8_t> used(static_cast<std::size_t>(total_cells), 0);
  for (const std::uint32_t c : point_cell) used[c] = 1;

  // Their corners, deformed as points are.
  constexpr std::int32_t kNone = -1;
  std::vector<std::int32_t> node_slot(index_in<D>(cells, node_size) + 1, kNone);
  std::vector<IVec<D>> used_cells;
  PointSet<D> nodes;
  for_each_index_in_box<D>(IVec<D>::Zero(), cells.array() - 1, [&](const IVec<D>& c) {
    if (!used[index_in<D>(c, cells)]) return;
    used_cells.push_back(c);
    for (int v = 0; v < (1 << D); ++v) {
      const IVec<D> node = c + corner_offset<D>(v);
      std::int32_t& slot = node_slot[index_in<D>(node, node_size)];
      if (slot != kNone) continue;
      slot = static_cast<std::int32_t>(nodes.positions.size());
      nodes.positions.push_back(lo + spacing * node.template cast<double>());
    }
  });
  nodes.normals.assign(nodes.positions.size(), Vec<D>::UnitX());
  deformation.deform(nodes, t0, t1, pool);
  stats.cells = used_cells.size();
  stats.nodes = nodes.size();

  // Each used cell's strain, added to its points.
  std::vector<float> cell_strain(used.size(), 0.0F);
  pool.parallel_for(used_cells.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      std::array<Vec<D>, 1 << D> images;
      for (int v = 0; v < (1 << D); ++v)
        images[static_cast<std::size_t>(v)] =
            nodes.positions[static_cast<std::size_t>(node_slot[index_in<D>(used_cells[k] + corner_offset<D>(v), node_size)])];
      cell_strain[index_in<D>(used_cells[k], cells)] = cube_strain<D>(images, spacing);
    }
  });
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) strain[i] += cell_strain[point_cell[i]];
  });
  return stats;
}

template StrainLatticeStats add_step_strain<2>(const Deformation<2>&, double, double, const std::vector<Vec<2>>&,
                                               double, std::vector<float>&, ThreadPool&);
template StrainLatticeStats add_step_strain<3>(const Deformation<3>&, double, double, const std::vector<Vec<3>>&,
                                               double, std::vector<float>&, ThreadPool&);
template float cube_strain<2>(const std::array<Vec<2>, 4>&, double);
template float cube_strain<3>(const std::array<Vec<3>, 8>&, double);
template float step_cube_strain<2>(const std::array<Vec<2>, 4>&, const std::array<Vec<2>, 4>&, double);
template float step_cube_strain<3>(const std::array<Vec<3>, 8>&, const std::array<Vec<3>, 8>&, double);

}  // namespace amls
