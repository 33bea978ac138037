#include "core/io/mesh_orientation.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <limits>
#include <utility>
#include <vector>

namespace amls {

namespace {

// One triangle's use of an edge: the edge (its ends in increasing order, as one key), the
// triangle, and whether the triangle runs through it from the lower end to the higher.
struct EdgeUse {
  std::uint64_t edge;
  std::uint32_t triangle;
  std::uint8_t side;  // which of the triangle's three edges
  bool ascending;
};

std::vector<EdgeUse> sorted_edge_uses(const TriangleMesh& mesh) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[t][static_cast<std::size_t>(k)];
      const std::uint32_t b = mesh.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
      if (a == b) continue;  // a degenerate triangle's collapsed edge joins nothing
      const auto [lo, hi] = std::minmax(a, b);
      uses.push_back({std::uint64_t{lo} << 32 | hi, t, static_cast<std::uint8_t>(k), a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.triangle < y.triangle;
  });
  return uses;
}

}  // namespace

MeshOrientation orient_consistently(TriangleMesh& mesh) {
  MeshOrientation out;
  const std::vector<EdgeUse> uses = sorted_edge_uses(mesh);
  // Per triangle edge (3 t + side), the neighbour across it where exactly two triangles share
  // it, and whether the two run through the edge alike (then one of them must turn for them to agree).
  struct Link {
    std::uint32_t other;
    bool alike;
  };
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<Link> links(3 * mesh.triangles.size(), Link{kNone, false});
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].edge == uses[i].edge) ++j;
    if (j - i == 2 && uses[i].triangle != uses[i + 1].triangle) {
      const bool alike = uses[i].ascending == uses[i + 1].ascending;
      links[3 * std::size_t{uses[i].triangle} + uses[i].side] = {uses[i + 1].triangle, alike};
      links[3 * std::size_t{uses[i + 1].triangle} + uses[i + 1].side] = {uses[i].triangle, alike};
    }
    i = j;
  }
  std::vector<std::uint8_t> seen(mesh.triangles.size(), 0), turn(mesh.triangles.size(), 0);
  std::vector<std::uint32_t> part;
  std::deque<std::uint32_t> queue;
  for (std::uint32_t seed = 0; seed < mesh.triangles.size(); ++seed) {
    if (seen[seed]) continue;
    part.clear();
    seen[seed] = 1;
    queue.push_back(seed);
    while (!queue.empty()) {
      const std::uint32_t t = queue.front();
      queue.pop_front();
      part.push_back(t);
      for (std::size_t side = 0; side < 3; ++side) {
        const Link& link = links[3 * std::size_t{t} + side];
        if (link.other == kNone) continue;
        const std::uint8_t wanted = static_cast<std::uint8_t>(turn[t] ^ (link.alike ? 1 : 0));
        if (!seen[link.other]) {
          seen[link.other] = 1;
          turn[link.other] = wanted;
          queue.push_back(link.other);
        } else if (turn[link.other] != wanted && t < link.other) {
          ++out.conflicts;  // counted once per edge
        }
      }
    }
    std::size_t turned = 0;
    for (const std::uint32_t t : part) turned += turn[t];
    if (2 * turned > part.size())
      for (const std::uint32_t t : part) turn[t] ^= 1;
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (turn[t]) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++out.turned;
    }
  return out;
}

}  // namespace amls
