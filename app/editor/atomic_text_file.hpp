#pragma once
// Text files written whole or not at all (the editor's saved scenes).
#include <string>

namespace amls::editor {

// Writes `text` to a hidden temporary file beside `path` and renames it over
// `path`: a failure leaves any previous file intact. Throws std::runtime_error
// naming the path. (The scenes branch adds core's write_text_file for the same.)
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace amls::editor
