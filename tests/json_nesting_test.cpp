// A glTF's nesting is checked before Assimp parses it (src/models/json_nesting.h): Assimp's
// JSON reader recursed once per level and a 400 KB glTF of nested "extras" overflowed the
// stack. The scan counts levels outside strings only, accepts kMaxNestingDepth levels and
// refuses one more, in a .gltf and in a .glb's JSON chunk, with one line naming the file.
#include "models/json_nesting.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "models/model_import.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace ncube::models {
namespace {

namespace fs = std::filesystem;

std::string nested(int levels) { return std::string(std::size_t(levels), '[') + std::string(std::size_t(levels), ']'); }

TEST(JsonNesting, CountsLevelsOutsideStrings) {
  EXPECT_EQ(too_deep_at(nested(16), 16), 32u);   // 16 levels: none too deep
  EXPECT_EQ(too_deep_at(nested(17), 16), 16u);   // the 17th opens at byte 16
  EXPECT_EQ(too_deep_at("{\"a\":[{}]}", 3), 10u);
  EXPECT_EQ(too_deep_at("{\"a\":[{}]}", 2), 6u);
  // Brackets in strings, after escaped quotes and backslashes, are text.
  EXPECT_EQ(too_deep_at(R"(["[[[", "\"[[[", "\\", "{{"])", 1), 28u);  // the whole text
  EXPECT_EQ(too_deep_at(R"(["\\", [[]]])", 2), 8u);  // the third level, after the string
  // Closed levels do not add up.
  EXPECT_EQ(too_deep_at("[[]] [[]] [[]]", 2), 14u);
}

// lamp.gltf with "extras" nested `levels` deep on its asset (the document itself is 2 deep
// there: {"asset": {"extras": ...}}).
std::string lamp_with_extras(int levels) {
  std::ifstream in(std::string(NCUBE_SOURCE_DIR) + "/tests/models/lamp.gltf");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t asset = text.find("\"asset\"");
  const std::size_t brace = text.find('{', asset);
  return text.substr(0, brace + 1) + "\"extras\": " + nested(levels) + ", " + text.substr(brace + 1);
}

struct NestedModel : testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::path(testing::TempDir()) / ("nested_model_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string refusal(const fs::path& path) {
    ImportSummary summary;
    try {
      import_model(path.string(), {}, summary);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(NestedModel, GltfAtTheLimitReadsAndDeeperIsRefused) {
  std::ofstream(dir / "ok.gltf") << lamp_with_extras(kMaxNestingDepth - 2);
  EXPECT_EQ(refusal(dir / "ok.gltf"), "");
  std::ofstream(dir / "over.gltf") << lamp_with_extras(kMaxNestingDepth - 1);
  EXPECT_NE(refusal(dir / "over.gltf").find("JSON nested deeper than 16"), std::string::npos);
  std::ofstream(dir / "deep.gltf") << lamp_with_extras(200000);  // 400 KB: crashed Assimp
  const std::string message = refusal(dir / "deep.gltf");
  EXPECT_EQ(message.rfind((dir / "deep.gltf").string() + ": JSON nested deeper than 16 arrays and objects", 0), 0u)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST_F(NestedModel, GlbJsonChunkIsChecked) {
  std::string json = lamp_with_extras(200000);
  json.resize((json.size() + 3) / 4 * 4, ' ');
  const auto word = [](std::uint32_t w) {
    return std::string{char(w & 0xff), char(w >> 8 & 0xff), char(w >> 16 & 0xff), char(w >> 24 & 0xff)};
  };
  std::ofstream(dir / "deep.glb", std::ios::binary)
      << "glTF" << word(2) << word(std::uint32_t(20 + json.size())) << word(std::uint32_t(json.size())) << "JSON" << json;
  const std::string message = refusal(dir / "deep.glb");
  EXPECT_NE(message.find("deep.glb: JSON nested deeper than 16 arrays and objects"), std::string::npos) << message;
  EXPECT_NE(message.find("(in its JSON chunk)"), std::string::npos) << message;
}

}  // namespace
}  // namespace ncube::models
