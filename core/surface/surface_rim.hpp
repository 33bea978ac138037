#pragma once
// Where an open surface ends: its rim samples and the domain they bound.
//
// F is defined wherever enough weight reaches (AmlsParameters::min_weight),
// which at the rim of an open scan is up to a support beyond its outermost
// samples; the paper's resampler puts new points there, and a loop that
// resamples its own output carries the rim outward by about half an h each
// time (an open cap closes into an egg). Following MeshLab's APSS domain and
// the boundary criteria of PCL and of Bendels, Schnabel and Klein, a sample
// is on the rim when its neighbours, projected on its tangent plane, leave
// an angular gap wider than kRimGap (in 2D: when they all lie on one side:
// a curve's end). Each rim sample gets an outward direction b_i (the gap's
// bisector) in its tangent plane, and the domain's side function
//
//   G(x) = sum_i w_i b_i.(x - p_i) / sum_i w_i,   w_i = phi(|x - p_i| / Delta_i),
//
// over the rim samples whose support reaches x and whose normal is within
// 120 degrees of x's (kRimFacing), is the signed distance past the rim line
// they draw: positive beyond the rim, negative inside; where no rim sample
// reaches, x is inside. Within 120 and not 90 degrees: a sheet that curls
// past the rim (normals 95 to 150 degrees from the rim sample's, near an
// open scan's rim) is cut there too; a thin sheet's far side (about 180) is not.
// (docs/design.md, "Open surfaces", says why this rule and not others.)
//
// Which points to test is decided cheaply during the normals' fits: a
// point's weighted neighbour centroid lies about 0.24 Delta off it, along
// the tangent plane, on a half-disc and near 0 inside a surface
// (kRimCandidateShift); only those candidates pay for the angular test.
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "core/geometry/point_index.hpp"
#include "core/math/vec.hpp"
#include "core/util/flat_hash_map.hpp"

namespace amls {

// The largest angular gap (radians) among a point's kRimNeighbours nearest
// tangential neighbours (within kRimReach supports) that still counts as surrounded. PCL's
// BoundaryEstimation takes pi / 2; a resample's first row of new points
// inside a rim (kRimBand h in, between rim points up to 1.5 h apart) sees
// the rim points across a gap of up to 112 degrees, and must not count as
// rim itself, or the rim would move inward by a row at every resample.
// A straight rim leaves 180 degrees, a hole's rim (concave) less the
// smaller the hole: 142 degrees at a radius of 1.5 h.
inline constexpr double kRimGap = 2.0 * std::numbers::pi / 3.0;
// How many nearest neighbours (within the support) the angular test looks
// at: near enough that the far side of a small hole does not close its gap,
// enough that an uneven scan's interior leaves no gap that wide.
inline constexpr int kRimNeighbours = 10;
// How far, in supports, those neighbours are looked for. Beyond one support:
// where an input is sparser than h says (its points a few h apart, each
// weighing within Delta), the points across a gap of one support still
// carry F over it, and the gap is no rim.
inline constexpr double kRimReach = 2.0;
// A gap narrower than this many supports (the mean of the two sides') is
// bridged: F, summing the weights of the points along both of its sides, is
// defined across it, and the widened supports were made to close such gaps
// in sparse scans, where a dense side's support meets a sparse side's wide
// one. A wider gap is a hole, and its sides are rims.
inline constexpr double kRimBridge = 1.5;
// The least cosine between a point's normal and a neighbour's for the
// neighbour to count (120 degrees), and between a position's normal and a
// rim sample's for the sample to count in SurfaceRim::side.
inline constexpr double kRimFacing = -0.5;
// The tangential shift of a point's weighted neighbour centroid, in units of
// its support, above which the angular test is run: a fifth of a
// half-disc's. At a third of it, rim samples with a few neighbours along
// the rim beside them were missed now and then, and a drag that carried
// the rim lost it there (a hole of 2 h in a dragged cap).
inline constexpr double kRimCandidateShift = 0.05;

// A neighbour of a point tested for the rim: where it lies from the point,
// and the distance across which it bridges a gap to it (kRimBridge times
// the mean of their supports).
template <int D>
struct RimNeighbour {
  Vec<D> offset;
  double bridge;
};

// The outward direction (unit, in the tangent plane of `normal`) of a point
// with these neighbours, if it is on the rim; nullopt when it is surrounded
// or has too few neighbours to tell (3D: 2, 2D: 1). The kRimNeighbours
// nearest decide the gap; the gap is bridged, and no rim, when any neighbour
// lies across it within its bridge (tangentially, within 60 degrees of the
// outward direction). A point `carried` as rim by the last resample is not
// asked about bridges: that was decided where its rim was first found, and a
// carried rim point that a notch of its own rim faces (the commonest false
// bridge) would break the rim line there, letting the next resample's
// crossings past it. It stays rim while its gap stays wider than kRimGap.
template <int D>
std::optional<Vec<D>> rim_outward(const Vec<D>& normal, std::span<const RimNeighbour<D>> neighbours,
                                  bool carried = false);

template <int D>
class SurfaceRim {
 public:
  // The rim samples: their ids among the surface's points, positions,
  // outward directions, normals and supports, side by side.
  struct Samples {
    std::vector<std::uint32_t> ids;
    std::vector<Vec<D>> positions;
    std::vector<Vec<D>> outward;
    std::vector<Vec<D>> normals;
    std::vector<double> radii;
  };

  SurfaceRim() = default;
  // Indexes the samples (taken in their order) for side().
  SurfaceRim(Samples samples, const Vec<D>& origin);

  bool empty() const { return samples_.ids.empty(); }
  std::size_t size() const { return samples_.ids.size(); }
  const Samples& samples() const { return samples_; }

  // G(x) for a position x whose surface normal is about `normal`; nullopt
  // where no rim sample reaches (inside).
  std::optional<double> side(const Vec<D>& x, const Vec<D>& normal) const;
  // Calls fn(k, position) for every rim sample k within `radius` of x.
  template <typename Fn>
  void for_each_within(const Vec<D>& x, double radius, Fn&& fn) const {
    if (!empty()) index_.for_each_within(x, radius, fn);
  }

 private:
  // Whether some rim sample may reach x: a single lookup, so that side()
  // costs little at the many positions that lie far from any rim.
  bool near(const Vec<D>& x) const;

  Samples samples_;
  PointIndex<D> index_;
  // The index's cells that hold a sample or touch one that does.
  FlatHashMap<std::uint8_t> reached_cells_;
};

extern template class SurfaceRim<2>;
extern template class SurfaceRim<3>;

}  // namespace amls
