#pragma once
// The AMLS surface S(P) of a point set (paper, section 2): the points, their
// neighbour index, their pseudo-normals (Step 1) and F with its fit gradient
// (Step 2) at any position.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/surface/gradient_fit.hpp"
#include "core/geometry/grid.hpp"
#include "core/util/id_lists.hpp"
#include "core/geometry/point_index.hpp"
#include "core/geometry/point_set.hpp"
#include "core/surface/pratt_fit.hpp"
#include "core/surface/surface_rim.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

struct AmlsParameters {
  // Delta = radius_factor * h (paper: Delta < d h with d = 3).
  double radius_factor = 3.0;
  // F is undefined at x where the weights reaching x sum to less than this,
  // i.e. less than one point at 0.575 Delta would give. Without it, fits at the
  // rim of the support extrapolate from one or two far points and put spurious
  // zero crossings there (tests/test_amls_surface.cpp shows one).
  double min_weight = 0.2;
  // Where two sheets of the surface come closer than Delta (a thin filament or
  // a narrow gap), their points carry opposite normals and a fit over both
  // averages them away, creating spurious zero sets between the sheets. With
  // this rule, fits use only the neighbours whose normal agrees (positive dot
  // product) with a reference: the point's own carried normal for the Pratt fit,
  // the pseudo-normal of the point nearest to x for F. On a surface whose
  // normals within Delta all agree (curvature radius above Delta / sqrt(2)) it
  // changes nothing.
  bool orientation_filter = true;
  // 3D only: F is corrected by the points' smoothed, limited offsets from the
  // surface, which removes the sphere fit's outward bias on sheets and tubes
  // (core/surface/surface_offsets.hpp; its effect on the Enright test:
  // docs/design.md). Ignored in 2D, which has no such bias.
  bool bias_correction = true;
  // Each point gets its own support Delta_i, wider than Delta where its
  // neighbours are far (core/surface/local_support.hpp), so that sparse parts
  // of an unevenly sampled input stay closed. Off for the paper's tests; where
  // every Delta_i equals Delta the surface is the same as without it.
  bool widen_support = false;
  // Open surfaces keep their rims (core/surface/surface_rim.hpp): samples
  // on a rim are found at Update_Normals, and the resampler places no point
  // beyond the rim line they draw and carries them into its output. A closed
  // surface has no rim sample, and nothing changes.
  bool keep_rims = true;
};

// Positions and pseudo-normals of the points near a region, copied side by side
// so that repeated evaluations there read contiguous memory.
template <int D>
struct Neighbourhood {
  std::vector<Vec<D>> positions;
  std::vector<Vec<D>> normals;
  // The points' offsets (AmlsParameters::bias_correction); empty: no correction.
  std::vector<double> offsets;
  // The points' 1 / Delta_i^2 (AmlsParameters::widen_support); empty: all 1 / Delta^2.
  std::vector<double> inverse_r2;
  // Every pair of normals agrees (all lie within 45 degrees of their mean), so
  // the orientation filter would keep every point and can be skipped.
  bool consistent = false;
};

struct NormalStats {
  std::size_t ok = 0;
  std::size_t too_few_neighbours = 0;
  std::size_t degenerate = 0;
  std::size_t no_solution = 0;
  std::size_t widened = 0;  // points whose support was widened (AmlsParameters::widen_support)
  std::size_t failed() const { return too_few_neighbours + degenerate + no_solution; }
  void count(FitStatus status) {
    switch (status) {
      case FitStatus::ok: ++ok; break;
      case FitStatus::too_few_neighbours: ++too_few_neighbours; break;
      case FitStatus::degenerate: ++degenerate; break;
      case FitStatus::no_solution: ++no_solution; break;
    }
  }
};

template <int D>
class AmlsSurface {
 public:
  AmlsSurface(const Grid<D>& grid, const AmlsParameters& parameters);

  const Grid<D>& grid() const { return grid_; }
  const AmlsParameters& parameters() const { return parameters_; }
  double radius() const { return radius_; }
  // Whether some Delta_i exceeds Delta (AmlsParameters::widen_support), decided at update_normals().
  bool widened() const { return !support_radii_.empty(); }
  // Every point's Delta_i when widened(), else empty.
  const std::vector<double>& support_radii() const { return support_radii_; }

  const PointSet<D>& points() const { return points_; }
  // Moving the points invalidates the index and the pseudo-normals until the
  // next hash_points() and update_normals().
  PointSet<D>& mutable_points() {
    ready_ = false;
    given_radii_.reset();
    return points_;
  }
  void set_points(PointSet<D> points);
  // The points with each one's Delta_i measured elsewhere (one per point, in
  // their order), used instead of measuring it on these points: a part of a
  // larger set whose points near the part's rim have neighbours outside it
  // (local resampling). Delta_i = Delta for all is one Delta, not widened.
  void set_points(PointSet<D> points, std::vector<double> support_radii);

  // Hash(): rebuilds the neighbour index (on `pool`: the same for any thread count).
  void hash_points();
  void hash_points(ThreadPool& pool);
  // Update_Normals(): the pseudo-normal of every point by the Pratt fit, oriented
  // to agree with the normal it carries; where the fit fails, the carried normal.
  NormalStats update_normals(ThreadPool& pool);
  const std::vector<Vec<D>>& pseudo_normals() const { return pseudo_normals_; }
  // The rim samples found by the last update_normals() (none when
  // AmlsParameters::keep_rims is off or the surface is closed).
  const SurfaceRim<D>& rim() const { return rim_; }
  // The support Delta_i of point i (Delta where no support is widened).
  double support_radius(std::uint32_t i) const { return widened() ? support_radii_[i] : radius_; }
  // The bias correction's offset of every point, empty when it is off.
  const std::vector<double>& offsets() const { return offsets_; }

  // Whether some point lies within `radius` of x.
  bool has_point_within(const Vec<D>& x, double radius) const;

  // F, in three parts: gather_ids() lists the points near a region, select()
  // copies those near a position into a Neighbourhood, and evaluate_in() or
  // evaluate_cube() fits over it. The resampler gathers once per brick and
  // selects once per cube; evaluate() does all three for one position.

  // F(x) and the fit's gradient, over all points whose support reaches x.
  Evaluation<D> evaluate(const Vec<D>& x) const;

  // Appends the ids of the points within `radius` of the box [lo, hi]. With
  // widened supports `radius` is Delta plus a margin, and a point counts
  // when its own Delta_i plus that margin reaches the box.
  void gather_ids(const Vec<D>& lo, const Vec<D>& hi, double radius, std::vector<std::uint32_t>& out) const;
  // Fills `out` with those of the points `ids` that lie within `radius` of x
  // (widened: within Delta_i + radius - Delta, with their 1 / Delta_i^2).
  void select(std::span<const std::uint32_t> ids, const Vec<D>& x, double radius, Neighbourhood<D>& out) const;
  // F at y from a neighbourhood holding every point whose support reaches y.
  Evaluation<D> evaluate_in(const Neighbourhood<D>& neighbourhood, const Vec<D>& y) const;
  // F at the 2^D corners of a grid cube, all from one neighbourhood holding
  // every point within Delta of each of them: one pass over the neighbours
  // serves all corners, with the corners in the innermost loop, where the
  // compiler vectorizes them. Gives evaluate_in()'s values.
  static constexpr int kCubeCorners = 1 << D;
  void evaluate_cube(const Neighbourhood<D>& neighbourhood, const std::array<Vec<D>, kCubeCorners>& corners,
                     std::array<Evaluation<D>, kCubeCorners>& out) const;
  // Step 1's fit at p, which carries the normal `carried`, from a
  // neighbourhood holding the positions and carried normals of every point
  // within Delta of p: the sums and orientation filter of update_normals(),
  // for callers with their own neighbour index (the ray-tracing baseline's
  // k-d tree), who solve it (PrattBatches).
  PrattFit<D> pratt_fit_in(const Neighbourhood<D>& neighbourhood, const Vec<D>& p, const Vec<D>& carried) const;

 private:
  // The orientation filter's test (AmlsParameters::orientation_filter), for
  // Step 1 and Step 2 alike: a neighbour counts when its normal agrees with
  // the reference.
  static bool agrees(const Vec<D>& normal, const Vec<D>& reference) { return normal.dot(reference) > 0.0; }
  // Whether F over `neighbourhood` needs the filter: not when every normal there agrees.
  bool filters(const Neighbourhood<D>& neighbourhood) const {
    return parameters_.orientation_filter && !neighbourhood.consistent;
  }
  void require_ready() const;
  // Each point's Delta_i and the index of the widened points, for the points as hashed.
  void widen_supports(ThreadPool& pool);
  // The supports' measure of a neighbour seen from a point (update_normals()).
  struct UniformSupport;
  struct WidenedSupport;
  template <typename Support>
  void fit_normals(const Support& support, std::vector<FitStatus>& status, ThreadPool& pool);
  // The rim samples among the points flagged by the fits (rim_candidates_).
  void find_rim(ThreadPool& pool);
  // gather_ids()' second part when widened(): the widened points beyond `radius` whose own support reaches.
  void gather_widened(const Vec<D>& lo, const Vec<D>& hi, double radius, std::vector<std::uint32_t>& out) const;
  template <bool kWidened>
  void select_with(std::span<const std::uint32_t> ids, const Vec<D>& x, double radius, Neighbourhood<D>& out) const;
  // evaluate_in()'s sums, with one Delta or each point's own.
  template <bool kWidened>
  GradientFit<D> fit_in(const Neighbourhood<D>& neighbourhood, const Vec<D>& y) const;
  template <bool kCorrected, bool kWidened>
  void evaluate_cube_with(const Neighbourhood<D>& neighbourhood, const std::array<Vec<D>, kCubeCorners>& corners,
                          std::array<Evaluation<D>, kCubeCorners>& out) const;

  Grid<D> grid_;
  AmlsParameters parameters_;
  double radius_;
  PointSet<D> points_;
  // Delta_i and 1 / Delta_i^2 of every point, in the points' order, when
  // some Delta_i exceeds Delta; else empty (one Delta for all).
  std::vector<double> support_radii_;
  std::vector<double> inverse_r2_;
  // The points whose Delta_i exceeds Delta, in cells as wide as the widest
  // (index_ keeps cells of Delta for all, so that the many regular points'
  // queries stay as small as without widening), and their ids.
  PointIndex<D> wide_index_;
  std::vector<std::uint32_t> wide_ids_;
  double widest_ = 0.0;
  bool supports_measured_ = false;  // widen_supports() ran since the last hash
  // Delta_i given with the points (set_points), kept in the points' order.
  std::optional<std::vector<double>> given_radii_;
  PointIndex<D> index_;
  std::vector<Vec<D>> pseudo_normals_;
  std::vector<double> offsets_;
  IdLists neighbours_;  // every point's neighbours within Delta, for the bias correction
  // Per point, whether its fit's neighbour centroid lies off it along the
  // tangent plane (kRimCandidateShift): the rim test's candidates.
  std::vector<std::uint8_t> rim_candidates_;
  SurfaceRim<D> rim_;
  bool hashed_ = false;
  bool ready_ = false;
};

extern template class AmlsSurface<2>;
extern template class AmlsSurface<3>;

}  // namespace amls
