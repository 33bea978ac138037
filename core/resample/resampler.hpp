#pragma once
// Marching-cubes-like point creation (paper, section 3.2): the new points are
// the crossings of S(P) with the grid edges near the old points.
//
// Update_Function() evaluates F once at every vertex of the block
// [H(p) - 1, H(p) + 2]^D of every point p (the 3^D cells centred on p's cell)
// except those with two or more coordinates on the block's bounds, the
// farthest from p (at least sqrt(2) h away): the block's 4 corners in 2D, the
// paper's 12-vertex stencil of Fig. 1(b); its 8 corners and 24 edge vertices
// in 3D, leaving 32 (the paper says 44 without a figure). Other points' blocks
// cover those vertices where the surface passes near them: leaving them out
// changed no point of the 2D vortex runs nor of the 128^3 Enright run, and
// saves evaluations (docs/performance.md).
//
// Resample() then lists every edge between two such vertices whose values are
// defined and of opposite signs (a value of exactly 0 counts as positive, so a
// surface through a vertex gives one crossing per edge leaving it towards
// negative values, all at that vertex, and HAVECLOSEPOINT keeps one),
// locates the crossings, and settles them with HAVECLOSEPOINT: of the
// crossings whose nearer edge end is the same vertex, one becomes a new point.
// (Crossings that certainly lose, judged on the root finder's first guesses,
// are dropped before locating: see drop_certain_losers(). A sign change that
// the root finder finds to be a jump of F, not a zero, is no crossing: where
// two sides of a sheet come within Delta, F switches between their fits where
// the point nearest to x switches sides, and a point there would lie on no
// surface, up to a support away from both sides. Nor is a crossing past the
// edge of such a sheet: core/resample/sheet_edge.hpp.)
// The paper keeps the first in walk order; we keep the one nearest to the
// vertex (ties: the first listed), which is where the surface passes closest
// to it, so the kept point sits between its neighbours rather than at one end
// of a gap (2D spacings right after a resample stay within [0.5 h, 1.5 h],
// tested). Two kept points are at least h / 2 apart: closer crossings share
// their nearer vertex.
//
// Where the paper visits, point by point, the L-shaped edges of each point's
// block and marks vertices VISITED so that no edge is examined twice, we list
// the edges brick by brick (core/geometry/vertex_field.hpp; bricks are created in the
// points' order), each edge exactly once by construction. The edges are the
// union of the points' blocks plus the few that join two blocks; the order is
// fixed and the choice at each vertex does not depend on it, so the result is
// the same for any thread count, while the listing and the locating run in
// parallel.
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/resample/rim_carrying.hpp"
#include "core/surface/amls_surface.hpp"
#include "core/util/default_init_allocator.hpp"
#include "core/util/id_lists.hpp"
#include "core/geometry/vertex_field.hpp"
#include "core/geometry/walk_marks.hpp"

namespace amls {

enum class Variant {
  exact,         // the crossing is the root of F on the edge, to near machine precision
  interpolated,  // the crossing is the zero of the linear interpolant of the vertex values
};

const char* to_string(Variant variant);
// Throws std::invalid_argument naming the accepted values.
Variant parse_variant(const std::string& name);

struct ResampleStats {
  std::size_t vertices = 0;            // vertices where F was evaluated
  std::size_t undefined_vertices = 0;  // of which F was undefined
  std::size_t crossings = 0;           // edges with a sign change
  std::size_t located = 0;             // of which the position was computed (the others lose HAVECLOSEPOINT)
  std::size_t inserted = 0;            // new points
  std::size_t root_fallbacks = 0;      // exact roots that met an undefined F and took the interpolant's zero
  std::size_t root_evaluations = 0;    // evaluations of F by the root finder
  std::size_t jumps = 0;               // located sign changes that are jumps of F, not zeros: no point
  std::size_t past_sheet_edge = 0;     // located crossings past the edge of a sheet (core/resample/sheet_edge.hpp): no point
  std::size_t rim_samples = 0;         // samples of the old points found on a rim (core/surface/surface_rim.hpp)
  std::size_t beyond_rim = 0;          // crossings dropped at an open surface's rim: outside the domain, or crowding a rim point
  std::size_t rim_carried = 0;         // rim samples carried into the new points
  std::size_t rim_inserted = 0;        // points inserted along stretched rims
};

template <int D>
class Resampler {
 public:
  // The positions whose walks Update_Function() covers: every point and,
  // with widened supports, the positions over each widened point's tangent
  // disc (core/surface/local_support.hpp).
  static std::vector<Vec<D>> walk_positions(const AmlsSurface<D>& surface, ThreadPool& pool);
  // Update_Function().
  void update_function(const AmlsSurface<D>& surface, ThreadPool& pool);
  // Update_Function() at the vertices of the walks of `walk_positions` only
  // (a part of the surface's points, best in cell order), so that Resample()
  // creates points only there (local resampling). F there still reads every
  // point of the surface.
  void update_function(const AmlsSurface<D>& surface, const std::vector<Vec<D>>& walk_positions, ThreadPool& pool);
  // Resample(); requires update_function() on the same surface first, once per resample.
  PointSet<D> resample(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool);

  const ResampleStats& stats() const { return stats_; }
  // Vertex slots allocated (whole bricks of 4^D): what the vertex data cost,
  // proportional to the surface, not to the grid's volume.
  std::size_t vertex_slots() const { return field_.slots(); }

  // The value of F cached at a vertex by the last update_function(), if any.
  const Evaluation<D>* vertex_value(const IVec<D>& vertex) const;

 private:
  // Plain data (no initialisers), so that the lists below grow without a
  // serial pass that zeroes them (DefaultInitAllocator).
  struct Crossing {
    std::uint32_t from;  // slot of the edge's lower vertex
    std::uint32_t to;    // slot of its upper vertex
    int axis;
    double t;            // position along the edge, 0 at `from`, 1 at `to`: estimated, then located
    Vec<D> normal;       // set when located
  };
  using Crossings = std::vector<Crossing, DefaultInitAllocator<Crossing>>;

  // How far, in h, a crossing's edge midpoint may lie from the centre of the
  // neighbourhood selected for an earlier crossing and still reuse it (see
  // locate_crossings()): more reuse, but more zero-weight points per evaluation.
  // In 3D the wider selection holds several times the points and costs more
  // than the selects it saves (docs/performance.md), so 3D selects per crossing.
  static constexpr double kReuseMargin = D == 2 ? 2.0 : 0.0;
  // How far, as a fraction of the edge, a crossing may lie from its estimated
  // position (estimate_segment_root()) for drop_certain_losers() to be sure.
  // In 2D this holds on every vortex run measured: the output is the same as
  // when every crossing is located (a tighter 0.01 changes it). In 3D the fit
  // gradients are rougher slope estimates, so a few choices differ slightly
  // (docs/performance.md).
  static constexpr double kEstimateUncertainty = 0.05;
  // locate_crossings()' mark on a crossing that makes no point: a position off its edge.
  static constexpr double kNoPointMark = -1.0;

  // Lists the edges with a sign change, each with its crossing's estimated position.
  void list_crossings(Variant variant, double h, ThreadPool& pool);
  // Cuts crossings_ to those inside the domain that an open surface's
  // carried rim draws (core/resample/rim_carrying.hpp), judged at their
  // estimated positions.
  void drop_beyond_rim(const CarriedRim<D>& rim, const AmlsSurface<D>& surface, ThreadPool& pool);
  // Cuts crossings_ to those that may win HAVECLOSEPOINT if every estimated
  // position is within `uncertainty` (a fraction of h) of the crossing.
  void drop_certain_losers(double uncertainty, ThreadPool& pool);
  // HAVECLOSEPOINT on the located positions: cuts crossings_ to the kept ones.
  void keep_closest_crossings(ThreadPool& pool);
  // The kept crossings' positions (exact roots or the interpolant's zeros) and
  // normals; cuts crossings_ to those that are zeros of F, not jumps, and lie
  // within the old points' sheets (core/resample/sheet_edge.hpp).
  void locate_crossings(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool);

  VertexField<D> field_;                // vertex <-> slot
  IdLists brick_points_;                // per brick: the points within Delta of its box
  WalkMarks<D> walk_;                   // the vertices the walk reads
  using Mask = typename WalkMarks<D>::Mask;
  // F at the needed vertices, brick by brick in slot order: a brick's first
  // at value_first_[brick], the others after it in their local order.
  std::vector<Evaluation<D>> values_;
  std::vector<std::size_t> value_first_;
  // F at a needed vertex's slot (the walk reads no other).
  Evaluation<D>& value_at(std::uint32_t slot) {
    return values_[value_index(slot)];
  }
  const Evaluation<D>& value_at(std::uint32_t slot) const { return values_[value_index(slot)]; }
  std::size_t value_index(std::uint32_t slot) const {
    const std::size_t brick = slot / VertexField<D>::kBrickVolume;
    const std::uint32_t local = slot % VertexField<D>::kBrickVolume;
    const auto below = static_cast<Mask>((std::uint64_t{1} << local) - 1);
    return value_first_[brick] + static_cast<std::size_t>(std::popcount(static_cast<Mask>(walk_.needed()[brick] & below)));
  }
  // Per brick, one bit per vertex (by local index): where F is defined, and
  // where it is also >= 0 (a zero counts as positive). The walk reads these
  // rather than the values, a few words per brick.
  struct BrickSigns {
    Mask defined = 0;
    Mask positive = 0;
  };
  std::vector<BrickSigns> signs_;
  Crossings crossings_;
  Crossings crossings_scratch_;  // keep_in_order()'s other buffer
  // Slot -> a distance to its nearest crossing: drop_certain_losers()' bound
  // on it from the estimates, then keep_closest_crossings()' from the located
  // positions. One array for both (a second one costs peak memory on large
  // surfaces), which holds kFar between their uses.
  static constexpr double kFar = std::numeric_limits<double>::infinity();
  std::vector<double>& slot_distances();
  std::vector<double> slot_distances_;
  std::vector<std::uint32_t> closest_crossing_;  // slot -> the crossing HAVECLOSEPOINT keeps there
  ResampleStats stats_;
  bool function_updated_ = false;
};

extern template class Resampler<2>;
extern template class Resampler<3>;

}  // namespace amls
