#include "models/model_import.h"

#include <sys/stat.h>

#include <algorithm>
#include <charconv>
#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "models/ply_file.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace ncube {
namespace {

using Point = glm::dvec3;
namespace fs = std::filesystem;

// Assimp holds numbers as floats: 0.6 in a file arrives as 0.60000002384. The shortest
// decimal that reads back as that float is what the file said (as written by any tool that
// wrote it from a float or by hand), and read as a double it is the file's own number, so a
// model gives the same scene as the JSON written with the same numbers.
double as_written(float value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  if (error != std::errc()) return double(value);
  double result = 0.0;
  std::from_chars(text, end, result);
  return result;
}

Point as_written(float x, float y, float z) { return Point(as_written(x), as_written(y), as_written(z)); }

// Tolerances (docs/scene-format.md, "Importing models"), relative to the face's diameter d:
// a quad is kept when its fourth corner is within kPlanarity d of the plane of the first
// three and every corner turns the same way by more than kTurn d^2 (slightly stricter than
// the scene loader's 1e-6 and 1e-12, so a kept quad always loads); a face or triangle whose
// area is at most kFlat d^2 is degenerate; corners within kSame d of each other are one.
constexpr double kPlanarity = 1e-7;
constexpr double kTurn = 1e-9;
constexpr double kFlat = 1e-10;
constexpr double kSame = 1e-12;
constexpr double kDefaultReflectance = 0.5;

// Assimp's file system, noting every file the model reads (the MTL, glTF buffers): the
// model's identity for sweeps and provenance is all of them.
// A file the model names but that is missing (an MTL library) is an error, where Assimp
// would go on with a default material.
class RecordingIOSystem : public Assimp::DefaultIOSystem {
 public:
  RecordingIOSystem(std::vector<std::string>& files, std::vector<std::string>& missing)
      : files_(files), missing_(missing) {}
  bool Exists(const char* file) const override {
    const bool exists = Assimp::DefaultIOSystem::Exists(file);
    if (!exists) note(missing_, file);
    return exists;
  }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    Assimp::IOStream* stream = Assimp::DefaultIOSystem::Open(file, mode);
    note(stream ? files_ : missing_, file);
    return stream;
  }

 private:
  static void note(std::vector<std::string>& list, const char* file) {
    if (std::find(list.begin(), list.end(), file) == list.end()) list.push_back(file);
  }
  std::vector<std::string>& files_;
  std::vector<std::string>& missing_;
};

std::string lower_extension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

std::string show(const Point& p) {
  std::ostringstream text;
  text << p.x << " " << p.y << " " << p.z;
  return text.str();
}

// A vector's length without underflow or overflow of its squares (a model scaled by 1e-100
// has areas near 1e-200, whose squares a plain length would lose).
double norm(const Point& v) {
  const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (m == 0.0 || !std::isfinite(m)) return m;
  const Point u = v / m;
  return m * std::sqrt(glm::dot(u, u));
}

double diameter(const std::vector<Point>& corners) {
  double d = 0.0;
  for (const Point& a : corners)
    for (const Point& b : corners) d = std::max(d, norm(a - b));
  return d;
}

// Newell's normal: twice the vector area of a planar polygon, the best plane of a bent one.
Point newell(const std::vector<Point>& corners) {
  Point n(0.0);
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Point& a = corners[i];
    const Point& b = corners[(i + 1) % corners.size()];
    n += Point((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

bool planar_convex_quad(const std::vector<Point>& q) {
  const double d = diameter(q);
  const Point n = glm::cross(q[1] - q[0], q[2] - q[0]);
  if (norm(n) <= 2 * kFlat * d * d) return false;
  const Point unit = n / norm(n);
  if (std::fabs(glm::dot(q[3] - q[0], unit)) > kPlanarity * d) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point turn = glm::cross(q[i] - q[(i + 3) % 4], q[(i + 1) % 4] - q[i]);
    if (glm::dot(turn, unit) <= kTurn * d * d) return false;
  }
  return true;
}

// Ear clipping in the face's best plane: triangles in the face's own winding, for faces that
// are concave, bent or have more than four corners.
std::vector<std::vector<Point>> triangulate(const std::vector<Point>& corners) {
  const Point normal = newell(corners);
  const Point n = normal / norm(normal);
  const Point u = glm::normalize(std::fabs(n.x) < 0.9 ? glm::cross(n, Point(1, 0, 0))
                                                        : glm::cross(n, Point(0, 1, 0)));
  const Point v = glm::cross(n, u);
  std::vector<glm::dvec2> flat;
  for (const Point& p : corners) flat.emplace_back(glm::dot(p, u), glm::dot(p, v));
  const auto cross2 = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  };
  std::vector<std::size_t> left(corners.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = i;
  std::vector<std::vector<Point>> triangles;
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
      const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k],
                        c = left[(k + 1) % left.size()];
      if (cross2(flat[a], flat[b], flat[c]) <= 0) continue;  // reflex (or straight) corner
      bool inside = false;
      for (std::size_t p : left) {
        if (p == a || p == b || p == c) continue;
        if (cross2(flat[a], flat[b], flat[p]) >= 0 && cross2(flat[b], flat[c], flat[p]) >= 0 &&
            cross2(flat[c], flat[a], flat[p]) >= 0)
          inside = true;
      }
      if (inside) continue;
      triangles.push_back({corners[a], corners[b], corners[c]});
      left.erase(left.begin() + std::ptrdiff_t(k));
      clipped = true;
    }
    if (!clipped) {  // a self-intersecting outline: a fan keeps what can be kept
      for (std::size_t k = 1; k + 1 < left.size(); ++k)
        triangles.push_back({corners[left[0]], corners[left[k]], corners[left[k + 1]]});
      return triangles;
    }
  }
  triangles.push_back({corners[left[0]], corners[left[1]], corners[left[2]]});
  return triangles;
}

// A quad that is not planar (or not convex) is cut along its diagonal from corner 0 when
// both halves face the quad's way (the usual convention, as scenes/generate cuts the Cornell
// box's bent wall); other faces by ear clipping.
std::vector<std::vector<Point>> split(const std::vector<Point>& corners) {
  if (corners.size() == 4) {
    const Point n = newell(corners);
    const std::vector<Point> a{corners[0], corners[1], corners[2]}, b{corners[2], corners[3], corners[0]};
    if (glm::dot(newell(a), n) > 0.0 && glm::dot(newell(b), n) > 0.0) return {a, b};
  }
  return triangulate(corners);
}

bool flat(const std::vector<Point>& polygon) {
  const double d = diameter(polygon);
  return d == 0.0 || 0.5 * norm(newell(polygon)) <= kFlat * d * d;
}

struct Material {
  Point reflectance{kDefaultReflectance};
  Point emission{0.0};
};

// A material's reflectance and emission, checked: never a silent clamp.
Material read_material(const aiMaterial& m, const std::string& where) {
  Material result;
  aiColor4D colour;
  if (m.Get(AI_MATKEY_BASE_COLOR, colour) == aiReturn_SUCCESS ||
      m.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == aiReturn_SUCCESS)
    result.reflectance = as_written(colour.r, colour.g, colour.b);
  aiColor3D emissive;
  if (m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == aiReturn_SUCCESS)
    result.emission = as_written(emissive.r, emissive.g, emissive.b);
  for (int c = 0; c < 3; ++c) {
    if (!(result.reflectance[c] >= 0.0 && result.reflectance[c] < 1.0))
      throw InputError(where + ": reflectance (Kd, base colour) " + show(result.reflectance) +
                       ": each channel must be in [0, 1) (1 would never lose energy)");
    if (!(result.emission[c] >= 0.0) || !std::isfinite(result.emission[c]))
      throw InputError(where + ": emission (Ke, emissive) " + show(result.emission) +
                       ": each channel must be finite and not negative");
  }
  return result;
}

// --light NAME[=R,G,B]: the emission it gives the material or mesh called NAME.
// `used` notes each --light that named something: one that names nothing (a typing error)
// is refused after the model is read, not ignored.
bool light_for(const std::vector<std::string>& lights, const std::string& name, Point& emission,
               std::vector<bool>& used) {
  for (std::size_t k = 0; k < lights.size(); ++k) {
    const std::string& light = lights[k];
    const std::size_t equals = light.find('=');
    if (light.substr(0, equals) != name) continue;
    used[k] = true;
    emission = Point(1.0);
    if (equals != std::string::npos) {
      std::istringstream values(light.substr(equals + 1));
      char comma1 = 0, comma2 = 0;
      if (!(values >> emission.r >> comma1 >> emission.g >> comma2 >> emission.b) ||
          comma1 != ',' || comma2 != ',' || !values.eof() || !(emission.r >= 0) ||
          !(emission.g >= 0) || !(emission.b >= 0) || !std::isfinite(emission.r + emission.g + emission.b))
        throw InputError("--light " + light + ": expected NAME or NAME=R,G,B with finite R, G, B >= 0");
    }
    return true;
  }
  return false;
}

// The element grid of a patch: `count` elements shaped after its two edge lengths, or cells
// of about `size` on a side.
std::pair<long, long> grid(const std::vector<Point>& corners, double size, double count) {
  const double a = norm(corners[1] - corners[0]);
  const double b = norm(corners.back() - corners[0]);
  // Counted in doubles and bounded before they become integers (a size of 1e-300 gives an
  // infinite count): at most 2^10 a side, 2^20 a patch (the loader's limit).
  const double most = double(1L << 10);
  double nu = 1, nv = 1;
  if (size > 0.0) {
    nu = std::ceil(a / size - 1e-9);
    nv = std::ceil(b / size - 1e-9);
  } else {
    nu = std::round(std::sqrt(count * a / b));
    nv = std::round(count / std::clamp(nu, 1.0, most));
  }
  return {long(std::clamp(nu, 1.0, most)), long(std::clamp(nv, 1.0, most))};
}

nlohmann::json point(const Point& p) { return {p.x, p.y, p.z}; }



// KHR_materials_emissive_strength of each glTF material, in the file's order (Assimp 5.2 does
// not read it; its materials keep the file's order). 1 where a material has none.
std::vector<double> gltf_emissive_strengths(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (lower_extension(path) == ".glb") {  // 12-byte header, then the JSON chunk
    if (text.size() < 20) return {};
    std::uint32_t length = 0;
    std::memcpy(&length, text.data() + 12, 4);
    text = text.substr(20, std::min<std::size_t>(length, text.size() - 20));
  }
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  std::vector<double> strengths;
  if (!document.is_object() || !document.contains("materials") || !document["materials"].is_array())
    return strengths;
  for (const nlohmann::json& material : document["materials"]) {
    double strength = 1.0;
    const nlohmann::json* extensions = material.is_object() && material.contains("extensions")
                                           ? &material["extensions"] : nullptr;
    if (extensions && extensions->is_object() && extensions->contains("KHR_materials_emissive_strength")) {
      const nlohmann::json& e = (*extensions)["KHR_materials_emissive_strength"];
      if (e.is_object() && e.contains("emissiveStrength") && e["emissiveStrength"].is_number())
        strength = e["emissiveStrength"].get<double>();
    }
    strengths.push_back(strength);
  }
  return strengths;
}

struct ImportedPatch {
  std::vector<Point> corners;
  Material material;
};

// --merge-coplanar: a triangle and a later one of the same material that share an edge, lie
// in one plane and together make a planar convex quad become that quad (patches are what
// shoots: a quad cut in two by a modelling tool or by glTF, which has triangles only, shoots as
// two). The quad starts at the first triangle's first corner, so the two halves of a quad
// (a, b, c) and (a, c, d) give back (a, b, c, d).
std::vector<ImportedPatch> merge_coplanar(const std::vector<ImportedPatch>& patches,
                                          ImportSummary& summary) {
  std::vector<bool> used(patches.size(), false);
  std::vector<ImportedPatch> merged;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    const ImportedPatch& first = patches[i];
    bool done = false;
    for (std::size_t j = i + 1; j < patches.size() && first.corners.size() == 3 && !done; ++j) {
      const ImportedPatch& second = patches[j];
      if (used[j] || second.corners.size() != 3 ||
          second.material.reflectance != first.material.reflectance ||
          second.material.emission != first.material.emission)
        continue;
      // The shared edge runs (a -> b) in the first triangle and (b -> a) in the second.
      for (int e = 0; e < 3 && !done; ++e) {
        const Point& a = first.corners[std::size_t(e)];
        const Point& b = first.corners[std::size_t((e + 1) % 3)];
        for (int f = 0; f < 3 && !done; ++f) {
          if (second.corners[std::size_t(f)] != b || second.corners[std::size_t((f + 1) % 3)] != a) continue;
          const Point& far = second.corners[std::size_t((f + 2) % 3)];
          std::vector<Point> quad;
          for (int k = 0; k < 3; ++k) {
            quad.push_back(first.corners[std::size_t(k)]);
            if (k == e) quad.push_back(far);
          }
          if (!planar_convex_quad(quad)) continue;
          merged.push_back({quad, first.material});
          used[j] = true;
          done = true;
          ++summary.merged;
        }
      }
    }
    if (!done) merged.push_back(first);
  }
  return merged;
}

}  // namespace

bool is_model_file(const std::string& path) {
  const std::string e = lower_extension(path);
  if (e == ".obj" || e == ".ply" || e == ".gltf" || e == ".glb") return true;
  // Formats Assimp reads but this does not test: refused by name rather than parsed as JSON.
  for (const char* other : {".fbx", ".dae", ".3ds", ".stl", ".blend", ".x3d", ".off", ".lwo", ".ase", ".ifc"})
    if (e == other)
      throw InputError(path + ": " + e + " models are not read (only .obj, .ply, .gltf, .glb; "
                       "docs/scene-format.md, \"Importing models\")");
  return false;
}

nlohmann::json import_model(const std::string& path, const ImportOptions& options,
                            ImportSummary& summary) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) throw InputError(path + ": cannot open model file");
  if (!S_ISREG(info.st_mode)) throw InputError(path + ": not a regular file");
  if (std::size_t(info.st_size) > kMaxSceneFileBytes)
    throw InputError(path + ": model file is larger than " + std::to_string(kMaxSceneFileBytes) +
                     " bytes (the limit)");
  if (!(options.scale >= 1e-100 && options.scale <= 1e100))
    throw InputError("--scale: must be from 1e-100 to 1e100");

  if (lower_extension(path) == ".ply") check_ply_length(path);
  Assimp::Importer importer;
  std::vector<std::string> missing;
  importer.SetIOHandler(new RecordingIOSystem(summary.files, missing));  // the importer owns it
  // No triangulation: quads stay quads, and which faces to split is decided here. The
  // validation step refuses out-of-range indices and other broken structures.
  const aiScene* model = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  for (const std::string& file : missing)
    throw InputError(path + ": names " + file + ", which cannot be opened");
  if (!model || !model->mRootNode) {
    const std::string error = importer.GetErrorString();
    // Assimp's OBJ reader leaves a face of 1 or 2 corners for its validation to find.
    if (error.find("is a LINE") != std::string::npos || error.find("is a POINT") != std::string::npos)
      throw InputError(path + ": a face with " + (error.find("LINE") != std::string::npos ? "2 corners" : "1 corner") +
                       " (points and lines are not surfaces): " + error);
    throw InputError(path + ": cannot read the model: " + error);
  }
  for (const std::string& file : summary.files) {
    struct stat part {};
    if (stat(file.c_str(), &part) == 0 && std::size_t(part.st_size) > kMaxSceneFileBytes)
      throw InputError(file + ": larger than " + std::to_string(kMaxSceneFileBytes) + " bytes");
  }

  const bool vertex_colours = lower_extension(path) == ".ply";
  // A PLY's faces may carry their own colour, which Assimp drops: read here, in the file's
  // face order, which is Assimp's when the file is one mesh (no material_index splitting it).
  const std::vector<Point> face_colours = vertex_colours ? ply_face_colours(path) : std::vector<Point>();
  if (!face_colours.empty() &&
      (model->mNumMeshes != 1 || model->mMeshes[0]->mNumFaces != face_colours.size()))
    throw InputError(path + ": face colours with faces split over " + std::to_string(model->mNumMeshes) +
                     " meshes (material_index) are not read");
  const bool gltf = lower_extension(path) == ".gltf" || lower_extension(path) == ".glb";
  const std::vector<double> strengths = gltf ? gltf_emissive_strengths(path) : std::vector<double>();
  std::vector<ImportedPatch> patches;
  // The meshes in the order of the file's nodes (an OBJ's groups as written), each through
  // its node's transformation (glTF node hierarchies).
  std::vector<std::pair<unsigned, aiMatrix4x4>> placed;
  const auto walk = [&placed](const aiNode* node, aiMatrix4x4 parent, const auto& self) -> void {
    const aiMatrix4x4 transform = parent * node->mTransformation;
    for (unsigned k = 0; k < node->mNumMeshes; ++k) placed.emplace_back(node->mMeshes[k], transform);
    for (unsigned k = 0; k < node->mNumChildren; ++k) self(node->mChildren[k], transform, self);
  };
  walk(model->mRootNode, aiMatrix4x4(), walk);
  std::vector<bool> lights_used(options.lights.size(), false);
  std::vector<std::string> names;  // the model's mesh and material names, for a --light that names none
  for (const auto& [m, transform] : placed) {
    const aiMesh& mesh = *model->mMeshes[m];
    const bool moved = !transform.IsIdentity();
    const aiMaterial& ai_material = *model->mMaterials[mesh.mMaterialIndex];
    const std::string material_name = ai_material.GetName().C_Str();
    const std::string mesh_name = mesh.mName.C_Str();
    const std::string where = path + ": mesh " + std::to_string(m) + " \"" + mesh_name +
                              "\", material \"" + material_name + "\"";
    // PLY has no materials (Assimp invents a white one): its reflectance is its vertex colours,
    // else the default.
    Material material = vertex_colours ? Material{} : read_material(ai_material, where);
    if (mesh.mMaterialIndex < strengths.size()) {
      const double strength = strengths[mesh.mMaterialIndex];
      if (!(strength >= 0.0) || !std::isfinite(strength))
        throw InputError(where + ": KHR_materials_emissive_strength " + std::to_string(strength) +
                         ": must be finite and not negative");
      material.emission *= strength;
    }
    // A PLY has no material names: --light names its file (all of it emits).
    light_for(options.lights, mesh_name, material.emission, lights_used) ||
        light_for(options.lights, material_name, material.emission, lights_used) ||
        (vertex_colours &&
         light_for(options.lights, fs::path(path).stem().string(), material.emission, lights_used));
    for (const std::string& name : {mesh_name, material_name})
      if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end())
        names.push_back(name);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      const std::string at = where + ", face " + std::to_string(f);
      ++summary.faces;
      if (face.mNumIndices < 3)
        throw InputError(at + ": " + std::to_string(face.mNumIndices) +
                         " corners (points and lines are not surfaces)");
      std::vector<Point> corners;
      Point colour(0.0);
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        const aiVector3D v = moved ? transform * mesh.mVertices[face.mIndices[k]]
                                   : mesh.mVertices[face.mIndices[k]];
        const Point p = as_written(v.x, v.y, v.z) * options.scale;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw InputError(at + ": vertex " + std::to_string(face.mIndices[k]) +
                           " is not a finite point");
        corners.push_back(p);
        if (vertex_colours && mesh.HasVertexColors(0)) {
          const aiColor4D& c = mesh.mColors[0][face.mIndices[k]];
          colour += as_written(c.r, c.g, c.b) / double(face.mNumIndices);
        }
      }
      Material this_face = material;
      // A face's own colour is what the file says of the face; its corners' colours only
      // when it has none.
      if (!face_colours.empty()) colour = face_colours[f];
      if (vertex_colours && (!face_colours.empty() || mesh.HasVertexColors(0))) {
        this_face.reflectance = colour;
        for (int c = 0; c < 3; ++c)
          if (!(colour[c] >= 0.0 && colour[c] < 1.0))
            throw InputError(at + (face_colours.empty() ? ": vertex colour " : ": face colour ") + show(colour) +
                             ": each channel must be in [0, 1) (a white of 255 is 1)");
      }
      if (options.flip_faces) std::reverse(corners.begin(), corners.end());
      // Repeated corners (consecutive, within kSame of the face's size) are one corner.
      const double d = diameter(corners);
      std::vector<Point> distinct;
      for (const Point& p : corners)
        if (distinct.empty() || norm(p - distinct.back()) > kSame * d) distinct.push_back(p);
      while (distinct.size() > 1 && norm(distinct.front() - distinct.back()) <= kSame * d)
        distinct.pop_back();
      if (distinct.size() < 3 || flat(distinct)) {
        ++summary.degenerate;
        continue;
      }
      if (distinct.size() == 3 || (distinct.size() == 4 && planar_convex_quad(distinct))) {
        patches.push_back({distinct, this_face});
        continue;
      }
      ++summary.split;
      for (std::vector<Point>& triangle : split(distinct))
        if (!flat(triangle)) patches.push_back({triangle, this_face});
    }
  }
  for (std::size_t k = 0; k < options.lights.size(); ++k) {
    if (lights_used[k]) continue;
    std::string known;
    for (const std::string& name : names) known += (known.empty() ? "\"" : ", \"") + name + "\"";
    if (vertex_colours) known += (known.empty() ? "\"" : ", \"") + fs::path(path).stem().string() + "\" (the file)";
    throw InputError("--light " + options.lights[k] + ": " + path + " has no material or mesh of that name (it has " +
                     known + ")");
  }
  if (patches.empty()) throw InputError(path + ": no face with an area (nothing to light)");
  if (options.merge_coplanar) patches = merge_coplanar(patches, summary);
  bool lit = false;
  for (const ImportedPatch& p : patches) lit = lit || p.material.emission != Point(0.0);
  if (!lit)
    throw InputError(path + ": no material emits light (no Ke, no emissive colour); mark one "
                     "with --light MATERIAL[=R,G,B] (a material or mesh name)");

  double total_area = 0.0;
  for (const ImportedPatch& p : patches) total_area += 0.5 * norm(newell(p.corners));
  const double budget = (options.element_budget > 0
                                   ? double(options.element_budget)
                                   : double(kDefaultElementsPerPatch) * double(patches.size()));
  nlohmann::json scene = {{"name", fs::path(path).stem().string()}};
  if (model->mNumCameras > 0) {
    // Assimp 5.2's glTF reader, the only one here with cameras, stores the node's
    // translation in the camera's own position as well (so the node's transformation alone
    // places it) and yfov x aspect in mHorizontalFOV (so yfov is that over the aspect).
    const aiCamera& camera = *model->mCameras[0];
    aiMatrix4x4 transform;
    for (const aiNode* node = model->mRootNode->FindNode(camera.mName); node; node = node->mParent)
      transform = node->mTransformation * transform;
    const aiVector3D eye = transform * aiVector3D(0, 0, 0);
    const aiVector3D look = transform * camera.mLookAt;
    const aiVector3D up = aiMatrix3x3(transform) * camera.mUp;
    const double vertical = camera.mAspect > 0 ? camera.mHorizontalFOV / camera.mAspect
                                               : camera.mHorizontalFOV;
    scene["camera"] = {{"eye", point(as_written(eye.x, eye.y, eye.z) * options.scale)},
                       {"look_at", point(as_written(look.x, look.y, look.z) * options.scale)},
                       {"up", point(as_written(up.x, up.y, up.z))},
                       {"fov_deg", as_written(float(vertical * 180.0 / M_PI))}};
  }
  importer.FreeScene();  // the faces are patches now: a large model is not held twice
  nlohmann::json list = nlohmann::json::array();
  for (const ImportedPatch& p : patches) {
    const double area = 0.5 * norm(newell(p.corners));
    const auto [nu, nv] = grid(p.corners, options.element_size,
                               std::max(1.0, std::round(budget * area / total_area)));
    nlohmann::json vertices = nlohmann::json::array();
    for (const Point& c : p.corners) vertices.push_back(point(c));
    nlohmann::json patch = {{"vertices", vertices},
                            {"reflectance", point(p.material.reflectance)},
                            {"elements", {nu, nv}}};
    if (p.material.emission != Point(0.0)) patch["emission"] = point(p.material.emission);
    list.push_back(patch);
  }
  scene["patches"] = list;
  summary.patches = long(patches.size());
  return scene;
}

}  // namespace ncube
