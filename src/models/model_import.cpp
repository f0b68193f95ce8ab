#include "models/model_import.h"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cmath>
#include <filesystem>

#include <glm/vec3.hpp>

#include "models/coplanar_merge.h"
#include "models/element_grid.h"
#include "models/face_shapes.h"
#include "models/gltf_extras.h"
#include "models/json_nesting.h"
#include "models/model_material.h"
#include "models/mtl_file.h"
#include "models/ply_file.h"
#include "models/recording_io.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {
namespace {

using namespace models;  // the importer's parts (src/models/*.h)
namespace fs = std::filesystem;

std::string lower_extension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

nlohmann::json point(const Point& p) { return {p.x, p.y, p.z}; }

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
  {  // the gate's refusals (a FIFO, a loop of links, too large) before Assimp's
    const InputFile model(path, kModelFile);
  }
  if (!(options.scale >= 1e-100 && options.scale <= 1e100))
    throw InputError("--scale: must be from 1e-100 to 1e100");

  if (lower_extension(path) == ".ply") check_ply_length(path);
  if (lower_extension(path) == ".gltf" || lower_extension(path) == ".glb")
    check_gltf_nesting(path, lower_extension(path) == ".glb");
  Assimp::Importer importer;
  std::vector<std::string> read, problems;  // this import's files (a summary may hold others)
  importer.SetIOHandler(new RecordingIOSystem(path, options.model_folders, read,
                                              problems));  // the importer owns it
  // No triangulation: quads stay quads, and which faces to split is decided here. The
  // validation step refuses out-of-range indices and other broken structures.
  const aiScene* model = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (!problems.empty()) throw InputError(problems.front());
  summary.files.insert(summary.files.end(), read.begin(), read.end());
  if (!model || !model->mRootNode) {
    const std::string error = importer.GetErrorString();
    // Assimp's OBJ reader leaves a face of 1 or 2 corners for its validation to find.
    if (error.find("is a LINE") != std::string::npos || error.find("is a POINT") != std::string::npos)
      throw InputError(path + ": a face with " + (error.find("LINE") != std::string::npos ? "2 corners" : "1 corner") +
                       " (points and lines are not surfaces): " + error);
    throw InputError(path + ": cannot read the model: " + error);
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
  const std::vector<GltfMaterialExtras> extras =
      gltf ? gltf_material_extras(path, lower_extension(path) == ".glb") : std::vector<GltfMaterialExtras>();
  if (gltf) summary.named_unread = gltf_image_files(path, lower_extension(path) == ".glb");
  const bool obj = lower_extension(path) == ".obj";
  const MtlNames mtl = obj ? mtl_names(read) : MtlNames();
  if (obj) {
    const std::string problem = obj_material_problem(path, mtl);
    if (!problem.empty()) throw InputError(path + ": " + problem);
  }
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
    // A mirroring placement (a glTF node scaled by -1 on an axis) turns the corners' winding
    // around; glTF defines the front by the winding after placement, so it is turned back.
    const bool mirrored = moved && transform.Determinant() < 0;
    const aiMaterial& ai_material = *model->mMaterials[mesh.mMaterialIndex];
    const std::string material_name = ai_material.GetName().C_Str();
    const std::string mesh_name = mesh.mName.C_Str();
    const std::string where = path + ": mesh " + std::to_string(m) + " \"" + mesh_name +
                              "\", material \"" + material_name + "\"";
    // PLY has no materials (Assimp invents a white one): its reflectance is its vertex colours,
    // else the default.
    // A colour the file does not give is the documented default, not Assimp's stand-in (0.6
    // for OBJ, glTF's white for a material without baseColorFactor or a primitive without one).
    const bool colour_given = gltf ? mesh.mMaterialIndex < extras.size() && extras[mesh.mMaterialIndex].base_colour
                                   : !obj || mtl.with_kd.count(material_name) > 0;
    Material material = vertex_colours ? Material{} : read_material(ai_material, where, colour_given);
    if (mesh.mMaterialIndex < extras.size()) {
      const double strength = extras[mesh.mMaterialIndex].emissive_strength;
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
      if (face.mNumIndices > kMaxFaceCorners)
        throw InputError(at + ": " + std::to_string(face.mNumIndices) + " corners, more than " +
                         std::to_string(kMaxFaceCorners) + " (the limit; triangulate it in the "
                         "modelling tool)");
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
      // The face's corner numbers as the file gives them, for messages.
      std::vector<unsigned> number(corners.size());
      for (unsigned k = 0; k < number.size(); ++k) number[k] = k;
      if (options.flip_faces != mirrored) {
        std::reverse(corners.begin(), corners.end());
        std::reverse(number.begin(), number.end());
      }
      // Repeated corners (consecutive, within kSame of the face's size) are one corner.
      const double d = diameter(corners);
      std::vector<Point> distinct;
      std::vector<unsigned> distinct_number;
      for (std::size_t k = 0; k < corners.size(); ++k)
        if (distinct.empty() || norm(corners[k] - distinct.back()) > kSame * d) {
          distinct.push_back(corners[k]);
          distinct_number.push_back(number[k]);
        }
      while (distinct.size() > 1 && norm(distinct.front() - distinct.back()) <= kSame * d)
        distinct.pop_back();
      if (distinct.size() < 3 || flat(distinct)) {
        if (distinct.size() >= 4 && spans_plane(distinct))
          throw InputError(at + ": self-intersecting face: its " + std::to_string(distinct.size()) +
                           " corners span a plane but enclose no net area (a bow-tie of two equal "
                           "halves; split it into simple polygons)");
        ++summary.degenerate;
        continue;
      }
      if (distinct.size() == 3 || (distinct.size() == 4 && planar_convex_quad(distinct))) {
        patches.push_back({distinct, this_face});
        continue;
      }
      // A face whose outline crosses itself (a pentagram) has no one inside: refused rather
      // than cut into pieces that overlap and face both ways.
      if (const auto crossing = crossing_edges(distinct)) {
        const auto edge = [&](std::size_t i) {
          return std::to_string(distinct_number[i]) + "-" +
                 std::to_string(distinct_number[(i + 1) % distinct.size()]);
        };
        throw InputError(at + ": self-intersecting face: its edges between corners " +
                         edge(crossing->first) + " and " + edge(crossing->second) +
                         " cross (corners counted from 0; split it into simple polygons)");
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
  if (options.merge_coplanar) patches = merge_coplanar(patches, summary.merged);
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
