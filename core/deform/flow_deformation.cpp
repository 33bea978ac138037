#include "core/deform/flow_deformation.hpp"

#include <algorithm>
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
  // Points are advanced kLanes at a time, each RK4 stage for all of them
  // before the next stage: a stage of one point waits on the previous one's
  // long chains of dependent multiply-adds (the field's sines and cosines),
  // and those of other points fill the wait. Each point still goes through
  // the same operations, so the result is the same bit for bit.
  constexpr std::size_t kLanes = 4;
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t first = begin; first < end; first += kLanes) {
      const std::size_t lanes = std::min(kLanes, end - first);
      std::array<Vec<D>, kLanes> x, n;
      for (std::size_t l = 0; l < lanes; ++l) {
        x[l] = points.positions[first + l];
        n[l] = points.normals[first + l];
      }
      for (const auto& [start, middle, finish] : amplitudes) {
        std::array<Rate, kLanes> k1, k2, k3, k4;
        for (std::size_t l = 0; l < lanes; ++l) k1[l] = rate(x[l], n[l], start);
        for (std::size_t l = 0; l < lanes; ++l) k2[l] = rate(x[l] + 0.5 * dt * k1[l].x, n[l] + 0.5 * dt * k1[l].n, middle);
        for (std::size_t l = 0; l < lanes; ++l) k3[l] = rate(x[l] + 0.5 * dt * k2[l].x, n[l] + 0.5 * dt * k2[l].n, middle);
        for (std::size_t l = 0; l < lanes; ++l) k4[l] = rate(x[l] + dt * k3[l].x, n[l] + dt * k3[l].n, finish);
        for (std::size_t l = 0; l < lanes; ++l) {
          x[l] += dt / 6.0 * (k1[l].x + 2.0 * k2[l].x + 2.0 * k3[l].x + k4[l].x);
          n[l] += dt / 6.0 * (k1[l].n + 2.0 * k2[l].n + 2.0 * k3[l].n + k4[l].n);
        }
      }
      for (std::size_t l = 0; l < lanes; ++l) {
        points.positions[first + l] = x[l];
        const double length = n[l].norm();
        if (length > 0.0 && std::isfinite(length)) points.normals[first + l] = n[l] / length;
      }
    }
  });
}

template class FlowDeformation<2>;
template class FlowDeformation<3>;

}  // namespace amls
