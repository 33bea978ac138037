#include "app/editor/point_recycler.hpp"

namespace amls::editor {

template <int D>
std::shared_ptr<const PreparedPoints> PointRecycler::prepare(const PointSet<D>& points, double spacing,
                                                             ThreadPool& pool) {
  std::unique_ptr<PreparedPoints> out;
  {
    std::lock_guard lock(spares_->mutex);
    if (!spares_->free.empty()) {
      out = std::move(spares_->free.back());
      spares_->free.pop_back();
    }
  }
  // Memory more than twice what is needed (after a smaller shape was loaded) goes back.
  if (!out || out->positions.capacity() > 2 * points.size()) out = std::make_unique<PreparedPoints>();
  prepare_points<D>(points, spacing, &pool, *out);
  return std::shared_ptr<const PreparedPoints>(out.release(), [spares = spares_](PreparedPoints* done) {
    std::unique_ptr<PreparedPoints> owned(done);
    std::lock_guard lock(spares->mutex);
    if (spares->free.size() < kKept) spares->free.push_back(std::move(owned));
  });
}

template std::shared_ptr<const PreparedPoints> PointRecycler::prepare<2>(const PointSet<2>&, double, ThreadPool&);
template std::shared_ptr<const PreparedPoints> PointRecycler::prepare<3>(const PointSet<3>&, double, ThreadPool&);

}  // namespace amls::editor
