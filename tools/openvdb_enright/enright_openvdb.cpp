// The 3D Enright test with OpenVDB's narrow-band level set: the baseline that
// `amls enright` is compared against (docs/openvdb-baseline.md). Built on its own by
// build_and_run.sh (g++ -O3 against Debian's libopenvdb-dev); not part of the
// project's CMake build.
//
// Unit cube, voxel size h = 1/N; a sphere of radius 0.15 centred at
// (0.35, 0.35, 0.35) as a narrow-band signed-distance level set
// (tools::createLevelSetSphere), advected from t = 0 to t = T = 3 in Enright's
// field
//   u =  2 sin^2(pi x) sin(2 pi y) sin(2 pi z) cos(pi t / T)
//   v =   -sin(2 pi x) sin^2(pi y) sin(2 pi z) cos(pi t / T)
//   w =   -sin(2 pi x) sin(2 pi y) sin^2(pi z) cos(pi t / T)
// by tools::LevelSetAdvection (HJWENO5_BIAS in space, TVD_RK3 in time, CFL
// sub-steps chosen by OpenVDB), after which the shape should be the sphere
// again. Reports wall times, the volume at t = 0 and t = T
// (tools::levelSetVolume), the volume loss and the symmetric difference with
// the exact sphere measured on a sub-voxel lattice.

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetAdvect.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <tbb/global_control.h>

#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kPeriod = 3.0;
constexpr double kRadius = 0.15;
const openvdb::Vec3d kCenter(0.35, 0.35, 0.35);

// Enright's time-dependent field, in world units, for LevelSetAdvection.
// LevelSetAdvection asks its field for VectorType, transform(), and
// operator()(position, time) in two forms: a world-space point (used when the
// field's transform differs from the grid's, as here: the field reports the
// identity transform, the grid has voxel size 1/N) and an index-space Coord
// (used when the transforms are equal). It samples the field once per CFL
// step, at the step's start time.
class EnrightVelocity {
 public:
  using ValueType = float;
  using VectorType = openvdb::math::Vec3<float>;

  openvdb::math::Transform transform() const { return transform_; }

  VectorType operator()(const openvdb::Vec3d& xyz, ValueType time) const {
    const double g = std::cos(kPi * static_cast<double>(time) / kPeriod);
    const double sx = std::sin(kPi * xyz[0]), sy = std::sin(kPi * xyz[1]), sz = std::sin(kPi * xyz[2]);
    const double s2x = std::sin(2 * kPi * xyz[0]), s2y = std::sin(2 * kPi * xyz[1]), s2z = std::sin(2 * kPi * xyz[2]);
    return VectorType(static_cast<float>(g * 2 * sx * sx * s2y * s2z), static_cast<float>(-g * s2x * sy * sy * s2z),
                      static_cast<float>(-g * s2x * s2y * sz * sz));
  }

  VectorType operator()(const openvdb::Coord& ijk, ValueType time) const {
    return (*this)(transform_.indexToWorld(ijk), time);
  }

 private:
  openvdb::math::Transform transform_;  // identity: world = index for this field
};

struct Options {
  int grid = 128;
  int threads = 0;  // 0: TBB's default (all cores)
  double half_width = 3.0;
  int sub = 4;
  std::string json;
};

void usage(std::FILE* out) {
  std::fprintf(out,
               "usage: enright_openvdb [--grid N] [--threads K] [--half-width W] [--sub S] [--json PATH]\n"
               "\n"
               "3D Enright test with OpenVDB's narrow-band level set (HJWENO5_BIAS, TVD_RK3).\n"
               "  --grid N        voxels per unit length, h = 1/N (default 128)\n"
               "  --threads K     TBB threads (tbb::global_control max_allowed_parallelism; default: all)\n"
               "  --half-width W  narrow-band half-width in voxels (default 3)\n"
               "  --sub S         lattice samples per voxel per axis for the symmetric difference (default 4)\n"
               "  --json PATH     write the figures as JSON\n"
               "  --help          this text\n");
}

bool parse_int(const char* text, int& out) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < 1 || value > 1 << 20) return false;
  out = static_cast<int>(value);
  return true;
}

bool parse_double(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0' && out > 0.0;
}

// Returns 0 to go on, 1 for --help, 2 on a bad command line.
int parse(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") return 1;
    if (i + 1 >= argc) {
      std::fprintf(stderr, "enright_openvdb: %s needs a value (or unknown option)\n", arg.c_str());
      return 2;
    }
    const char* value = argv[++i];
    bool ok = true;
    if (arg == "--grid") ok = parse_int(value, options.grid);
    else if (arg == "--threads") ok = parse_int(value, options.threads);
    else if (arg == "--half-width") ok = parse_double(value, options.half_width);
    else if (arg == "--sub") ok = parse_int(value, options.sub);
    else if (arg == "--json") options.json = value;
    else {
      std::fprintf(stderr, "enright_openvdb: unknown option %s\n", arg.c_str());
      return 2;
    }
    if (!ok) {
      std::fprintf(stderr, "enright_openvdb: bad value '%s' for %s\n", value, arg.c_str());
      return 2;
    }
  }
  return 0;
}

// Inside/outside of the level set against the exact sphere on a lattice of
// S^3 points per voxel (cell centres of the sub-voxels), over the index box
// that holds the level set's active voxels and the exact sphere. The level set
// is read by trilinear interpolation (tools::BoxSampler); the background
// value outside the narrow band carries the right sign, and the inside of a
// narrow-band level set cannot reach past its active voxels.
struct LatticeMeasure {
  double volume = 0.0;                // the level set's inside, world units
  double symmetric_difference = 0.0;  // |inside(level set) xor inside(sphere)|, world units
  long long samples = 0;
};

LatticeMeasure lattice_measure(const openvdb::FloatGrid& grid, int sub) {
  using openvdb::Coord;
  const double h = grid.voxelSize()[0];
  openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
  const Coord sphere_lo(static_cast<int>(std::floor((kCenter[0] - kRadius) / h)) - 1,
                        static_cast<int>(std::floor((kCenter[1] - kRadius) / h)) - 1,
                        static_cast<int>(std::floor((kCenter[2] - kRadius) / h)) - 1);
  const Coord sphere_hi(static_cast<int>(std::ceil((kCenter[0] + kRadius) / h)) + 1,
                        static_cast<int>(std::ceil((kCenter[1] + kRadius) / h)) + 1,
                        static_cast<int>(std::ceil((kCenter[2] + kRadius) / h)) + 1);
  if (box.empty()) box = openvdb::CoordBBox(sphere_lo, sphere_hi);
  box.expand(openvdb::CoordBBox(sphere_lo, sphere_hi));

  openvdb::FloatGrid::ConstAccessor accessor = grid.getConstAccessor();
  const double step = 1.0 / sub;
  long long inside = 0, differ = 0, samples = 0;
  const Coord lo = box.min(), hi = box.max();
  for (int i = lo.x(); i <= hi.x(); ++i)
    for (int a = 0; a < sub; ++a) {
      const double x = i + (a + 0.5) * step;
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int b = 0; b < sub; ++b) {
          const double y = j + (b + 0.5) * step;
          for (int k = lo.z(); k <= hi.z(); ++k)
            for (int c = 0; c < sub; ++c) {
              const double z = k + (c + 0.5) * step;
              float phi = 0.0f;
              openvdb::tools::BoxSampler::sample(accessor, openvdb::Vec3d(x, y, z), phi);
              const bool in_set = phi < 0.0f;
              const openvdb::Vec3d world(x * h, y * h, z * h);
              const bool in_sphere = (world - kCenter).length() < kRadius;
              inside += in_set;
              differ += in_set != in_sphere;
              ++samples;
            }
        }
    }
  const double cell = std::pow(h * step, 3);
  LatticeMeasure out;
  out.volume = static_cast<double>(inside) * cell;
  out.symmetric_difference = static_cast<double>(differ) * cell;
  out.samples = samples;
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// User + system CPU seconds of this process, all threads.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The 1-minute load average (-1 when unavailable): the machine is shared, so
// every run records how busy it was.
double load_average() {
  double load[1] = {-1.0};
  return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  switch (parse(argc, argv, options)) {
    case 1: usage(stdout); return 0;
    case 2: usage(stderr); return 2;
    default: break;
  }

  // Kept alive for the whole run: caps every TBB parallel region, OpenVDB's included.
  std::unique_ptr<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                         static_cast<std::size_t>(options.threads));
  const int threads =
      static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));

  const double load_before = load_average();
  const auto start = std::chrono::steady_clock::now();
  openvdb::initialize();
  const float h = 1.0f / static_cast<float>(options.grid);
  openvdb::FloatGrid::Ptr grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
      static_cast<float>(kRadius), openvdb::Vec3f(kCenter), h, static_cast<float>(options.half_width));
  const double setup_time = seconds_since(start);
  const double volume_initial = openvdb::tools::levelSetVolume(*grid);
  const openvdb::FloatGrid::Ptr initial = grid->deepCopy();
  const std::size_t voxels_initial = grid->activeVoxelCount();

  const auto advect_start = std::chrono::steady_clock::now();
  const double advect_cpu_start = cpu_seconds();
  EnrightVelocity field;
  openvdb::tools::LevelSetAdvection<openvdb::FloatGrid, EnrightVelocity> advection(*grid, field);
  advection.setSpatialScheme(openvdb::math::HJWENO5_BIAS);
  advection.setTemporalScheme(openvdb::math::TVD_RK3);
  // The tracker (narrow-band rebuild after every CFL step) keeps OpenVDB's
  // defaults: HJWENO5_BIAS, TVD_RK1, normalisation count = half-width 3.
  const std::size_t cfl_steps = advection.advect(0.0f, static_cast<float>(kPeriod));
  const double advect_time = seconds_since(advect_start);
  const double advect_cpu = cpu_seconds() - advect_cpu_start;
  const double load_after = load_average();

  // levelSetVolume throws on a grid with no active voxels: then the shape is gone.
  const double volume_final = grid->activeVoxelCount() == 0 ? 0.0 : openvdb::tools::levelSetVolume(*grid);
  const double total_time = seconds_since(start);

  const auto lattice_start = std::chrono::steady_clock::now();
  const LatticeMeasure lattice_initial = lattice_measure(*initial, options.sub);
  const LatticeMeasure lattice_final = lattice_measure(*grid, options.sub);
  const double lattice_time = seconds_since(lattice_start);

  const double volume_exact = 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;
  const double volume_loss = (volume_initial - volume_final) / volume_initial;
  const double volume_loss_exact = (volume_exact - volume_final) / volume_exact;
  const double lattice_loss = (lattice_initial.volume - lattice_final.volume) / lattice_initial.volume;
  const double symdiff = lattice_final.symmetric_difference / volume_exact;
  const double symdiff_initial = lattice_initial.symmetric_difference / volume_exact;

  std::printf("OpenVDB %s Enright test: grid %d^3 (h = 1/%d), narrow band half-width %g voxels, %d thread(s)\n",
              openvdb::getLibraryVersionString(), options.grid, options.grid, options.half_width, threads);
  std::printf("scheme: HJWENO5_BIAS / TVD_RK3, %zu CFL steps from t = 0 to %g\n", cfl_steps, kPeriod);
  std::printf("active voxels: %zu at t = 0, %zu at t = T\n", voxels_initial,
              static_cast<std::size_t>(grid->activeVoxelCount()));
  std::printf("time: %.3f s advection, %.3f s total (setup %.3f s; lattice measure %.3f s, not in total)\n",
              advect_time, total_time, setup_time, lattice_time);
  std::printf("advection CPU time %.3f s (%.2f cores busy on average); load average %.2f before, %.2f after\n",
              advect_cpu, advect_cpu / advect_time, load_before, load_after);
  std::printf("volume (levelSetVolume): exact %.6e, t = 0 %.6e, t = T %.6e\n", volume_exact, volume_initial,
              volume_final);
  std::printf("volume loss: %.3f %% of V(t=0); %.3f %% of the exact sphere\n", 100 * volume_loss,
              100 * volume_loss_exact);
  std::printf("lattice (%d^3 samples per voxel, %lld samples): volume t = 0 %.6e, t = T %.6e, loss %.3f %%\n",
              options.sub, lattice_final.samples, lattice_initial.volume, lattice_final.volume, 100 * lattice_loss);
  std::printf("symmetric difference with the exact sphere: %.3f %% of its volume at t = T (%.3f %% at t = 0)\n",
              100 * symdiff, 100 * symdiff_initial);

  if (!options.json.empty()) {
    std::FILE* out = std::fopen(options.json.c_str(), "w");
    if (!out) {
      std::fprintf(stderr, "enright_openvdb: cannot write %s: %s\n", options.json.c_str(), std::strerror(errno));
      return 1;
    }
    std::fprintf(out,
                 "{\n"
                 "  \"program\": \"enright_openvdb\",\n"
                 "  \"openvdb_version\": \"%s\",\n"
                 "  \"grid\": %d,\n"
                 "  \"threads\": %d,\n"
                 "  \"half_width_voxels\": %.17g,\n"
                 "  \"spatial_scheme\": \"HJWENO5_BIAS\",\n"
                 "  \"temporal_scheme\": \"TVD_RK3\",\n"
                 "  \"cfl_steps\": %zu,\n"
                 "  \"time_s\": %.6f,\n"
                 "  \"advect_time_s\": %.6f,\n"
                 "  \"setup_time_s\": %.6f,\n"
                 "  \"advect_cpu_time_s\": %.6f,\n"
                 "  \"load_average_before\": %.2f,\n"
                 "  \"load_average_after\": %.2f,\n"
                 "  \"volume_exact\": %.17g,\n"
                 "  \"volume_initial\": %.17g,\n"
                 "  \"volume_final\": %.17g,\n"
                 "  \"volume_loss\": %.17g,\n"
                 "  \"volume_loss_vs_exact\": %.17g,\n"
                 "  \"lattice_samples_per_voxel\": %d,\n"
                 "  \"lattice_volume_initial\": %.17g,\n"
                 "  \"lattice_volume_final\": %.17g,\n"
                 "  \"lattice_volume_loss\": %.17g,\n"
                 "  \"symmetric_difference\": %.17g,\n"
                 "  \"symmetric_difference_initial\": %.17g,\n"
                 "  \"symmetric_difference_volume\": %.17g\n"
                 "}\n",
                 openvdb::getLibraryVersionString(), options.grid, threads, options.half_width, cfl_steps, total_time,
                 advect_time, setup_time, advect_cpu, load_before, load_after, volume_exact, volume_initial, volume_final, volume_loss, volume_loss_exact,
                 options.sub, lattice_initial.volume, lattice_final.volume, lattice_loss, symdiff, symdiff_initial,
                 lattice_final.symmetric_difference);
    if (std::fclose(out) != 0) {
      std::fprintf(stderr, "enright_openvdb: cannot write %s\n", options.json.c_str());
      return 1;
    }
  }
  return 0;
}
