#pragma once
// Whether a point lies inside a closed triangle mesh, by its generalized
// winding number (Jacobson, Kavan and Sorkine-Hornung 2013): the solid angle
// the triangles subtend at the point, over 4 pi, is +-1 inside and 0 outside
// (the sign is the faces' winding, so either winding works), and it degrades
// gracefully where the mesh is not quite closed. The mesh export asks it at
// every grid vertex around the surface (core/resample/mesh_extraction.hpp,
// KnownSide), hundreds of thousands of times a mesh, so MeshInside sums it
// over a bounding-volume tree: a cluster of triangles far from the point
// counts as one dipole (Barill et al. 2018, first order), the near ones
// exactly.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/io/mesh_io.hpp"

namespace amls {

// The exact sum over every triangle; MeshInside's reference.
double winding_number(const TriangleMesh& mesh, const Vec<3>& x);

// Whether the mesh bounds a solid whose inside the winding number gives:
// every edge is run through by exactly two triangles, in opposite directions.
// (A mesh wound every which way, as CGAL's *-shuffled.off are, is not: its
// winding number is neither 0 nor +-1 around it.)
bool closed_and_consistently_wound(const TriangleMesh& mesh);

// A mesh's area, and the volume and mean thickness 3 V / A of the solid it
// bounds: a ball's radius, 1.5 times a slab's thickness, 0.75 times a square
// beam's side; the scale a grid must resolve to keep the volume. The last two
// mean something only where the mesh bounds a solid, which this does not ask
// (closed_and_consistently_wound, a pass over every edge, is the caller's).
struct MeshMeasures {
  double area = 0.0;
  double volume = 0.0;
  double mean_thickness = 0.0;
};
MeshMeasures measure_mesh(const TriangleMesh& mesh);

class MeshInside {
 public:
  // Keeps a reference to `mesh`, which must outlive this.
  explicit MeshInside(const TriangleMesh& mesh);

  // The winding number at x: the exact one within kFarRatio cluster radii of
  // the triangles, their dipoles beyond (off by about 1e-2 of a unit).
  double winding_number(const Vec<3>& x) const;
  bool inside(const Vec<3>& x) const { return std::abs(winding_number(x)) > 0.5; }

 private:
  struct Node {
    Vec<3> center = Vec<3>::Zero();       // the triangles' area-weighted centroid
    Vec<3> area_vector = Vec<3>::Zero();  // the sum of their area-weighted normals, as wound
    double radius = 0.0;                  // from the center to the farthest of their corners
    std::uint32_t begin = 0, end = 0;     // their range in order_
    std::uint32_t children = 0;           // index of the first of two children; 0 for a leaf
  };

  void build(std::uint32_t self, std::uint32_t begin, std::uint32_t end);

  const TriangleMesh& mesh_;
  std::vector<std::uint32_t> order_;  // triangle indices, each node's a contiguous range
  std::vector<Node> nodes_;
};

}  // namespace amls
