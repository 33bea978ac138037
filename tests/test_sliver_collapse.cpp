#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "core/geometry/sliver_collapse.hpp"
#include "core/geometry/surface_mesh.hpp"

using namespace amls;

namespace {

constexpr double kH = 0.1;
const Grid<3> kGrid(Vec<3>::Zero(), kH);

// Appends a triangle facing away from `inside` (the shapes here are convex).
void add_outward(SurfaceMesh<3>& mesh, std::array<std::uint32_t, 3> t, const Vec<3>& inside) {
  const Vec<3>& a = mesh.vertices[t[0]];
  const Vec<3> normal = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
  if (normal.dot(a - inside) < 0.0) std::swap(t[1], t[2]);
  mesh.cells.push_back(t);
}

// A tetrahedron whose apex `d` (a grid vertex) is cut off by a tiny triangle d1 d2 d3, each at
// `cut` of its edge from d: 6 vertices, 8 triangles, the slivers of a surface through d.
void add_cut_tetrahedron(SurfaceMesh<3>& mesh, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d,
                         double cut) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const Vec<3>& p : {a, b, c, Vec<3>(d + cut * (a - d)), Vec<3>(d + cut * (b - d)), Vec<3>(d + cut * (c - d))}) {
    mesh.vertices.push_back(p);
    mesh.normals.push_back(Vec<3>::UnitZ());
  }
  const Vec<3> inside = (a + b + c + d) / 4.0;
  const std::uint32_t A = base, B = base + 1, C = base + 2, D1 = base + 3, D2 = base + 4, D3 = base + 5;
  for (const std::array<std::uint32_t, 3>& t : std::vector<std::array<std::uint32_t, 3>>{
           {A, B, C}, {A, B, D2}, {A, D2, D1}, {B, C, D3}, {B, D3, D2}, {C, A, D1}, {C, D1, D3}, {D1, D2, D3}})
    add_outward(mesh, t, inside);
}

long euler_characteristic(const SurfaceMesh<3>& mesh) {
  return static_cast<long>(mesh.vertices.size()) - static_cast<long>(mesh_topology(mesh).facets) +
         static_cast<long>(mesh.cells.size());
}

}  // namespace

TEST_CASE("collapse_slivers: a cluster beside a grid vertex becomes one vertex, the mesh stays closed") {
  SurfaceMesh<3> mesh;
  const Vec<3> apex(0.3, 0.3, 0.3);  // a grid vertex
  add_cut_tetrahedron(mesh, {0.0, 0.0, 0.0}, {0.6, 0.0, 0.05}, {0.0, 0.6, 0.05}, apex, 0.005);
  REQUIRE(mesh_topology(mesh).closed());
  REQUIRE(euler_characteristic(mesh) == 2);
  CHECK(collapse_slivers(mesh, kGrid) == 2);
  CHECK(mesh.vertices.size() == 4);
  CHECK(mesh.cells.size() == 4);
  CHECK(mesh_topology(mesh).closed());
  CHECK(euler_characteristic(mesh) == 2);
  // The merged vertex is the cut's centre: within the cut of the apex.
  CHECK((mesh.vertices[3] - apex).norm() < 0.005 * 0.6);
}

TEST_CASE("collapse_slivers: a cluster reaching 0.07 h from its grid vertex is merged too") {
  // On a flat face at an angle to the grid (CGAL's 3torus.off), a sliver's far corner lay 0.071 h
  // from the grid vertex: the needle left beside it lay nearly in the plane of a triangle 0.04 h
  // away, and Open3D took the two for crossing.
  SurfaceMesh<3> mesh;
  const Vec<3> apex(0.3, 0.3, 0.3);
  add_cut_tetrahedron(mesh, {0.0, 0.0, 0.0}, {0.6, 0.0, 0.05}, {0.0, 0.6, 0.05}, apex, 0.0135);
  for (std::size_t k = 3; k < 6; ++k) {
    const double away = (mesh.vertices[k] - apex).norm() / kH;
    REQUIRE(away > 0.06);
    REQUIRE(away < 0.075);
  }
  CHECK(collapse_slivers(mesh, kGrid) == 2);
  CHECK(mesh_topology(mesh).closed());
  CHECK(euler_characteristic(mesh) == 2);
}

TEST_CASE("collapse_slivers: vertices farther than the reach, or nowhere near a grid vertex, stay") {
  SurfaceMesh<3> mesh;
  add_cut_tetrahedron(mesh, {0.0, 0.0, 0.0}, {0.6, 0.0, 0.05}, {0.0, 0.6, 0.05}, {0.3, 0.3, 0.3}, 0.2);
  const SurfaceMesh<3> before = mesh;
  CHECK(collapse_slivers(mesh, kGrid) == 0);
  CHECK(mesh.cells == before.cells);
}

TEST_CASE("collapse_slivers: two sheets meeting at one grid vertex are not pinched together, each merged on its own") {
  // Two cut tetrahedra whose cut apexes face each other across the grid vertex (0.3, 0.3, 0.3): merging the
  // six vertices would join the two closed surfaces at one vertex, which is not a manifold. Each cut (a
  // polyhedron's corner beside a grid vertex, sheets of one surface) becomes its own vertex instead.
  SurfaceMesh<3> mesh;
  const Vec<3> v(0.3, 0.3, 0.3);
  const Vec<3> up(0.0, 0.0, 0.3);
  add_cut_tetrahedron(mesh, v - up + Vec<3>(-0.2, -0.2, 0), v - up + Vec<3>(0.3, -0.1, 0), v - up + Vec<3>(-0.1, 0.3, 0),
                      v - Vec<3>(0, 0, 0.002), 0.003);
  add_cut_tetrahedron(mesh, v + up + Vec<3>(-0.2, -0.2, 0), v + up + Vec<3>(0.3, -0.1, 0), v + up + Vec<3>(-0.1, 0.3, 0),
                      v + Vec<3>(0, 0, 0.002), 0.003);
  REQUIRE(mesh_topology(mesh).closed());
  CHECK(collapse_slivers(mesh, kGrid) == 4);
  CHECK(mesh.vertices.size() == 8);
  CHECK(mesh.cells.size() == 8);
  CHECK(mesh_topology(mesh).closed());
  CHECK(euler_characteristic(mesh) == 4);
  // Still two surfaces apart: the lower tetrahedron's triangles use none of the upper one's vertices.
  std::vector<int> side(mesh.vertices.size(), 0);
  bool shared = false;
  for (const auto& t : mesh.cells) {
    const int mine = mesh.vertices[t[0]].z() + mesh.vertices[t[1]].z() + mesh.vertices[t[2]].z() < 3 * v.z() ? 1 : 2;
    for (std::uint32_t u : t) {
      shared = shared || (side[u] != 0 && side[u] != mine);
      side[u] = mine;
    }
  }
  CHECK_FALSE(shared);
}
