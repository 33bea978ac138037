#include "core/io/point_set_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <stdexcept>
#include <system_error>

#include "core/io/file_format.hpp"
#include "core/io/point_set_repair.hpp"
#include "core/io/raw_point_file.hpp"
#include "core/util/file_error.hpp"

namespace amls {

namespace {

namespace fs = std::filesystem;
using detail::fail;
using detail::RawPointFile;
using detail::shortest;

// The first point (if any) that does not lie in the plane z = 0 with its normal in it.
std::optional<std::size_t> first_off_plane(const PointSet<3>& points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points.positions[i].z() != 0.0 || (i < points.normals.size() && points.normals[i].z() != 0.0)) return i;
  return std::nullopt;
}

int decide_dimension(RawPointFile& raw, int dimension_override) {
  const std::optional<std::size_t> off_plane = first_off_plane(raw.points);
  const int dimension = dimension_override != 0 ? dimension_override : raw.declared_dimension;
  if (dimension == 2 && off_plane) {
    const std::size_t i = *off_plane;
    const std::string why =
        dimension_override != 0 ? "the dimension is forced to 2 (--dim 2)" : "the file says it holds a 2D set";
    fail(raw.path, raw.where(i) + ": z = " + shortest(raw.points.positions[i].z()) + ", nz = " +
                       shortest(raw.points.normals[i].z()) + ", but " + why + ", which needs z = 0 and nz = 0");
  }
  if (dimension != 0) return dimension;
  if (raw.points.empty() || off_plane) return 3;
  raw.warnings.push_back(raw.path + ": every z" + (raw.has_normals ? " and nz" : "") +
                         " is 0, so the set is read as 2D (force the dimension with --dim 3 to keep it 3D)");
  return 2;
}

void check_writable(const PointSet<3>& points, const std::string& path, bool& with_normals) {
  auto bad = [&](const std::string& what) { throw std::invalid_argument("cannot write " + path + ": " + what); };
  if (!points.normals.empty() && points.normals.size() != points.size())
    bad(std::to_string(points.size()) + " positions but " + std::to_string(points.normals.size()) + " normals");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points.positions[i].allFinite()) bad("point " + std::to_string(i) + " has a non-finite coordinate");
  std::size_t zero = 0, first_zero = 0;
  for (std::size_t i = 0; i < points.normals.size(); ++i) {
    if (!points.normals[i].allFinite()) bad("point " + std::to_string(i) + " has a non-finite normal");
    if (points.normals[i].isZero(0.0) && zero++ == 0) first_zero = i;
  }
  with_normals = zero < points.normals.size();
  if (with_normals && zero > 0) bad("point " + std::to_string(first_zero) + " has a zero normal while others have one");
}

// Writes through a temporary file in the target's directory, renamed over the
// target once complete: a failure leaves the old file (or no file) behind.
template <typename WriteBody>
void write_atomically(const std::string& path, WriteBody&& write_body) {
  const fs::path target(path);
  const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::random_device entropy;
  fs::path temporary;
  std::FILE* file = nullptr;
  int error = 0;
  for (int attempt = 0; attempt < 16 && !file; ++attempt) {
    std::string name = target.filename().string();
    name.insert(0, 1, '.');  // hidden while incomplete
    temporary = directory / (name + ".tmp" + std::to_string(entropy()));
    errno = 0;
    file = std::fopen(temporary.c_str(), "wbx");  // x: never reuse a file that is already there
    error = errno;
    if (!file && error != EEXIST) break;
  }
  if (!file)
    throw FileError(path + ": cannot create a temporary file in " + directory.string() + ": " + std::strerror(error),
                    error);
  try {
    detail::FileSink sink(file, path);
    write_body(sink);
    sink.flush();
    const int closed = std::fclose(file);
    file = nullptr;
    if (closed != 0) {
      const int close_error = errno;
      throw FileError(path + ": write failed: " + std::strerror(close_error), close_error);
    }
    std::error_code rename_error;
    fs::rename(temporary, target, rename_error);
    if (rename_error)
      throw FileError(path + ": cannot replace the file: " + rename_error.message(), rename_error.value());
  } catch (...) {
    if (file) std::fclose(file);
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

void write_3d(const std::string& path, const PointSet<3>& points, int dimension, PointFileFormat format,
              double spacing) {
  bool with_normals = false;
  check_writable(points, path, with_normals);
  if (!std::isfinite(spacing) || spacing < 0.0)
    throw std::invalid_argument("cannot write " + path + ": the spacing to record is " + shortest(spacing));
  write_atomically(path, [&](detail::FileSink& sink) {
    if (format == PointFileFormat::xyz) {
      detail::write_xyz(sink, points, dimension, with_normals, spacing);
    } else {
      detail::write_ply(sink, points, dimension, with_normals, spacing, format);
    }
  });
}

}  // namespace

const char* to_string(PointFileFormat format) {
  switch (format) {
    case PointFileFormat::ply_ascii:
      return "ply_ascii";
    case PointFileFormat::ply_binary_little_endian:
      return "ply_binary_little_endian";
    case PointFileFormat::ply_binary_big_endian:
      return "ply_binary_big_endian";
    case PointFileFormat::xyz:
      return "xyz";
  }
  return "?";
}

PointFileFormat format_from_extension(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".ply") return PointFileFormat::ply_binary_little_endian;
  if (extension == ".xyz") return PointFileFormat::xyz;
  if (extension.empty()) throw std::invalid_argument(path + ": no file extension (expected .ply or .xyz)");
  throw std::invalid_argument(path + ": unknown point-set file extension '" + extension + "' (expected .ply or .xyz)");
}

LoadedPointSet read_point_set(const std::string& path, int dimension_override) {
  if (dimension_override != 0 && dimension_override != 2 && dimension_override != 3)
    throw std::invalid_argument("dimension must be 2 or 3 (or 0 to read it from the file), got " +
                                std::to_string(dimension_override));
  reject_directory(path, "point-set file");
  const std::optional<ShapeFileFormat> format = shape_file_format(path);
  if (!is_point_set_file(path)) {
    const std::string extension = lower_extension(path);
    throw std::invalid_argument(path + ": " +
                                (extension.empty() ? std::string("no file extension")
                                 : format ? "a " + extension + " file holds a triangle mesh, not a point set"
                                          : "unknown point-set file extension '" + extension + "'") +
                                " (expected " + kPointSetFileExtensions + ")");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_cannot_open(path, "cannot open");
  std::error_code error;
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) fail(path, "cannot tell its size: " + error.message());
  if (size == 0) fail(path, "the file is empty");
  RawPointFile raw = *format == ShapeFileFormat::xyz   ? detail::read_xyz(in, path)
                     : *format == ShapeFileFormat::off ? detail::read_off(in, size, path)
                                                       : detail::read_ply(in, size, path);
  std::vector<std::uint8_t> unusable_normals = detail::prepare_points(raw);
  LoadedPointSet loaded;
  loaded.dimension = decide_dimension(raw, dimension_override);
  detail::repair_points(raw, loaded.dimension, std::move(unusable_normals));
  loaded.has_normals = raw.has_normals;
  loaded.spacing = raw.declared_spacing;
  loaded.points = std::move(raw.points);
  if (!loaded.has_normals) std::fill(loaded.points.normals.begin(), loaded.points.normals.end(), Vec<3>::Zero());
  loaded.warnings = std::move(raw.warnings);
  return loaded;
}

PointSet<2> to_2d(const PointSet<3>& points) {
  if (const std::optional<std::size_t> i = first_off_plane(points))
    throw std::invalid_argument("point " + std::to_string(*i) +
                                " is not a 2D point: z = " + shortest(points.positions[*i].z()) +
                                (*i < points.normals.size() ? ", nz = " + shortest(points.normals[*i].z()) : ""));
  PointSet<2> out;
  out.positions.reserve(points.size());
  for (const Vec<3>& p : points.positions) out.positions.emplace_back(p.x(), p.y());
  out.normals.reserve(points.normals.size());
  for (const Vec<3>& n : points.normals) out.normals.emplace_back(n.x(), n.y());
  out.rim = points.rim;
  return out;
}

PointSet<3> to_3d(const PointSet<2>& points) {
  PointSet<3> out;
  out.positions.reserve(points.size());
  for (const Vec<2>& p : points.positions) out.positions.emplace_back(p.x(), p.y(), 0.0);
  out.normals.reserve(points.normals.size());
  for (const Vec<2>& n : points.normals) out.normals.emplace_back(n.x(), n.y(), 0.0);
  out.rim = points.rim;
  return out;
}

void write_point_set(const std::string& path, const PointSet<2>& points, PointFileFormat format, double spacing) {
  write_3d(path, to_3d(points), 2, format, spacing);
}

void write_point_set(const std::string& path, const PointSet<3>& points, PointFileFormat format, double spacing) {
  write_3d(path, points, 3, format, spacing);
}

void write_text_file(const std::string& path, const std::string& text) {
  write_atomically(path, [&](detail::FileSink& sink) { sink.write(text); });
}

namespace detail {

void write_through_temporary(const std::string& path, const std::function<void(FileSink&)>& write_body) {
  write_atomically(path, write_body);
}

}  // namespace detail

}  // namespace amls
