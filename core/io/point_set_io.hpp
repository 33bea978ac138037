#pragma once
// Point-set files, read and written in 2D and 3D. Read: PLY (ASCII, binary
// little and big endian), OFF, and text columns (.xyz, .pwn, .csv, .txt);
// written: PLY and XYZ. The extension picks the format (core/io/file_format.hpp).
//
// Reading
// - PLY: the `vertex` element's `x y z` and, if present, `nx ny nz` or
//   `normal_x normal_y normal_z`, of any PLY scalar type. Other properties
//   (colours, scalars, lists) and other elements (faces, even `element face 0`,
//   edges, materials) are read past and ignored. In ASCII, one item per line;
//   blank lines are skipped.
// - OFF: the vertices, with normals from NOFF; faces and colours are read past
//   (core/io/off_format.cpp).
// - Text columns: one point per line, separated by spaces, tabs, commas or
//   semicolons, with an optional header line naming the columns; without one,
//   `x y z` or `x y z nx ny nz`, and for a 2D set `x y` or `x y nx ny`.
//   `#` starts a comment line (core/io/xyz_format.cpp).
// - CRLF line ends are accepted everywhere.
// - The dimension is, in order: `dimension_override` if it is 2 or 3; else the
//   file's `amls dim N` comment (`comment amls dim 2` in PLY, `# amls dim 2` in
//   text) or, in text, columns without z; else 2 if every z (and every nz) is
//   0, with a warning; else 3. A set read as 2D must have z = 0 and nz = 0.
// - The spacing: a comment `amls spacing H` (`comment amls spacing 0.01` in
//   PLY, `# amls spacing 0.01` in text) says the points were made on a grid of
//   spacing H; the rule that chooses h takes it (core/geometry/sample_spacing.hpp).
// - Normals of length 1 within 1e-12 are kept bit for bit (so that round trips
//   are exact); others are normalised (a warning says so when some were off by
//   more than 1e-4, i.e. were not unit normals stored in float).
// - Small defects are repaired, each kind with a warning that counts them and
//   names the first (core/io/point_set_repair.hpp): points with a non-finite
//   coordinate are dropped, points at exactly an earlier point's position are
//   merged into it, and zero or non-finite normals among others are estimated
//   from the neighbours. A file whose normals are all zero (or non-finite) is
//   read as a file without normals, with a warning.
// - Broken files throw std::runtime_error naming the file and the line (text)
//   or the vertex (binary): unparsable numbers, wrong column or value counts,
//   truncation, data after the last element. Header counts are checked against
//   the file's size before anything is allocated.
//
// Writing
// - PLY with `double` properties, XYZ and ASCII PLY with the shortest decimal
//   that reads back as the same double: every round trip is bit-exact.
// - 2D sets are written with z = 0, nz = 0 and an `amls dim 2` comment; 3D sets
//   carry `amls dim 3`, so that a flat 3D set stays 3D when read back.
// - Given the grid spacing h the points were made at, an `amls spacing h`
//   comment records it, so that reading them back chooses the same h.
// - Normals are written unless the set has none (an empty normal array, or all
//   normals zero as read from a file without normals).
// - The file is written to a temporary file in the same directory and renamed
//   over `path`: an export that fails (bad value, full disk, ...) leaves any
//   previous file intact and no partial file behind. There is no fsync, so this
//   protects against failures of the process, not of the machine.
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"

namespace amls {

enum class PointFileFormat { ply_ascii, ply_binary_little_endian, ply_binary_big_endian, xyz };

const char* to_string(PointFileFormat format);

// For writing: `.ply` -> binary little endian (the compact, exact choice),
// `.xyz` -> xyz; the extension's case does not matter. Throws
// std::invalid_argument otherwise.
PointFileFormat format_from_extension(const std::string& path);

// A point set as read from a file. Both dimensions are held in 3D: a 2D set
// has z = 0 and nz = 0 (to_2d() drops them).
struct LoadedPointSet {
  int dimension = 3;
  PointSet<3> points;
  // false: the file had no normals (or only zero ones) and every normal is zero.
  bool has_normals = false;
  // The grid spacing the file says its points were made at (`amls spacing`); 0 if it does not say.
  double spacing = 0.0;
  // Things the caller should tell the user (each names the file).
  std::vector<std::string> warnings;
};

// dimension_override: 0 decides from the file, 2 or 3 forces the dimension.
// The format is chosen by the extension (any PLY encoding is read from `.ply`);
// others, `.obj` included, throw std::invalid_argument.
LoadedPointSet read_point_set(const std::string& path, int dimension_override = 0);

// Throws std::invalid_argument naming the first point with z != 0 or nz != 0.
PointSet<2> to_2d(const PointSet<3>& points);
PointSet<3> to_3d(const PointSet<2>& points);

// A set held in 3D as a set of dimension D: to_2d() for D = 2, itself for D = 3.
template <int D>
PointSet<D> from_3d(PointSet<3> points) {
  if constexpr (D == 2) {
    return to_2d(points);
  } else {
    return points;
  }
}

// The first D coordinates of each vector (handles and the like, held in 3D).
template <int D>
std::vector<Vec<D>> from_3d(const std::vector<Vec<3>>& vectors) {
  std::vector<Vec<D>> out;
  out.reserve(vectors.size());
  for (const Vec<3>& v : vectors) out.push_back(v.template head<D>());
  return out;
}

// `spacing` > 0: the grid spacing h the points were made at, recorded as
// `amls spacing h`. Throws std::invalid_argument for non-finite values, a
// normal array of another size than the positions, a zero normal among
// non-zero ones, or a non-finite spacing; and std::runtime_error naming
// `path` when the file cannot be written.
void write_point_set(const std::string& path, const PointSet<2>& points, PointFileFormat format,
                     double spacing = 0.0);
void write_point_set(const std::string& path, const PointSet<3>& points, PointFileFormat format,
                     double spacing = 0.0);

// Writes `text` to `path` the same way: through a temporary file renamed over it.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace amls
