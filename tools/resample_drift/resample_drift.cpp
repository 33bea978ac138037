// Diagnostic for the Enright volume drift: how much one resample moves S(P).
//
//   resample_drift torus GRID MINOR_RADIUS_IN_H RESAMPLES
//     resamples a torus (major radius 0.2) again and again with no deformation
//     and prints the volume of S(P) after each resample;
//   resample_drift enright GRID EVERY
//     runs the Enright test (default options) and, every EVERY steps, prints the
//     volume of S(P) just before and just after that step's resample.
//
// Volumes are measured on S(P) itself, not by rays from the sphere's centre (the
// shape is not star-shaped mid-run): F's zeros along every z grid line near the
// points, located by bisection, V = h^2 sum (z_exit - z_entry).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/run/deforming_surface.hpp"
#include "core/deform/flow_deformation.hpp"
#include "core/geometry/shapes.hpp"
#include "core/deform/velocity_field.hpp"

using namespace amls;

namespace {

// The zero of F on the z edge from `base` (F = f0 there) to base + h e_z.
double edge_root(const AmlsSurface<3>& s, const Vec<3>& base, double f0) {
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    Vec<3> y = base;
    y[2] += mid * s.grid().spacing();
    const Evaluation<3> e = s.evaluate(y);
    if (!e.defined) break;
    ((e.value >= 0.0) == (f0 >= 0.0) ? lo : hi) = mid;
  }
  return base[2] + 0.5 * (lo + hi) * s.grid().spacing();
}

// Volume inside F < 0; `bad_columns` counts z lines whose crossings do not alternate.
double enclosed_volume(const AmlsSurface<3>& s, long& bad_columns) {
  const Grid<3>& g = s.grid();
  std::unordered_set<std::uint64_t> keys;
  for (const Vec<3>& p : s.points().positions) {
    const IVec<3> c = g.cell_of(p);
    for_each_index_in_box<3>(IVec<3>(c.array() - 3), IVec<3>(c.array() + 4),
                             [&](const IVec<3>& v) { keys.insert(Grid<3>::key(v)); });
  }
  std::unordered_map<std::uint64_t, Evaluation<3>> value;
  for (const std::uint64_t k : keys) value.emplace(k, s.evaluate(g.vertex_position(Grid<3>::unkey(k))));
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::pair<double, int>>> columns;
  for (const auto& [k, e0] : value) {
    IVec<3> v = Grid<3>::unkey(k);
    IVec<3> up = v;
    ++up[2];
    const auto it = value.find(Grid<3>::key(up));
    if (!e0.defined || it == value.end() || !it->second.defined) continue;
    if ((e0.value >= 0.0) == (it->second.value >= 0.0)) continue;
    columns[{v[0], v[1]}].push_back({edge_root(s, g.vertex_position(v), e0.value), e0.value < 0.0 ? +1 : -1});
  }
  double volume = 0.0;
  bad_columns = 0;
  for (auto& [column, crossings] : columns) {
    std::sort(crossings.begin(), crossings.end());
    bool alternates = crossings.size() % 2 == 0;
    for (std::size_t i = 0; i < crossings.size(); ++i) {
      alternates = alternates && crossings[i].second == (i % 2 == 0 ? -1 : +1);
      volume += crossings[i].second * crossings[i].first;
    }
    bad_columns += alternates ? 0 : 1;
  }
  return volume * g.spacing() * g.spacing();
}

double volume_now(DeformingSurface<3>& loop, long& bad) {
  loop.refresh_normals();
  return enclosed_volume(loop.surface(), bad);
}

int torus(int grid_cells, double minor_in_h, int resamples) {
  const Grid<3> grid = Grid<3>::unit(grid_cells);
  const double h = grid.spacing();
  DeformingSurface<3> loop(grid, AmlsParameters{}, Variant::exact, 2);
  loop.set_points(sample_torus(Vec<3>(0.5, 0.5, 0.5), 0.2, minor_in_h * h, 0.5 * h));
  long bad = 0;
  const double v0 = volume_now(loop, bad);
  std::printf("torus minor radius %.2f h: V(S(P0)) = %.6g (exact torus %.6g)\n", minor_in_h, v0,
              2.0 * std::numbers::pi * std::numbers::pi * 0.2 * minor_in_h * minor_in_h * h * h);
  for (int k = 1; k <= resamples; ++k) {
    loop.resample_only();
    const double v = volume_now(loop, bad);
    std::printf("resample %3d: V / V0 - 1 = %+.4f %% (%+.5f %% per resample), %zu points, %ld bad columns\n", k,
                100.0 * (v / v0 - 1.0), 100.0 * (v / v0 - 1.0) / k, loop.points().size(), bad);
  }
  return 0;
}

int enright(int grid_cells, int every) {
  const Grid<3> grid = Grid<3>::unit(grid_cells);
  const double h = grid.spacing(), radius = 0.15;
  const double v_exact = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  DeformingSurface<3> loop(grid, AmlsParameters{}, Variant::exact, 2);
  // As core/run/flow_test.cpp: the sphere sampled at spacing h / 2.
  const double area = 4.0 * std::numbers::pi * radius * radius;
  loop.set_points(sample_sphere(Vec<3>(0.35, 0.35, 0.35), radius,
                                static_cast<std::size_t>(std::ceil(area / (0.25 * h * h)))));
  const FlowDeformation<3> flow(std::make_shared<EnrightField>(3.0), 1);
  loop.resample_only();
  long bad_before = 0, bad_after = 0;
  for (int k = 0; k < 300; ++k) {
    const double t0 = 3.0 * k / 300.0, t1 = 3.0 * (k + 1) / 300.0;
    if (k % every != 0) {
      loop.step(flow, t0, t1, true);
      continue;
    }
    const double before = volume_now(loop, bad_before);
    const std::size_t points_before = loop.points().size();
    loop.resample_only();
    const double after = volume_now(loop, bad_after);
    std::printf("step %3d t %.2f: V(S(P)) / V0 - 1 = %+.4f %% before the resample, %+.4f %% after (%+.4f %%), "
                "points %zu -> %zu, bad columns %ld / %ld\n",
                k, t0, 100.0 * (before / v_exact - 1.0), 100.0 * (after / v_exact - 1.0),
                100.0 * (after - before) / v_exact, points_before, loop.points().size(), bad_before, bad_after);
    std::fflush(stdout);
    loop.step(flow, t0, t1, false);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && !std::strcmp(argv[1], "torus")) return torus(std::atoi(argv[2]), std::atof(argv[3]), std::atoi(argv[4]));
  if (argc == 4 && !std::strcmp(argv[1], "enright")) return enright(std::atoi(argv[2]), std::atoi(argv[3]));
  std::fprintf(stderr, "usage: %s torus GRID MINOR_RADIUS_IN_H RESAMPLES | enright GRID EVERY\n", argv[0]);
  return 2;
}
