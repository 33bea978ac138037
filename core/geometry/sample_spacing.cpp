#include "core/geometry/sample_spacing.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/geometry/kd_tree.hpp"

namespace amls {

double median_of(std::vector<double> values) {
  auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

template <int D>
std::vector<double> kth_neighbour_distances(const std::vector<Vec<D>>& positions, int k) {
  if (k < 1) throw std::invalid_argument("the neighbour rank must be at least 1, got " + std::to_string(k));
  const std::size_t n = positions.size();
  const auto rank = static_cast<std::size_t>(k);
  if (n <= rank)
    throw std::invalid_argument("measuring the spacing needs more than " + std::to_string(k) + " points, got " +
                                std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    if (!positions[i].allFinite())
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
  KdTree<D> tree;
  tree.build(positions);
  std::vector<double> out(n);
  std::vector<std::uint32_t> ids;
  std::vector<double> squared;
  for (std::size_t i = 0; i < n; ++i) {
    // The point itself is among its k + 1 nearest, at distance 0 (as is any duplicate).
    tree.nearest(positions[i], rank + 1, ids, squared);
    out[i] = std::sqrt(squared.back());
  }
  return out;
}

std::string SampleSpacing::explanation() const {
  std::ostringstream out;
  out << "the median distance from each of the " << points << " points to its " << kSpacingNeighbours
      << "th nearest neighbour (" << kth_median << ") / " << kSpacingNeighbourDivisor
      << "; median nearest-neighbour distance " << nearest_median;
  return out.str();
}

template <int D>
SampleSpacing sample_spacing(const std::vector<Vec<D>>& positions) {
  SampleSpacing s;
  s.points = positions.size();
  s.nearest_median = median_of(kth_neighbour_distances<D>(positions, 1));
  s.kth_median = median_of(kth_neighbour_distances<D>(positions, kSpacingNeighbours));
  if (!(s.kth_median > 0.0))
    throw std::invalid_argument("most of the " + std::to_string(positions.size()) +
                                " points coincide with others, so they have no spacing to choose h from");
  s.h = s.kth_median / kSpacingNeighbourDivisor;
  return s;
}

template std::vector<double> kth_neighbour_distances<2>(const std::vector<Vec<2>>&, int);
template std::vector<double> kth_neighbour_distances<3>(const std::vector<Vec<3>>&, int);
template SampleSpacing sample_spacing<2>(const std::vector<Vec<2>>&);
template SampleSpacing sample_spacing<3>(const std::vector<Vec<3>>&);

}  // namespace amls
