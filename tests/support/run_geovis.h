// Runs the geovis program in-process (cli/command.h) with `args` after the program name; returns
// its exit code. One helper for the CLI tests (compiled in unity units, CMakeLists.txt).
#pragma once

#include <string>
#include <vector>

#include "cli/command.h"

namespace geovis::testing_support {

inline int run_args(std::vector<std::string> args) {
  args.insert(args.begin(), "geovis");
  std::vector<const char*> argv;
  for (auto& a : args) argv.push_back(a.c_str());
  return cli::run(static_cast<int>(argv.size()), argv.data());
}

}  // namespace geovis::testing_support
