#include "core/surface_offsets.hpp"

#include <cmath>
#include <cstdint>
#include <span>

#include "core/gradient_fit.hpp"
#include "core/weight.hpp"

namespace amls {

namespace {

// The neighbours of every point on its side within Delta, gathered once and
// read by all three passes: per point, a run of one thread block's list.
struct NeighbourRuns {
  struct Run {
    int block = 0;
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
  };
  std::vector<std::vector<std::uint32_t>> ids;  // per block
  std::vector<Run> runs;                        // per point

  std::span<const std::uint32_t> of(std::size_t i) const {
    const Run& r = runs[i];
    return std::span(ids[static_cast<std::size_t>(r.block)]).subspan(r.begin, r.end - r.begin);
  }
};

}  // namespace

template <int D>
std::vector<double> surface_offsets(const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                                    const PointIndex<D>& index, const SurfaceOffsetOptions& options,
                                    ThreadPool& pool) {
  const std::size_t n = positions.size();
  const double inverse_r2 = 1.0 / (options.radius * options.radius);
  const bool filter = options.orientation_filter;
  NeighbourRuns neighbours;
  neighbours.ids.resize(static_cast<std::size_t>(pool.threads()));
  neighbours.runs.resize(n);

  // 1. o_i = F(p_i) over the neighbours on p_i's side (p_i is its own nearest
  // point, so this is the evaluation's own orientation reference).
  std::vector<double> raw(n, 0.0);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int block) {
    std::vector<std::uint32_t>& ids = neighbours.ids[static_cast<std::size_t>(block)];
    for (std::size_t i = begin; i < end; ++i) {
      const Vec<D>& p = positions[i];
      const Vec<D>& own = normals[i];
      NeighbourRuns::Run& run = neighbours.runs[i];
      run.block = block;
      run.begin = static_cast<std::uint32_t>(ids.size());
      GradientFit<D> fit;
      const IVec<D> cell = index.cell_of(p);
      index.for_each_in_cells(cell.array() - 1, cell.array() + 1, [&](std::uint32_t id, const Vec<D>& q) {
        const Vec<D> d = q - p;
        const double s2 = d.squaredNorm() * inverse_r2;
        if (s2 > 1.0 || (filter && normals[id].dot(own) <= 0.0)) return;
        ids.push_back(id);
        fit.add(d, normals[id], weight_of_squared_ratio(s2));
      });
      run.end = static_cast<std::uint32_t>(ids.size());
      const Evaluation<D> e = fit.solve(options.min_weight);
      raw[i] = e.defined ? e.value : 0.0;
    }
  });

  // 2. Smoothed over Delta with the fit's weights (p_i itself has weight 1).
  std::vector<double> smoothed(n, 0.0);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      double sum_w = 0.0, sum_o = 0.0;
      for (const std::uint32_t id : neighbours.of(i)) {
        const double w = weight_of_squared_ratio((positions[id] - positions[i]).squaredNorm() * inverse_r2);
        sum_w += w;
        sum_o += w * raw[id];
      }
      smoothed[i] = sum_w > 0.0 ? sum_o / sum_w : 0.0;
    }
  });

  // 3. Limited: minmod over the smoothed offsets within Delta / 2.
  std::vector<double> limited(n, 0.0);
  const double limiter_r2 = 0.25 * options.radius * options.radius;
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      double o = smoothed[i];
      for (const std::uint32_t id : neighbours.of(i)) {
        if ((positions[id] - positions[i]).squaredNorm() > limiter_r2) continue;
        const double q = smoothed[id];
        if (!(q * o > 0.0)) {
          o = 0.0;
          break;
        }
        if (std::abs(q) < std::abs(o)) o = q;
      }
      limited[i] = o;
    }
  });
  return limited;
}

template std::vector<double> surface_offsets<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&,
                                                const PointIndex<3>&, const SurfaceOffsetOptions&, ThreadPool&);

}  // namespace amls
