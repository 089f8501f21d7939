// A uniformly distributed double in [lo, hi) for the randomised tests (one helper for every test
// file: the test files of a layer are compiled in unity units, CMakeLists.txt).
#pragma once

#include <random>

namespace geovis::testing_support {

inline double uni(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

}  // namespace geovis::testing_support
