// The text of a file in tests/fixtures/, for the readers' tests
// (test_io.cpp, test_io_tags.cpp).
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace subdivlab {

/// tests/fixtures/`name` byte for byte.
inline std::string fixture_text(const std::string& name) {
  std::ifstream in(std::string(FIXTURES_DIR) + "/" + name, std::ios::binary);
  EXPECT_TRUE(in.good()) << name;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace subdivlab
