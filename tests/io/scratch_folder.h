// Folders of their own for the files a test makes: a path unique to the
// running test and process, and a fixture that makes it and removes it at
// the end; the io tests write outputs and inputs there.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace csgray::test {

// temp/<prefix><pid>_<test's name>, one level deep: a parameterised
// test's name holds a '/' ("IsPrintableAndReadsBackInEveryFormat/torus"),
// which would nest the folder inside one that removing it leaves behind.
inline std::filesystem::path scratchPathFor(const std::string& prefix) {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::replace(name.begin(), name.end(), '/', '_');
  return std::filesystem::temp_directory_path() /
         (prefix + std::to_string(::getpid()) + "_" + name);
}

class ScratchFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchPathFor("csgray_");
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // The path of a file in the folder; path("") is the folder itself.
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  std::filesystem::path dir_;
};

}  // namespace csgray::test
