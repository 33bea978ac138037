#include "core/geometry/surface_mesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace amls {

namespace {

// One cell's use of a facet: the facet's vertices in increasing order, and
// whether the cell runs through it that way (+1) or the other (-1).
struct FacetUse {
  std::uint32_t low;
  std::uint32_t high;  // equal to low in 2D, where a facet is a vertex
  int direction;
  bool operator<(const FacetUse& o) const { return low != o.low ? low < o.low : high < o.high; }
};

template <int D>
std::vector<FacetUse> facet_uses(const SurfaceMesh<D>& mesh) {
  std::vector<FacetUse> uses;
  uses.reserve(mesh.cells.size() * D);
  for (std::size_t k = 0; k < mesh.cells.size(); ++k) {
    const auto& cell = mesh.cells[k];
    for (const std::uint32_t v : cell)
      if (v >= mesh.vertices.size())
        throw std::invalid_argument("mesh cell " + std::to_string(k) + " names vertex " + std::to_string(v) + " of " +
                                    std::to_string(mesh.vertices.size()));
    if constexpr (D == 2) {
      // A segment leaves its first vertex and enters its second.
      uses.push_back({cell[0], cell[0], +1});
      uses.push_back({cell[1], cell[1], -1});
    } else {
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = cell[static_cast<std::size_t>(e)];
        const std::uint32_t b = cell[static_cast<std::size_t>((e + 1) % 3)];
        uses.push_back(a < b ? FacetUse{a, b, +1} : FacetUse{b, a, -1});
      }
    }
  }
  return uses;
}

}  // namespace

template <int D>
MeshTopology mesh_topology(const SurfaceMesh<D>& mesh) {
  std::vector<FacetUse> uses = facet_uses(mesh);
  std::sort(uses.begin(), uses.end());
  MeshTopology topology;
  for (std::size_t first = 0; first < uses.size();) {
    std::size_t last = first;
    int sum = 0;
    while (last < uses.size() && !(uses[first] < uses[last])) sum += uses[last++].direction;
    ++topology.facets;
    const std::size_t count = last - first;
    if (count == 1) ++topology.boundary;
    if (count > 2) ++topology.non_manifold;
    if (count == 2 && sum != 0) ++topology.misoriented;
    first = last;
  }
  return topology;
}

template MeshTopology mesh_topology<2>(const SurfaceMesh<2>&);
template MeshTopology mesh_topology<3>(const SurfaceMesh<3>&);

}  // namespace amls
