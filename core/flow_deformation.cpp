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
  auto normal_rate = [&](const Vec<D>& x, const Vec<D>& n, double t) -> Vec<D> {
    return -v.jacobian(x, t).transpose() * n;
  };
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec<D> x = points.positions[i];
      Vec<D> n = points.normals[i];
      for (int s = 0; s < substeps_; ++s) {
        const double t = t0 + s * dt;
        const Vec<D> kx1 = v.velocity(x, t);
        const Vec<D> kn1 = normal_rate(x, n, t);
        const Vec<D> x2 = x + 0.5 * dt * kx1, n2 = n + 0.5 * dt * kn1;
        const Vec<D> kx2 = v.velocity(x2, t + 0.5 * dt);
        const Vec<D> kn2 = normal_rate(x2, n2, t + 0.5 * dt);
        const Vec<D> x3 = x + 0.5 * dt * kx2, n3 = n + 0.5 * dt * kn2;
        const Vec<D> kx3 = v.velocity(x3, t + 0.5 * dt);
        const Vec<D> kn3 = normal_rate(x3, n3, t + 0.5 * dt);
        const Vec<D> x4 = x + dt * kx3, n4 = n + dt * kn3;
        const Vec<D> kx4 = v.velocity(x4, t + dt);
        const Vec<D> kn4 = normal_rate(x4, n4, t + dt);
        x += dt / 6.0 * (kx1 + 2.0 * kx2 + 2.0 * kx3 + kx4);
        n += dt / 6.0 * (kn1 + 2.0 * kn2 + 2.0 * kn3 + kn4);
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
