// A fresh, empty temporary directory for one test, removed with everything in it at the end. One
// helper for every test executable (the test files of a layer are compiled in unity units, where
// a local copy per file would clash; CMakeLists.txt).
#pragma once

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace geovis::testing_support {

struct TempDir {
  std::filesystem::path path;
  /// <tmp>/geovis_test_<pid>_<test name>_<address>: unique among concurrent tests and processes.
  TempDir() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path = std::filesystem::temp_directory_path() /
           ("geovis_test_" + std::to_string(::getpid()) + "_" + (info ? info->name() : "none") + "_" +
            std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// The path of file `name` in the directory.
  std::string file(const std::string& name) const { return (path / name).string(); }
  /// Writes `text` to file `name` (creating its folders); returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = path / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  /// Number of regular files in the directory.
  int count() const {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(path)) n += e.is_regular_file();
    return n;
  }
};

}  // namespace geovis::testing_support
