// The solution mesh (--mesh): a real run of simulate writes it beside the result file; Assimp
// reads it back (the library viewers use); a reader written here from the PLY specification
// reads the raw doubles. Checked against values worked out independently of the writer: the
// result file's patch radiosities (area-weighted means of the elements), the sRGB formula, and
// the absence of T-junction cracks with adaptive subdivision.
#include <assimp/Importer.hpp>
#include <assimp/mesh.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "suite_scratch.h"

namespace {

namespace fs = std::filesystem;

struct PlyVertex {
  std::array<double, 3> position;
  std::array<std::uint8_t, 3> colour;
  std::array<double, 3> radiosity;
};
struct PlyFace {
  std::vector<int> vertices;
  int patch = 0, element = 0;
  std::array<double, 3> radiosity;
};
struct Ply {
  double exposure = 0;
  std::vector<PlyVertex> vertices;
  std::vector<PlyFace> faces;
};

template <typename T>
T take(std::istream& in) {
  T value;
  in.read(reinterpret_cast<char*>(&value), sizeof value);  // the test host is little-endian
  return value;
}

// Reads the layout simulate documents (src/models/solution_mesh.h), checking the header.
Ply read_ply(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  Ply ply;
  std::string line, header;
  std::size_t vertices = 0, faces = 0;
  bool wide = false;
  while (std::getline(in, line) && line != "end_header") {
    header += line + "\n";
    std::istringstream words(line);
    std::string a, b;
    words >> a >> b;
    if (a == "element" && b == "vertex") words >> vertices;
    if (a == "element" && b == "face") words >> faces;
    if (a == "comment" && b == "exposure") words >> ply.exposure;
    if (a == "property" && b == "list") wide = line.find("list uint ") != std::string::npos;
  }
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("property double radiosity_r"), std::string::npos);
  for (std::size_t i = 0; i < vertices; ++i) {
    PlyVertex v;
    for (double& x : v.position) x = take<double>(in);
    for (std::uint8_t& c : v.colour) c = take<std::uint8_t>(in);
    for (double& r : v.radiosity) r = take<double>(in);
    ply.vertices.push_back(v);
  }
  for (std::size_t i = 0; i < faces; ++i) {
    PlyFace f;
    const std::uint32_t n = wide ? take<std::uint32_t>(in) : take<std::uint8_t>(in);
    for (std::uint32_t k = 0; k < n; ++k) f.vertices.push_back(take<std::int32_t>(in));
    f.patch = take<std::int32_t>(in);
    f.element = take<std::int32_t>(in);
    for (double& r : f.radiosity) r = take<double>(in);
    ply.faces.push_back(f);
  }
  EXPECT_TRUE(in.good());
  EXPECT_EQ(in.peek(), EOF) << "bytes after the last face";
  return ply;
}

// The polygon's area (a planar polygon, by the cross products of a fan).
double area(const Ply& ply, const PlyFace& f) {
  const auto& p0 = ply.vertices[std::size_t(f.vertices[0])].position;
  double n[3] = {0, 0, 0};
  for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k) {
    const auto& a = ply.vertices[std::size_t(f.vertices[k])].position;
    const auto& b = ply.vertices[std::size_t(f.vertices[k + 1])].position;
    const double u[3] = {a[0] - p0[0], a[1] - p0[1], a[2] - p0[2]};
    const double v[3] = {b[0] - p0[0], b[1] - p0[1], b[2] - p0[2]};
    n[0] += u[1] * v[2] - u[2] * v[1];
    n[1] += u[2] * v[0] - u[0] * v[2];
    n[2] += u[0] * v[1] - u[1] * v[0];
  }
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

struct SolutionMesh : testing::Test {
  fs::path dir;
  Ply ply;
  nlohmann::json result;

  void SetUp() override {
    const char* simulate = std::getenv("NCUBE_SIMULATE");
    if (!simulate) GTEST_SKIP() << "NCUBE_SIMULATE is not set (ctest sets it)";
    // One run for the whole suite (every test reads it, none changes it): the suite's scratch
    // folder, where the first test to run writes it, then marks it done.
    dir = ncube::suite_scratch("solution_mesh");
    if (!fs::exists(dir / "done")) {
      // Adaptive subdivision: elements of several levels side by side, T-vertices on edges.
      const std::string command = std::string(simulate) +
                                  " cornell-box.json --R 2 --iterations 12 --subdivide --quiet"
                                  " --json " + (dir / "r.json").string() +
                                  " --mesh " + (dir / "m.ply").string();
      ASSERT_EQ(std::system(command.c_str()), 0) << command;
      std::ofstream(dir / "done") << "simulate's run for every test of the suite\n";
    }
    ply = read_ply(dir / "m.ply");
    std::ifstream in(dir / "r.json");
    result = nlohmann::json::parse(in);
  }
};

TEST_F(SolutionMesh, HasOneFacePerElementAndThePatchRadiosities) {
  ASSERT_EQ(ply.faces.size(), result["elements_at_end"].get<std::size_t>());
  const nlohmann::json& patches = result["patch_radiosity"];
  std::vector<std::array<double, 4>> sums(patches.size(), {0, 0, 0, 0});
  for (const PlyFace& f : ply.faces) {
    const double a = area(ply, f);
    for (int c = 0; c < 3; ++c) sums[std::size_t(f.patch)][std::size_t(c)] += a * f.radiosity[std::size_t(c)];
    sums[std::size_t(f.patch)][3] += a;
  }
  for (std::size_t p = 0; p < patches.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double expected = patches[p][std::size_t(c)].get<double>();
      EXPECT_NEAR(sums[p][std::size_t(c)] / sums[p][3], expected, 1e-9 * (1 + expected))
          << "patch " << p << " channel " << c;
    }
}

// No vertex of a patch lies inside an edge of a face of that patch: every T-vertex a finer
// neighbour puts on a coarse element's edge is a vertex of the coarse face too.
TEST_F(SolutionMesh, HasNoTJunctionCracks) {
  std::map<int, std::vector<int>> patch_vertices;
  for (const PlyFace& f : ply.faces)
    for (int v : f.vertices) patch_vertices[f.patch].push_back(v);
  int t_vertices = 0, cracks = 0;
  for (const PlyFace& f : ply.faces) {
    t_vertices += int(f.vertices.size()) - 4 > 0 ? int(f.vertices.size()) - 4 : 0;
    for (std::size_t k = 0; k < f.vertices.size(); ++k) {
      const auto& a = ply.vertices[std::size_t(f.vertices[k])].position;
      const auto& b = ply.vertices[std::size_t(f.vertices[(k + 1) % f.vertices.size()])].position;
      const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double length2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
      for (int v : patch_vertices[f.patch]) {
        const auto& p = ply.vertices[std::size_t(v)].position;
        const double ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
        const double t = (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / length2;
        if (t <= 1e-9 || t >= 1 - 1e-9) continue;
        const double off[3] = {ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]};
        if (off[0] * off[0] + off[1] * off[1] + off[2] * off[2] < 1e-12 * length2) ++cracks;
      }
    }
  }
  EXPECT_GT(t_vertices, 0) << "the run made no T-vertices: the test would prove nothing";
  EXPECT_EQ(cracks, 0);
}

// Newell's normal of a polygon's corners: twice its vector area, along its front side's normal
// for corners counter-clockwise seen from the front.
std::array<double, 3> newell(const std::vector<std::array<double, 3>>& corners) {
  std::array<double, 3> n{0, 0, 0};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % corners.size()];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

// Every face is wound counter-clockwise seen from its patch's front (src/models/solution_mesh.h),
// the front being the side the scene file's corners give (docs/scene-format.md), read here
// from scenes/cornell-box.json itself: each face's normal points along its patch's, and its
// area is the face's own (no face folded over).
TEST_F(SolutionMesh, FacesAreWoundAsTheirPatchFaces) {
  std::ifstream in(std::string(NCUBE_SOURCE_DIR) + "/scenes/cornell-box.json");
  const nlohmann::json scene = nlohmann::json::parse(in);
  std::vector<std::array<double, 3>> patch_normal;
  for (const nlohmann::json& patch : scene["patches"])
    patch_normal.push_back(newell(patch["vertices"].get<std::vector<std::array<double, 3>>>()));
  ASSERT_EQ(patch_normal.size(), result["patch_radiosity"].size());
  for (std::size_t f = 0; f < ply.faces.size(); ++f) {
    const PlyFace& face = ply.faces[f];
    std::vector<std::array<double, 3>> corners;
    for (int v : face.vertices) corners.push_back(ply.vertices[std::size_t(v)].position);
    const std::array<double, 3> n = newell(corners);
    const std::array<double, 3>& p = patch_normal[std::size_t(face.patch)];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double patch_length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    // cos(angle) between the face's and the patch's normal: 1 for a planar patch's faces
    // (the Cornell box's bent wall is cut into planar triangles, so its faces too).
    EXPECT_GT((n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / (length * patch_length), 0.99)
        << "face " << f << " of patch " << face.patch << " is wound backwards";
    EXPECT_NEAR(0.5 * length, area(ply, face), 1e-9 * area(ply, face)) << "face " << f;
  }
}

// A vertex belongs to one patch (each patch has its own nodal radiosities): where two patches
// meet (the Cornell box's floor and walls share corners) each has its own vertex at the same
// position.
TEST_F(SolutionMesh, VerticesAreNotSharedAcrossPatches) {
  std::vector<int> patch_of_vertex(ply.vertices.size(), -1);
  for (const PlyFace& f : ply.faces)
    for (int v : f.vertices) {
      int& owner = patch_of_vertex[std::size_t(v)];
      EXPECT_TRUE(owner == -1 || owner == f.patch)
          << "vertex " << v << " is used by patches " << owner << " and " << f.patch;
      owner = f.patch;
    }
  std::map<std::array<double, 3>, std::vector<int>> patches_at;
  for (std::size_t v = 0; v < ply.vertices.size(); ++v)
    patches_at[ply.vertices[v].position].push_back(patch_of_vertex[v]);
  int shared_positions = 0;
  for (const auto& [position, patches] : patches_at) {
    std::map<int, int> count;
    for (int patch : patches) ++count[patch];
    for (const auto& [patch, n] : count) EXPECT_EQ(n, 1) << "patch " << patch << " repeats a vertex";
    shared_positions += count.size() > 1;
  }
  EXPECT_GT(shared_positions, 0) << "no two patches meet: the test would prove nothing";
}

// Each vertex's radiosity is a mean of the elements around it: within the range of its
// faces' radiosities. Its colour is the picture's tone mapping of that radiosity.
TEST_F(SolutionMesh, VerticesAreNodalMeansColouredAsThePicture) {
  ASSERT_GT(ply.exposure, 0.0);
  std::vector<std::array<double, 6>> range(ply.vertices.size(), {1e300, 1e300, 1e300, -1e300, -1e300, -1e300});
  for (const PlyFace& f : ply.faces)
    for (int v : f.vertices)
      for (std::size_t c = 0; c < 3; ++c) {
        range[std::size_t(v)][c] = std::min(range[std::size_t(v)][c], f.radiosity[c]);
        range[std::size_t(v)][c + 3] = std::max(range[std::size_t(v)][c + 3], f.radiosity[c]);
      }
  for (std::size_t v = 0; v < ply.vertices.size(); ++v)
    for (std::size_t c = 0; c < 3; ++c) {
      const double r = ply.vertices[v].radiosity[c];
      EXPECT_GE(r, range[v][c] * (1 - 1e-12) - 1e-300) << "vertex " << v;
      EXPECT_LE(r, range[v][c + 3] * (1 + 1e-12) + 1e-300) << "vertex " << v;
      const double linear = std::min(std::max(r * ply.exposure, 0.0), 1.0);
      const double srgb = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
      // The header's exposure is printed to 6 digits: one step of rounding either way.
      EXPECT_NEAR(ply.vertices[v].colour[c], 255 * srgb, 0.5 + 255 * 1e-5) << "vertex " << v;
    }
}

// Assimp (what MeshLab-like tools and the importer use) reads the same faces, positions and
// colours.
TEST_F(SolutionMesh, AssimpReadsTheSameMesh) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "m.ply").string(), 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 1u);
  const aiMesh* mesh = scene->mMeshes[0];
  ASSERT_EQ(mesh->mNumFaces, ply.faces.size());
  ASSERT_TRUE(mesh->HasVertexColors(0));
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    const aiFace& face = mesh->mFaces[f];
    ASSERT_EQ(face.mNumIndices, ply.faces[f].vertices.size()) << "face " << f;
    for (unsigned k = 0; k < face.mNumIndices; ++k) {
      const PlyVertex& ours = ply.vertices[std::size_t(ply.faces[f].vertices[k])];
      const aiVector3D& p = mesh->mVertices[face.mIndices[k]];
      const aiColor4D& c = mesh->mColors[0][face.mIndices[k]];
      EXPECT_NEAR(p.x, ours.position[0], 1e-3 * (1 + std::fabs(ours.position[0])));
      EXPECT_NEAR(p.y, ours.position[1], 1e-3 * (1 + std::fabs(ours.position[1])));
      EXPECT_NEAR(p.z, ours.position[2], 1e-3 * (1 + std::fabs(ours.position[2])));
      EXPECT_NEAR(c.r * 255, ours.colour[0], 0.01);
      EXPECT_NEAR(c.g * 255, ours.colour[1], 0.01);
      EXPECT_NEAR(c.b * 255, ours.colour[2], 0.01);
    }
  }
}

}  // namespace
