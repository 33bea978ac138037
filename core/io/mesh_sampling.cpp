#include "core/io/mesh_sampling.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "core/util/parameter_ranges.hpp"

namespace amls {

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

struct EdgeUse {
  Vec<3> normal = Vec<3>::Zero();  // sum of the adjacent faces' area-weighted normals
  int triangles = 0;
};

// Pieces of about `spacing` a length is cut into; a double, so that it may be
// counted before it is known to be small.
double segment_count(double length, double spacing) { return std::max(1.0, std::ceil(length / spacing - 1e-9)); }

std::size_t segments(double length, double spacing) { return static_cast<std::size_t>(segment_count(length, spacing)); }

// The samples sample_mesh makes of the triangles with a nonzero area normal,
// counted without making them: each vertex and edge once, plus each
// triangle's interior lattice, (n - 1)(n - 2) / 2 points for n segments.
double sample_count(const TriangleMesh& mesh, const std::vector<Vec<3>>& area_normals, double spacing) {
  const std::vector<Vec<3>>& v = mesh.vertices;
  double count = static_cast<double>(v.size());  // an upper bound of the vertices used
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (area_normals[f].isZero(0.0)) continue;
    const auto& t = mesh.triangles[f];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double length = (v[t[static_cast<std::size_t>((k + 1) % 3)]] - v[t[static_cast<std::size_t>(k)]]).norm();
      longest = std::max(longest, length);
      count += 0.5 * (segment_count(length, spacing) - 1.0);  // an edge is shared by about two triangles
    }
    const double n = segment_count(longest, spacing);
    count += 0.5 * (n - 1.0) * (n - 2.0);
  }
  return count;
}

}  // namespace

MeshSamples sample_mesh(const TriangleMesh& mesh, double spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("mesh sampling: the spacing must be positive, got " + std::to_string(spacing));
  MeshSamples out;
  const std::vector<Vec<3>>& v = mesh.vertices;
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t)
      if (i >= v.size())
        throw std::invalid_argument("mesh sampling: vertex index " + std::to_string(i) + " is out of range");

  // Twice the area times the unit normal, per triangle; zero for skipped ones.
  std::vector<Vec<3>> area_normals(mesh.triangles.size(), Vec<3>::Zero());
  double extent2 = 0.0;
  if (!v.empty()) {
    Vec<3> lo = v.front(), hi = lo;
    for (const Vec<3>& p : v) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    extent2 = (hi - lo).squaredNorm();
  }
  double volume6 = 0.0;
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  std::vector<Vec<3>> vertex_normals(v.size(), Vec<3>::Zero());
  std::vector<bool> used(v.size(), false);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const Vec<3> n = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(n.norm() > 1e-14 * extent2)) {
      ++out.degenerate_triangles;
      continue;
    }
    area_normals[f] = n;
    volume6 += v[t[0]].dot(v[t[1]].cross(v[t[2]]));
    for (int k = 0; k < 3; ++k) {
      vertex_normals[t[static_cast<std::size_t>(k)]] += n;
      used[t[static_cast<std::size_t>(k)]] = true;
      EdgeUse& e = edges[edge_key(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)])];
      e.normal += n;
      ++e.triangles;
    }
  }
  if (out.degenerate_triangles == mesh.triangles.size())
    throw std::invalid_argument("mesh sampling: the mesh has no triangle of positive area");
  for (const auto& [key, e] : edges) {
    if (e.triangles == 1) ++out.boundary_edges;
    if (e.triangles > 2) ++out.nonmanifold_edges;
  }
  // Bounded before any is made: a mesh with a stray far vertex would otherwise
  // be sampled for hours. Samples grow as 1 / spacing^2.
  const double count = sample_count(mesh, area_normals, spacing);
  if (!ranges::kMeshSamples.contains(count))
    throw std::invalid_argument("mesh sampling: spacing " + format_number(spacing) + " would make about " +
                                format_number(count) + " samples, more than " +
                                format_number(ranges::kMeshSamples.max) + " (the mesh spans " +
                                format_number(std::sqrt(extent2)) + " across); a spacing of " +
                                format_number(spacing * std::sqrt(count / ranges::kMeshSamples.max) * 1.01) +
                                " or more would fit");
  out.flipped = out.boundary_edges == 0 && out.nonmanifold_edges == 0 && volume6 < 0.0;
  const double sign = out.flipped ? -1.0 : 1.0;
  // A mean normal that cancels out (a sheet folded onto itself) falls back to `fallback`.
  auto unit = [&](const Vec<3>& sum, const Vec<3>& fallback) {
    const Vec<3>& n = sum.norm() > 1e-12 * fallback.norm() ? sum : fallback;
    return Vec<3>(sign * n.normalized());
  };

  PointSet<3>& points = out.points;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (area_normals[f].isZero(0.0)) continue;
    const auto& t = mesh.triangles[f];
    const Vec<3>& a = v[t[0]];
    const Vec<3>& b = v[t[1]];
    const Vec<3>& c = v[t[2]];
    const Vec<3> face_normal = sign * area_normals[f].normalized();
    // Vertices: once each, from the first triangle that uses them.
    for (std::uint32_t i : t)
      if (used[i]) {
        points.add(v[i], unit(vertex_normals[i], area_normals[f]));
        used[i] = false;
      }
    // Edges: once each, from the first triangle that has them.
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = t[static_cast<std::size_t>(k)], j = t[static_cast<std::size_t>((k + 1) % 3)];
      const auto it = edges.find(edge_key(i, j));
      if (it == edges.end() || it->second.triangles < 0) continue;
      const std::size_t n = segments((v[j] - v[i]).norm(), spacing);
      const Vec<3> normal = unit(it->second.normal, area_normals[f]);
      for (std::size_t s = 1; s < n; ++s) {
        const double u = static_cast<double>(s) / static_cast<double>(n);
        points.add((1.0 - u) * v[i] + u * v[j], normal);
      }
      it->second.triangles = -1;  // done
    }
    // Interior: the barycentric lattice (i, j, k) / n with every weight >= 1.
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const std::size_t n = segments(longest, spacing);
    for (std::size_t i = 1; i + 2 <= n; ++i)
      for (std::size_t j = 1; i + j + 1 <= n; ++j) {
        const std::size_t k = n - i - j;
        const double dn = static_cast<double>(n);
        points.add((static_cast<double>(i) * a + static_cast<double>(j) * b + static_cast<double>(k) * c) / dn,
                   face_normal);
      }
  }
  return out;
}

}  // namespace amls
