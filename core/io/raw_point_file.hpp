#pragma once
// Internal to the point-set file code (point_set_io.cpp, ply_format.cpp,
// xyz_format.cpp): what a format's reader hands back before the dimension is
// decided and the normals are checked, the byte sink the writers fill, and the
// text helpers both formats share.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <istream>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/io/point_set_io.hpp"

namespace amls::detail {

// Column or property names and the coordinate they hold: 0-2 the position, 3-5 the
// normal. PLY properties and text-column headers use the same names.
int coordinate_slot(std::string_view name);

struct RawPointFile {
  std::string path;
  PointSet<3> points;  // normals all zero when has_normals is false
  bool has_normals = false;
  // From an `amls dim N` comment (or, in XYZ, 2 or 4 columns); 0 if the file does not say.
  int declared_dimension = 0;
  // From an `amls spacing H` comment; 0 if the file does not say.
  double declared_spacing = 0.0;
  // For text formats, the line each point came from, so that messages can name it.
  std::vector<std::size_t> lines;
  // For binary files once points were dropped or merged, each point's vertex
  // index in the file (empty while they are all there, in order).
  std::vector<std::size_t> vertices;
  std::vector<std::string> warnings;
  // PLY: the face element's polygons, fan-triangulated (indices checked against the vertex count).
  bool has_faces = false;
  std::uint64_t faces = 0;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::string face_problem;  // the first face that could not be used (skipped), if any

  // "line 12" or "vertex 5": where point i stands in the file.
  std::string where(std::size_t i) const;
};

// One face's vertex indices, fan-triangulated into raw.triangles and counted
// in raw.faces. A face that cannot be used is skipped, and the first such is
// noted in raw.face_problem as "`where` `number`: what is wrong": only a mesh
// reader needs the faces, so only it fails on them.
void add_face(RawPointFile& raw, const std::vector<double>& indices, std::uint64_t vertex_count, std::string_view where,
              std::uint64_t number);

// Throws std::runtime_error("path: what").
[[noreturn]] void fail(const std::string& path, const std::string& what);

// Reads up to and including the next '\n' and drops a final '\r'. Returns false
// at the end of the file when nothing was read. Throws if the line is longer
// than `max_length` (so that a binary file read as text cannot fill memory).
bool read_line(std::istream& in, std::string& line, std::size_t max_length, const std::string& path,
               std::size_t line_number);

// Drops a UTF-8 byte order mark from the start of a file's first line, as
// some Windows programs write one.
void drop_byte_order_mark(std::string& first_line);

// 'text', in quotes, for messages.
std::string quoted(std::string_view text);

// Splits on spaces and tabs; the views point into `text`.
void split_words(std::string_view text, std::vector<std::string_view>& words);

// The whole word as a number, or nothing. A leading '+' is accepted; "nan" and
// "inf" are numbers here (the caller rejects them with a better message).
std::optional<double> parse_double(std::string_view word);
std::optional<std::int64_t> parse_integer(std::string_view word);

// What a file's `amls` comments declare: `amls dim N` (N = 2 or 3) and
// `amls spacing H` (the grid spacing h its points were made at, H > 0).
struct AmlsComments {
  int dimension = 0;     // 0: not declared
  double spacing = 0.0;  // 0: not declared
  // Notes one comment, given its words after `comment` or `#`; any other
  // comment is ignored. Throws naming the line for a malformed `amls dim` or
  // `amls spacing` comment, or one that contradicts an earlier one.
  void note(std::span<const std::string_view> words, const std::string& path, std::size_t line_number);
};

// Appends the shortest decimal that reads back as exactly `value`.
void append_double(std::string& out, double value);
// The same, as a string.
std::string shortest(double value);

// Buffered output to a file that throws, naming `path`, when a write fails.
class FileSink {
 public:
  FileSink(std::FILE* file, std::string path) : file_(file), path_(std::move(path)) {}
  void write(std::string_view bytes);
  void flush();

 private:
  std::FILE* file_;
  std::string path_;
  std::string buffer_;
};

// Writes a file as write_point_set does: `write_body` fills a sink on a
// temporary file in the target's folder, which is renamed over `path` once complete.
void write_through_temporary(const std::string& path, const std::function<void(FileSink&)>& write_body);

// Read the rest of `in` (whose first `file_size` bytes are the file).
RawPointFile read_ply(std::istream& in, std::uint64_t file_size, const std::string& path);
RawPointFile read_xyz(std::istream& in, const std::string& path);
RawPointFile read_off(std::istream& in, std::uint64_t file_size, const std::string& path);

// The face count a file's header declares (0 without faces), reading the header only.
std::uint64_t ply_face_count(std::istream& in, const std::string& path);
std::uint64_t off_face_count(std::istream& in, std::uint64_t file_size, const std::string& path);

// `points` holds a 2D set as z = 0; `with_normals` says whether to write
// normals; `spacing` > 0 is written as an `amls spacing` comment.
void write_ply(FileSink& out, const PointSet<3>& points, int dimension, bool with_normals, double spacing,
               PointFileFormat format);
void write_xyz(FileSink& out, const PointSet<3>& points, int dimension, bool with_normals, double spacing);

// The `amls` comments a written file starts with, without the comment marker:
// {"amls dim 3", "amls spacing 0.01"}.
std::vector<std::string> amls_comment_lines(int dimension, double spacing);

}  // namespace amls::detail
