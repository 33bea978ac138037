#pragma once
// CPU side of a point upload: the checks, the float conversion and the numbers
// (spacing, bounds) computed once per point set, never per frame. No GL here.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "render/camera.hpp"

namespace amls {

class ThreadPool;

// A core position or normal as a float vector for GL; 2D gets z = 0.
template <int D>
glm::vec3 to_vec3(const Vec<D>& v) {
  if constexpr (D == 2)
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f};
  else
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// An allocator whose vectors leave new elements uninitialised: prepare_points sizes its
// arrays, then writes each element once, in parallel. (Zeros first would be one more pass
// over the memory, and the pages would be first touched by one thread.)
template <typename T>
struct UninitializedAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

using FloatPoints = std::vector<glm::vec3, UninitializedAllocator<glm::vec3>>;

struct PreparedPoints {
  int dimension = 3;
  // The drawable points as floats (2D sets get z = 0); normals are unit length.
  FloatPoints positions;
  FloatPoints normals;
  // The input index of each drawable point; empty when every point was drawable.
  std::vector<std::uint32_t> source_index;
  std::size_t input_count = 0;
  std::size_t skipped = 0;  // points with a non-finite position or a non-finite or zero normal
  double spacing = 0.0;     // as given, else estimated (estimate_spacing)
  BoundingSphere bounds;    // of the drawable points, widened by the spacing (a splat's overhang)

  std::size_t size() const { return positions.size(); }
};

// Values per point (sampling quality, say) ready to draw with a prepared point set.
struct PreparedScalars {
  std::vector<float> values;       // one per drawable point, in their order
  std::optional<glm::vec2> range;  // of the finite values; none if none is
};

// Throws std::invalid_argument unless there is one value per input point
// (`input_count`; `source_index` as PreparedPoints::source_index).
PreparedScalars prepare_scalars(std::span<const double> values, std::size_t input_count,
                                std::span<const std::uint32_t> source_index);

// Checks and converts a point set. `spacing` is the sampling spacing (h) if known;
// otherwise it is estimated from the points. Throws std::invalid_argument if positions
// and normals differ in number, the set is too large for 32-bit indices, or `spacing`
// is given but not a positive finite number. Undrawable points are skipped and counted.
// With a pool, the conversion and the bounds run on it (the editor's worker, every
// step of a drag); the result is the same.
template <int D>
PreparedPoints prepare_points(const PointSet<D>& points, std::optional<double> spacing, ThreadPool* pool = nullptr);
// The same into `out`, in the memory of its arrays where they are large enough: a
// caller that prepares point set after point set need not have new pages for each.
template <int D>
void prepare_points(const PointSet<D>& points, std::optional<double> spacing, ThreadPool* pool, PreparedPoints& out);

// The median distance from a point to its nearest neighbour, over an evenly strided
// subset of at most 4096 points (exact for smaller sets). All positions must be finite.
// Returns 0 if there are fewer than two distinct positions.
template <int D>
double estimate_spacing(const std::vector<Vec<D>>& positions);

}  // namespace amls
