// Text columns, one point per line: XYZ, CGAL's PWN, CSV and plain text.
// - Separators: spaces and tabs, or commas, or semicolons (spaces around them
//   allowed), decided by the first line of numbers: a semicolon makes it
//   semicolons, else a comma commas. One trailing separator is allowed.
// - An optional header line before the numbers names the columns, in any
//   case: x y z, nx ny nz or normal_x normal_y normal_z (a leading `//`, as
//   CloudCompare writes, is dropped); other columns, e.g. colours, are read
//   past. Without z the set is 2D.
// - Without a header, the column count says what they are: x y z or
//   x y z nx ny nz in 3D; x y or x y nx ny for a 2D set (unambiguous, since
//   the counts differ).
// - Every line has the same number of columns. Lines starting with '#' are
//   comments; `# amls dim N` sets the dimension.
#include <algorithm>
#include <array>

#include "core/io/file_format.hpp"
#include "core/io/raw_point_file.hpp"

namespace amls::detail {

namespace {

constexpr std::size_t kMaxLine = std::size_t{1} << 16;
constexpr std::size_t kNoColumn = static_cast<std::size_t>(-1);

// Where x y z nx ny nz are among a line's fields (kNoColumn: absent).
struct Columns {
  std::size_t count = 0;  // fields a line has
  std::array<std::size_t, 6> of{kNoColumn, kNoColumn, kNoColumn, kNoColumn, kNoColumn, kNoColumn};
  bool is_2d() const { return of[2] == kNoColumn; }
  bool has_normals() const { return of[3] != kNoColumn; }
};

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// Splits `line` into fields at `separator` (' ' for runs of spaces and tabs).
// Returns false if a field other than a trailing one is empty.
bool split_fields(std::string_view line, char separator, std::vector<std::string_view>& fields) {
  if (separator == ' ') {
    split_words(line, fields);
    return true;
  }
  fields.clear();
  for (std::size_t begin = 0;;) {
    const std::size_t end = std::min(line.find(separator, begin), line.size());
    fields.push_back(trim(line.substr(begin, end - begin)));
    if (end == line.size()) break;
    begin = end + 1;
  }
  if (fields.size() > 1 && fields.back().empty()) fields.pop_back();
  return std::none_of(fields.begin(), fields.end(), [](std::string_view f) { return f.empty(); });
}

// The columns a header line names; `fail_here` throws.
template <typename Fail>
Columns header_columns(std::vector<std::string_view> names, Fail&& fail_here) {
  if (names[0].starts_with("//")) names[0] = trim(names[0].substr(2));
  Columns columns;
  columns.count = names.size();
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string name = lower_case(names[k]);
    const int slot = coordinate_slot(name);
    if (slot < 0) continue;
    const auto at = static_cast<std::size_t>(slot);
    if (columns.of[at] != kNoColumn) fail_here("the header names '" + name + "' twice");
    columns.of[at] = k;
  }
  if (columns.of[0] == kNoColumn || columns.of[1] == kNoColumn)
    fail_here("the header line names no 'x' and 'y' columns (or, if it is not a header, " + quoted(names[0]) +
              " is not a number)");
  const std::size_t normals = static_cast<std::size_t>(
      std::count_if(columns.of.begin() + 3, columns.of.end(), [](std::size_t c) { return c != kNoColumn; }));
  const std::size_t wanted = columns.is_2d() ? 2 : 3;
  if (normals != 0 && (normals != wanted || (columns.is_2d() && columns.of[5] != kNoColumn)))
    fail_here(std::string("the header names only some of the normal columns (") +
              (columns.is_2d() ? "nx ny for x y" : "nx ny nz for x y z") + ")");
  return columns;
}

// The columns of a file without a header, from its first line's field count.
template <typename Fail>
Columns counted_columns(std::size_t count, Fail&& fail_here) {
  if (count != 2 && count != 3 && count != 4 && count != 6)
    fail_here(std::to_string(count) +
              " values; expected x y z or x y z nx ny nz (or, for a 2D set, x y or x y nx ny), or a header line "
              "naming the columns (such as x,y,z,nx,ny,nz)");
  Columns columns;
  columns.count = count;
  const bool flat = count == 2 || count == 4;
  const std::size_t d = flat ? 2 : 3;
  for (std::size_t a = 0; a < d; ++a) columns.of[a] = a;
  if (count == 2 * d)
    for (std::size_t a = 0; a < d; ++a) columns.of[3 + a] = d + a;
  return columns;
}

}  // namespace

RawPointFile read_xyz(std::istream& in, const std::string& path) {
  RawPointFile raw;
  raw.path = path;
  std::string line;
  std::vector<std::string_view> fields;
  std::optional<Columns> columns;  // fixed by the header or the first line of numbers
  std::size_t columns_line = 0;
  char separator = ' ';
  AmlsComments declared;
  for (std::size_t number = 1; read_line(in, line, kMaxLine, path, number); ++number) {
    auto fail_here = [&](const std::string& what) { fail(path, "line " + std::to_string(number) + ": " + what); };
    if (number == 1) drop_byte_order_mark(line);
    const std::string_view text = trim(line);
    if (text.empty()) continue;
    if (text.front() == '#') {
      // "#amls dim 2" and "# amls dim 2" alike.
      split_words(text.substr(1), fields);
      declared.note(fields, path, number);
      continue;
    }
    if (!columns)
      separator = text.find(';') != std::string_view::npos ? ';' : text.find(',') != std::string_view::npos ? ',' : ' ';
    if (!split_fields(text, separator, fields))
      fail_here(std::string("an empty value between two ") + (separator == ';' ? "semicolons" : "commas"));
    if (!columns) {
      columns_line = number;
      if (!parse_double(fields[0])) {
        columns = header_columns(fields, fail_here);
        continue;
      }
      columns = counted_columns(fields.size(), fail_here);
    }
    if (fields.size() != columns->count)
      fail_here(std::to_string(fields.size()) + " values, but line " + std::to_string(columns_line) + " has " +
                std::to_string(columns->count));
    double v[6] = {};
    for (std::size_t slot = 0; slot < 6; ++slot) {
      const std::size_t k = columns->of[slot];
      if (k == kNoColumn) continue;
      const std::optional<double> value = parse_double(fields[k]);
      if (!value) fail_here(quoted(fields[k]) + " is not a number");
      v[slot] = *value;
    }
    raw.points.add(Vec<3>(v[0], v[1], v[2]), Vec<3>(v[3], v[4], v[5]));
    raw.lines.push_back(number);
  }
  raw.has_normals = columns && columns->has_normals();
  const bool column_2d = columns && columns->is_2d();
  if (column_2d && declared.dimension == 3)
    fail(path, "line " + std::to_string(columns_line) +
                   ": the columns make 2D points (no z), but the file says 'amls dim 3'");
  raw.declared_dimension = column_2d ? 2 : declared.dimension;
  raw.declared_spacing = declared.spacing;
  return raw;
}

void write_xyz(FileSink& out, const PointSet<3>& points, int dimension, bool with_normals, double spacing) {
  for (const std::string& comment : amls_comment_lines(dimension, spacing)) out.write("# " + comment + "\n");
  std::string text;
  for (std::size_t i = 0; i < points.size(); ++i) {
    text.clear();
    for (int k = 0; k < 3; ++k) {
      if (k > 0) text += ' ';
      append_double(text, points.positions[i][k]);
    }
    if (with_normals)
      for (int k = 0; k < 3; ++k) {
        text += ' ';
        append_double(text, points.normals[i][k]);
      }
    text += '\n';
    out.write(text);
  }
}

}  // namespace amls::detail
