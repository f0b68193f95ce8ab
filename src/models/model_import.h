// A researcher's own model (OBJ + MTL, PLY, glTF) as a scene (docs/scene-format.md,
// "Importing models"): Assimp reads the file; this turns its faces into patches, its materials
// into reflectance and emission and chooses each patch's element grid, and writes the
// project's scene JSON, which the scene loader then checks like any scene file. So an imported
// scene can be exported (--export-scene), edited and run again with the same result.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ncube {

struct ImportOptions {
  double scale = 1.0;          // --scale: multiplies every coordinate (and the camera)
  double element_size = 0.0;   // --element-size: target element edge length (after scaling)
  int element_budget = 0;      // --element-budget: elements over the whole scene, by area
                               // (0 and no element size: kDefaultElementsPerPatch x patches)
  bool flip_faces = false;     // --flip-faces: for models whose normals point inward
  bool merge_coplanar = false; // --merge-coplanar: two triangles that make a planar convex
                               // quad of one material are one patch
  std::vector<std::string> lights;  // --light NAME[=R,G,B]: a material or mesh that emits
  // --model-folder DIR: a folder besides the model's own whose files the model may name
  std::vector<std::string> model_folders;
};

// The paper's scenes have about 14 to 22 elements per patch.
constexpr long kDefaultElementsPerPatch = 16;

// What the import did, for the summary.
struct ImportSummary {
  long faces = 0;           // polygons read
  long patches = 0;         // patches written
  long split = 0;           // faces split into triangles (not planar, not convex, > 4 corners)
  long degenerate = 0;      // faces dropped: zero area or repeated corners
  long merged = 0;          // pairs of triangles merged into quads (--merge-coplanar)
  std::vector<std::string> files;  // every file read (the model, its MTL, its buffers), as opened
  std::vector<std::string> named_unread;  // files the model names and the import never reads
                                          // (a glTF's images): never an output either
};

// Whether `path` names a model file this reads (by extension: .obj, .ply, .gltf, .glb).
// Throws InputError for the extension of another model format (.fbx, .dae, .stl, ...).
bool is_model_file(const std::string& path);

// The model at `path` as the project's scene document. Throws InputError naming the file,
// the item (material, mesh and face) and what is wrong.
nlohmann::json import_model(const std::string& path, const ImportOptions& options,
                            ImportSummary& summary);

}  // namespace ncube
