// Region handles two ways, on the unit sphere with a cap at each pole: the
// south cap (z < -0.6) pinned, the north cap (z > 0.6) lifted by 0.4 in 40
// steps, resampled every step (`always`) or locally:
//
//   region  - each cap a region handle (core/deform/region_handle.hpp): its
//             gap-weighted frame, rigid within reach;
//   fps:K   - each cap as K point handles, its members' farthest-point
//             samples, each following the cap's motion;
//   points  - one point handle at each pole (the cost of a point handle).
//
// Prints, for each: how far the final points within each cap's reach are from
// the cap's sphere (moved or not), in h, and the deformation's time per step.
// Then the north cap (z > 0.8) lifted by 0.5 and turned by 90 degrees about
// the x axis in 10 steps, as a region: how far the points within its reach
// are from the sphere so moved, all of them and those more than 3 h inside
// its rim (the MLS support of a point nearer the rim reaches the bent neck),
// and the sampling's largest gap and closest pair (the seam between the
// region's points, which the resample keeps, and the resampled neck).
//
//   amls_region_bench [h] [threads] [always|local|both] [quick]
//
// Defaults 0.05, 1 and both; `quick` runs only the regions and the point
// handles (the comparison of their costs) and skips the turned cap.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "core/geometry/shapes.hpp"
#include "core/resample/resample_policy.hpp"
#include "core/run/scene_run.hpp"
#include "core/surface/metrics.hpp"

using namespace amls;

namespace {

std::shared_ptr<const PointRegion<3>> cap(double h, double sign, double from_pole = 0.6) {
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, sphere_points_for_spacing(1.0, h));
  std::vector<Vec<3>> members;
  for (const Vec<3>& p : sphere.positions)
    if (sign * p.z() > from_pole) members.push_back(p);
  return std::make_shared<const PointRegion<3>>(std::move(members), h);
}

// The north cap (z > 0.8) lifted and turned by 90 degrees about x in 10 steps.
void turned_cap(double h, int threads, ResamplePolicy::Kind policy) {
  const auto north = cap(h, 1.0, 0.8), south = cap(h, -1.0, 0.6);
  RegionMotion<3> turned;
  turned.translation = Vec<3>(0.0, 0.0, 0.5);
  turned.rotation = Vec<3>(0.5 * 3.141592653589793, 0.0, 0.0);
  Scene<3> scene;
  scene.shape.type = ShapeType::sphere;
  scene.grid_spacing = h;
  scene.history.begin_stage({}, {{south, {}, true}, {north, {}, false}});
  scene.history.add_target({}, 10, {RegionMotion<3>{}, turned});
  SceneRunOptions options;
  options.tracers_per_point = 1;
  options.threads = threads;
  options.policy.kind = policy;
  PointSet<3> last;
  run_scene<3>(scene, options, [&](std::size_t, const PointSet<3>& p) { last = p; });
  const RegionHandle<3> placed{north, turned, false};
  const PointRegion<3> now(placed.placed_members(), h);
  const Mat<3> linear = turned.linear();
  const Vec<3> offset = turned.offset(north->centre());
  const double rim = std::acos(0.8), inner = std::cos(rim - 3.0 * h);
  double all = 0.0, interior = 0.0;
  for (const Vec<3>& x : last.positions) {
    if (!now.contains(x)) continue;
    const Vec<3> rest = linear.transpose() * (x - offset);
    const double off = std::abs(rest.norm() - 1.0) / h;
    all = std::max(all, off);
    if (rest.normalized().z() > inner) interior = std::max(interior, off);
  }
  // The seam between the region's points and the resampled neck: no hole, no cluster.
  ThreadPool pool(threads);
  const double gap = sampling_quality(last, h, ResamplePolicy{}.search_radius(), pool).gap;
  const std::vector<double> spacing = nearest_neighbour_spacing_per_point(last, h, pool);
  std::printf("turned by 90 degrees (%s): within reach %.4f h, more than 3 h inside the rim %.4f h; "
              "sampling gap %.2f h, closest neighbours %.3f h\n",
              policy == ResamplePolicy::Kind::always ? "always" : "local", all, interior, gap,
              *std::min_element(spacing.begin(), spacing.end()));
}

// K of the members, each the farthest from those taken before (the first: the one nearest the centre).
std::vector<Vec<3>> farthest_point_samples(const PointRegion<3>& region, std::size_t k) {
  const std::vector<Vec<3>>& m = region.members();
  std::vector<double> gap(m.size());
  std::size_t next = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if ((m[i] - region.centre()).norm() < (m[next] - region.centre()).norm()) next = i;
  std::fill(gap.begin(), gap.end(), INFINITY);
  std::vector<Vec<3>> out;
  while (out.size() < std::min(k, m.size())) {
    out.push_back(m[next]);
    for (std::size_t i = 0; i < m.size(); ++i) gap[i] = std::min(gap[i], (m[i] - m[next]).norm());
    next = static_cast<std::size_t>(std::max_element(gap.begin(), gap.end()) - gap.begin());
  }
  return out;
}

struct Outcome {
  double pinned_h = 0.0, moving_h = 0.0;  // worst distance from the cap's sphere, in h
  double deform_ms = 0.0;                  // per step
};

Outcome run(const Scene<3>& scene, ResamplePolicy::Kind policy, int threads, const PointRegion<3>& south,
            const PointRegion<3>& north, const Vec<3>& lift, double h) {
  SceneRunOptions options;
  options.tracers_per_point = 1;
  options.threads = threads;
  options.policy.kind = policy;
  PointSet<3> last;
  const SceneRunReport report = run_scene<3>(scene, options, [&](std::size_t, const PointSet<3>& p) { last = p; });
  Outcome out;
  std::vector<Vec<3>> lifted;
  for (const Vec<3>& m : north.members()) lifted.push_back(m + lift);
  const PointRegion<3> north_now(lifted, north.reach());
  for (const Vec<3>& x : last.positions) {
    if (south.contains(x)) out.pinned_h = std::max(out.pinned_h, std::abs(x.norm() - 1.0) / h);
    if (north_now.contains(x)) out.moving_h = std::max(out.moving_h, std::abs((x - lift).norm() - 1.0) / h);
  }
  out.deform_ms = 1e3 * report.timings.deform / static_cast<double>(report.steps);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const double h = argc > 1 ? std::atof(argv[1]) : 0.05;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 1;
  const std::string only = argc > 3 ? argv[3] : "both";
  const bool quick = argc > 4 && std::string(argv[4]) == "quick";
  if ((only != "both" && only != "always" && only != "local") || (argc > 4 && !quick) || !(h > 0.0) || threads < 1) {
    std::fprintf(stderr, "usage: amls_region_bench [h > 0] [threads >= 1] [always|local|both] [quick]\n");
    return 2;
  }
  constexpr std::size_t kSteps = 40;
  const Vec<3> lift(0.0, 0.0, 0.4);
  const auto south = cap(h, -1.0), north = cap(h, 1.0);
  Scene<3> base;
  base.shape.type = ShapeType::sphere;
  base.grid_spacing = h;
  std::printf("h = %g, %zu + %zu cap members, %zu steps, %d thread(s)\n", h, south->members().size(),
              north->members().size(), kSteps, threads);
  std::printf("%-8s %-7s %12s %12s %12s\n", "policy", "handles", "pinned (h)", "moving (h)", "deform ms");
  for (const ResamplePolicy::Kind policy : {ResamplePolicy::Kind::always, ResamplePolicy::Kind::local}) {
    const char* policy_name = policy == ResamplePolicy::Kind::always ? "always" : "local";
    if (only != "both" && only != policy_name) continue;
    auto report = [&](const std::string& name, const Scene<3>& scene) {
      const Outcome o = run(scene, policy, threads, *south, *north, lift, h);
      std::printf("%-8s %-7s %12.4f %12.4f %12.3f\n", policy_name, name.c_str(), o.pinned_h, o.moving_h, o.deform_ms);
    };
    Scene<3> regions = base;
    RegionMotion<3> moved;
    moved.translation = lift;
    regions.history.begin_stage({}, {{south, {}, true}, {north, {}, false}});
    regions.history.add_target({}, kSteps, {RegionMotion<3>{}, moved});
    report("region", regions);
    for (const std::size_t k : {16, 32, 64}) {
      if (quick) break;
      Scene<3> fps = base;
      std::vector<Vec<3>> from = farthest_point_samples(*south, k), to = from;
      for (const Vec<3>& p : farthest_point_samples(*north, k)) {
        from.push_back(p);
        to.push_back(p + lift);
      }
      fps.history.begin_stage(from);
      fps.history.add_target(to, kSteps);
      report("fps:" + std::to_string(k), fps);
    }
    Scene<3> points = base;
    points.history.begin_stage({Vec<3>(0, 0, -1), Vec<3>(0, 0, 1)});
    points.history.add_target({Vec<3>(0, 0, -1), Vec<3>(0, 0, 1) + lift}, kSteps);
    report("points", points);
  }
  if (!quick)
    for (const ResamplePolicy::Kind policy : {ResamplePolicy::Kind::always, ResamplePolicy::Kind::local})
      if (only == "both" || only == (policy == ResamplePolicy::Kind::always ? "always" : "local"))
        turned_cap(h, threads, policy);
  return 0;
}
