#include "core/flow_deformation.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace amls {

template <int D>
FlowDeformation<D>::FlowDeformation(std::shared_ptr<const VelocityField<D>> field, int substeps)
    : field_(std::move(field)), substeps_(substeps) {
  if (!field_) throw std::invalid_argument("flow deformation needs a velocity field");
  if (substeps < 1) throw std::invalid_argument("--substeps must be at least 1, got " + std::to_string(substeps));
}

template <int D>
void FlowDeformation<D>::deform(PointSet<D>& points, double t0, double t1, ThreadPool& pool) const {
  const double dt = (t1 - t0) / substeps_;
  const VelocityField<D>& v = *field_;
  // The state is (x, n) with dx/dt = v(x, t) and dn/dt = -J(x, t)^T n.
  struct Rate {
    Vec<D> x, n;
  };
  auto rate = [&](const Vec<D>& x, const Vec<D>& n, double amplitude) -> Rate {
    const FlowSample<D> f = v.pattern(x);
    return {amplitude * f.velocity, -amplitude * (f.jacobian.transpose() * n)};
  };
  // The time factor at the RK4 stages' times (start, middle, end) of each substep.
  std::vector<std::array<double, 3>> amplitudes(static_cast<std::size_t>(substeps_));
  for (int s = 0; s < substeps_; ++s) {
    const double t = t0 + s * dt;
    amplitudes[static_cast<std::size_t>(s)] = {v.amplitude(t), v.amplitude(t + 0.5 * dt), v.amplitude(t + dt)};
  }
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec<D> x = points.positions[i];
      Vec<D> n = points.normals[i];
      for (const auto& [start, middle, finish] : amplitudes) {
        const Rate k1 = rate(x, n, start);
        const Rate k2 = rate(x + 0.5 * dt * k1.x, n + 0.5 * dt * k1.n, middle);
        const Rate k3 = rate(x + 0.5 * dt * k2.x, n + 0.5 * dt * k2.n, middle);
        const Rate k4 = rate(x + dt * k3.x, n + dt * k3.n, finish);
        x += dt / 6.0 * (k1.x + 2.0 * k2.x + 2.0 * k3.x + k4.x);
        n += dt / 6.0 * (k1.n + 2.0 * k2.n + 2.0 * k3.n + k4.n);
      }
      points.positions[i] = x;
      const double length = n.norm();
      if (length > 0.0 && std::isfinite(length)) points.normals[i] = n / length;
    }
  });
}

template class FlowDeformation<2>;
template class FlowDeformation<3>;

}  // namespace amls
