// The scenes of scenes/, for tests that run on every one of them (INSTANTIATE_TEST_SUITE_P
// over scene_files(), named by scene_test_name).
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace ncube {

// The scene names (file stems), sorted.
inline std::vector<std::string> scene_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(NCUBE_SOURCE_DIR) + "/scenes"))
    if (entry.path().extension() == ".json") files.push_back(entry.path().stem().string());
  std::sort(files.begin(), files.end());
  return files;
}

// A test name for a scene (gtest names allow no '-').
inline std::string scene_test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

}  // namespace ncube
