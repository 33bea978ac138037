#include "core/geometry/sliver_collapse.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace amls {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The vertices within `reach` h of a grid vertex, grouped by it; groups of
// two or more, in the order of their first vertex.
std::vector<std::vector<std::uint32_t>> clusters_of(const SurfaceMesh<3>& mesh, const Grid<3>& grid, double reach) {
  const double h = grid.spacing();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> near;
  for (std::uint32_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec<3> cell = (mesh.vertices[i] - grid.origin()) / h;
    IVec<3> nearest;
    for (int a = 0; a < 3; ++a) nearest[a] = static_cast<std::int64_t>(std::llround(cell[a]));
    if ((mesh.vertices[i] - grid.vertex_position(nearest)).norm() < reach * h) near.emplace_back(Grid<3>::key(nearest), i);
  }
  std::sort(near.begin(), near.end());
  std::vector<std::vector<std::uint32_t>> out;
  for (std::size_t b = 0; b < near.size();) {
    std::size_t e = b + 1;
    while (e < near.size() && near[e].first == near[b].first) ++e;
    if (e - b >= 2) {
      out.emplace_back();
      for (std::size_t k = b; k < e; ++k) out.back().push_back(near[k].second);  // increasing, as sorted
    }
    b = e;
  }
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.front() < y.front(); });
  return out;
}

// Whether triangles (each holding `v`) form one fan around v whose every edge
// from v is run through once in each direction.
bool closes_one_fan(std::uint32_t v, const std::vector<Triangle>& triangles) {
  if (triangles.size() < 3) return false;
  // Each triangle rotated to (v, a, b) contributes the link edge a -> b.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> link;
  for (const Triangle& t : triangles) {
    int k = 0;
    while (t[static_cast<std::size_t>(k)] != v) ++k;
    link.emplace_back(t[static_cast<std::size_t>((k + 1) % 3)], t[static_cast<std::size_t>((k + 2) % 3)]);
  }
  std::sort(link.begin(), link.end());
  for (std::size_t k = 1; k < link.size(); ++k)
    if (link[k].first == link[k - 1].first) return false;  // an edge from v run through twice the same way
  // Follow the link from its first vertex: one cycle through every edge.
  auto next = [&](std::uint32_t a) -> const std::pair<std::uint32_t, std::uint32_t>* {
    const auto it = std::lower_bound(link.begin(), link.end(), std::make_pair(a, std::uint32_t{0}));
    return it != link.end() && it->first == a ? &*it : nullptr;
  };
  std::uint32_t at = link.front().first;
  for (std::size_t steps = 1; steps <= link.size(); ++steps) {
    const auto* edge = next(at);
    if (edge == nullptr) return false;  // the fan is open
    at = edge->second;
    if (at == link.front().first) return steps == link.size();
  }
  return false;
}

// Where the surface folds sharply within a cluster (a thin fin), two triangles can become the same
// triangle run both ways: a flat pillow enclosing nothing. Both go, as the fold they stood for.
void cancel_folded_pairs(std::vector<Triangle>& kept, std::vector<std::uint32_t>& ids) {
  std::vector<std::size_t> order(kept.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  auto sorted = [&](std::size_t k) {
    Triangle t = kept[k];
    std::sort(t.begin(), t.end());
    return t;
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sorted(a) < sorted(b); });
  std::vector<bool> gone(kept.size(), false);
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const std::size_t a = order[k], b = order[k + 1];
    if (gone[a] || sorted(a) != sorted(b)) continue;
    // Opposite orientations: b is a read backwards, i.e. not one of a's rotations.
    const Triangle& ta = kept[a];
    const Triangle& tb = kept[b];
    bool same = false;
    for (int r = 0; r < 3; ++r)
      same = same || (tb[0] == ta[static_cast<std::size_t>(r)] && tb[1] == ta[static_cast<std::size_t>((r + 1) % 3)]);
    if (same) continue;
    gone[a] = gone[b] = true;
  }
  std::size_t out = 0;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (gone[k]) continue;
    kept[out] = kept[k];
    ids[out++] = ids[k];
  }
  kept.resize(out);
  ids.resize(out);
}

// The parts of `cluster` (ascending) that the edges of the live triangles join, each ascending,
// in the order of their first vertex.
std::vector<std::vector<std::uint32_t>> joined_parts(const std::vector<std::uint32_t>& cluster,
                                                     const std::vector<Triangle>& cells,
                                                     const std::vector<std::uint32_t>& first,
                                                     const std::vector<std::uint32_t>& around,
                                                     const std::vector<bool>& alive) {
  // Union-find over the cluster's places.
  std::vector<std::size_t> parent(cluster.size());
  for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = k;
  auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  auto place = [&](std::uint32_t u) {
    const auto it = std::lower_bound(cluster.begin(), cluster.end(), u);
    return it != cluster.end() && *it == u ? static_cast<std::size_t>(it - cluster.begin()) : cluster.size();
  };
  for (std::size_t k = 0; k < cluster.size(); ++k)
    for (std::uint32_t c = first[cluster[k]]; c < first[cluster[k] + 1]; ++c) {
      if (!alive[around[c]]) continue;
      for (std::uint32_t u : cells[around[c]]) {
        const std::size_t j = place(u);
        if (j < cluster.size()) parent[root(j)] = root(k);
      }
    }
  std::vector<std::vector<std::uint32_t>> parts;
  std::vector<std::size_t> part_of(cluster.size(), cluster.size());
  for (std::size_t k = 0; k < cluster.size(); ++k) {
    std::size_t& part = part_of[root(k)];
    if (part == cluster.size()) {
      part = parts.size();
      parts.emplace_back();
    }
    parts[part].push_back(cluster[k]);
  }
  return parts;
}

// V - E + F, and the facet counts, of the mesh: what a merge must keep.
struct Shape {
  MeshTopology topology;
  long euler = 0;
};

Shape shape_of(const SurfaceMesh<3>& mesh) {
  Shape out;
  out.topology = mesh_topology(mesh);
  out.euler = static_cast<long>(mesh.vertices.size()) - static_cast<long>(out.topology.facets) +
              static_cast<long>(mesh.cells.size());
  return out;
}

}  // namespace

std::size_t collapse_slivers(SurfaceMesh<3>& mesh, const Grid<3>& grid, double reach) {
  const std::vector<std::vector<std::uint32_t>> clusters = clusters_of(mesh, grid, reach);
  if (clusters.empty()) return 0;
  // Each merge is checked where it happens; the whole is checked once more at the end, and the
  // mesh given back as it was should a merge have changed its topology after all.
  SurfaceMesh<3> original = mesh;
  const Shape before = shape_of(mesh);
  const std::size_t n = mesh.vertices.size();
  // The triangles around each vertex (indices into mesh.cells).
  std::vector<std::uint32_t> first(n + 1, 0), around;
  for (const Triangle& t : mesh.cells)
    for (std::uint32_t v : t) ++first[v + 1];
  for (std::size_t i = 0; i < n; ++i) first[i + 1] += first[i];
  around.resize(first[n]);
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t c = 0; c < mesh.cells.size(); ++c)
      for (std::uint32_t v : mesh.cells[c]) around[fill[v]++] = c;
  }
  std::vector<std::uint32_t> merged_into(n);
  for (std::uint32_t i = 0; i < n; ++i) merged_into[i] = i;
  std::vector<bool> alive(mesh.cells.size(), true);
  std::vector<std::uint32_t> touched;
  std::vector<Triangle> kept;
  std::vector<std::uint32_t> kept_ids;
  std::size_t removed = 0;
  // Merges `group` (ascending) into its first vertex where the triangles around it close one fan
  // afterwards; false (and nothing changed) where they do not.
  auto merge = [&](const std::vector<std::uint32_t>& group) {
    const std::uint32_t v = group.front();
    touched.clear();
    for (std::uint32_t m : group)
      for (std::uint32_t k = first[m]; k < first[m + 1]; ++k)
        if (alive[around[k]]) touched.push_back(around[k]);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    kept.clear();
    kept_ids.clear();
    auto target = [&](std::uint32_t u) {
      return std::binary_search(group.begin(), group.end(), u) ? v : merged_into[u];
    };
    for (std::uint32_t c : touched) {
      const Triangle t{target(mesh.cells[c][0]), target(mesh.cells[c][1]), target(mesh.cells[c][2])};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // a sliver: it goes
      kept.push_back(t);
      kept_ids.push_back(c);
    }
    cancel_folded_pairs(kept, kept_ids);
    if (!closes_one_fan(v, kept)) return false;
    Vec<3> position = Vec<3>::Zero(), normal = Vec<3>::Zero();
    for (std::uint32_t m : group) {
      position += mesh.vertices[m];
      normal += mesh.normals[m];
      merged_into[m] = v;
    }
    mesh.vertices[v] = position / static_cast<double>(group.size());
    if (normal.norm() > 0.0) mesh.normals[v] = normal.normalized();
    for (std::uint32_t c : touched) alive[c] = false;
    for (std::size_t k = 0; k < kept.size(); ++k) {
      alive[kept_ids[k]] = true;
      mesh.cells[kept_ids[k]] = kept[k];
    }
    removed += group.size() - 1;
    return true;
  };
  for (const std::vector<std::uint32_t>& cluster : clusters) {
    if (merge(cluster)) continue;
    // Two sheets of the surface near one grid vertex (a polyhedron's corner there) cannot become
    // one vertex, but each sheet's own slivers can: the parts of the cluster that the mesh's edges
    // join, each merged on its own.
    for (const std::vector<std::uint32_t>& part : joined_parts(cluster, mesh.cells, first, around, alive))
      if (part.size() >= 2) merge(part);
  }
  if (removed == 0) return 0;
  // Drop the dead triangles and the vertices no triangle uses any more (the merged ones, and any a
  // cancelled fold left alone), keeping the order of the rest.
  std::vector<bool> used(n, false);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c)
    if (alive[c])
      for (std::uint32_t u : mesh.cells[c]) used[u] = true;
  std::vector<std::uint32_t> index(n, 0);
  std::uint32_t next = 0;
  std::size_t unused_before = 0;
  for (std::uint32_t i = 0; i < n; ++i) unused_before += static_cast<std::size_t>(first[i] == first[i + 1]);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!used[i]) continue;
    index[i] = next;
    mesh.vertices[next] = mesh.vertices[i];
    mesh.normals[next] = mesh.normals[i];
    ++next;
  }
  mesh.vertices.resize(next);
  mesh.normals.resize(next);
  std::size_t out = 0;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    if (!alive[c]) continue;
    for (std::uint32_t& u : mesh.cells[c]) u = index[u];
    mesh.cells[out++] = mesh.cells[c];
  }
  mesh.cells.resize(out);
  const Shape after = shape_of(mesh);
  const bool kept_shape = after.topology.boundary == before.topology.boundary &&
                          after.topology.non_manifold <= before.topology.non_manifold &&
                          after.topology.misoriented <= before.topology.misoriented &&
                          after.euler + static_cast<long>(unused_before) == before.euler;
  if (!kept_shape) {
    mesh = std::move(original);
    return 0;
  }
  return n - mesh.vertices.size();
}

}  // namespace amls
