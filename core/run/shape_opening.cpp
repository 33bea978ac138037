#include "core/run/shape_opening.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/geometry/sample_spacing.hpp"
#include "core/geometry/surface_scatter.hpp"
#include "core/io/mesh_inside.hpp"
#include "core/io/point_set_io.hpp"

namespace amls {

namespace {

// x rounded to `digits` significant digits.
double round_significant(double x, int digits) {
  const double scale = std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(x))));
  return std::round(x * scale) / scale;
}

// A mesh's h is at most its bounding box's longest side over this many cells.
// Its vertices' rule measures the vertices, and a coarse polyhedron's few
// vertices lie a side apart: CGAL's cube.off got h = 1.41 on a side of 2, a
// grid of one or two cells that rounds the shape away (volumes off by tens
// of percent, and an inside known from the input mesh that no grid vertex
// samples). Its faces are sampled at h whatever h is, so a finer h costs only
// samples: a cube at 32 cells has some 6,000.
constexpr double kMinMeshCells = 32.0;
// A closed mesh whose faces, not its vertices, carry its shape (sampled at
// h it would give more than kFewVerticesRatio samples a vertex: a polyhedron
// or a CAD part of large flat faces; a scanned or modelled mesh gives 3 to 8)
// also gets h at most its mean thickness (core/io/mesh_inside.hpp) over
// kMinThicknessCells. The MLS surface rounds a sharp edge off at the scale of
// h, so a thin part a few h thick loses its volume there: CGAL's beam.off
// (0.4 x 0.4 x 3.6) lost 12 % at h = 0.11, 2.3 % at 0.05 and 0.4 % at its
// thickness / 16 (0.018). A cube's thickness / 16 is its side / 32, where
// the first bound already is; a smooth mesh keeps its volume at a few cells
// per thickness (the elephant's 11), so its vertices' h stands.
constexpr double kFewVerticesRatio = 8.0;
constexpr double kMinThicknessCells = 16.0;

// h at most the mesh's thickness bound above, where it applies.
SpacingChoice bound_by_thickness(const TriangleMesh& mesh, const SpacingChoice& choice) {
  const MeshMeasures measures = measure_mesh(mesh);
  const double samples = measures.area / (choice.h * choice.h);
  const double bound = measures.mean_thickness / kMinThicknessCells;
  if (!(bound > 0.0) || choice.h <= bound || samples <= kFewVerticesRatio * static_cast<double>(mesh.vertices.size()) ||
      !closed_and_consistently_wound(mesh))
    return choice;
  std::ostringstream reason;
  reason << "the mesh's mean thickness 3V/A (" << measures.mean_thickness << ") / " << kMinThicknessCells
         << ", finer than h = " << choice.h << " from " << choice.reason;
  return {bound, reason.str()};
}

// A noisy point set's h is at least this many times its scatter across the
// surface (core/geometry/surface_scatter.hpp). Where a raw scan's noise is
// wider than the spacing of its points, h from the spacing resolves the
// noise: the fits within Delta see a slab thicker than they are wide, and F
// has zeros between the noisy points. CGAL's sphere_20k.xyz (radii scattered
// by 0.041, h from its neighbours 0.021) gave a mesh of 47,728 boundary edges,
// at h = 0.1 still 50, at 0.12 and 0.16 a closed one (volume -0.48 % and
// -0.75 % of the unit sphere's); its scatter measures 0.034, so 4 times it
// is 0.135. A clean scan is not noisy (its thickness, not its scatter, says
// so), and its h stands.
constexpr double kMinScatterCells = 4.0;

// h at least the noise bound above, where the points are noisy.
template <int D>
SpacingChoice bound_by_scatter(const std::vector<Vec<D>>& positions, const SpacingChoice& choice) {
  const SurfaceScatter measured = surface_scatter<D>(positions);
  if (!measured.noisy() || kMinScatterCells * measured.scatter <= choice.h) return choice;
  std::ostringstream reason;
  reason << kMinScatterCells << " x the points' scatter across the surface (" << measured.scatter
         << ", the RMS residual of quadric fits to " << SurfaceScatter::kScatterNeighbours
         << " neighbours), coarser than h = " << choice.h << " from " << choice.reason
         << ": the points scatter by more than they lie apart (thickness " << measured.thickness
         << "), and that h would resolve the noise, not the surface";
  return {kMinScatterCells * measured.scatter, reason.str()};
}

// h for the file as read, and the cost of a resampling at it.
template <int D>
SpacingChoice spacing_for(const SurfaceInput& input, const PointSetResampling& given) {
  const std::vector<Vec<D>> positions = from_3d<D>(input.positions());
  PointSetResampling options = given;
  options.recorded_spacing = input.recorded_spacing();
  const bool by_rule = given.spacing <= 0.0 && given.grid <= 0;
  // A mesh of a few vertices (a tetrahedron, a quad) has too few to measure a spacing on, but its faces
  // say how large it is: h from the bound below alone.
  const bool few_vertices = input.is_mesh && positions.size() <= static_cast<std::size_t>(kSpacingNeighbours);
  const double longest = input.is_mesh && by_rule ? longest_side(positions) : 0.0;
  SpacingChoice choice;
  if (by_rule && few_vertices) {
    if (!(longest > 0.0))
      throw std::invalid_argument(input.path + ": cannot choose h: the mesh's " + std::to_string(positions.size()) +
                                  " vertices all lie at one position");
    std::ostringstream reason;
    reason << "the mesh's longest side (" << longest << ") / " << kMinMeshCells << ": its " << positions.size()
           << " vertices are too few to measure a spacing on";
    choice = {longest / kMinMeshCells, reason.str()};
  } else {
    try {
      choice = choose_spacing(positions, options);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(input.path + ": cannot choose h: " + e.what() + "; give --spacing or --grid");
    }
  }
  if (input.is_mesh && by_rule) {
    if (choice.h > longest / kMinMeshCells) {
      std::ostringstream reason;
      reason << "the mesh's longest side (" << longest << ") / " << kMinMeshCells << ", finer than h = " << choice.h
             << " from " << choice.reason;
      choice = {longest / kMinMeshCells, reason.str()};
    }
    choice = bound_by_thickness(input.mesh, choice);
  }
  // A spacing the file records is the one its points were made at (amls's own output), kept as it is.
  if (!input.is_mesh && by_rule && options.recorded_spacing <= 0.0) choice = bound_by_scatter(positions, choice);
  if (positions.size() > static_cast<std::size_t>(kSpacingNeighbours)) {
    try {
      check_resampling_cost(D, sampled_extent(positions), choice.h, options);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(input.path + ": " + e.what());
    }
  }
  return choice;
}

}  // namespace

OpenedShape open_shape_file(const std::string& path, const ShapeOpening& options, ThreadPool& pool) {
  pool.poll_cancel();
  if (options.step) options.step("reading the file", 0, kShapeOpeningSteps);
  return open_shape(read_surface_input(path, options.dimension), options, pool);
}

OpenedShape open_shape(SurfaceInput input, const ShapeOpening& options, ThreadPool& pool) {
  auto step = [&](const char* name, int index) {
    pool.poll_cancel();
    if (options.step) options.step(name, index, kShapeOpeningSteps);
  };
  OpenedShape out;
  out.file_points = input.positions().size();
  out.dimension = input.dimension();
  step("choosing h", 1);
  out.spacing =
      out.dimension == 2 ? spacing_for<2>(input, options.resampling) : spacing_for<3>(input, options.resampling);
  if (options.spacing_digits > 0) out.spacing.h = round_significant(out.spacing.h, options.spacing_digits);
  const bool estimating = !input.is_mesh && (options.estimate_normals || !input.point_set.has_normals);
  step(input.is_mesh ? "sampling the mesh" : estimating ? "estimating normals" : "checking the normals", 2);
  SurfaceSampleOptions sampling;
  sampling.spacing = out.spacing.h;
  sampling.normal_radius = options.resampling.radius_factor * out.spacing.h;
  sampling.dimension = out.dimension;
  sampling.estimate_normals = options.estimate_normals;
  SurfaceSamples samples = surface_samples(std::move(input), sampling, pool);
  out.points = std::move(samples.points);
  out.source = std::move(samples.source);
  out.warnings = std::move(samples.warnings);
  out.closed_mesh = std::move(samples.closed_mesh);
  return out;
}

}  // namespace amls
