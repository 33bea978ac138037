#include <doctest/doctest.h>

#include "core/io/mesh_sampling.hpp"
#include "core/surface/metrics.hpp"
#include "mesh_fixtures.hpp"

using namespace amls;

namespace {

// The unit cube [0, 1]^3, counter-clockwise seen from outside unless `inward`.
TriangleMesh cube(bool inward = false) { return amls::test::box_mesh(Vec<3>::Zero(), Vec<3>::Ones(), inward); }

}  // namespace

TEST_CASE("mesh sampling: a cube's samples lie on it, no farther apart than the spacing, with outward normals") {
  for (const bool inward : {false, true}) {
    const MeshSamples s = sample_mesh(cube(inward), 0.1);
    CHECK(s.flipped == inward);
    CHECK(s.boundary_edges == 0);
    CHECK(s.degenerate_triangles == 0);
    const PointSet<3>& p = s.points;
    REQUIRE(p.size() > 6 * 81);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec<3>& x = p.positions[i];
      const double to_face = std::min(x.minCoeff(), 1.0 - x.maxCoeff());
      CHECK(to_face == doctest::Approx(0.0).epsilon(1e-12));
      CHECK(p.normals[i].norm() == doctest::Approx(1.0));
      // Outward: the normal points away from the centre.
      CHECK(p.normals[i].dot(x - Vec<3>::Constant(0.5)) > 0.0);
    }
    const SpacingStats st = spacing_stats(p, 0.1);
    CHECK(st.max <= 1.0 + 1e-9);
    CHECK(st.min > 0.1);
  }
  TriangleMesh open = cube();
  open.triangles.resize(10);
  CHECK(sample_mesh(open, 0.25).boundary_edges == 4);
  TriangleMesh flat;
  flat.vertices = {Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::UnitX()};
  flat.triangles = {{0, 1, 2}};
  CHECK_THROWS_WITH(sample_mesh(flat, 0.1), doctest::Contains("no triangle of positive area"));
}
