// XYZ: plain text, one point per line. 3D: `x y z` or `x y z nx ny nz`; a 2D
// set may also be given as `x y` or `x y nx ny` (unambiguous, since the two
// layouts have different column counts). Every line has the same number of
// columns. Lines starting with '#' are comments; `# amls dim N` sets the dimension.
#include "core/io/raw_point_file.hpp"

namespace amls::detail {

namespace {

constexpr std::size_t kMaxLine = std::size_t{1} << 16;

}  // namespace

RawPointFile read_xyz(std::istream& in, const std::string& path) {
  RawPointFile raw;
  raw.path = path;
  std::string line;
  std::vector<std::string_view> words;
  std::size_t columns = 0;  // fixed by the first point's line
  std::size_t columns_line = 0;
  int comment_dimension = 0;
  for (std::size_t number = 1; read_line(in, line, kMaxLine, path, number); ++number) {
    auto fail_here = [&](const std::string& what) { fail(path, "line " + std::to_string(number) + ": " + what); };
    split_words(line, words);
    if (words.empty()) continue;
    if (words[0].front() == '#') {
      // "#amls dim 2" and "# amls dim 2" alike.
      words[0].remove_prefix(1);
      const std::span<const std::string_view> comment =
          std::span<const std::string_view>(words).subspan(words[0].empty() ? 1 : 0);
      const int dimension = parse_dimension_comment(comment, path, number);
      if (dimension != 0 && comment_dimension != 0 && dimension != comment_dimension)
        fail_here("conflicting 'amls dim' comments");
      if (dimension != 0) comment_dimension = dimension;
      continue;
    }
    if (columns == 0) {
      if (words.size() != 2 && words.size() != 3 && words.size() != 4 && words.size() != 6)
        fail_here(std::to_string(words.size()) +
                  " values; expected x y z or x y z nx ny nz (or, for a 2D set, x y or x y nx ny)");
      columns = words.size();
      columns_line = number;
    } else if (words.size() != columns) {
      fail_here(std::to_string(words.size()) + " values, but line " + std::to_string(columns_line) + " has " +
                std::to_string(columns));
    }
    double v[6] = {};
    for (std::size_t k = 0; k < words.size(); ++k) {
      const std::optional<double> value = parse_double(words[k]);
      if (!value) fail_here(quoted(words[k]) + " is not a number");
      v[k] = *value;
    }
    if (columns == 2 || columns == 4) {
      raw.points.add(Vec<3>(v[0], v[1], 0.0), Vec<3>(v[2], v[3], 0.0));
    } else {
      raw.points.add(Vec<3>(v[0], v[1], v[2]), Vec<3>(v[3], v[4], v[5]));
    }
    raw.lines.push_back(number);
  }
  raw.has_normals = columns == 4 || columns == 6;
  const int column_dimension = columns == 2 || columns == 4 ? 2 : 0;
  if (column_dimension == 2 && comment_dimension == 3)
    fail(path, "line " + std::to_string(columns_line) + ": " + std::to_string(columns) +
                   " values make a 2D point, but the file says 'amls dim 3'");
  raw.declared_dimension = column_dimension != 0 ? column_dimension : comment_dimension;
  return raw;
}

void write_xyz(FileSink& out, const PointSet<3>& points, int dimension, bool with_normals) {
  out.write("# amls dim " + std::to_string(dimension) + "\n");
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
