#pragma once
// TempFolderTest: a GoogleTest fixture with a fresh folder under /tmp (`dir`), removed with
// everything in it after each test; path(name) is dir + "/" + name.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <string>

namespace slicereuse::test {

class TempFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char name[] = "/tmp/slicereuse-test-XXXXXX";
    ASSERT_NE(::mkdtemp(name), nullptr);
    dir = name;
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string path(const std::string& name) const { return dir + "/" + name; }
  std::string dir;
};

}  // namespace slicereuse::test
