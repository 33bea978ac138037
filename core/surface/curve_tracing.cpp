#include "core/surface/curve_tracing.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace amls {

namespace {

// A vertex of the tracing grid with F there.
struct TracedVertex {
  std::uint64_t key = 0;
  Evaluation<2> value;
};

// Where F = 0 on the edge from `lower` to `upper` (a vertex and its +x or +y
// neighbour). Always computed in this direction, so both cells sharing the
// edge get the same point to the last bit.
Vec<2> edge_crossing(const Vec<2>& lower, const Vec<2>& upper, double f_lower, double f_upper) {
  const double t = f_lower / (f_lower - f_upper);
  return lower + t * (upper - lower);
}

}  // namespace

TracedCurve trace_curve(const AmlsSurface<2>& surface, ThreadPool& pool, const CurveTracing& options) {
  if (options.subdivision < 1)
    throw std::invalid_argument("curve tracing subdivision must be at least 1, got " +
                                std::to_string(options.subdivision));
  if (options.margin < 0)
    throw std::invalid_argument("curve tracing margin must not be negative, got " + std::to_string(options.margin));
  TracedCurve out;
  const PointSet<2>& points = surface.points();
  if (points.empty()) return out;

  const Grid<2>& grid = surface.grid();
  const std::int64_t sub = options.subdivision;
  const Grid<2> tracing(grid.origin(), grid.spacing() / static_cast<double>(sub));

  // The tracing cells near the points, each once, in key order.
  std::vector<std::uint64_t> cells;
  const std::int64_t reach = options.margin;
  cells.reserve(points.size() * static_cast<std::size_t>((2 * reach + 1) * (2 * reach + 1) * sub * sub));
  for (const Vec<2>& p : points.positions) {
    const IVec<2> c = grid.cell_of(p);
    const IVec<2> lo = (c - IVec<2>::Constant(reach)) * sub;
    const IVec<2> hi = (c + IVec<2>::Constant(reach + 1)) * sub - IVec<2>::Ones();
    for_each_index_in_box<2>(lo, hi, [&](const IVec<2>& t) { cells.push_back(Grid<2>::key(t)); });
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  out.cells = cells.size();

  // F at their corners, each vertex once.
  std::vector<TracedVertex> vertices;
  vertices.reserve(cells.size() * 2);
  for (const std::uint64_t key : cells) {
    const IVec<2> c = Grid<2>::unkey(key);
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) vertices.push_back({Grid<2>::key(IVec<2>(c[0] + dx, c[1] + dy)), {}});
  }
  std::sort(vertices.begin(), vertices.end(),
            [](const TracedVertex& x, const TracedVertex& y) { return x.key < y.key; });
  vertices.erase(std::unique(vertices.begin(), vertices.end(),
                             [](const TracedVertex& x, const TracedVertex& y) { return x.key == y.key; }),
                 vertices.end());
  pool.parallel_for(vertices.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i)
      vertices[i].value = surface.evaluate(tracing.vertex_position(Grid<2>::unkey(vertices[i].key)));
  });
  out.evaluations = vertices.size();
  auto value_at = [&](const IVec<2>& v) -> const Evaluation<2>& {
    const std::uint64_t key = Grid<2>::key(v);
    const auto it = std::lower_bound(vertices.begin(), vertices.end(), key,
                                     [](const TracedVertex& x, std::uint64_t k) { return x.key < k; });
    return it->value;
  };

  // Marching squares. Corners counter-clockwise from the lowest: 0 (i, j), 1 (i+1, j),
  // 2 (i+1, j+1), 3 (i, j+1); edge k joins corner k and corner k+1 (mod 4).
  // As in the resampler, a value of exactly 0 counts as outside (positive).
  static constexpr int kEdgeLower[4] = {0, 1, 3, 0};  // the edge's lower end (towards -x or -y)
  static constexpr int kEdgeUpper[4] = {1, 2, 2, 3};
  for (const std::uint64_t key : cells) {
    const IVec<2> c = Grid<2>::unkey(key);
    const IVec<2> corner[4] = {c, IVec<2>(c[0] + 1, c[1]), IVec<2>(c[0] + 1, c[1] + 1), IVec<2>(c[0], c[1] + 1)};
    double f[4];
    bool defined = true;
    for (int k = 0; k < 4; ++k) {
      const Evaluation<2>& e = value_at(corner[k]);
      defined = defined && e.defined;
      f[k] = e.value;
    }
    if (!defined) continue;
    bool inside[4];
    for (int k = 0; k < 4; ++k) inside[k] = f[k] < 0.0;
    Vec<2> crossing[4];
    int crossed[4];
    int count = 0;
    for (int e = 0; e < 4; ++e) {
      const int lo = kEdgeLower[e], hi = kEdgeUpper[e];
      if (inside[lo] == inside[hi]) continue;
      crossing[e] =
          edge_crossing(tracing.vertex_position(corner[lo]), tracing.vertex_position(corner[hi]), f[lo], f[hi]);
      crossed[count++] = e;
    }
    if (count == 2) {
      out.segments.push_back({crossing[crossed[0]], crossing[crossed[1]]});
    } else if (count == 4) {
      // A saddle: corners 0 and 2 agree, 1 and 3 agree. The centre's sign (the
      // mean of the corners) says which pair is joined through the middle.
      const bool centre_inside = 0.25 * (f[0] + f[1] + f[2] + f[3]) < 0.0;
      if (centre_inside == inside[0]) {  // 0 and 2 joined: cut off corners 1 and 3
        out.segments.push_back({crossing[0], crossing[1]});
        out.segments.push_back({crossing[2], crossing[3]});
      } else {  // cut off corners 0 and 2
        out.segments.push_back({crossing[3], crossing[0]});
        out.segments.push_back({crossing[1], crossing[2]});
      }
    }
  }
  return out;
}

}  // namespace amls
