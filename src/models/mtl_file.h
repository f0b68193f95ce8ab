// What Assimp 5.2 does not say of an OBJ's materials: whether an MTL material gives its
// diffuse colour, and which faces it gives a material they did not ask for (a face before any
// usemtl, a usemtl naming no material), each in silence.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace ncube::models {

struct MtlNames {
  std::set<std::string> defined;  // every newmtl
  std::set<std::string> with_kd;  // those with a Kd line
};

// The materials of the files among `files` that end in .mtl (the libraries an OBJ read).
// Assimp fills a missing Kd with its own 0.6 grey; the importer's documented default is 0.5.
MtlNames mtl_names(const std::vector<std::string>& files);

// What is wrong with the materials the OBJ at `path` asks for, "" if nothing: "line N: ..."
// for the first face that follows mtllib with no usemtl before it (Assimp gives it the
// library's last material) or the first usemtl naming a material no library defines (Assimp
// gives it a default).
std::string obj_material_problem(const std::string& path, const MtlNames& names);

// The line of the OBJ at `path` that holds its `n`th mtllib (1 for the first), 0 when it has
// fewer: which line a message names when the model's material libraries are read too often
// (recording_io.h, kBytesNamedAgain).
long obj_library_line(const std::string& path, long n);

}  // namespace ncube::models
