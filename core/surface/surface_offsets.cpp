#include "core/surface/surface_offsets.hpp"

#include <cmath>
#include <cstdint>

#include "core/surface/gradient_fit.hpp"
#include "core/math/weight.hpp"

namespace amls {

namespace {

// surface_offsets() with `inverse_r2_of(id)` the 1 / Delta^2 neighbour id
// weighs by and `limiter_r2_of(i)` the squared radius of point i's limiter:
// constants for one Delta, each point's own when widened.
template <int D, typename InverseR2, typename LimiterR2>
std::vector<double> limited_offsets(const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                                    const IdLists& neighbours, const SurfaceOffsetOptions& options,
                                    InverseR2 inverse_r2_of, LimiterR2 limiter_r2_of, ThreadPool& pool) {
  const std::size_t n = positions.size();
  const bool filter = options.orientation_filter;
  // Whether neighbour `id` of point i is on i's side.
  auto same_side = [&](std::size_t i, std::uint32_t id) { return !filter || normals[id].dot(normals[i]) > 0.0; };

  // 1. o_i = F(p_i) over the neighbours on p_i's side (p_i is its own nearest
  // point, so this is the evaluation's own orientation reference).
  std::vector<double> raw(n, 0.0);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      GradientFit<D> fit;
      for (const std::uint32_t id : neighbours.of(i)) {
        if (!same_side(i, id)) continue;
        const Vec<D> d = positions[id] - positions[i];
        const double dd = d.squaredNorm();
        fit.add(d, dd, normals[id], weight_of_squared_ratio(dd * inverse_r2_of(id)));
      }
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
        if (!same_side(i, id)) continue;
        const double w = weight_of_squared_ratio((positions[id] - positions[i]).squaredNorm() * inverse_r2_of(id));
        sum_w += w;
        sum_o += w * raw[id];
      }
      smoothed[i] = sum_w > 0.0 ? sum_o / sum_w : 0.0;
    }
  });

  // 3. Limited: minmod over the smoothed offsets within Delta / 2.
  std::vector<double> limited(n, 0.0);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      const double limiter_r2 = limiter_r2_of(i);
      double o = smoothed[i];
      for (const std::uint32_t id : neighbours.of(i)) {
        if (!same_side(i, id) || (positions[id] - positions[i]).squaredNorm() > limiter_r2) continue;
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

}  // namespace

template <int D>
std::vector<double> surface_offsets(const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                                    const IdLists& neighbours, const SurfaceOffsetOptions& options,
                                    ThreadPool& pool) {
  if (!options.inverse_r2.empty()) {
    const std::span<const double> inverse_r2 = options.inverse_r2;
    return limited_offsets<D>(
        positions, normals, neighbours, options, [inverse_r2](std::uint32_t id) { return inverse_r2[id]; },
        [inverse_r2](std::size_t i) { return 0.25 / inverse_r2[i]; }, pool);
  }
  const double inverse_r2 = 1.0 / (options.radius * options.radius);
  const double limiter_r2 = 0.25 * options.radius * options.radius;
  return limited_offsets<D>(
      positions, normals, neighbours, options, [inverse_r2](std::uint32_t) { return inverse_r2; },
      [limiter_r2](std::size_t) { return limiter_r2; }, pool);
}

template std::vector<double> surface_offsets<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&,
                                                const IdLists&, const SurfaceOffsetOptions&, ThreadPool&);

}  // namespace amls
