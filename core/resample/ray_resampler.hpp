#pragma once
// The ray-tracing resampler of Gois et al., "Front tracking with
// moving-least-squares surfaces" (J. Comput. Phys. 2008; the paper's [GNNB08]):
// the baseline that the paper's grid walk replaces ("Original" in its Table 1).
//
// The rays are the grid lines: the lines parallel to each axis through the grid
// vertices. F can only be defined within Delta of a point, so each line is cut
// by the balls of radius Delta around the points: the ray-sphere intersections
// are chords, and the chords of one line, merged where they overlap, are the
// intervals where F may be defined. In each interval F is sampled every
// h / samples_per_cell, at the same places on every ray (vertices and, by
// default, edge midpoints; a sample where F is undefined brackets nothing), and
// each sign change between two consecutive samples is located by the bracketed
// root finder of the walk (core/resample/segment_root.hpp): a candidate point with the fitted
// normal there. A zero counts as positive, as in the grid walk.
//
// The points whose chords make up an interval are exactly the points that can
// reach any place in it, so no neighbour query is needed there: F at a sample is
// evaluated over the chords that overlap a window of two cells around it
// (widened by one sample step back, so that a bracket ending in the window is
// covered too), selected once per window from the interval's chords sorted by
// start.
//
// Rays on different axes cross the surface at nearby places, so candidates come
// in clusters; Remove_Clusters keeps, in candidate order (axis, line, position
// along the line), each candidate that lies no closer than cluster_threshold * h
// to every candidate kept before it. Its neighbour queries use a k-d tree over
// the candidates. The kept points are therefore pairwise at least that far apart.
//
// Rays are processed in parallel in contiguous blocks whose outputs are joined
// in ray order, and the cluster removal decides sequentially from neighbour
// lists computed in parallel: the result does not depend on the thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "core/surface/amls_surface.hpp"
#include "core/util/flat_hash_map.hpp"
#include "core/geometry/kd_tree.hpp"

namespace amls {

struct RaySettings {
  // F is sampled every h / samples_per_cell along each ray. Two samples per
  // cell see a double crossing that a cell-sized step would miss; one sample
  // per cell evaluates F where the grid walk does (at the vertices only).
  int samples_per_cell = 2;
  // Remove_Clusters removes candidates closer than this many h to a kept one:
  // crossings of rays of different axes less than h/2 apart are one crossing.
  double cluster_threshold = 0.5;
};

struct RayResampleStats {
  std::size_t rays = 0;               // grid lines cut by at least one ball
  std::size_t chords = 0;             // ray-sphere intersections
  std::size_t intervals = 0;          // chords merged where they overlap
  std::size_t samples = 0;            // evaluations of F at samples
  std::size_t undefined_samples = 0;  // of which F was undefined
  std::size_t crossings = 0;          // sign changes between samples: the candidates
  std::size_t root_evaluations = 0;   // evaluations of F by the root finder
  std::size_t root_fallbacks = 0;     // roots that met an undefined F and took the interpolant's zero
  std::size_t removed = 0;            // candidates removed by Remove_Clusters
  std::size_t inserted = 0;           // points kept
  RayResampleStats& operator+=(const RayResampleStats& o);
};

template <int D>
class RayResampler {
 public:
  explicit RayResampler(const RaySettings& settings = {});

  const RaySettings& settings() const { return settings_; }

  // Intersections: the candidates, the crossings of F = 0 with the grid lines of
  // `definition.grid()` near `positions`. F is `definition`'s (Delta, parameters,
  // evaluate_in()) over `positions` and their `pseudo_normals`; the definition's
  // own points are not used.
  void intersect(const AmlsSurface<D>& definition, std::span<const Vec<D>> positions,
                 std::span<const Vec<D>> pseudo_normals, ThreadPool& pool);
  // Remove_Clusters: the candidates of the last intersect(), less the clusters.
  PointSet<D> remove_clusters(double h, ThreadPool& pool);
  // Both, on a ready surface's own points and pseudo-normals.
  PointSet<D> resample(const AmlsSurface<D>& surface, ThreadPool& pool);

  // The candidates of the last intersect(), in order.
  const PointSet<D>& candidates() const { return candidates_; }
  // Of the last intersect() and remove_clusters().
  const RayResampleStats& stats() const { return stats_; }

 private:
  struct Ray {
    int axis = 0;
    IVec<D> line = IVec<D>::Zero();  // the line's vertex indices off its axis (0 on the axis)
    std::uint32_t begin = 0;         // its points: line_points_[begin, end)
    std::uint32_t end = 0;
  };
  struct Chord {
    double lo = 0.0;
    double hi = 0.0;
    std::uint32_t id = 0;
  };
  // Per thread block, reused from call to call; a cache line apart, so that
  // threads growing their vectors do not write to each other's lines.
  struct alignas(64) Scratch {
    std::vector<Chord> chords;
    std::vector<std::uint32_t> active;  // chords that overlap the current cell's window
    Neighbourhood<D> neighbourhood;
    PointSet<D> found;
    RayResampleStats stats;
    std::vector<std::uint32_t> near;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> close_pairs;  // (i, j), i < j, closer than the threshold
  };

  void cut_rays(const Grid<D>& grid, double radius, std::span<const Vec<D>> positions);
  void trace(const AmlsSurface<D>& definition, const Ray& ray, std::span<const Vec<D>> positions,
             std::span<const Vec<D>> pseudo_normals, Scratch& scratch) const;

  RaySettings settings_;
  std::vector<Ray> rays_;
  std::vector<std::uint32_t> line_points_;  // per ray, the points whose balls cut it, in point order
  FlatHashMap<std::uint32_t> lines_;        // one axis's lines: count, then start, then fill cursor
  std::vector<std::uint64_t> line_keys_;    // one axis's lines, sorted
  std::vector<Scratch> scratch_;
  PointSet<D> candidates_;
  KdTree<D> candidate_tree_;
  std::vector<std::uint8_t> removed_;
  RayResampleStats stats_;
};

extern template class RayResampler<2>;
extern template class RayResampler<3>;

}  // namespace amls
