#include "core/geometry/sample_spacing.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
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
  if (rule == SpacingRule::recorded) {
    out << "the spacing the file records ('amls spacing')";
    return out.str();
  }
  const std::string neighbours = "the median distance from each of the " + std::to_string(points) + " points to its " +
                                 std::to_string(kSpacingNeighbours) + "th nearest neighbour";
  if (rule == SpacingRule::grid_lines) {
    out << "the step between the grid lines the points lie on: " << 100.0 * grid_lines.share
        << " % of them have all coordinates but one on the lines' lattice; " << neighbours << ", halved, would give "
        << neighbour_h;
    return out.str();
  }
  out << neighbours << " (" << kth_median << ") / " << kSpacingNeighbourDivisor << "; median nearest-neighbour distance "
      << nearest_median;
  return out.str();
}

namespace {

// x's place between two multiples of `step`, in [0, 1).
double residue(double x, double step) {
  const double r = std::fmod(x, step) / step;
  return r < 0.0 ? r + 1.0 : r;
}

// The residue (in [0, 1)) of the lattice most of `shared` lie on: the densest
// cluster of their residues, within kGridLineTolerance, around the circle.
// (A free coordinate may be shared too, by a symmetry of the shape, but lies off the lattice.)
double lattice_residue(const std::vector<double>& shared, double step) {
  std::vector<double> r;
  r.reserve(shared.size() * 2);
  for (double x : shared) r.push_back(residue(x, step));
  std::sort(r.begin(), r.end());
  const std::size_t m = r.size();
  for (std::size_t i = 0; i < m && r[i] <= 2.0 * kGridLineTolerance; ++i) r.push_back(r[i] + 1.0);
  std::size_t best = 0, begin = 0;
  double at = r.front();
  for (std::size_t end = 0; end < r.size(); ++end) {
    while (r[end] - r[begin] > 2.0 * kGridLineTolerance) ++begin;
    if (end - begin + 1 > best) {
      best = end - begin + 1;
      at = r[begin + (end - begin) / 2];
    }
  }
  return at >= 1.0 ? at - 1.0 : at;
}

}  // namespace

template <int D>
GridLines grid_lines_of(const std::vector<Vec<D>>& positions) {
  GridLines out;
  const std::size_t n = positions.size();
  if (n < 2) return out;
  // Per axis, the values several points share: a grid line's coordinate, computed
  // once per line, is equal bit for bit on all its points.
  std::vector<double> steps;
  std::array<std::vector<double>, D> shared;
  std::vector<double> values(n);
  for (int a = 0; a < D; ++a) {
    for (std::size_t i = 0; i < n; ++i) values[i] = positions[i][a];
    std::sort(values.begin(), values.end());
    for (std::size_t begin = 0, end = 0; begin < n; begin = end) {
      for (end = begin + 1; end < n && values[end] == values[begin];) ++end;
      if (end - begin < 2) continue;
      if (!shared[a].empty()) steps.push_back(values[begin] - shared[a].back());
      shared[a].push_back(values[begin]);
    }
  }
  if (steps.empty()) return out;
  out.step = median_of(std::move(steps));
  if (!(out.step > 0.0)) return out;
  std::array<double, D> lattice{};
  for (int a = 0; a < D; ++a)
    if (!shared[a].empty()) lattice[a] = lattice_residue(shared[a], out.step);
  auto on_lattice = [&](int a, double x) {
    if (shared[a].empty()) return false;
    const double d = std::abs(residue(x, out.step) - lattice[a]);
    return std::min(d, 1.0 - d) <= kGridLineTolerance;
  };
  std::size_t on_lines = 0;
  for (const Vec<D>& p : positions) {
    int axes = 0;
    for (int a = 0; a < D; ++a) axes += on_lattice(a, p[a]) ? 1 : 0;
    on_lines += axes == D - 1 ? 1 : 0;
  }
  out.share = static_cast<double>(on_lines) / static_cast<double>(n);
  return out;
}

template <int D>
SampleSpacing sample_spacing(const std::vector<Vec<D>>& positions, double recorded) {
  SampleSpacing s;
  s.points = positions.size();
  if (recorded != 0.0) {
    if (!(recorded > 0.0) || !std::isfinite(recorded))
      throw std::invalid_argument("the recorded spacing must be a positive number, got " + std::to_string(recorded));
    s.rule = SpacingRule::recorded;
    s.h = recorded;
    return s;
  }
  s.nearest_median = median_of(kth_neighbour_distances<D>(positions, 1));
  s.kth_median = median_of(kth_neighbour_distances<D>(positions, kSpacingNeighbours));
  if (!(s.kth_median > 0.0))
    throw std::invalid_argument("most of the " + std::to_string(positions.size()) +
                                " points coincide with others, so they have no spacing to choose h from");
  s.neighbour_h = s.kth_median / kSpacingNeighbourDivisor;
  s.h = s.neighbour_h;
  s.grid_lines = grid_lines_of<D>(positions);
  const double ratio = s.grid_lines.step / s.neighbour_h;
  if (s.grid_lines.share >= kGridLineShare && ratio >= kGridLineBandLow && ratio <= kGridLineBandHigh) {
    s.rule = SpacingRule::grid_lines;
    s.h = s.grid_lines.step;
  }
  return s;
}

template std::vector<double> kth_neighbour_distances<2>(const std::vector<Vec<2>>&, int);
template std::vector<double> kth_neighbour_distances<3>(const std::vector<Vec<3>>&, int);
template GridLines grid_lines_of<2>(const std::vector<Vec<2>>&);
template GridLines grid_lines_of<3>(const std::vector<Vec<3>>&);
template SampleSpacing sample_spacing<2>(const std::vector<Vec<2>>&, double);
template SampleSpacing sample_spacing<3>(const std::vector<Vec<3>>&, double);

}  // namespace amls
