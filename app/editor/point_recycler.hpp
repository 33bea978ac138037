#pragma once
// Where the editor's worker makes the points of its snapshots ready to draw:
// in the memory of earlier ones the snapshots have let go. A drag on a million
// points makes a new set every step, and new arrays would each be fresh pages
// the kernel maps and zeroes, costing more than filling them. Points return
// here when the last snapshot holding them goes, on whichever thread that is
// (the UI's, mostly); they outlive the recycler if they must. No GL.
#include <memory>
#include <mutex>
#include <vector>

#include "core/util/thread_pool.hpp"
#include "render/point_data.hpp"

namespace amls::editor {

class PointRecycler {
 public:
  // prepare_points on `pool`, into the memory of points let go where there are some.
  template <int D>
  std::shared_ptr<const PreparedPoints> prepare(const PointSet<D>& points, double spacing, ThreadPool& pool);

 private:
  struct Spares {
    std::mutex mutex;
    std::vector<std::unique_ptr<PreparedPoints>> free;
  };
  // Two spares cover a drag: the worker fills one while the UI shows another.
  static constexpr std::size_t kKept = 2;

  std::shared_ptr<Spares> spares_ = std::make_shared<Spares>();
};

}  // namespace amls::editor
