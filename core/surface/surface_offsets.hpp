#pragma once
// The correction of the sphere fit's bias on anisotropically curved surfaces
// (3D only; see AmlsParameters::bias_correction).
//
// On a cylinder of radius rho the gradient-constrained fit (Step 2) finds a
// sphere of radius about 2 rho, whose zero set runs outside the points by
// about Delta^4 / rho^3 (second-order terms cancel, fourth-order ones do not).
// Every resample puts the new points on that zero set, so a thin sheet or tube
// grows a little at each resample: +7.6 % of the volume over the 128^3 Enright
// test, nearly all of it at the resamples (tools/resample_drift). A circle is
// reproduced exactly in 2D and a curve has one curvature, so 2D has no such
// bias and is left alone.
//
// The offset of a point p is how far the surface passes from it, F(p) (F is
// close to a signed distance near the surface, its fit gradient being a unit
// normal there). Corrected, F becomes F(x) - sum w_i o_i / sum w_i over the
// same neighbours and weights as the fit, whose zero set passes through the
// points where the offsets o_i vary smoothly. Taken raw, the offsets also
// carry grid-scale noise and, where a feature is smaller than Delta (a droplet
// pinching off, a filament's tip), large values of either sign; correcting by
// them undoes the smoothing that keeps such features stable, and the 128^3
// Enright run blows up at t = 1.6. So the offsets are
//   1. measured: o_i = F(p_i), from the fit over p_i's neighbours on its side;
//   2. smoothed: the weighted mean of the neighbours' o over Delta (the bias
//      varies with curvature, on the scale of the feature; the noise does not);
//   3. limited (minmod): where the smoothed offsets within Delta / 2 of p_i do
//      not all share one sign, the surface is not resolved there and o_i = 0;
//      else o_i is the smallest of them in magnitude.
// (A limiter over h instead of Delta / 2 sees too few neighbours to catch a
// droplet and the Enright run blows up; over Delta it flattens the correction
// at the tips where it is needed: +6.7 % instead of +3.6 %. Keeping o_i itself
// where the signs agree, rather than the smallest, blows up too: minmod's
// pull towards zero near a sign change is part of what keeps it stable. It
// also makes the correction partial: a static torus of tube radius 2h grows
// 0.14 % per resample instead of 0.57 % without it, where raw offsets would
// give 0.017 %.)
#include <span>
#include <vector>

#include "core/util/id_lists.hpp"
#include "core/util/thread_pool.hpp"
#include "core/math/vec.hpp"

namespace amls {

struct SurfaceOffsetOptions {
  double radius = 0.0;             // Delta
  double min_weight = 0.0;         // F is undefined below it: offset 0
  bool orientation_filter = true;  // neighbours count only if their normal agrees (AmlsParameters)
  // Every point's 1 / Delta_i^2 when supports are widened (AmlsParameters::widen_support):
  // a neighbour then weighs by its own support, and the limiter looks within Delta_i / 2.
  // Empty: Delta for all.
  std::span<const double> inverse_r2 = {};
};

// The limited offsets o_i of the points `positions` with pseudo-normals
// `normals`; `neighbours` holds, for each point, every point within Delta of
// it (itself included; with widened supports, every point whose support
// reaches it) in a fixed order. The same for any thread count.
template <int D>
std::vector<double> surface_offsets(const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                                    const IdLists& neighbours, const SurfaceOffsetOptions& options,
                                    ThreadPool& pool);

extern template std::vector<double> surface_offsets<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&,
                                                       const IdLists&, const SurfaceOffsetOptions&,
                                                       ThreadPool&);

}  // namespace amls
