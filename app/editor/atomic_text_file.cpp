#include "app/editor/atomic_text_file.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace amls::editor {

void write_text_atomically(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.filename().empty()) throw std::runtime_error(path + ": not a file name");
  std::string name = target.filename().string();
  name.insert(0, 1, '.');  // hidden while incomplete
  name += ".tmp" + std::to_string(::getpid());
  const fs::path temporary = target.parent_path() / name;
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) throw std::runtime_error(path + ": cannot create " + temporary.string());
      out << text;
      out.flush();
      if (!out) throw std::runtime_error(path + ": write failed");
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) throw std::runtime_error(path + ": cannot replace the file: " + error.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

}  // namespace amls::editor
