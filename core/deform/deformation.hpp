#pragma once
// A deformation history phi_{s->t} (paper, section 4): moves points, and the
// normals they carry, from time t0 to time t1.
#include "core/geometry/point_set.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

template <int D>
class Deformation {
 public:
  virtual ~Deformation() = default;
  // Deform_Points(). Carried normals must stay unit length; they only orient
  // the next fit, so an approximate transport is enough.
  virtual void deform(PointSet<D>& points, double t0, double t1, ThreadPool& pool) const = 0;
};

}  // namespace amls
