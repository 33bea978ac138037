#include "python/surface_projection.hpp"

#include <cmath>
#include <limits>

namespace amls::python {

template <int D>
void project_onto(const AmlsSurface<D>& surface, std::vector<Vec<D>>& positions, ThreadPool& pool) {
  const double tolerance = 1e-9 * surface.grid().spacing();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  pool.parallel_for(positions.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec<D>& x = positions[i];
      for (int k = 0; k < kProjectionSteps; ++k) {
        const Evaluation<D> e = surface.evaluate(x);
        const double g2 = e.gradient.squaredNorm();
        if (!e.defined || !(g2 > 0.0)) {
          x.setConstant(nan);
          break;
        }
        if (std::abs(e.value) <= tolerance) break;
        x -= (e.value / g2) * e.gradient;
      }
    }
  });
}

template <int D>
std::vector<double> evaluate_all(const AmlsSurface<D>& surface, const std::vector<Vec<D>>& positions,
                                 ThreadPool& pool) {
  std::vector<double> out(positions.size());
  pool.parallel_for(positions.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      const Evaluation<D> e = surface.evaluate(positions[i]);
      out[i] = e.defined ? e.value : std::numeric_limits<double>::quiet_NaN();
    }
  });
  return out;
}

template void project_onto<2>(const AmlsSurface<2>&, std::vector<Vec<2>>&, ThreadPool&);
template void project_onto<3>(const AmlsSurface<3>&, std::vector<Vec<3>>&, ThreadPool&);
template std::vector<double> evaluate_all<2>(const AmlsSurface<2>&, const std::vector<Vec<2>>&, ThreadPool&);
template std::vector<double> evaluate_all<3>(const AmlsSurface<3>&, const std::vector<Vec<3>>&, ThreadPool&);

}  // namespace amls::python
