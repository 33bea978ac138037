#include <doctest/doctest.h>

#include <utility>

#include "core/io/mesh_inside.hpp"
#include "core/io/mesh_sampling.hpp"
#include "core/run/mesh_export.hpp"
#include "core/run/point_set_resampling.hpp"
#include "mesh_fixtures.hpp"
#include "temp_dir.hpp"

using namespace amls;
using amls::test::box_mesh;

TEST_CASE("winding number: +-1 inside a closed mesh, 0 outside, whichever way its faces are wound") {
  for (const bool inward : {false, true}) {
    const TriangleMesh box = box_mesh(Vec<3>::Zero(), Vec<3>(1.0, 2.0, 0.1), inward);
    CHECK(winding_number(box, Vec<3>(0.5, 1.0, 0.05)) == doctest::Approx(inward ? -1.0 : 1.0));
    CHECK(winding_number(box, Vec<3>(0.999, 1.999, 0.001)) == doctest::Approx(inward ? -1.0 : 1.0));
    CHECK(winding_number(box, Vec<3>(0.5, 1.0, 0.11)) == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(winding_number(box, Vec<3>(-3.0, 5.0, 2.0)) == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(inside_mesh(box, Vec<3>(0.2, 0.2, 0.02)));
    CHECK_FALSE(inside_mesh(box, Vec<3>(1.01, 0.2, 0.02)));
  }
}

TEST_CASE("only a closed, consistently wound mesh has an inside to ask") {
  TriangleMesh box = box_mesh(Vec<3>::Zero(), Vec<3>::Ones());
  CHECK(closed_and_consistently_wound(box));
  CHECK(closed_and_consistently_wound(box_mesh(Vec<3>::Zero(), Vec<3>::Ones(), true)));
  std::swap(box.triangles[3][1], box.triangles[3][2]);  // one face wound the other way
  CHECK_FALSE(closed_and_consistently_wound(box));
  box.triangles.erase(box.triangles.begin() + 3);  // a hole
  CHECK_FALSE(closed_and_consistently_wound(box));
}

TEST_CASE("a closed input mesh gives a closed mesh: where F is undefined, the input's inside decides") {
  // A slab thinner than Delta: the orientation filter makes F jump in sign
  // between its faces, and past its edges the jumps run on until F is
  // undefined, where the mesh was left open.
  const double h = 0.02;
  const TriangleMesh slab = box_mesh(Vec<3>(0.25, 0.25, 0.48), Vec<3>(0.75, 0.75, 0.52));
  PointSetResampling options;
  options.spacing = h;
  options.threads = 2;
  const ResampledPointSet<3> resampled = resample_point_set(sample_mesh(slab, h).points, options);
  amls::test::TempDir dir;
  const MeshExport open = export_resampled_mesh(dir.file("open.ply"), resampled, options);
  CHECK(open.topology.boundary > 0);
  const MeshExport closed = export_resampled_mesh(dir.file("closed.ply"), resampled, options, &slab);
  CHECK(closed.topology.closed());
  // The grid vertices the input mesh decided are few: the mesh is F's zero set elsewhere.
  CHECK(closed.stats.undefined_cubes > 0);
  CHECK(closed.vertices < open.vertices + open.vertices / 4);
}
