#include "core/geometry/kd_tree.hpp"

#include <nanoflann.hpp>

namespace amls {

namespace {

// nanoflann's view of our points.
template <int D>
struct Cloud {
  std::vector<Vec<D>> positions;

  std::size_t kdtree_get_point_count() const { return positions.size(); }
  double kdtree_get_pt(std::uint32_t id, std::size_t axis) const { return positions[id][static_cast<Eigen::Index>(axis)]; }
  template <typename Box>
  bool kdtree_get_bbox(Box&) const {
    return false;  // let the tree compute it
  }
};

// A radius query's results appended to a caller's vector, without the
// (id, distance) pairs and the sort of nanoflann's RadiusResultSet.
struct AppendIds {
  double radius2;
  std::vector<std::uint32_t>* out;

  std::size_t size() const { return out->size(); }
  bool full() const { return true; }
  bool addPoint(double, std::uint32_t id) {  // nanoflann only passes distances below worstDist()
    out->push_back(id);
    return true;
  }
  double worstDist() const { return radius2; }
};

// Leaves of this many points: nanoflann's default, a good trade between depth
// and leaf scans for radius queries holding tens of points.
constexpr std::size_t kLeafSize = 10;

}  // namespace

template <int D>
struct KdTree<D>::Impl {
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud<D>, double, std::uint32_t>,
                                                   Cloud<D>, D, std::uint32_t>;
  Cloud<D> cloud;
  Tree tree{D, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize)};
};

template <int D>
KdTree<D>::KdTree() : impl_(std::make_unique<Impl>()) {}
template <int D>
KdTree<D>::~KdTree() = default;
template <int D>
KdTree<D>::KdTree(KdTree&&) noexcept = default;
template <int D>
KdTree<D>& KdTree<D>::operator=(KdTree&&) noexcept = default;

template <int D>
void KdTree<D>::build(std::span<const Vec<D>> positions) {
  impl_->cloud.positions.assign(positions.begin(), positions.end());
  impl_->tree.buildIndex();
}

template <int D>
std::size_t KdTree<D>::size() const {
  return impl_->cloud.positions.size();
}

template <int D>
void KdTree<D>::gather(const Vec<D>& x, double radius, std::vector<std::uint32_t>& out) const {
  if (impl_->cloud.positions.empty()) return;
  AppendIds results{radius * radius, &out};
  impl_->tree.findNeighbors(results, x.data(), nanoflann::SearchParams());
}

template <int D>
void KdTree<D>::nearest(const Vec<D>& x, std::size_t count, std::vector<std::uint32_t>& ids,
                        std::vector<double>& squared) const {
  ids.resize(count);
  squared.resize(count);
  const std::size_t found = impl_->tree.knnSearch(x.data(), count, ids.data(), squared.data());
  ids.resize(found);
  squared.resize(found);
}

template class KdTree<2>;
template class KdTree<3>;

}  // namespace amls
