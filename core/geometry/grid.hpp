#pragma once
// The regular Cartesian grid of spacing h (paper, section 3.1). It hashes points
// to cells, H(p) = floor((p - origin) / h), and names vertices by packed 64-bit
// keys so that every map over vertices is sparse: memory follows the surface,
// never the grid's volume.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/math/vec.hpp"

namespace amls {

template <int D>
class Grid {
 public:
  // Bits per axis in a packed key: 32 in 2D, 21 in 3D.
  static constexpr int kKeyBits = 64 / D;
  // Largest |index| a key can hold on each axis.
  static constexpr std::int64_t kMaxIndex = (std::int64_t{1} << (kKeyBits - 1)) - 1;

  Grid(const Vec<D>& origin, double spacing) : origin_(origin), spacing_(spacing) {
    if (!(spacing > 0.0) || !std::isfinite(spacing))
      throw std::invalid_argument("grid spacing must be a positive finite number, got " + std::to_string(spacing));
    if (!origin.allFinite()) throw std::invalid_argument("grid origin must be finite");
  }

  // The grid of `cells` cells per axis over the unit square or cube: h = 1/cells.
  static Grid unit(int cells) {
    if (cells < 1) throw std::invalid_argument("--grid must be at least 1, got " + std::to_string(cells));
    return Grid(Vec<D>::Zero(), 1.0 / cells);
  }

  const Vec<D>& origin() const { return origin_; }
  double spacing() const { return spacing_; }

  // H(p): the cell whose lowest vertex is the returned index.
  IVec<D> cell_of(const Vec<D>& p) const {
    IVec<D> c;
    for (int a = 0; a < D; ++a) c[a] = static_cast<std::int64_t>(std::floor((p[a] - origin_[a]) / spacing_));
    return c;
  }

  Vec<D> vertex_position(const IVec<D>& v) const { return origin_ + spacing_ * v.template cast<double>(); }

  // Whether every vertex index of p's neighbourhood (a few cells around it) fits in a key.
  bool contains_with_margin(const Vec<D>& p, std::int64_t margin) const {
    for (int a = 0; a < D; ++a) {
      const double c = std::floor((p[a] - origin_[a]) / spacing_);
      if (!(std::abs(c) + static_cast<double>(margin) < static_cast<double>(kMaxIndex))) return false;
    }
    return true;
  }

  static std::uint64_t key(const IVec<D>& v) {
    std::uint64_t k = 0;
    for (int a = 0; a < D; ++a) {
      const auto biased = static_cast<std::uint64_t>(v[a] + kMaxIndex + 1);
      k |= biased << (a * kKeyBits);
    }
    return k;
  }

  static IVec<D> unkey(std::uint64_t k) {
    constexpr std::uint64_t mask = kKeyBits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << kKeyBits) - 1;
    IVec<D> v;
    for (int a = 0; a < D; ++a)
      v[a] = static_cast<std::int64_t>((k >> (a * kKeyBits)) & mask) - kMaxIndex - 1;
    return v;
  }

 private:
  Vec<D> origin_;
  double spacing_;
};

// Calls fn(index) for every integer index in the box [lo, hi] (inclusive),
// axis 0 fastest: left to right, then bottom to top (then front to back).
template <int D, typename Fn>
void for_each_index_in_box(const IVec<D>& lo, const IVec<D>& hi, Fn&& fn) {
  for (int a = 0; a < D; ++a)
    if (hi[a] < lo[a]) return;
  IVec<D> c = lo;
  while (true) {
    fn(static_cast<const IVec<D>&>(c));
    int a = 0;
    for (; a < D; ++a) {
      if (++c[a] <= hi[a]) break;
      c[a] = lo[a];
    }
    if (a == D) return;
  }
}

// Corner v of the unit cube: bit a of v is the offset along axis a.
template <int D>
IVec<D> corner_offset(int v) {
  IVec<D> offset;
  for (int a = 0; a < D; ++a) offset[a] = (v >> a) & 1;
  return offset;
}

}  // namespace amls
