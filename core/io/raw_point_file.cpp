#include "core/io/raw_point_file.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "core/util/file_error.hpp"

namespace amls::detail {

std::string RawPointFile::where(std::size_t i) const {
  if (i < lines.size()) return "line " + std::to_string(lines[i]);
  return "vertex " + std::to_string(i < vertices.size() ? vertices[i] : i);
}

void add_face(RawPointFile& raw, const std::vector<double>& indices, std::uint64_t vertex_count, std::string_view where,
              std::uint64_t number) {
  ++raw.faces;
  auto problem = [&](const std::string& what) {
    if (raw.face_problem.empty()) raw.face_problem = std::string(where) + " " + std::to_string(number) + ": " + what;
  };
  if (indices.size() < 3)
    return problem("has " + std::to_string(indices.size()) + " vertices (a face needs at least 3)");
  for (double index : indices)
    if (index < 0.0 || index >= static_cast<double>(vertex_count))
      return problem("vertex index " + std::to_string(static_cast<std::int64_t>(index)) +
                     " is out of range (the file has " + std::to_string(vertex_count) + " vertices)");
  auto at = [&](std::size_t k) { return static_cast<std::uint32_t>(indices[k]); };
  for (std::size_t k = 1; k + 1 < indices.size(); ++k) raw.triangles.push_back({at(0), at(k), at(k + 1)});
}

void fail(const std::string& path, const std::string& what) { throw std::runtime_error(path + ": " + what); }

bool read_line(std::istream& in, std::string& line, std::size_t max_length, const std::string& path,
               std::size_t line_number) {
  using Traits = std::char_traits<char>;
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  bool any = false;
  while (true) {
    const Traits::int_type c = buffer->sbumpc();
    if (Traits::eq_int_type(c, Traits::eof())) break;
    any = true;
    if (c == '\n') break;
    if (line.size() >= max_length)
      fail(path, "line " + std::to_string(line_number) + ": longer than " + std::to_string(max_length) +
                     " characters (is this really a text line?)");
    line.push_back(Traits::to_char_type(c));
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return any;
}

void drop_byte_order_mark(std::string& first_line) {
  if (first_line.starts_with("\xEF\xBB\xBF")) first_line.erase(0, 3);
}

std::string quoted(std::string_view text) {
  // Built by appending: "'" + std::string(...) trips a false -Wrestrict in GCC 12 at -O3.
  std::string out;
  out.reserve(text.size() + 2);
  out += '\'';
  out.append(text);
  out += '\'';
  return out;
}

void split_words(std::string_view text, std::vector<std::string_view>& words) {
  words.clear();
  std::size_t i = 0;
  while (true) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    if (i == text.size()) return;
    const std::size_t begin = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    words.push_back(text.substr(begin, i - begin));
  }
}

namespace {

// from_chars takes no '+'; accept one, but not "+-1".
std::string_view drop_plus(std::string_view word) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '-' && word[1] != '+') word.remove_prefix(1);
  return word;
}

}  // namespace

std::optional<double> parse_double(std::string_view word) {
  word = drop_plus(word);
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view word) {
  word = drop_plus(word);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

void AmlsComments::note(std::span<const std::string_view> words, const std::string& path, std::size_t line_number) {
  if (words.size() < 2 || words[0] != "amls") return;
  auto fail_here = [&](const std::string& what) { fail(path, "line " + std::to_string(line_number) + ": " + what); };
  if (words[1] == "dim") {
    if (words.size() != 3 || (words[2] != "2" && words[2] != "3")) fail_here("expected 'amls dim 2' or 'amls dim 3'");
    const int declared = words[2] == "2" ? 2 : 3;
    if (dimension != 0 && declared != dimension) fail_here("conflicting 'amls dim' comments");
    dimension = declared;
  } else if (words[1] == "spacing") {
    const std::optional<double> value = words.size() == 3 ? parse_double(words[2]) : std::nullopt;
    if (!value || !(*value > 0.0) || !std::isfinite(*value))
      fail_here("expected 'amls spacing H' with H a positive number");
    if (spacing != 0.0 && *value != spacing) fail_here("conflicting 'amls spacing' comments");
    spacing = *value;
  }
}

std::vector<std::string> amls_comment_lines(int dimension, double spacing) {
  std::vector<std::string> lines{"amls dim " + std::to_string(dimension)};
  if (spacing > 0.0) lines.push_back("amls spacing " + shortest(spacing));
  return lines;
}

void append_double(std::string& out, double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  if (error != std::errc()) throw std::logic_error("to_chars failed on a double");  // 32 characters always suffice
  out.append(text, end);
}

std::string shortest(double value) {
  std::string text;
  append_double(text, value);
  return text;
}

void FileSink::write(std::string_view bytes) {
  buffer_.append(bytes);
  if (buffer_.size() >= (std::size_t{1} << 20)) flush();
}

void FileSink::flush() {
  if (buffer_.empty()) return;
  errno = 0;
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
    const int error = errno;
    throw FileError(path_ + ": write failed" + (error ? std::string(": ") + std::strerror(error) : ""), error);
  }
  buffer_.clear();
}

int coordinate_slot(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, int>, 9> kSlots{{{"x", 0},
                                                                           {"y", 1},
                                                                           {"z", 2},
                                                                           {"nx", 3},
                                                                           {"ny", 4},
                                                                           {"nz", 5},
                                                                           {"normal_x", 3},
                                                                           {"normal_y", 4},
                                                                           {"normal_z", 5}}};
  for (const auto& [known, slot] : kSlots)
    if (name == known) return slot;
  return -1;
}

}  // namespace amls::detail
