// The Enright test as `amls enright --grid N` runs it under `always` (the same
// start, steps and parameters, so the same points), writing the point set
// that each K-th step's resample reads as DIR/fKKK.ply and one line of
// resampler figures per step, so that where the points multiply can be
// looked at frame by frame (sheets.py).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>

#include "core/deform/flow_deformation.hpp"
#include "core/deform/velocity_field.hpp"
#include "core/geometry/shapes.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/deforming_surface.hpp"

using namespace amls;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s GRID EVERY DIR\n", argv[0]);
    return 2;
  }
  const int cells = std::atoi(argv[1]);
  const int every = std::atoi(argv[2]);
  const std::string dir = argv[3];
  if (cells < 8 || every < 1) {
    std::fprintf(stderr, "GRID must be at least 8 and EVERY at least 1\n");
    return 2;
  }
  const Grid<3> grid = Grid<3>::unit(cells);
  const double h = grid.spacing();
  const Vec<3> center(0.35, 0.35, 0.35);
  const double radius = 0.15;
  const double area = 4.0 * std::numbers::pi * radius * radius;
  DeformingSurface<3> surface(grid, AmlsParameters{}, Variant::exact, 2);
  surface.set_points(sample_sphere(center, radius, static_cast<std::size_t>(std::ceil(area / (0.25 * h * h)))));
  surface.resample_only();
  const FlowDeformation<3> flow(std::make_shared<EnrightField>(3.0), 1);
  constexpr int kSteps = 300;
  std::printf("step t points crossings jumps past_sheet_edge rim_samples beyond_rim\n");
  for (int k = 0; k < kSteps; ++k) {
    if (k % every == 0) {
      const std::string name = dir + "/f" + std::string(k < 10 ? "00" : k < 100 ? "0" : "") + std::to_string(k) + ".ply";
      write_point_set(name, surface.points(), PointFileFormat::ply_binary_little_endian);
    }
    // The steps' times as run_flow() computes them: the run is chaotic, so
    // they must be the same to the bit.
    const ResampleStats r = surface.step(flow, 3.0 * k / kSteps, 3.0 * (k + 1) / kSteps).resample;
    std::printf("%d %.2f %zu %zu %zu %zu %zu %zu\n", k + 1, 3.0 * (k + 1) / kSteps, surface.points().size(),
                r.crossings, r.jumps, r.past_sheet_edge, r.rim_samples, r.beyond_rim);
  }
  return 0;
}
