#pragma once
// Whether a point set's samples scatter across the surface they sample by
// more than they lie apart along it (the noise of a raw scan), and by how
// much: so that h can be chosen to resolve the surface rather than the noise
// (core/run/shape_opening.hpp).
//
// Thickness: around each measured point, its kThicknessNeighbours nearest
// neighbours' spread along their least principal axis over that along the
// next one (the square root of the covariance's two smallest eigenvalues'
// ratio), the median over the points. Samples of a surface finer than it
// curves lie in a disk around each point: near 0 (CGAL's kitten.xyz 0.08,
// hippo1.ply 0.12; a scan of ragged parts, oni.ply, 0.36). Where the noise
// is wider than the spacing the neighbours fill a ball instead: about 0.74
// (sphere_20k.xyz, blobby.xyz, oneK.xyz: 0.73 to 0.74). Figures: docs/real-data.md.
//
// Scatter, measured only where the thickness says noisy: around each measured
// point, its kScatterNeighbours nearest neighbours fitted with a quadric height
// field over their principal plane (a parabola over their principal line in
// 2D); the median, over the points, of the fit's RMS residual. The quadric
// follows the surface's curvature, so the residual is the noise: sphere_20k.xyz,
// a unit sphere whose radii scatter by a standard deviation of 0.041, measures
// 0.034. The count is large enough that the neighbours spread along the surface
// further than they scatter across it, which lets the principal plane find the
// surface; it is a count, not a radius in units of h, since h is what is being
// chosen. Sharp edges, where no quadric fits, are a minority of the points and
// leave both medians alone.
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

struct SurfaceScatter {
  static constexpr int kThicknessNeighbours = 16;
  static constexpr double kNoisyThickness = 0.5;
  static constexpr int kScatterNeighbours = 100;
  // At most this many points are measured (every k-th of a larger set, in its
  // order), which keeps the cost of a few million points in check; the median
  // of 20,000 values is as good as that of all.
  static constexpr int kMostPoints = 20000;

  double thickness = 0.0;  // the median ratio above (0: too few points to tell)
  double scatter = 0.0;    // the median residual above, in the points' units (0: not noisy, not measured)
  bool noisy() const { return thickness > kNoisyThickness; }
};

// Both measures; a set of at most kScatterNeighbours points measures 0 (too
// few to tell noise from shape). Positions must be finite.
template <int D>
SurfaceScatter surface_scatter(const std::vector<Vec<D>>& positions);

extern template SurfaceScatter surface_scatter<2>(const std::vector<Vec<2>>&);
extern template SurfaceScatter surface_scatter<3>(const std::vector<Vec<3>>&);

}  // namespace amls
