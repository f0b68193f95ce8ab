// The files a model names (src/models/recording_io.h): read only inside the model's own folder
// or one named with --model-folder, whichever way they escape it (absolute path, file: URI,
// .., a symbolic link), for OBJ and glTF alike, and with one outcome whether the model itself
// is named by a relative or an absolute path. Every message is worked out here from the
// folder layout alone.
#include "models/recording_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "models/model_import.h"
#include "util/input_error.h"

namespace ncube {
namespace {

namespace fs = std::filesystem;

const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl light\nf 1 2 3 4\n";
const char* kLibrary = "newmtl light\nKe 1 1 1\nKd 0.5 0.5 0.5\n";

// A glTF triangle whose one buffer is `uri` (36 bytes: three float32 points).
std::string gltf(const std::string& uri) {
  return R"({"asset":{"version":"2.0"},"buffers":[{"uri":")" + uri +
         R"(","byteLength":36}],)"
         R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,)"
         R"("componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],)"
         R"("materials":[{"name":"light","emissiveFactor":[1,1,1]}],)"
         R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
}

std::string triangle_bytes() {
  const float points[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  return std::string(reinterpret_cast<const char*>(points), sizeof points);
}

// <dir>/model/ holds the models, <dir>/outside/ what they must not reach.
struct ModelReferences : testing::Test {
  fs::path dir, model, outside;
  fs::path cwd = fs::current_path();
  void SetUp() override {
    dir = fs::path(testing::TempDir()) /
          ("recording_io_" +
           std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir / "model" / "sub");
    fs::create_directories(dir / "outside");
    dir = fs::canonical(dir);
    model = dir / "model";
    outside = dir / "outside";
    std::ofstream(outside / "secret.mtl") << kLibrary;
    std::ofstream(outside / "secret.bin", std::ios::binary) << triangle_bytes();
    std::ofstream(model / "inside.mtl") << kLibrary;
    std::ofstream(model / "inside.bin", std::ios::binary) << triangle_bytes();
    fs::create_symlink("../outside/secret.mtl", model / "link.mtl");
    fs::create_symlink("../outside/secret.bin", model / "link.bin");
  }
  void TearDown() override {
    fs::current_path(cwd);
    fs::remove_all(dir);
  }
  // Writes model/<name> and imports it, named by an absolute path, then by a relative one
  // (from <dir>); returns the message (the same both ways, less the model's name) or "".
  std::string outcome(const std::string& name, const std::string& text,
                      ImportOptions options = {}) {
    std::ofstream(model / name, std::ios::binary) << text;
    std::string messages[2];
    for (const bool absolute : {true, false}) {
      fs::current_path(dir);
      const std::string path = absolute ? (model / name).string() : "model/" + name;
      ImportSummary summary;
      try {
        import_model(path, options, summary);
      } catch (const InputError& e) {
        std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        messages[absolute] = message.substr(path.size());
      }
      fs::current_path(cwd);
    }
    EXPECT_EQ(messages[0], messages[1]) << "relative and absolute model paths differ";
    return messages[1];
  }
  std::string escapes(const std::string& reference, const std::string& why) const {
    return ": names " + reference + ", which lies outside the model's folder " + model.string() +
           " (" + why +
           "); a model reads only files in its own folder or one named with "
           "--model-folder";
  }
};

TEST_F(ModelReferences, ObjLibraryInsideIsRead) {
  EXPECT_EQ(outcome("a.obj", "mtllib inside.mtl\n" + std::string(kSquare)), "");
  // A .. that stays inside the folder is inside.
  EXPECT_EQ(outcome("b.obj", "mtllib sub/../inside.mtl\n" + std::string(kSquare)), "");
}

TEST_F(ModelReferences, ObjLibraryEscapingIsRefused) {
  const std::string absolute = (outside / "secret.mtl").string();
  EXPECT_EQ(outcome("a.obj", "mtllib " + absolute + "\n" + kSquare),
            escapes(absolute, "an absolute path"));
  EXPECT_EQ(outcome("b.obj", "mtllib ../outside/secret.mtl\n" + std::string(kSquare)),
            escapes("../outside/secret.mtl", "a .. path"));
  EXPECT_EQ(outcome("c.obj", "mtllib link.mtl\n" + std::string(kSquare)),
            escapes("link.mtl", "through a symbolic link"));
  EXPECT_EQ(outcome("d.obj", "mtllib file://" + absolute + "\n" + kSquare),
            ": names file://" + absolute +
                ", a file: URI (a model names its files by paths relative to its folder)");
}

TEST_F(ModelReferences, GltfBufferInsideIsRead) {
  EXPECT_EQ(outcome("a.gltf", gltf("inside.bin")), "");
}

TEST_F(ModelReferences, GltfBufferEscapingIsRefused) {
  const std::string absolute = (outside / "secret.bin").string();
  EXPECT_EQ(outcome("a.gltf", gltf(absolute)), escapes(absolute, "an absolute path"));
  EXPECT_EQ(outcome("b.gltf", gltf("../outside/secret.bin")),
            escapes("../outside/secret.bin", "a .. path"));
  EXPECT_EQ(outcome("c.gltf", gltf("link.bin")), escapes("link.bin", "through a symbolic link"));
  EXPECT_EQ(outcome("d.gltf", gltf("file://" + absolute)),
            ": names file://" + absolute +
                ", a file: URI (a model names its files by paths relative to its folder)");
}

TEST_F(ModelReferences, ModelFolderOptionAllowsAFolder) {
  ImportOptions options;
  options.model_folders = {outside.string()};
  const std::string absolute = (outside / "secret.bin").string();
  EXPECT_EQ(outcome("a.gltf", gltf(absolute), options), "");
  EXPECT_EQ(outcome("b.gltf", gltf("../outside/secret.bin"), options), "");
  EXPECT_EQ(outcome("c.obj", "mtllib link.mtl\n" + std::string(kSquare), options), "");
  options.model_folders = {(dir / "none").string()};
  ImportSummary summary;
  try {
    import_model((model / "a.gltf").string(), options, summary);
    FAIL() << "a missing --model-folder was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--model-folder " + (dir / "none").string() +
                                         ": not a folder (No such file or directory)");
  }
}

TEST_F(ModelReferences, PartsThatAreNoFiles) {
  ASSERT_EQ(mkfifo((model / "fifo.bin").c_str(), 0600), 0);
  EXPECT_NE(outcome("a.gltf", gltf("fifo.bin"))
                .find("fifo.bin: model part is a FIFO, not a regular file"),
            std::string::npos);
  ASSERT_EQ(mkfifo((model / "fifo.mtl").c_str(), 0600), 0);
  EXPECT_NE(outcome("b.obj", "mtllib fifo.mtl\n" + std::string(kSquare))
                .find("fifo.mtl: model part is a FIFO, not a regular file"),
            std::string::npos);
  fs::create_symlink("loop2.bin", model / "loop1.bin");
  fs::create_symlink("loop1.bin", model / "loop2.bin");
  EXPECT_NE(outcome("c.gltf", gltf("loop1.bin"))
                .find("loop1.bin: cannot open model part: a loop of symbolic links"),
            std::string::npos);
  // /dev/zero behind an innocent name is outside the folder before it is a device.
  fs::create_symlink("/dev/zero", model / "zero.bin");
  EXPECT_EQ(outcome("d.gltf", gltf("zero.bin")), escapes("zero.bin", "through a symbolic link"));
  ImportOptions anywhere;
  anywhere.model_folders = {"/dev"};
  EXPECT_NE(outcome("e.gltf", gltf("zero.bin"), anywhere)
                .find("zero.bin: model part is a character device"),
            std::string::npos);
}

TEST_F(ModelReferences, ModelThatIsALinkLoop) {
  fs::create_symlink("loop2.obj", model / "loop1.obj");
  fs::create_symlink("loop1.obj", model / "loop2.obj");
  ImportSummary summary;
  try {
    import_model((model / "loop1.obj").string(), {}, summary);
    FAIL() << "a loop was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (model / "loop1.obj").string() +
                                         ": cannot open model file: a loop of symbolic links");
  }
}

TEST(LiesIn, ComparesWholeNames) {
  EXPECT_TRUE(models::lies_in("/a/b/c", "/a/b"));
  EXPECT_TRUE(models::lies_in("/a/b", "/a/b"));
  EXPECT_FALSE(models::lies_in("/a/bc", "/a/b"));
  EXPECT_FALSE(models::lies_in("/a", "/a/b"));
  EXPECT_TRUE(models::lies_in("/a", "/"));
}

}  // namespace
}  // namespace ncube
