#include "core/flow_deformation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

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
  auto rate = [&](const Vec<D>& x, const Vec<D>& n, double t) -> Rate {
    const FlowSample<D> f = v.sample(x, t);
    return {f.velocity, -f.jacobian.transpose() * n};
  };
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec<D> x = points.positions[i];
      Vec<D> n = points.normals[i];
      for (int s = 0; s < substeps_; ++s) {
        const double t = t0 + s * dt;
        const Rate k1 = rate(x, n, t);
        const Rate k2 = rate(x + 0.5 * dt * k1.x, n + 0.5 * dt * k1.n, t + 0.5 * dt);
        const Rate k3 = rate(x + 0.5 * dt * k2.x, n + 0.5 * dt * k2.n, t + 0.5 * dt);
        const Rate k4 = rate(x + dt * k3.x, n + dt * k3.n, t + dt);
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
