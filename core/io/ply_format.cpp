// PLY (Turk's polygon file format, version 1.0): ASCII and binary, either byte
// order. Only the vertex element's positions and normals are kept; everything
// else is read past, but still checked, so that a damaged file is reported
// rather than half read.
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>

#include "core/io/raw_point_file.hpp"

namespace amls::detail {

namespace {

static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big,
              "mixed-endian machines are not supported");

constexpr std::size_t kMaxHeaderLine = std::size_t{1} << 16;
// An ASCII item is one line; a face may list many vertices.
constexpr std::size_t kMaxBodyLine = std::size_t{1} << 24;

enum class Encoding { ascii, binary_little_endian, binary_big_endian };

enum class ScalarType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct TypeName {
  std::string_view name;
  ScalarType type;
};

// PLY 1.0 names first, then the sized names many writers use.
constexpr std::array<TypeName, 16> kTypeNames{{{"char", ScalarType::int8},
                                               {"uchar", ScalarType::uint8},
                                               {"short", ScalarType::int16},
                                               {"ushort", ScalarType::uint16},
                                               {"int", ScalarType::int32},
                                               {"uint", ScalarType::uint32},
                                               {"float", ScalarType::float32},
                                               {"double", ScalarType::float64},
                                               {"int8", ScalarType::int8},
                                               {"uint8", ScalarType::uint8},
                                               {"int16", ScalarType::int16},
                                               {"uint16", ScalarType::uint16},
                                               {"int32", ScalarType::int32},
                                               {"uint32", ScalarType::uint32},
                                               {"float32", ScalarType::float32},
                                               {"float64", ScalarType::float64}}};

std::optional<ScalarType> scalar_type(std::string_view name) {
  for (const TypeName& t : kTypeNames)
    if (t.name == name) return t.type;
  return std::nullopt;
}

std::string_view name_of(ScalarType type) {
  for (const TypeName& t : kTypeNames)
    if (t.type == type) return t.name;
  return "?";
}

std::size_t size_of(ScalarType type) {
  switch (type) {
    case ScalarType::int8:
    case ScalarType::uint8:
      return 1;
    case ScalarType::int16:
    case ScalarType::uint16:
      return 2;
    case ScalarType::int32:
    case ScalarType::uint32:
    case ScalarType::float32:
      return 4;
    case ScalarType::float64:
      return 8;
  }
  return 8;
}

bool is_integer(ScalarType type) { return type != ScalarType::float32 && type != ScalarType::float64; }

// The range of an integer type, as doubles (exact: every bound fits in 32 bits).
std::pair<double, double> integer_range(ScalarType type) {
  switch (type) {
    case ScalarType::int8:
      return {-128.0, 127.0};
    case ScalarType::uint8:
      return {0.0, 255.0};
    case ScalarType::int16:
      return {-32768.0, 32767.0};
    case ScalarType::uint16:
      return {0.0, 65535.0};
    case ScalarType::int32:
      return {-2147483648.0, 2147483647.0};
    default:
      return {0.0, 4294967295.0};
  }
}

struct Property {
  std::string name;
  ScalarType type = ScalarType::float64;  // of the value, or of a list's items
  bool is_list = false;
  ScalarType count_type = ScalarType::uint8;  // of a list's length
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;

  bool has_lists() const {
    return std::any_of(properties.begin(), properties.end(), [](const Property& p) { return p.is_list; });
  }
  // Bytes of one binary item, counting each list as empty.
  std::uint64_t min_binary_bytes() const {
    std::uint64_t bytes = 0;
    for (const Property& p : properties) bytes += size_of(p.is_list ? p.count_type : p.type);
    return bytes;
  }
};

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  AmlsComments declared;
  std::size_t lines = 0;  // lines read so far
};

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// Where the vertex element's properties go: slot 0..5 is x y z nx ny nz,
// kRimSlot the rim mark amls writes (PointSet::rim), -1 is ignored. And where
// the faces are, if the file has any.
constexpr int kRimSlot = 6;
constexpr std::string_view kRimProperty = "rim";
using VertexValues = std::array<double, kRimSlot + 1>;

struct VertexLayout {
  std::size_t element = 0;
  std::vector<int> slot;
  bool has_normals = false;
  bool has_rim = false;
  std::uint64_t vertex_count = 0;
  std::size_t face_element = kNone;   // the `face` element
  std::size_t face_property = kNone;  // its `vertex_indices` (or `vertex_index`) list
};

// Header lines, one keyword each; `fail_here` throws with the line's number.
template <typename Fail>
Encoding format_line(const std::vector<std::string_view>& words, Fail&& fail_here) {
  if (words.size() != 3) fail_here("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
  Encoding encoding = Encoding::ascii;
  if (words[1] == "binary_little_endian") {
    encoding = Encoding::binary_little_endian;
  } else if (words[1] == "binary_big_endian") {
    encoding = Encoding::binary_big_endian;
  } else if (words[1] != "ascii") {
    fail_here("unknown format '" + std::string(words[1]) + "' (expected ascii, binary_little_endian or binary_big_endian)");
  }
  if (words[2] != "1.0") fail_here("unsupported PLY version '" + std::string(words[2]) + "' (expected 1.0)");
  return encoding;
}

template <typename Fail>
Element element_line(const std::vector<std::string_view>& words, const Header& header, Fail&& fail_here) {
  if (words.size() != 3) fail_here("expected 'element NAME COUNT'");
  Element element;
  element.name = std::string(words[1]);
  const std::optional<std::int64_t> count = parse_integer(words[2]);
  if (count && *count < 0) fail_here("element '" + element.name + "' has a negative count (" + std::string(words[2]) + ")");
  if (!count) fail_here("element '" + element.name + "' count '" + std::string(words[2]) + "' is not a valid number");
  element.count = static_cast<std::uint64_t>(*count);
  for (const Element& e : header.elements)
    if (e.name == element.name) fail_here("a second element named '" + element.name + "'");
  return element;
}

template <typename Fail>
Property property_line(const std::vector<std::string_view>& words, const Element& element, Fail&& fail_here) {
  Property property;
  auto type_of = [&](std::string_view name) {
    const std::optional<ScalarType> type = scalar_type(name);
    if (!type) fail_here("unknown property type '" + std::string(name) + "'");
    return *type;
  };
  if (words.size() >= 2 && words[1] == "list") {
    if (words.size() != 5) fail_here("expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
    property.is_list = true;
    property.count_type = type_of(words[2]);
    if (!is_integer(property.count_type))
      fail_here("a list's length type must be an integer type, not '" + std::string(words[2]) + "'");
    property.type = type_of(words[3]);
    property.name = std::string(words[4]);
  } else {
    if (words.size() != 3) fail_here("expected 'property TYPE NAME'");
    property.type = type_of(words[1]);
    property.name = std::string(words[2]);
  }
  for (const Property& p : element.properties)
    if (p.name == property.name)
      fail_here("element '" + element.name + "' has two properties named '" + property.name + "'");
  return property;
}

Header read_header(std::istream& in, const std::string& path) {
  Header header;
  std::string line;
  std::vector<std::string_view> words;
  auto fail_here = [&](const std::string& what) { fail(path, "line " + std::to_string(header.lines) + ": " + what); };

  // The magic word is checked before any line is read, so that a large file
  // of something else fails at once.
  header.lines = 1;
  char magic[3] = {};
  in.read(magic, 3);
  if (in.gcount() != 3 || std::string_view(magic, 3) != "ply")
    fail_here("missing the 'ply' magic word: not a PLY file");
  read_line(in, line, kMaxHeaderLine, path, header.lines);
  split_words(line, words);
  if (!words.empty()) fail_here("missing the 'ply' magic word: not a PLY file");

  bool have_format = false;
  while (true) {
    ++header.lines;
    if (!read_line(in, line, kMaxHeaderLine, path, header.lines))
      fail(path, "the header ends without 'end_header' (truncated, or not a PLY file)");
    split_words(line, words);
    if (words.empty()) continue;
    const std::string_view key = words[0];
    if (key == "end_header") {
      if (words.size() != 1) fail_here("unexpected words after 'end_header'");
      break;
    }
    if (key == "format") {
      if (have_format) fail_here("a second 'format' line");
      header.encoding = format_line(words, fail_here);
      have_format = true;
    } else if (key == "comment") {
      header.declared.note(std::span<const std::string_view>(words).subspan(1), path, header.lines);
    } else if (key == "obj_info") {
      // Free text, like a comment.
    } else if (key == "element") {
      header.elements.push_back(element_line(words, header, fail_here));
    } else if (key == "property") {
      if (header.elements.empty()) fail_here("'property' before any 'element'");
      header.elements.back().properties.push_back(property_line(words, header.elements.back(), fail_here));
    } else {
      fail_here("unknown header keyword '" + std::string(key) + "'");
    }
  }
  if (!have_format) fail(path, "the header has no 'format' line");
  return header;
}

VertexLayout vertex_layout(const Header& header, const std::string& path) {
  VertexLayout layout;
  const auto vertex =
      std::find_if(header.elements.begin(), header.elements.end(), [](const Element& e) { return e.name == "vertex"; });
  if (vertex == header.elements.end()) fail(path, "the header has no 'vertex' element");
  layout.element = static_cast<std::size_t>(vertex - header.elements.begin());
  std::array<const Property*, 6> found{};
  for (const Property& p : vertex->properties) {
    if (p.name == kRimProperty && !p.is_list && is_integer(p.type)) {
      layout.slot.push_back(kRimSlot);
      layout.has_rim = true;
      continue;
    }
    const int slot = coordinate_slot(p.name);
    layout.slot.push_back(slot);
    if (slot < 0) continue;
    if (p.is_list) fail(path, "vertex property '" + p.name + "' is a list; expected a single value");
    if (found[static_cast<std::size_t>(slot)])
      fail(path, "vertex properties '" + found[static_cast<std::size_t>(slot)]->name + "' and '" + p.name +
                     "' name the same coordinate");
    found[static_cast<std::size_t>(slot)] = &p;
  }
  std::string missing;
  for (std::size_t a = 0; a < 3; ++a)
    if (!found[a]) missing += std::string(missing.empty() ? "" : ", ") + "xyz"[a];
  if (!missing.empty()) fail(path, "the vertex element has no '" + missing + "' property (x, y and z are required)");
  const auto normals = std::count_if(found.begin() + 3, found.end(), [](const Property* p) { return p != nullptr; });
  if (normals != 0 && normals != 3)
    fail(path, "the vertex element has only some of the normal properties (nx ny nz, or normal_x normal_y normal_z)");
  layout.has_normals = normals == 3;
  layout.vertex_count = vertex->count;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    if (header.elements[e].name != "face") continue;
    const std::vector<Property>& properties = header.elements[e].properties;
    for (std::size_t k = 0; k < properties.size(); ++k) {
      const Property& p = properties[k];
      if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
      if (!p.is_list) fail(path, "face property '" + p.name + "' is not a list");
      if (!is_integer(p.type))
        fail(path, "face property '" + p.name + "' holds " + std::string(name_of(p.type)) +
                       " values; vertex indices must be integers");
      layout.face_element = e;
      layout.face_property = k;
    }
  }
  return layout;
}

// Items of `element` need at least `bytes_per_item` bytes each: refuse counts
// the rest of the file cannot hold before anything is allocated for them.
void check_count_fits(const Element& element, std::uint64_t bytes_per_item, std::uint64_t bytes_left,
                      const std::string& path) {
  if (bytes_per_item == 0 || element.count <= bytes_left / bytes_per_item) return;
  fail(path, "truncated: the header promises " + std::to_string(element.count) + " '" + element.name +
                 "' items of at least " + std::to_string(bytes_per_item) + " bytes each, but only " +
                 std::to_string(bytes_left) + " bytes follow");
}

void store(RawPointFile& raw, const VertexLayout& layout, const VertexValues& v) {
  raw.points.positions.emplace_back(v[0], v[1], v[2]);
  raw.points.normals.emplace_back(v[3], v[4], v[5]);
  if (layout.has_rim) raw.points.rim.push_back(v[kRimSlot] != 0.0 ? 1 : 0);
}

// ---- ASCII ----

std::optional<double> parse_scalar(std::string_view word, ScalarType type) {
  if (!is_integer(type)) return parse_double(word);
  const std::optional<std::int64_t> value = parse_integer(word);
  if (!value) return std::nullopt;
  const auto [lo, hi] = integer_range(type);
  const auto v = static_cast<double>(*value);
  if (v < lo || v > hi) return std::nullopt;
  return v;
}

void read_ascii_body(std::istream& in, std::uint64_t bytes_left, Header& header, const VertexLayout& layout,
                     RawPointFile& raw) {
  const std::string& path = raw.path;
  std::string line;
  std::vector<std::string_view> words;
  auto fail_here = [&](const std::string& what) { fail(path, "line " + std::to_string(header.lines) + ": " + what); };
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const Element& element = header.elements[e];
    const bool is_vertex = e == layout.element;
    const bool is_face = e == layout.face_element;
    std::vector<double> face;
    // An item is one line: at least one word and one separator per property.
    check_count_fits(element, 2 * element.properties.size(), bytes_left + 1, path);
    if (element.properties.empty()) continue;
    if (is_vertex) {
      raw.points.reserve(element.count);
      raw.lines.reserve(element.count);
    }
    for (std::uint64_t item = 0; item < element.count; ++item) {
      do {
        ++header.lines;
        if (!read_line(in, line, kMaxBodyLine, path, header.lines))
          fail(path, "truncated: the file ends after " + std::to_string(item) + " of the " +
                         std::to_string(element.count) + " '" + element.name + "' items the header promises");
        split_words(line, words);
      } while (words.empty());  // blank lines carry nothing
      VertexValues values{};
      std::size_t w = 0;
      auto next_word = [&](const Property& p) {
        if (w == words.size())
          fail_here("too few values for a '" + element.name + "' item (none for '" + p.name + "')");
        return words[w++];
      };
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& p = element.properties[k];
        if (!p.is_list) {
          const std::string_view word = next_word(p);
          const std::optional<double> value = parse_scalar(word, p.type);
          if (!value)
            fail_here(quoted(word) + " is not a valid " + std::string(name_of(p.type)) + " for '" + p.name + "'");
          if (is_vertex && layout.slot[k] >= 0) values[static_cast<std::size_t>(layout.slot[k])] = *value;
          continue;
        }
        const std::string_view word = next_word(p);
        const std::optional<std::int64_t> length = parse_integer(word);
        if (length && *length < 0) fail_here("negative list length " + std::string(word) + " for '" + p.name + "'");
        if (!length || !parse_scalar(word, p.count_type))
          fail_here(quoted(word) + " is not a valid " + std::string(name_of(p.count_type)) + " list length for '" +
                    p.name + "'");
        if (static_cast<std::uint64_t>(*length) > words.size() - w)
          fail_here("too few values for a '" + element.name + "' item (list '" + p.name + "' promises " +
                    std::string(word) + ")");
        const bool is_face_list = is_face && k == layout.face_property;
        face.clear();
        for (std::int64_t j = 0; j < *length; ++j) {
          const std::string_view item_word = words[w++];
          const std::optional<double> value = parse_scalar(item_word, p.type);
          if (!value)
            fail_here(quoted(item_word) + " is not a valid " + std::string(name_of(p.type)) + " in list '" + p.name +
                      "'");
          if (is_face_list) face.push_back(*value);
        }
        if (is_face_list) add_face(raw, face, layout.vertex_count, "face", item);
      }
      if (w != words.size())
        fail_here(std::to_string(words.size() - w) + " values too many for a '" + element.name + "' item");
      if (is_vertex) {
        store(raw, layout, values);
        raw.lines.push_back(header.lines);
      }
    }
  }
  while (true) {
    ++header.lines;
    if (!read_line(in, line, kMaxBodyLine, path, header.lines)) break;
    split_words(line, words);
    if (!words.empty()) fail_here("data after the last element (are the header's counts too small?)");
  }
}

// ---- binary ----

template <typename T>
double load(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);
  return static_cast<double>(value);
}

double decode(const unsigned char* bytes, ScalarType type, bool swap) {
  unsigned char b[8];
  const std::size_t n = size_of(type);
  std::memcpy(b, bytes, n);
  if (swap) std::reverse(b, b + n);
  switch (type) {
    case ScalarType::int8:
      return load<std::int8_t>(b);
    case ScalarType::uint8:
      return load<std::uint8_t>(b);
    case ScalarType::int16:
      return load<std::int16_t>(b);
    case ScalarType::uint16:
      return load<std::uint16_t>(b);
    case ScalarType::int32:
      return load<std::int32_t>(b);
    case ScalarType::uint32:
      return load<std::uint32_t>(b);
    case ScalarType::float32:
      return load<float>(b);
    case ScalarType::float64:
      return load<double>(b);
  }
  return 0.0;
}

class BinaryBody {
 public:
  BinaryBody(std::istream& in, std::uint64_t bytes_left, bool swap, const std::string& path)
      : in_(in), bytes_left_(bytes_left), swap_(swap), path_(path) {}

  std::uint64_t bytes_left() const { return bytes_left_; }

  // `layout` for the vertex element, else null; `faces` for the face element's index list, else kNone.
  void read_element(const Element& element, const VertexLayout* layout, RawPointFile& raw, std::size_t faces = kNone,
                    std::uint64_t vertex_count = 0) {
    faces_ = faces;
    vertex_count_ = vertex_count;
    check_count_fits(element, element.min_binary_bytes(), bytes_left_, path_);
    if (element.count == 0 || element.properties.empty()) return;
    if (layout) raw.points.reserve(element.count);
    if (element.has_lists()) {
      for (std::uint64_t item = 0; item < element.count; ++item) read_item_with_lists(element, item, layout, raw);
      return;
    }
    const std::uint64_t record = element.min_binary_bytes();
    if (!layout) {
      skip(element.count * record, element, 0);  // fits: checked above
      return;
    }
    // Fixed-size vertices: read many records at once.
    std::vector<std::size_t> offsets;
    for (std::size_t k = 0, offset = 0; k < element.properties.size(); ++k) {
      offsets.push_back(offset);
      offset += size_of(element.properties[k].type);
    }
    const std::uint64_t batch = std::max<std::uint64_t>(1, (std::uint64_t{1} << 16) / record);
    for (std::uint64_t first = 0; first < element.count; first += batch) {
      const std::uint64_t n = std::min(batch, element.count - first);
      take(static_cast<std::size_t>(n * record), element, first);
      for (std::uint64_t i = 0; i < n; ++i) {
        const unsigned char* bytes = buffer_.data() + i * record;
        VertexValues values{};
        for (std::size_t k = 0; k < element.properties.size(); ++k)
          if (layout->slot[k] >= 0)
            values[static_cast<std::size_t>(layout->slot[k])] =
                decode(bytes + offsets[k], element.properties[k].type, swap_);
        store(raw, *layout, values);
      }
    }
  }

 private:
  void read_item_with_lists(const Element& element, std::uint64_t item, const VertexLayout* layout, RawPointFile& raw) {
    VertexValues values{};
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
      const Property& p = element.properties[k];
      if (!p.is_list) {
        take(size_of(p.type), element, item);
        if (layout && layout->slot[k] >= 0)
          values[static_cast<std::size_t>(layout->slot[k])] = decode(buffer_.data(), p.type, swap_);
        continue;
      }
      take(size_of(p.count_type), element, item);
      const double length = decode(buffer_.data(), p.count_type, swap_);
      if (length < 0.0)
        fail(path_, quoted(element.name) + " item " + std::to_string(item) + ": negative list length " +
                        std::to_string(static_cast<std::int64_t>(length)) + " for '" + p.name + "'");
      if (k == faces_) {
        const std::size_t size = size_of(p.type);
        take(static_cast<std::size_t>(length) * size, element, item);
        face_.clear();
        for (std::size_t j = 0; j < static_cast<std::size_t>(length); ++j)
          face_.push_back(decode(buffer_.data() + j * size, p.type, swap_));
        add_face(raw, face_, vertex_count_, "face", item);
        continue;
      }
      // length < 2^32 and an item is at most 8 bytes: no overflow.
      skip(static_cast<std::uint64_t>(length) * size_of(p.type), element, item);
    }
    if (layout) store(raw, *layout, values);
  }

  void truncated(const Element& element, std::uint64_t item) const {
    fail(path_, "truncated: the file ends inside '" + element.name + "' item " + std::to_string(item) + " of the " +
                    std::to_string(element.count) + " the header promises");
  }

  // Reads n bytes into buffer_.
  void take(std::size_t n, const Element& element, std::uint64_t item) {
    if (n > bytes_left_) truncated(element, item);
    buffer_.resize(n);
    in_.read(reinterpret_cast<char*>(buffer_.data()), static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(in_.gcount()) != n) truncated(element, item);
    bytes_left_ -= n;
  }

  void skip(std::uint64_t n, const Element& element, std::uint64_t item) {
    if (n > bytes_left_) truncated(element, item);
    // Short skips (list items) are read, so that the stream's buffer is kept;
    // long ones (whole elements) seek.
    if (n <= 4096) {
      take(static_cast<std::size_t>(n), element, item);
      return;
    }
    in_.seekg(static_cast<std::streamoff>(n), std::ios::cur);
    if (!in_) truncated(element, item);
    bytes_left_ -= n;
  }

  std::istream& in_;
  std::uint64_t bytes_left_;
  bool swap_;
  const std::string& path_;
  std::vector<unsigned char> buffer_;
  std::size_t faces_ = kNone;
  std::uint64_t vertex_count_ = 0;
  std::vector<double> face_;
};

}  // namespace

RawPointFile read_ply(std::istream& in, std::uint64_t file_size, const std::string& path) {
  RawPointFile raw;
  raw.path = path;
  Header header = read_header(in, path);
  const VertexLayout layout = vertex_layout(header, path);
  raw.declared_dimension = header.declared.dimension;
  raw.declared_spacing = header.declared.spacing;
  raw.has_normals = layout.has_normals;
  raw.has_faces = layout.face_element != kNone;
  const std::streamoff header_bytes = in.tellg();
  if (header_bytes < 0) fail(path, "cannot tell where the header ends");
  const std::uint64_t bytes_left = file_size - std::min(file_size, static_cast<std::uint64_t>(header_bytes));
  if (header.encoding == Encoding::ascii) {
    read_ascii_body(in, bytes_left, header, layout, raw);
    return raw;
  }
  const std::endian file_order =
      header.encoding == Encoding::binary_little_endian ? std::endian::little : std::endian::big;
  BinaryBody body(in, bytes_left, file_order != std::endian::native, path);
  for (std::size_t e = 0; e < header.elements.size(); ++e)
    body.read_element(header.elements[e], e == layout.element ? &layout : nullptr, raw,
                      e == layout.face_element ? layout.face_property : kNone, layout.vertex_count);
  if (body.bytes_left() > 0)
    raw.warnings.push_back(path + ": " + std::to_string(body.bytes_left()) +
                           " bytes after the last element were ignored");
  return raw;
}

std::uint64_t ply_face_count(std::istream& in, const std::string& path) {
  const Header header = read_header(in, path);
  const VertexLayout layout = vertex_layout(header, path);
  return layout.face_element == kNone ? 0 : header.elements[layout.face_element].count;
}

void write_ply(FileSink& out, const PointSet<3>& points, int dimension, bool with_normals, double spacing,
               PointFileFormat format) {
  std::string text = "ply\nformat ";
  text += format == PointFileFormat::ply_ascii                  ? "ascii"
          : format == PointFileFormat::ply_binary_little_endian ? "binary_little_endian"
                                                                : "binary_big_endian";
  text += " 1.0\n";
  for (const std::string& comment : amls_comment_lines(dimension, spacing)) text += "comment " + comment + "\n";
  text += "element vertex " + std::to_string(points.size()) + "\nproperty double x\nproperty double y\nproperty double z\n";
  if (with_normals) text += "property double nx\nproperty double ny\nproperty double nz\n";
  // The rim marks, so that resampling this file keeps its rim where this resample put it.
  if (!points.rim.empty() && points.rim.size() != points.size())
    throw std::logic_error("write_ply: " + std::to_string(points.rim.size()) + " rim marks for " +
                           std::to_string(points.size()) + " points");
  const bool with_rim = std::any_of(points.rim.begin(), points.rim.end(), [](std::uint8_t m) { return m != 0; });
  if (with_rim) text += "property uchar " + std::string(kRimProperty) + "\n";
  text += "end_header\n";
  out.write(text);
  const int values = with_normals ? 6 : 3;
  auto value = [&](std::size_t i, int k) { return k < 3 ? points.positions[i][k] : points.normals[i][k - 3]; };
  if (format == PointFileFormat::ply_ascii) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      text.clear();
      for (int k = 0; k < values; ++k) {
        if (k > 0) text += ' ';
        append_double(text, value(i, k));
      }
      if (with_rim) text += points.rim[i] != 0 ? " 1" : " 0";
      text += '\n';
      out.write(text);
    }
    return;
  }
  const std::endian order =
      format == PointFileFormat::ply_binary_little_endian ? std::endian::little : std::endian::big;
  char record[6 * sizeof(double) + 1];
  const std::size_t record_size = static_cast<std::size_t>(values) * sizeof(double) + (with_rim ? 1 : 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int k = 0; k < values; ++k) {
      char* bytes = record + k * sizeof(double);
      const double v = value(i, k);
      std::memcpy(bytes, &v, sizeof v);
      if (order != std::endian::native) std::reverse(bytes, bytes + sizeof v);
    }
    if (with_rim) record[record_size - 1] = points.rim[i] != 0 ? 1 : 0;
    out.write(std::string_view(record, record_size));
  }
}

}  // namespace amls::detail
