#include <doctest/doctest.h>

#include <fstream>

#include "app/editor/directory_listing.hpp"
#include "temp_dir.hpp"

using namespace amls::editor;

TEST_CASE("a folder lists its sub-folders first, then the files the editor opens, by name") {
  amls::test::TempDir dir;
  for (const char* name : {"b.XYZ", "a.ply", "c.json", "d.off", "notes.md", ".hidden.ply"})
    std::ofstream(dir.file(name)) << "x";
  std::filesystem::create_directory(dir.file("shapes"));
  const DirectoryListing listing = list_directory(dir.file(""));
  CHECK(listing.error.empty());
  REQUIRE(listing.entries.size() == 5);
  CHECK(listing.entries[0].name == "shapes");
  CHECK(listing.entries[0].is_directory);
  CHECK(listing.entries[1].name == "a.ply");
  CHECK(listing.entries[1].size == 1);
  CHECK(listing.entries[2].name == "b.XYZ");
  CHECK(listing.entries[3].name == "c.json");
  CHECK(listing.entries[4].name == "d.off");
  CHECK(listing.path.filename() != "");
}

TEST_CASE("a folder that cannot be read gives a message and no entries") {
  const DirectoryListing listing = list_directory("/nonexistent/folder");
  CHECK(listing.entries.empty());
  CHECK(listing.error.find("/nonexistent/folder") != std::string::npos);
}

TEST_CASE("openable files are point sets, meshes and scenes, in any case") {
  CHECK(is_openable_file("x.PLY"));
  CHECK(is_openable_file("/a/b.xyz"));
  CHECK(is_openable_file("s.json"));
  for (const char* name : {"a.OFF", "b.pwn", "c.csv", "d.txt"}) CHECK(is_openable_file(name));
  CHECK(is_openable_file("x.obj"));
  CHECK(is_openable_file("x.STL"));
  CHECK(!is_openable_file("x.3mf"));
  CHECK(!is_openable_file("ply"));
}
