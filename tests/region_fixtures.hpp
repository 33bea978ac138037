#pragma once
// Scenes with region handles shared by the tests: the unit sphere with a cap
// at each pole.
#include <memory>

#include "core/geometry/shapes.hpp"
#include "core/run/scene.hpp"

namespace amls::test {

// The unit sphere's Fibonacci points (at spacing h) with |z| > `from_pole`
// on the side of `sign`: a polar cap.
inline std::shared_ptr<const PointRegion<3>> sphere_cap(double h, double sign, double from_pole) {
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, sphere_points_for_spacing(1.0, h));
  std::vector<Vec<3>> members;
  for (const Vec<3>& p : sphere.positions)
    if (sign * p.z() > from_pole) members.push_back(p);
  return std::make_shared<const PointRegion<3>>(std::move(members), h);
}

// The unit sphere at h, its south cap (z < -0.6) pinned and its north cap
// (z > north_from_pole) moved by `moved` in `steps` steps: one stage, regions only.
inline Scene<3> sphere_with_caps(double h, const RegionMotion<3>& moved, std::size_t steps,
                                 double north_from_pole = 0.6) {
  Scene<3> scene;
  scene.name = "sphere with caps";
  scene.shape.type = ShapeType::sphere;
  scene.grid_spacing = h;
  const RegionHandle<3> pinned{sphere_cap(h, -1.0, 0.6), {}, true};
  const RegionHandle<3> moving{sphere_cap(h, 1.0, north_from_pole), {}, false};
  scene.history.begin_stage({}, {pinned, moving});
  scene.history.add_target({}, steps, {RegionMotion<3>{}, moved});
  return scene;
}

}  // namespace amls::test
