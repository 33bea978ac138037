#pragma once
// The 2D MLS curve S(P) = {F = 0} as line segments, for display: marching
// squares over the cells of a tracing grid near the points. Cells are the
// surface's grid cells split `subdivision` times per axis; F is evaluated once
// per tracing vertex, and a crossing is placed on its edge by linear
// interpolation of the vertex values (so neighbouring cells share their
// endpoints exactly and the traced curve is a chain). A cell with a vertex where
// F is undefined draws nothing, so the curve shows where S(P) breaks.
#include <cstddef>
#include <vector>

#include "core/surface/amls_surface.hpp"

namespace amls {

struct CurveSegment {
  Vec<2> a;
  Vec<2> b;
};

struct CurveTracing {
  int subdivision = 2;  // tracing cells per grid cell and axis (>= 1)
  int margin = 1;       // grid cells traced around each point's own cell (>= 0)
};

struct TracedCurve {
  std::vector<CurveSegment> segments;
  std::size_t cells = 0;        // tracing cells visited
  std::size_t evaluations = 0;  // evaluations of F
};

// Requires a surface that can be evaluated (hashed, with pseudo-normals).
// Throws std::invalid_argument for a subdivision below 1 or a negative margin.
// Cells are visited in a fixed order, so the result does not depend on the pool.
TracedCurve trace_curve(const AmlsSurface<2>& surface, ThreadPool& pool, const CurveTracing& options = {});

}  // namespace amls
