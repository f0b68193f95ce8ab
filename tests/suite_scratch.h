// What the tests of one suite share: a folder for files every test reads and none changes.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace ncube {

// The suite's scratch folder when the suite runs as `unit_tests --suite NAME` (which creates it
// and removes it afterwards: tests/unit_main.cpp), else a folder of this process's own, so a
// test run alone (--gtest_filter) makes what it needs itself.
inline std::filesystem::path suite_scratch(const std::string& name) {
  // This process's own folder, removed when the process ends.
  struct Own {
    std::filesystem::path path =
        std::filesystem::path(testing::TempDir()) / ("ncube_tests_" + std::to_string(getpid()));
    ~Own() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  const char* shared = std::getenv("NCUBE_SUITE_SCRATCH");
  static Own own;
  const std::filesystem::path dir = (shared ? std::filesystem::path(shared) : own.path) / name;
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace ncube
