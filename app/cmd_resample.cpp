// amls resample: one resampling of a point set with oriented normals.
#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/io/surface_samples.hpp"

namespace amls::app {

namespace {

struct ResampleOptions {
  PointSetResampling resampling;
  std::string input;
  std::string output;
  std::string variant = "exact";
  int dimension = 0;
};

template <int D>
void resample_and_write(const PointSet<D>& input, const ResampleOptions& options, PointFileFormat format) {
  const ResampledPointSet<D> result = resample_point_set(input, options.resampling);
  if (result.points.empty())
    throw std::runtime_error(
        "resampling produced no points: the surface has no crossing with the grid near the "
        "points (is the input too sparse for h = " +
        std::to_string(result.grid.spacing()) + " and --radius-factor " +
        std::to_string(options.resampling.radius_factor) + "?)");
  write_point_set(options.output, result.points, format);
  std::cout << "resample (" << D << "D, " << to_string(options.resampling.variant) << "): " << input.size()
            << " points in -> " << result.points.size() << " points out, h = " << result.grid.spacing()
            << ", nearest-neighbour spacing min/median/max = " << result.spacing_h.min << " / "
            << result.spacing_h.median << " / " << result.spacing_h.max << " h, wrote " << options.output << "\n";
}

}  // namespace

void add_resample_command(CLI::App& app) {
  auto options = std::make_shared<ResampleOptions>();
  CLI::App* cmd = app.add_subcommand(
      "resample",
      "resample a surface once on a grid (unit square/cube, or the input's padded bounding box when it lies "
      "outside) and write the new points. Input: a point set with normals (.ply, .xyz; 2D or 3D), one without "
      "(normals estimated by the Pratt fit and oriented over a neighbour graph), or a triangle mesh (.obj, .ply "
      "with faces; sampled at h with face normals)");
  cmd->add_option("input", options->input, "point set or mesh to read (.ply, .xyz or .obj)")->required();
  cmd->add_option("--out", options->output, "file to write (.ply: binary little endian, .xyz)")->required();
  CLI::Option* grid = cmd->add_option("--grid", options->resampling.grid, "cells per unit length: h = 1/N")
                          ->check(in_range(ranges::kGridCells))
                          ->capture_default_str();
  cmd->add_option("--spacing", options->resampling.spacing, "grid spacing h (instead of --grid)")
      ->check(in_range(ranges::kSpacing))
      ->excludes(grid);
  cmd->add_option("--dim", options->dimension, "read the input as 2D or 3D (default: from the file)")
      ->check(CLI::IsMember({2, 3}));
  add_radius_factor_option(*cmd, options->resampling.radius_factor);
  add_variant_option(*cmd, options->variant);
  add_threads_option(*cmd, options->resampling.threads);
  cmd->callback([options] {
    options->resampling.variant = parse_variant(options->variant);
    // Check the output's extension before any work is done.
    const PointFileFormat format = format_from_extension(options->output);
    // Meshes are sampled at h, and normals are estimated over Delta where the file has none.
    const double h = options->resampling.spacing > 0.0 ? options->resampling.spacing : 1.0 / options->resampling.grid;
    SurfaceSampleOptions sampling;
    sampling.spacing = h;
    sampling.normal_radius = options->resampling.radius_factor * h;
    sampling.dimension = options->dimension;
    sampling.threads = options->resampling.threads;
    SurfaceSamples loaded = load_surface_samples(options->input, sampling);
    for (const std::string& warning : loaded.warnings) std::cerr << "amls: warning: " << warning << "\n";
    std::cout << options->input << ": " << loaded.source << "\n";
    if (loaded.dimension == 2) {
      resample_and_write(to_2d(loaded.points), *options, format);
    } else {
      resample_and_write(loaded.points, *options, format);
    }
  });
}

}  // namespace amls::app
