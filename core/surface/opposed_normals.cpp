#include "core/surface/opposed_normals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/geometry/point_index.hpp"

namespace amls {

namespace {

template <int D>
bool is_opposed(std::size_t i, const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                const PointIndex<D>& index, double radius) {
  static const double beside = std::sin(OpposedNormals::kBesideDegrees * std::numbers::pi / 180.0);
  static const double against_cos = std::cos(OpposedNormals::kAgainstDegrees * std::numbers::pi / 180.0);
  const Vec<D>& p = positions[i];
  const Vec<D>& n = normals[i];
  int voters = 0, against = 0;
  index.for_each_within(p, radius, [&](std::uint32_t j, const Vec<D>& q) {
    if (j == i) return;
    const Vec<D> offset = q - p;
    if (std::abs(offset.dot(n)) > beside * offset.norm()) return;
    ++voters;
    if (normals[j].dot(n) < against_cos) ++against;
  });
  return voters >= OpposedNormals::kFewestBeside && against >= OpposedNormals::kOpposedShare * voters;
}

}  // namespace

template <int D>
OpposedNormals turn_opposed_normals(const std::vector<Vec<D>>& positions, std::vector<Vec<D>>& normals, double radius,
                                    ThreadPool& pool) {
  OpposedNormals out;
  if (positions.empty()) return out;
  PointIndex<D> index;
  index.build(positions, positions.front(), radius, pool);
  const std::size_t n = positions.size();
  std::vector<std::uint8_t> ever_turned(n, 0), to_test(n, 1), opposed(n, 0);
  for (int round = 0; round < OpposedNormals::kMostRounds; ++round) {
    // Every point tests the normals as the round found them: the same turns
    // for any thread count.
    pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t i = begin; i < end; ++i)
        opposed[i] = to_test[i] && is_opposed<D>(i, positions, normals, index, radius);
    });
    std::fill(to_test.begin(), to_test.end(), std::uint8_t{0});
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!opposed[i]) continue;
      any = true;
      normals[i] = -normals[i];
      ever_turned[i] ^= 1;
      index.for_each_within(positions[i], radius, [&](std::uint32_t j, const Vec<D>&) { to_test[j] = 1; });
    }
    if (!any) break;
    ++out.rounds;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (ever_turned[i]) out.turned.push_back(i);
  return out;
}

template OpposedNormals turn_opposed_normals<2>(const std::vector<Vec<2>>&, std::vector<Vec<2>>&, double, ThreadPool&);
template OpposedNormals turn_opposed_normals<3>(const std::vector<Vec<3>>&, std::vector<Vec<3>>&, double, ThreadPool&);

}  // namespace amls
