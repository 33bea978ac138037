#pragma once
// Positions moved onto S(P), for Surface.project(): Newton's steps along the
// fitted gradient, x <- x - F(x) g / |g|^2, until |F| is below 1e-9 h or the
// step count runs out. A position where F is undefined (no point's support
// reaches it) comes back as NaN.
#include <vector>

#include "core/surface/amls_surface.hpp"

namespace amls::python {

inline constexpr int kProjectionSteps = 32;

// `surface` must be ready to evaluate. The positions are independent: the
// result does not depend on the pool's thread count.
template <int D>
void project_onto(const AmlsSurface<D>& surface, std::vector<Vec<D>>& positions, ThreadPool& pool);

// F at each position (NaN where undefined).
template <int D>
std::vector<double> evaluate_all(const AmlsSurface<D>& surface, const std::vector<Vec<D>>& positions, ThreadPool& pool);

extern template void project_onto<2>(const AmlsSurface<2>&, std::vector<Vec<2>>&, ThreadPool&);
extern template void project_onto<3>(const AmlsSurface<3>&, std::vector<Vec<3>>&, ThreadPool&);
extern template std::vector<double> evaluate_all<2>(const AmlsSurface<2>&, const std::vector<Vec<2>>&, ThreadPool&);
extern template std::vector<double> evaluate_all<3>(const AmlsSurface<3>&, const std::vector<Vec<3>>&, ThreadPool&);

}  // namespace amls::python
