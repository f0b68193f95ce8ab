// What the importer reads of a PLY file itself, beside Assimp: the header's promise checked
// against the file's length (Assimp 5.2 reads a short file without a word), and the faces'
// own colours (Assimp 5.2 reads vertex colours only and drops a face's red, green and blue:
// without this a face-coloured model would turn 0.5 grey in silence).
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace ncube {

// Throws InputError when the header has no end_header (Assimp 5.2 would read on forever), an
// unknown format or an impossible record count, or when the body is too short for the records
// the header declares (for a binary file, at least the bytes of every fixed-size property and
// list count; for an ASCII file, one line per record).
void check_ply_length(const std::string& path);

// The colour of each face in the file's order, from the face element's `red`, `green`, `blue`
// (or `diffuse_red`, ...) properties: integers over their type's largest value (255 for
// uchar), floats as they are. Empty when the faces have no colour. Throws InputError naming
// the file and the face when the body ends early or a value is not a number.
std::vector<glm::dvec3> ply_face_colours(const std::string& path);

}  // namespace ncube
