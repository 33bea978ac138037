#include "core/geometry/coverage.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/geometry/kd_tree.hpp"
#include "core/geometry/sample_spacing.hpp"

namespace amls {

double Coverage::input_fraction() const {
  return input_points == 0 ? 1.0 : static_cast<double>(input_covered) / static_cast<double>(input_points);
}

double Coverage::output_fraction() const {
  return output_points == 0 ? 1.0 : static_cast<double>(output_on_input) / static_cast<double>(output_points);
}

double Coverage::gap_fraction() const {
  return output_points == 0 ? 0.0 : static_cast<double>(output_in_gaps) / static_cast<double>(output_points);
}

bool Coverage::clear_loss() const {
  return input_fraction() < kLeastInputCovered || output_fraction() < kLeastOutputOnInput ||
         gap_fraction() > kMostOutputInGaps;
}

namespace {

std::string percent(double fraction) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  out << 100.0 * fraction << " %";
  return out.str();
}

}  // namespace

std::string Coverage::summary() const {
  return percent(input_fraction()) + " of the " + std::to_string(input_points) + " input points covered, " +
         percent(output_fraction()) + " of the " + std::to_string(output_points) + " output points on the input, " +
         percent(gap_fraction()) + " in gaps";
}

std::string Coverage::loss_message() const {
  std::ostringstream out;
  if (input_fraction() < kLeastInputCovered) {
    out << "the output misses part of the input: " << input_points - input_covered << " of " << input_points
        << " input points (" << percent(1.0 - input_fraction()) << ", more than " << percent(1.0 - kLeastInputCovered)
        << ") have no output point within " << kCoverageReach << " x their local spacing; the largest hole is near ("
        << worst_uncovered[0] << ", " << worst_uncovered[1] << ", " << worst_uncovered[2] << ")";
  }
  if (output_fraction() < kLeastOutputOnInput) {
    if (out.tellp() > 0) out << "; ";
    out << output_points - output_on_input << " of " << output_points << " output points ("
        << percent(1.0 - output_fraction()) << ", more than " << percent(1.0 - kLeastOutputOnInput)
        << ") lie off the input, on a surface that is not there";
  }
  if (gap_fraction() > kMostOutputInGaps) {
    if (out.tellp() > 0) out << "; ";
    out << "the output is torn: " << output_in_gaps << " of " << output_points << " output points ("
        << percent(gap_fraction()) << ", more than " << percent(kMostOutputInGaps)
        << ") lie at the rim of a gap, with no output neighbours around them within " << kGapReach << " h";
  }
  return out.str();
}

template <int D>
Coverage measure_coverage(const std::vector<Vec<D>>& input, const std::vector<Vec<D>>& output, double h) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw std::invalid_argument("coverage: h must be a positive number, got " + std::to_string(h));
  std::vector<double> local = kth_neighbour_distances<D>(input, kSpacingNeighbours);
  for (double& s : local) s = std::max(h, s / kSpacingNeighbourDivisor);

  Coverage c;
  c.input_points = input.size();
  c.output_points = output.size();
  std::vector<std::uint32_t> ids;
  std::vector<double> squared;
  if (!output.empty()) {
    KdTree<D> output_tree;
    output_tree.build(output);
    double worst = 0.0;
    for (std::size_t i = 0; i < input.size(); ++i) {
      output_tree.nearest(input[i], 1, ids, squared);
      const double reach = kCoverageReach * local[i];
      const double distance = std::sqrt(squared.front());
      if (distance <= reach) {
        ++c.input_covered;
      } else if (distance / reach > worst) {
        worst = distance / reach;
        for (int a = 0; a < D; ++a) c.worst_uncovered[static_cast<std::size_t>(a)] = input[i][a];
      }
    }
  } else if (!input.empty()) {
    for (int a = 0; a < D; ++a) c.worst_uncovered[static_cast<std::size_t>(a)] = input.front()[a];
  }

  KdTree<D> input_tree;
  input_tree.build(input);
  for (const Vec<D>& o : output) {
    input_tree.nearest(o, 1, ids, squared);  // the nearest input point decides, with its own reach
    const double reach = kCoverageReach * local[ids.front()];
    if (squared.front() <= reach * reach) ++c.output_on_input;
  }
  return c;
}

template Coverage measure_coverage<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&, double);
template Coverage measure_coverage<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&, double);

}  // namespace amls
