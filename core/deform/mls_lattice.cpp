#include "core/deform/mls_lattice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>

#include "core/deform/strain_lattice.hpp"
#include "core/geometry/grid.hpp"

namespace amls {

namespace {

// The dense tables cost a few bytes per lattice cell: beyond this many cells
// per point (plus a floor for small sets) the points are too scattered for a
// lattice to pay.
constexpr double kMaxCellsPerPoint = 4.0;
constexpr double kMinCells = 4096.0;

// A point that no region's reach holds (see map()).
constexpr std::uint32_t kHeldByNone = std::numeric_limits<std::uint32_t>::max();

// The map at a point: its image, and the matrix that carries its normal
// (normal_transform of the local map's L).
template <int D>
struct Sample {
  Vec<D> position;
  Mat<D> normals;
};

// What the interpolation blends at a node, in one vector so that the blend
// of a cell's corners is one weighted sum of them: c = P - H r, H and N,
// where P is the node's image, r its rest position, H half the map's
// Jacobian there (the weight of the Taylor blend) and N the matrix that
// carries normals there. The blended c + H x is the header's third-order
// position; the blended N carries the normals.
template <int D>
using Blend = Eigen::Matrix<double, D + 2 * D * D, 1>;

template <int D>
Blend<D> make_blend(const Vec<D>& rest, const Vec<D>& image, const Mat<D>& half_jacobian, const Mat<D>& normals) {
  Blend<D> b;
  b.template head<D>() = image - half_jacobian * rest;
  b.template segment<D * D>(D) = half_jacobian.reshaped();
  b.template tail<D * D>() = normals.reshaped();
  return b;
}

template <int D>
Mat<D> half_jacobian_of(const Blend<D>& b) {
  return b.template segment<D * D>(D).reshaped(D, D);
}

template <int D>
struct Node {
  Vec<D> rest;
  Vec<D> position;  // its image
  Blend<D> blend;
};

// `gaps`: the regions' gaps at x (MlsDeformation::region_gaps), or empty.
template <int D>
Sample<D> exact_sample(const MlsDeformation<D>& map, const Vec<D>& x, std::span<const double> gaps = {}) {
  const MlsLocalMap<D> local = map.local_map(x, gaps);
  return {local.position, normal_transform<D>(local.linear)};
}

// A box of cells, `cells` per axis from `origin`, numbered row-major (axis 0 fastest).
template <int D>
struct Box {
  Vec<D> origin = Vec<D>::Zero();
  double spacing = 1.0;
  IVec<D> cells = IVec<D>::Ones();
  // locate() keeps this many cells free on every side (a point rounded onto
  // the box's edge still lands in a cell whose halo fits).
  std::int64_t margin = 0;

  std::size_t count(std::int64_t extra) const {
    std::size_t n = 1;
    for (int a = 0; a < D; ++a) n *= static_cast<std::size_t>(cells[a] + extra);
    return n;
  }
  std::size_t cell_index(const IVec<D>& c) const { return index_in(c, 0); }
  std::size_t node_index(const IVec<D>& n) const { return index_in(n, 1); }
  // The cell holding x (clamped into the box within its margin) and x's place in it, each coordinate in [0, 1].
  IVec<D> locate(const Vec<D>& x, Vec<D>& t) const {
    IVec<D> c;
    for (int a = 0; a < D; ++a)
      c[a] = std::clamp(static_cast<std::int64_t>(std::floor(across(x, a))), margin, cells[a] - 1 - margin);
    t = place_in(c, x);
    return c;
  }
  // x's place in cell c, as locate() gives it when c is the cell it found:
  // a caller that knows the cell spares the floors.
  Vec<D> place_in(const IVec<D>& c, const Vec<D>& x) const {
    Vec<D> t;
    for (int a = 0; a < D; ++a) t[a] = std::clamp(across(x, a) - static_cast<double>(c[a]), 0.0, 1.0);
    return t;
  }
  Vec<D> node_position(const IVec<D>& n) const { return origin + spacing * n.template cast<double>(); }
  // Whether x lies within `reach` cells of cell c.
  bool near_cell(const IVec<D>& c, const Vec<D>& x, double reach) const {
    for (int a = 0; a < D; ++a) {
      const double u = (x[a] - origin[a]) / spacing - static_cast<double>(c[a]);
      if (u < -reach || u > 1.0 + reach) return false;
    }
    return true;
  }

 private:
  // x's coordinate along axis a, in cells from the origin.
  double across(const Vec<D>& x, int a) const { return (x[a] - origin[a]) / spacing; }
  std::size_t index_in(const IVec<D>& v, std::int64_t extra) const {
    std::size_t index = 0;
    for (int a = D - 1; a >= 0; --a)
      index = index * static_cast<std::size_t>(cells[a] + extra) + static_cast<std::size_t>(v[a]);
    return index;
  }
};

template <int D>
using Corners = std::array<const Node<D>*, 1 << D>;

template <int D>
Vec<D> cell_centre(const Box<D>& box, const IVec<D>& c) {
  return box.node_position(c).array() + 0.5 * box.spacing;
}

// What a map's regions decide on a lattice of rest points, which depends
// only on their first places: a drag's steps from one rest state share it,
// so it is made at the first step's map and kept, sparing the later steps a
// search of the members at every node and every point near a region.
template <int D>
struct RegionLayout {
  std::vector<RegionHandle<D>> regions;  // the first places it was made for
  // The regions' gaps (MlsDeformation::region_gaps) at node k, region r at k * regions.size() + r.
  std::vector<double> node_gaps;
  std::vector<double> centre_gaps;        // the same at cell k's centre
  std::vector<std::uint8_t> all_held;     // per cell: every point of it lies within a region's reach
  std::vector<std::uint32_t> holder;      // per point: the region whose reach holds it, or kHeldByNone

  std::span<const double> at(const std::vector<double>& gaps, std::size_t k) const {
    return std::span<const double>(gaps).subspan(k * regions.size(), regions.size());
  }
};

// The multilinear weight of each corner v at t in [0, 1]^D: the product
// over the axes, in order, of t or 1 - t as v's bit for the axis is set or
// not, the lower axes' products shared between the corners that have them
// in common.
template <int D>
std::array<double, 1 << D> corner_weights(const Vec<D>& t) {
  std::array<double, 1 << D> w;
  w[0] = 1.0;
  for (int a = 0; a < D; ++a) {
    const std::size_t below = std::size_t{1} << a;
    for (std::size_t v = 0; v < below; ++v) {
      w[v + below] = w[v] * t[a];
      w[v] *= 1.0 - t[a];
    }
  }
  return w;
}

// The map at x, at t in its cell: positions to third order (the header's
// mean of the multilinear interpolant and the Taylor blend), the normals'
// transform multilinearly.
template <int D>
[[gnu::always_inline]] inline Sample<D> interpolate(const Corners<D>& corners, const Vec<D>& t, const Vec<D>& x) {
  const std::array<double, 1 << D> w = corner_weights<D>(t);
  Blend<D> sum = w[0] * corners[0]->blend;
  for (std::size_t v = 1; v < w.size(); ++v) sum += w[v] * corners[v]->blend;
  return {sum.template head<D>() + half_jacobian_of<D>(sum) * x, sum.template tail<D * D>().reshaped(D, D)};
}

// The nodes of a box, for the cells asked.
template <int D>
struct BoxNodes {
  std::vector<std::int32_t> slot;  // node index -> node, -1: not mapped
  std::vector<Node<D>> nodes;

  Corners<D> corners(const Box<D>& box, const IVec<D>& c) const {
    Corners<D> out;
    for (int v = 0; v < (1 << D); ++v)
      out[static_cast<std::size_t>(v)] = &nodes[static_cast<std::size_t>(slot[box.node_index(c + corner_offset<D>(v))])];
    return out;
  }
};

// A refined cell: its sub-cells' box, the nodes of the sub-cells it maps,
// and which of those map exactly.
template <int D>
struct Refined {
  Box<D> box;
  BoxNodes<D> nodes;
  std::vector<std::uint8_t> exact;
  std::size_t checked = 0;  // sub-cells checked: those holding points to interpolate
};

// Whether the map at a cell's centre is off the interpolant by more than the
// tolerance, or a handle lies within one cell of it. A region handle needs no
// rule of its own: outside its reach the map differs from the region's
// motion by O(g^2) in the gap g, so it meets the motion with its first
// derivative and the interpolation follows it (the centre check stands
// guard), and the points within reach take the motion exactly (see map()).
// `centre_gaps`: the regions' gaps at the centre, or empty.
template <int D>
bool needs_refinement(const MlsDeformation<D>& map, const Box<D>& box, const IVec<D>& c, const Corners<D>& corners,
                      double tolerance, std::span<const double> centre_gaps = {}) {
  for (const Vec<D>& handle : map.from())
    if (box.near_cell(c, handle, 1.0)) return true;
  const Vec<D> centre = cell_centre(box, c);
  return (interpolate<D>(corners, Vec<D>::Constant(0.5), centre).position - map.local_map(centre, centre_gaps).position)
             .norm() > tolerance;
}

// Sub-nodes are mapped exactly; their Jacobians, which the exact map does not
// give, are interpolated from the coarse cell's corners: errors of second
// order in the coarse spacing, times offsets within a sub-cell. Only the
// sub-cells that hold some of the cell's points (`ids`) not held by a region
// are checked and have their corners mapped: on a surface most sub-cells of
// a cell hold none, and near a region most of the rest are held.
template <int D>
Refined<D> refine(const MlsDeformation<D>& map, const Box<D>& coarse, const IVec<D>& c, const Corners<D>& corners,
                  std::span<const std::uint32_t> ids, const std::vector<Vec<D>>& positions,
                  const std::vector<std::uint32_t>& holder, const MlsLatticeOptions& o) {
  Refined<D> r;
  r.box.origin = coarse.node_position(c);
  r.box.spacing = coarse.spacing / o.refinement;
  r.box.cells = IVec<D>::Constant(o.refinement);
  std::vector<std::uint8_t> interpolated(r.box.count(0), 0);
  Vec<D> place;
  for (const std::uint32_t i : ids)
    if (holder[i] == kHeldByNone) interpolated[r.box.cell_index(r.box.locate(positions[i], place))] = 1;
  std::vector<std::uint8_t> needed(r.box.count(1), 0);
  for_each_index_in_box<D>(IVec<D>::Zero(), r.box.cells.array() - 1, [&](const IVec<D>& s) {
    if (!interpolated[r.box.cell_index(s)]) return;
    for (int v = 0; v < (1 << D); ++v) needed[r.box.node_index(s + corner_offset<D>(v))] = 1;
  });
  r.nodes.slot.assign(needed.size(), -1);
  for_each_index_in_box<D>(IVec<D>::Zero(), r.box.cells, [&](const IVec<D>& n) {
    if (!needed[r.box.node_index(n)]) return;
    r.nodes.slot[r.box.node_index(n)] = static_cast<std::int32_t>(r.nodes.nodes.size());
    const Vec<D> x = r.box.node_position(n);
    const Vec<D> t = n.template cast<double>() / static_cast<double>(o.refinement);
    const std::array<double, 1 << D> w = corner_weights<D>(t);
    Mat<D> half_jacobian = Mat<D>::Zero();
    for (std::size_t v = 0; v < w.size(); ++v) half_jacobian += w[v] * half_jacobian_of<D>(corners[v]->blend);
    const Sample<D> exact = exact_sample(map, x);
    r.nodes.nodes.push_back({x, exact.position, make_blend<D>(x, exact.position, half_jacobian, exact.normals)});
  });
  r.exact.assign(interpolated.size(), 0);
  for_each_index_in_box<D>(IVec<D>::Zero(), r.box.cells.array() - 1, [&](const IVec<D>& s) {
    if (!interpolated[r.box.cell_index(s)]) return;
    r.exact[r.box.cell_index(s)] =
        needs_refinement(map, r.box, s, r.nodes.corners(r.box, s), o.tolerance) ? 1 : 0;
    ++r.checked;
  });
  return r;
}

}  // namespace

template <int D>
struct MlsRestLattice<D>::Layout {
  MlsLatticeOptions options;
  std::size_t points = 0;
  bool fell_back = false;  // see MlsLatticeStats::fell_back
  // One cell wider on every side than the points' box, so that the halo fits.
  Box<D> box;
  std::vector<IVec<D>> cells;                                 // the cells holding points, row-major
  std::vector<std::array<std::uint32_t, 1 << D>> cell_nodes;  // each cell's corners, in node_list
  // The cells' corners first (`corner_nodes` of them), then the halo: their
  // neighbours along the axes that are no corner.
  std::vector<IVec<D>> node_list;
  std::size_t corner_nodes = 0;
  // Each corner's neighbours in node_list: 2a one below along axis a, 2a + 1 one above.
  std::vector<std::array<std::uint32_t, 2 * D>> neighbours;
  std::vector<std::uint32_t> point_cell;  // each point's cell, in `cells`
  // The points cell by cell: cell k's are by_cell[cell_first[k]] up to cell_first[k + 1].
  std::vector<std::uint32_t> cell_first;
  std::vector<std::uint32_t> by_cell;

  // The layout of the regions of the last map with regions (none before
  // one). Kept behind a lock: the lattice is shared and map() is const.
  mutable std::mutex region_layout_lock;
  mutable std::shared_ptr<const RegionLayout<D>> region_layout;

  // The layout of `map`'s regions at their first places over `positions`
  // (the lattice's points): the one kept if it is for the same places, else
  // made now and kept (a cancelled pool throws before it is). Null without
  // regions.
  std::shared_ptr<const RegionLayout<D>> regions_of(const MlsDeformation<D>& map, const std::vector<Vec<D>>& positions,
                                                    ThreadPool& pool) const {
    if (map.from_regions().empty()) return nullptr;
    const std::lock_guard<std::mutex> hold(region_layout_lock);
    if (region_layout && same_places(region_layout->regions, map.from_regions())) return region_layout;
    auto r = std::make_shared<RegionLayout<D>>();
    r->regions = map.from_regions();
    const std::size_t count = r->regions.size();
    r->node_gaps.resize(node_list.size() * count);
    r->centre_gaps.resize(cells.size() * count);
    pool.parallel_for(node_list.size(), [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t k = begin; k < end; ++k)
        map.region_gaps(box.node_position(node_list[k]), std::span<double>(r->node_gaps).subspan(k * count, count));
    });
    // A cell whose centre is within half a diagonal of a region's reach may
    // have all its points held; only its points are asked.
    const double half_diagonal = 0.5 * std::sqrt(static_cast<double>(D)) * box.spacing;
    r->all_held.resize(cells.size());
    pool.parallel_for(cells.size(), [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t k = begin; k < end; ++k) {
        const std::span<double> at_centre = std::span<double>(r->centre_gaps).subspan(k * count, count);
        map.region_gaps(cell_centre(box, cells[k]), at_centre);
        r->all_held[k] = *std::min_element(at_centre.begin(), at_centre.end()) <= half_diagonal ? 1 : 0;
      }
    });
    r->holder.assign(positions.size(), kHeldByNone);
    pool.parallel_for(positions.size(), [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t i = begin; i < end; ++i)
        if (r->all_held[point_cell[i]])
          if (const std::optional<std::size_t> held = map.region_holding(positions[i]))
            r->holder[i] = static_cast<std::uint32_t>(*held);
    });
    for (std::size_t i = 0; i < positions.size(); ++i)
      if (r->holder[i] == kHeldByNone) r->all_held[point_cell[i]] = 0;
    region_layout = std::move(r);
    return region_layout;
  }

  std::span<const std::uint32_t> points_of(std::size_t cell) const {
    return std::span<const std::uint32_t>(by_cell).subspan(cell_first[cell], cell_first[cell + 1] - cell_first[cell]);
  }

  template <typename T>
  std::array<const T*, 1 << D> corners(const std::vector<T>& at_nodes, std::size_t cell) const {
    std::array<const T*, 1 << D> out;
    for (std::size_t v = 0; v < out.size(); ++v) out[v] = &at_nodes[cell_nodes[cell][v]];
    return out;
  }
};

template <int D>
MlsRestLattice<D>::MlsRestLattice(const PointSet<D>& points, const MlsLatticeOptions& options, ThreadPool& pool)
    : layout_(std::make_unique<Layout>()) {
  if (!(options.spacing > 0.0) || (options.interpolate && !(options.tolerance > 0.0)) || options.refinement < 1)
    throw std::invalid_argument("MLS lattice: spacing and tolerance must be positive and refinement at least 1");
  const std::size_t n = points.size();
  if (points.normals.size() != n)
    throw std::invalid_argument("MLS lattice: " + std::to_string(n) + " points but " +
                                std::to_string(points.normals.size()) + " normals");
  Layout& l = *layout_;
  l.options = options;
  l.points = n;
  if (n == 0) return;

  // The points' box, in lattice cells, and one more cell on every side.
  Vec<D> lo = points.positions.front(), hi = lo;
  for (const Vec<D>& p : points.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  l.box.origin = lo.array() - options.spacing;
  l.box.spacing = options.spacing;
  l.box.margin = 1;
  double total_cells = 1.0;
  for (int a = 0; a < D; ++a) {
    const double across = std::floor((hi[a] - lo[a]) / options.spacing) + 3.0;
    total_cells *= across;
    l.box.cells[a] = std::isfinite(across) ? static_cast<std::int64_t>(std::min(across, 1e9)) : 1;
  }
  if (!std::isfinite(total_cells) || total_cells > kMaxCellsPerPoint * static_cast<double>(n) + kMinCells) {
    l.fell_back = true;
    return;
  }

  // The cells holding points (first by their index in the box), their corners, then the halo.
  l.point_cell.resize(n);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    Vec<D> t;
    for (std::size_t i = begin; i < end; ++i)
      l.point_cell[i] = static_cast<std::uint32_t>(l.box.cell_index(l.box.locate(points.positions[i], t)));
  });
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> cell_in_list(l.box.count(0), kNone);
  for (const std::uint32_t c : l.point_cell) cell_in_list[c] = 0;
  std::vector<std::uint32_t> node_in_list(l.box.count(1), kNone);
  auto node_slot = [&](const IVec<D>& node) {
    std::uint32_t& slot = node_in_list[l.box.node_index(node)];
    if (slot == kNone) {
      slot = static_cast<std::uint32_t>(l.node_list.size());
      l.node_list.push_back(node);
    }
    return slot;
  };
  for_each_index_in_box<D>(IVec<D>::Zero(), l.box.cells.array() - 1, [&](const IVec<D>& c) {
    std::uint32_t& in_list = cell_in_list[l.box.cell_index(c)];
    if (in_list == kNone) return;
    in_list = static_cast<std::uint32_t>(l.cells.size());
    l.cells.push_back(c);
    std::array<std::uint32_t, 1 << D>& corners = l.cell_nodes.emplace_back();
    for (int v = 0; v < (1 << D); ++v) corners[static_cast<std::size_t>(v)] = node_slot(c + corner_offset<D>(v));
  });
  l.corner_nodes = l.node_list.size();
  l.neighbours.resize(l.corner_nodes);
  for (std::size_t k = 0; k < l.corner_nodes; ++k)
    for (int a = 0; a < D; ++a) {
      // node_list grows here: copy the corner rather than hold a reference into it.
      const IVec<D> node = l.node_list[k];
      l.neighbours[k][static_cast<std::size_t>(2 * a)] = node_slot(node - IVec<D>::Unit(a));
      l.neighbours[k][static_cast<std::size_t>(2 * a + 1)] = node_slot(node + IVec<D>::Unit(a));
    }
  for (std::uint32_t& c : l.point_cell) c = cell_in_list[c];
  l.cell_first.assign(l.cells.size() + 1, 0);
  for (const std::uint32_t c : l.point_cell) ++l.cell_first[c + 1];
  for (std::size_t k = 0; k < l.cells.size(); ++k) l.cell_first[k + 1] += l.cell_first[k];
  std::vector<std::uint32_t> next(l.cell_first.begin(), l.cell_first.end() - 1);
  l.by_cell.resize(n);
  for (std::size_t i = 0; i < n; ++i) l.by_cell[next[l.point_cell[i]]++] = static_cast<std::uint32_t>(i);
}

template <int D>
MlsRestLattice<D>::~MlsRestLattice() = default;
template <int D>
MlsRestLattice<D>::MlsRestLattice(MlsRestLattice&&) noexcept = default;
template <int D>
MlsRestLattice<D>& MlsRestLattice<D>::operator=(MlsRestLattice&&) noexcept = default;

template <int D>
MlsLatticeStats MlsRestLattice<D>::map(const MlsDeformation<D>& map, const PointSet<D>& points, PointSet<D>& mapped,
                                       std::vector<float>* strain, MlsNodeImages<D>* last, ThreadPool& pool) const {
  const Layout& l = *layout_;
  const MlsLatticeOptions& options = l.options;
  const std::size_t n = points.size();
  if (n != l.points || points.normals.size() != n)
    throw std::invalid_argument("MLS lattice: built over " + std::to_string(l.points) + " points, asked to map " +
                                std::to_string(n) + " points with " + std::to_string(points.normals.size()) +
                                " normals");
  MlsLatticeStats stats;
  if (strain) strain->resize(n, 0.0F);
  // The exact map, in place on the destination (a copy of the source unless they are one).
  auto map_exactly = [&] {
    if (&mapped != &points) mapped = points;
    map.apply(mapped, pool);
  };
  if (n == 0 || map.empty()) {
    if (&mapped != &points) mapped = points;
    return stats;
  }
  if (l.fell_back) {
    stats.fell_back = true;
    stats.exact_points = stats.evaluations = n;
    map_exactly();
    if (strain) std::fill(strain->begin(), strain->end(), std::numeric_limits<float>::infinity());
    if (last) last->clear();
    return stats;
  }
  const Box<D>& box = l.box;
  const std::shared_ptr<const RegionLayout<D>> regions = l.regions_of(map, points.positions, pool);
  auto node_gaps = [&](std::size_t k) { return regions ? regions->at(regions->node_gaps, k) : std::span<const double>(); };
  auto centre_gaps = [&](std::size_t k) {
    return regions ? regions->at(regions->centre_gaps, k) : std::span<const double>();
  };

  // The nodes, mapped exactly, then the corners' Jacobians from their neighbours.
  std::vector<Node<D>> nodes(l.node_list.size());
  std::vector<Mat<D>> normals(l.corner_nodes);
  pool.parallel_for(l.node_list.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const Vec<D> x = box.node_position(l.node_list[k]);
      const Sample<D> exact = exact_sample(map, x, node_gaps(k));
      nodes[k].rest = x;
      nodes[k].position = exact.position;
      if (k < l.corner_nodes) normals[k] = exact.normals;
    }
  });
  pool.parallel_for(l.corner_nodes, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      Mat<D> half_jacobian;
      for (int a = 0; a < D; ++a)
        half_jacobian.col(a) = (nodes[l.neighbours[k][static_cast<std::size_t>(2 * a + 1)]].position -
                                nodes[l.neighbours[k][static_cast<std::size_t>(2 * a)]].position) /
                               (4.0 * box.spacing);
      nodes[k].blend = make_blend<D>(nodes[k].rest, nodes[k].position, half_jacobian, normals[k]);
    }
  });
  stats.nodes = nodes.size();

  // The step's strain per cell, from the corners' images under the last map and this one.
  std::vector<float> cell_strain(l.cells.size(), 0.0F);
  const bool from_rest = !last || last->empty();
  pool.parallel_for(l.cells.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      std::array<Vec<D>, 1 << D> before, after;
      for (std::size_t v = 0; v < before.size(); ++v) {
        const Node<D>& node = nodes[l.cell_nodes[k][v]];
        before[v] = from_rest ? node.rest : (*last)[l.cell_nodes[k][v]];
        after[v] = node.position;
      }
      cell_strain[k] = from_rest ? cube_strain<D>(after, box.spacing) : step_cube_strain<D>(before, after, box.spacing);
    }
  });
  if (last) {
    last->resize(l.corner_nodes);
    for (std::size_t k = 0; k < l.corner_nodes; ++k) (*last)[k] = nodes[k].position;
  }
  auto add_strain = [&] {
    if (!strain) return;
    pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t i = begin; i < end; ++i) (*strain)[i] += cell_strain[l.point_cell[i]];
    });
  };
  stats.cells = l.cells.size();
  if (!options.interpolate) {
    stats.evaluations = nodes.size() + n;
    stats.exact_points = n;
    map_exactly();
    add_strain();
    return stats;
  }

  // The points within a region's reach take its motion exactly. A cell
  // whose points all do reads no interpolation, so it is neither checked nor
  // refined: the map's weights change fast off the surface near a region (the
  // gap grows with the height above it), and its volume would fail the check
  // where its points never needed it.
  std::vector<std::uint8_t> none_held;
  std::vector<std::uint32_t> held_by_none;
  if (!regions) {
    none_held.assign(l.cells.size(), 0);
    held_by_none.assign(n, kHeldByNone);
  }
  const std::vector<std::uint8_t>& all_held = regions ? regions->all_held : none_held;
  const std::vector<std::uint32_t>& holder = regions ? regions->holder : held_by_none;

  // Check every other cell; refine those that fail.
  constexpr std::uint32_t kInterpolated = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> refined_of(l.cells.size(), kInterpolated);  // cell -> its Refined, if refined
  pool.parallel_for(l.cells.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k)
      if (!all_held[k] &&
          needs_refinement(map, box, l.cells[k], l.corners(nodes, k), options.tolerance, centre_gaps(k)))
        refined_of[k] = 0;
  });
  std::vector<std::size_t> to_refine;
  for (std::size_t k = 0; k < l.cells.size(); ++k)
    if (refined_of[k] != kInterpolated) {
      refined_of[k] = static_cast<std::uint32_t>(to_refine.size());
      to_refine.push_back(k);
    }
  std::vector<Refined<D>> refined(to_refine.size());
  pool.parallel_for(to_refine.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k)
      refined[k] = refine(map, box, l.cells[to_refine[k]], l.corners(nodes, to_refine[k]), l.points_of(to_refine[k]),
                          points.positions, holder, options);
  });

  // The points.
  stats.refined_cells = refined.size();
  // Nodes and centre checks, coarse and refined; the exact points are added below.
  stats.evaluations = nodes.size();
  for (std::size_t k = 0; k < l.cells.size(); ++k) stats.evaluations += all_held[k] ? 0 : 1;
  for (const Refined<D>& r : refined) stats.evaluations += r.nodes.nodes.size() + r.checked;
  for (const Refined<D>& r : refined)
    for (const std::uint8_t e : r.exact) stats.exact_cells += e;
  std::vector<std::size_t> exact_points(static_cast<std::size_t>(pool.threads()), 0);
  mapped.positions.resize(n);
  mapped.normals.resize(n);
  if (&mapped != &points) mapped.rim = points.rim;
  // Cell by cell: a cell's corners are looked up once for all its points,
  // and its refinement checked once.
  pool.parallel_for(l.cells.size(), [&](std::size_t begin, std::size_t end, int block) {
    std::size_t exact_here = 0;
    Vec<D> t;
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t r = refined_of[k];
      const Corners<D> corners = l.corners(nodes, k);
      for (const std::uint32_t i : l.points_of(k)) {
        const Vec<D> p = points.positions[i];
        Sample<D> sample;
        if (holder[i] != kHeldByNone) {
          const MlsLocalMap<D> on = map.region_map(holder[i], p);
          sample = {on.position, normal_transform<D>(on.linear)};
          ++exact_here;
        } else if (r == kInterpolated) {
          sample = interpolate<D>(corners, box.place_in(l.cells[k], p), p);
        } else {
          const Refined<D>& cell = refined[r];
          const IVec<D> s = cell.box.locate(p, t);
          if (cell.exact[cell.box.cell_index(s)]) {
            sample = exact_sample(map, p);
            ++exact_here;
          } else {
            sample = interpolate<D>(cell.nodes.corners(cell.box, s), t, p);
          }
        }
        mapped.positions[i] = sample.position;
        mapped.normals[i] = transform_normal<D>(sample.normals, points.normals[i]);
      }
    }
    exact_points[static_cast<std::size_t>(block)] += exact_here;
  });
  for (const std::size_t e : exact_points) stats.exact_points += e;
  stats.evaluations += stats.exact_points;
  add_strain();
  return stats;
}

template <int D>
MlsLatticeStats apply_on_lattice(const MlsDeformation<D>& map, PointSet<D>& points, std::vector<float>* strain,
                                 const MlsLatticeOptions& options, ThreadPool& pool) {
  return MlsRestLattice<D>(points, options, pool).map(map, points, points, strain, nullptr, pool);
}

template class MlsRestLattice<2>;
template class MlsRestLattice<3>;
template MlsLatticeStats apply_on_lattice<2>(const MlsDeformation<2>&, PointSet<2>&, std::vector<float>*,
                                             const MlsLatticeOptions&, ThreadPool&);
template MlsLatticeStats apply_on_lattice<3>(const MlsDeformation<3>&, PointSet<3>&, std::vector<float>*,
                                             const MlsLatticeOptions&, ThreadPool&);

}  // namespace amls
