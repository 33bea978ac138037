#pragma once
// An output directory that only appears once it is complete (`amls deform
// --out-dir`): files are written into DIR.partial, and commit() renames it to
// DIR. A run that fails or is interrupted leaves DIR.partial, never a DIR that
// looks complete. A complete DIR holds the file named `marker` (written last,
// before commit), which is how an earlier complete output is recognised and
// may be replaced.
#include <string>

namespace amls {

class StagedDirectory {
 public:
  // Checks that `path` can be (re)placed - it must not exist, be an empty
  // directory, or be a directory holding `marker` - and creates path.partial
  // afresh (removing one left by an earlier failed run). Throws
  // std::runtime_error naming the directory otherwise.
  StagedDirectory(std::string path, std::string marker);

  const std::string& path() const { return path_; }
  const std::string& staging_path() const { return staging_; }
  // The path of a file inside the staging directory.
  std::string file(const std::string& name) const;

  // Replaces `path` by the staging directory. Throws std::runtime_error if
  // the marker file was not written or a rename fails.
  void commit();
  bool committed() const { return committed_; }

 private:
  std::string path_;
  std::string staging_;
  std::string marker_;
  bool committed_ = false;
};

}  // namespace amls
