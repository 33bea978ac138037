// OFF (Geomview's object file format, also CGAL's): text only. The header
// keyword is [ST][C][N][4][n]OFF (optional, as in Geomview; the prefixes in
// any order), then `vertices faces [edges]` on the same line or the next,
// then one vertex per line - x y z, w if 4, the normal if N, then a colour and
// texture coordinates that are read past - and one face per line: a count,
// that many 0-based vertex indices, and an optional colour. `#` starts a
// comment anywhere. Vertices are lines rather than a stream of numbers
// because a colour may have 1, 3 or 4 components. Binary OFF is refused.
#include <iterator>
#include <string_view>

#include "core/io/raw_point_file.hpp"

namespace amls::detail {

namespace {

constexpr std::size_t kMaxLine = std::size_t{1} << 24;
// A face line may end in a colour of up to 4 values.
constexpr std::size_t kMaxFaceColour = 4;

struct OffHeader {
  bool normals = false;      // N: x y z nx ny nz
  bool homogeneous = false;  // 4: x y z w
  bool extras = false;       // C or ST: colours or texture coordinates follow
  std::uint64_t vertices = 0;
  std::uint64_t faces = 0;
};

// Reads lines, dropping comments and counting them, skipping blank ones.
class OffLines {
 public:
  OffLines(std::istream& in, const std::string& path) : in_(in), path_(path) {}

  // The next line with any words, split; false at the end of the file.
  bool next(std::vector<std::string_view>& words) {
    while (true) {
      ++number_;
      if (!read_line(in_, line_, kMaxLine, path_, number_)) return false;
      if (number_ == 1) drop_byte_order_mark(line_);
      const std::size_t comment = line_.find('#');
      split_words(std::string_view(line_).substr(0, comment), words);
      if (!words.empty()) return true;
    }
  }
  std::size_t number() const { return number_; }
  [[noreturn]] void fail_here(const std::string& what) const {
    fail(path_, "line " + std::to_string(number_) + ": " + what);
  }

 private:
  std::istream& in_;
  const std::string& path_;
  std::string line_;
  std::size_t number_ = 0;
};

// The keyword's prefixes, each at most once: Geomview orders them ST C N 4 n,
// but writers also put N first (NCOFF); false if `word` is no OFF keyword.
bool parse_keyword(std::string_view word, OffHeader& header, bool& dimension_follows) {
  if (!word.ends_with("OFF")) return false;
  word.remove_suffix(3);
  bool texture = false, colour = false;
  bool* flags[] = {&texture, &colour, &header.normals, &header.homogeneous, &dimension_follows};
  constexpr std::string_view kPrefixes[] = {"ST", "C", "N", "4", "n"};
  while (!word.empty()) {
    std::size_t p = 0;
    while (p < std::size(kPrefixes) && (!word.starts_with(kPrefixes[p]) || *flags[p])) ++p;
    if (p == std::size(kPrefixes)) return false;
    *flags[p] = true;
    word.remove_prefix(kPrefixes[p].size());
  }
  header.extras = texture || colour;
  return true;
}

OffHeader read_header(OffLines& lines, std::vector<std::string_view>& words, std::uint64_t file_size) {
  OffHeader header;
  if (!lines.next(words)) lines.fail_here("no OFF header (the file holds only comments or blank lines)");
  bool dimension_follows = false;
  std::size_t w = 0;
  if (parse_keyword(words[0], header, dimension_follows)) {
    w = 1;
    if (w < words.size() && words[w] == "BINARY")
      lines.fail_here("binary OFF is not supported; save the file as text OFF");
  } else if (!parse_integer(words[0])) {
    lines.fail_here("expected an OFF header such as 'OFF', 'NOFF' or 'COFF', got " + quoted(words[0]));
  }
  // The numbers after the keyword: [dimension] vertices faces [edges], on as many lines as they take.
  std::vector<std::int64_t> numbers;
  const std::size_t wanted = dimension_follows ? 3 : 2;
  while (true) {
    for (; w < words.size(); ++w) {
      const std::optional<std::int64_t> value = parse_integer(words[w]);
      if (!value) lines.fail_here(quoted(words[w]) + " is not a whole number (expected the vertex and face counts)");
      numbers.push_back(*value);
      if (dimension_follows && numbers.size() == 1 && *value != 3)
        lines.fail_here("nOFF with vertices of dimension " + std::to_string(*value) + ": only 3 is supported");
    }
    if (numbers.size() >= wanted) break;
    if (!lines.next(words)) lines.fail_here("the file ends before the header's vertex and face counts");
    w = 0;
  }
  const std::size_t k = dimension_follows ? 1 : 0;
  if (numbers.size() > k + 3) lines.fail_here("too many numbers in the header (expected vertices faces [edges])");
  const std::int64_t vertices = numbers[k], faces = numbers[k + 1];
  if (vertices < 0 || faces < 0)
    lines.fail_here("negative counts (" + std::to_string(vertices) + " vertices, " + std::to_string(faces) + " faces)");
  header.vertices = static_cast<std::uint64_t>(vertices);
  header.faces = static_cast<std::uint64_t>(faces);
  // The shortest vertex line is "0 0 0\n" (two bytes a value), the shortest
  // face "3 0 1 2\n": refuse counts the file cannot hold before allocating.
  const std::uint64_t vertex_bytes = 2 * (3 + (header.homogeneous ? 1 : 0) + (header.normals ? 3 : 0));
  const std::uint64_t face_bytes = 8;
  if (header.vertices > file_size / vertex_bytes ||
      header.faces > (file_size - header.vertices * vertex_bytes) / face_bytes)
    lines.fail_here("truncated: the header promises " + std::to_string(header.vertices) + " vertices and " +
                    std::to_string(header.faces) + " faces, more than a file of " + std::to_string(file_size) +
                    " bytes can hold");
  return header;
}

void read_vertices(OffLines& lines, std::vector<std::string_view>& words, const OffHeader& header, RawPointFile& raw) {
  const std::size_t values = 3 + (header.homogeneous ? 1 : 0) + (header.normals ? 3 : 0);
  raw.points.reserve(header.vertices);
  raw.lines.reserve(header.vertices);
  for (std::uint64_t i = 0; i < header.vertices; ++i) {
    if (!lines.next(words))
      fail(raw.path, "truncated: the file ends after " + std::to_string(i) + " of the " +
                         std::to_string(header.vertices) + " vertices the header promises");
    if (words.size() < values)
      lines.fail_here(std::to_string(words.size()) + " values for a vertex; expected " + std::to_string(values));
    if (words.size() > values && !header.extras)
      lines.fail_here(std::to_string(words.size()) + " values for a vertex; expected " + std::to_string(values) +
                      " (colours need a COFF header)");
    double v[7] = {};
    for (std::size_t k = 0; k < words.size(); ++k) {
      const std::optional<double> value = parse_double(words[k]);
      if (!value) lines.fail_here(quoted(words[k]) + " is not a number");
      if (k < values) v[k] = *value;
    }
    Vec<3> position(v[0], v[1], v[2]);
    if (header.homogeneous) position /= v[3];
    const double* normal = v + (header.homogeneous ? 4 : 3);
    raw.points.add(position, header.normals ? Vec<3>(normal[0], normal[1], normal[2]) : Vec<3>::Zero());
    raw.lines.push_back(lines.number());
  }
}

void read_faces(OffLines& lines, std::vector<std::string_view>& words, const OffHeader& header, RawPointFile& raw) {
  std::vector<double> face;
  for (std::uint64_t f = 0; f < header.faces; ++f) {
    if (!lines.next(words))
      fail(raw.path, "truncated: the file ends after " + std::to_string(f) + " of the " + std::to_string(header.faces) +
                         " faces the header promises");
    const std::optional<std::int64_t> corners = parse_integer(words[0]);
    if (!corners || *corners < 0) lines.fail_here(quoted(words[0]) + " is not a valid count of face vertices");
    const auto n = static_cast<std::size_t>(*corners);
    if (words.size() - 1 < n)
      lines.fail_here("the face promises " + std::to_string(n) + " vertices but lists " +
                      std::to_string(words.size() - 1));
    if (words.size() - 1 - n > kMaxFaceColour)
      lines.fail_here(std::to_string(words.size() - 1 - n) +
                      " values after the face's vertices (at most 4, a colour, may follow)");
    face.clear();
    for (std::size_t k = 1; k <= n; ++k) {
      const std::optional<std::int64_t> index = parse_integer(words[k]);
      if (!index) lines.fail_here(quoted(words[k]) + " is not a vertex index");
      face.push_back(static_cast<double>(*index));
    }
    for (std::size_t k = n + 1; k < words.size(); ++k)
      if (!parse_double(words[k])) lines.fail_here(quoted(words[k]) + " is not a number (a face colour)");
    add_face(raw, face, header.vertices, "line", lines.number());
  }
}

}  // namespace

RawPointFile read_off(std::istream& in, std::uint64_t file_size, const std::string& path) {
  RawPointFile raw;
  raw.path = path;
  OffLines lines(in, path);
  std::vector<std::string_view> words;
  const OffHeader header = read_header(lines, words, file_size);
  raw.has_normals = header.normals;
  raw.has_faces = header.faces > 0;
  read_vertices(lines, words, header, raw);
  read_faces(lines, words, header, raw);
  if (lines.next(words)) lines.fail_here("data after the last face (are the header's counts too small?)");
  return raw;
}

std::uint64_t off_face_count(std::istream& in, std::uint64_t file_size, const std::string& path) {
  OffLines lines(in, path);
  std::vector<std::string_view> words;
  return read_header(lines, words, file_size).faces;
}

}  // namespace amls::detail
