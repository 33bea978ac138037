#include "core/surface/broken_normals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "core/geometry/point_index.hpp"

namespace amls {

namespace {

enum class Mend : std::uint8_t { kNone, kTurn, kReplace };

double cos_degrees(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }

// The normals of the points beside point i: how many, how many point
// against its own, and their sum.
template <int D>
struct Beside {
  int count = 0;
  int against = 0;
  Vec<D> sum = Vec<D>::Zero();
  // Their mean direction, where there are enough of them and they agree.
  std::optional<Vec<D>> agreed_mean() const {
    const double length = sum.norm();
    if (count < BrokenNormals::kFewestBeside || length < BrokenNormals::kAgreeing * count) return std::nullopt;
    return Vec<D>(sum / length);
  }
};

template <int D>
Beside<D> beside_of(std::size_t i, const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                    const PointIndex<D>& index, double radius) {
  static const double beside = std::sin(BrokenNormals::kBesideDegrees * std::numbers::pi / 180.0);
  static const double against = -cos_degrees(BrokenNormals::kBrokenDegrees);
  const Vec<D>& p = positions[i];
  const Vec<D>& n = normals[i];
  Beside<D> out;
  index.for_each_within(p, radius, [&](std::uint32_t j, const Vec<D>& q) {
    if (j == i) return;
    const Vec<D> offset = q - p;
    if (std::abs(offset.dot(n)) > beside * offset.norm()) return;
    ++out.count;
    out.against += normals[j].dot(n) < against ? 1 : 0;
    out.sum += normals[j];
  });
  return out;
}

// What point i's normal needs; `mean` gets the direction to replace it by.
template <int D>
Mend needed(std::size_t i, const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
            const PointIndex<D>& index, double radius, Vec<D>& mean) {
  static const double broken = cos_degrees(BrokenNormals::kBrokenDegrees);
  const Beside<D> beside = beside_of<D>(i, positions, normals, index, radius);
  if (beside.count < BrokenNormals::kFewestBeside) return Mend::kNone;
  if (beside.against >= BrokenNormals::kOpposedShare * beside.count) return Mend::kTurn;
  const std::optional<Vec<D>> agreed = beside.agreed_mean();
  if (!agreed || normals[i].dot(*agreed) >= broken) return Mend::kNone;
  mean = *agreed;
  return Mend::kReplace;
}

}  // namespace

template <int D>
BrokenNormals mend_broken_normals(const std::vector<Vec<D>>& positions, std::vector<Vec<D>>& normals, double radius,
                                  ThreadPool& pool) {
  BrokenNormals out;
  if (positions.empty()) return out;
  PointIndex<D> index;
  index.build(positions, positions.front(), radius, pool);
  const std::size_t n = positions.size();
  std::vector<Mend> mend(n, Mend::kNone), ever(n, Mend::kNone);
  std::vector<Vec<D>> means(n);
  std::vector<std::uint8_t> to_test(n, 1);
  for (int round = 0; round < BrokenNormals::kMostRounds; ++round) {
    // Every point tests the normals as the round found them: the same
    // mending for any thread count.
    pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t i = begin; i < end; ++i)
        mend[i] = to_test[i] ? needed<D>(i, positions, normals, index, radius, means[i]) : Mend::kNone;
    });
    std::fill(to_test.begin(), to_test.end(), std::uint8_t{0});
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (mend[i] == Mend::kNone) continue;
      any = true;
      if (mend[i] == Mend::kTurn) {
        normals[i] = -normals[i];
        // Turned twice is as given; replaced once stays replaced.
        if (ever[i] != Mend::kReplace) ever[i] = ever[i] == Mend::kTurn ? Mend::kNone : Mend::kTurn;
      } else {
        normals[i] = means[i];
        ever[i] = Mend::kReplace;
      }
      index.for_each_within(positions[i], radius, [&](std::uint32_t j, const Vec<D>&) { to_test[j] = 1; });
    }
    if (!any) break;
    ++out.rounds;
  }
  // A replaced normal took the mean over a band across the surface (the
  // points beside a normal that lay across it) and over neighbours that were
  // broken too; now that it and they are mended, the points beside it are
  // the right ones.
  for (std::size_t i = 0; i < n; ++i)
    if (ever[i] == Mend::kReplace)
      means[i] = beside_of<D>(i, positions, normals, index, radius).agreed_mean().value_or(normals[i]);
  for (std::size_t i = 0; i < n; ++i)
    if (ever[i] == Mend::kReplace) normals[i] = means[i];
  for (std::size_t i = 0; i < n; ++i) {
    if (ever[i] == Mend::kTurn) out.turned.push_back(i);
    if (ever[i] == Mend::kReplace) out.replaced.push_back(i);
  }
  return out;
}

template BrokenNormals mend_broken_normals<2>(const std::vector<Vec<2>>&, std::vector<Vec<2>>&, double, ThreadPool&);
template BrokenNormals mend_broken_normals<3>(const std::vector<Vec<3>>&, std::vector<Vec<3>>&, double, ThreadPool&);

}  // namespace amls
