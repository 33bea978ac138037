#include <doctest/doctest.h>

#include <filesystem>

#include "core/util/staged_directory.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;
namespace fs = std::filesystem;

TEST_CASE("staged directory: the output appears only on commit, and a failed run leaves only DIR.partial") {
  TempDir dir;
  const std::string out = dir.file("frames");
  {
    StagedDirectory staged(out, "report.json");
    write_text(staged.file("frame_00000.ply"), "x");
    CHECK(fs::exists(out + ".partial/frame_00000.ply"));
    CHECK_FALSE(fs::exists(out));
    // A run that fails before writing its marker cannot commit.
    CHECK_THROWS_WITH(staged.commit(), doctest::Contains("report.json was not written"));
  }
  CHECK_FALSE(fs::exists(out));
  {
    StagedDirectory staged(out, "report.json");  // clears what the failed run left
    CHECK_FALSE(fs::exists(out + ".partial/frame_00000.ply"));
    write_text(staged.file("frame_00001.ply"), "y");
    write_text(staged.file("report.json"), "{}");
    staged.commit();
  }
  CHECK(fs::exists(out + "/frame_00001.ply"));
  CHECK_FALSE(fs::exists(out + ".partial"));
  {
    // An earlier complete output is replaced whole.
    StagedDirectory staged(out + "/", "report.json");
    write_text(staged.file("report.json"), "{}");
    staged.commit();
  }
  CHECK_FALSE(fs::exists(out + "/frame_00001.ply"));
  CHECK(fs::exists(out + "/report.json"));
  // A directory that is not an earlier output is never replaced.
  fs::create_directory(dir.file("mine"));
  write_text(dir.file("mine/notes.txt"), "keep");
  CHECK_THROWS_WITH(StagedDirectory(dir.file("mine"), "report.json"), doctest::Contains("is not an earlier output"));
  CHECK(fs::exists(dir.file("mine/notes.txt")));
}
