#pragma once
// The deformation of a velocity field, integrated with classical RK4.
#include <memory>

#include "core/deform/deformation.hpp"
#include "core/deform/velocity_field.hpp"

namespace amls {

template <int D>
class FlowDeformation final : public Deformation<D> {
 public:
  // `substeps` RK4 steps per call of deform().
  FlowDeformation(std::shared_ptr<const VelocityField<D>> field, int substeps = 1);

  // Positions follow dx/dt = v(x, t); carried normals follow the inverse
  // transpose of the flow's Jacobian, dn/dt = -J^T n, integrated alongside and
  // renormalised.
  void deform(PointSet<D>& points, double t0, double t1, ThreadPool& pool) const override;

  const VelocityField<D>& field() const { return *field_; }

 private:
  std::shared_ptr<const VelocityField<D>> field_;
  int substeps_;
};

extern template class FlowDeformation<2>;
extern template class FlowDeformation<3>;

}  // namespace amls
