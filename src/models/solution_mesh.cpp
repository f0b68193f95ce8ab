#include "models/solution_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <sstream>
#include <tuple>

#include "render/exposure.h"
#include "render/render_records.h"

namespace ncube {
namespace {

// PLY's binary little-endian values, whatever the host's order.
template <typename T>
void put(std::string& out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  bool little = true;
  const std::uint16_t probe = 1;
  std::memcpy(&little, &probe, 1);
  if (!little)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

std::uint8_t display_byte(double radiosity, double exposure) {
  const double linear = std::fmin(std::fmax(radiosity * exposure, 0.0), 1.0);
  return std::uint8_t(std::lround(255.0 * srgb_encode(linear)));
}

// A vertex's identity within a patch: the bits of its position.
using VertexKey = std::tuple<int, std::uint64_t, std::uint64_t, std::uint64_t>;

std::uint64_t bits(double value) {
  std::uint64_t b;
  std::memcpy(&b, &value, sizeof b);
  return b;
}

}  // namespace

std::string solution_mesh_ply(const Scene& scene, const std::vector<PatchSolution>& solution,
                              double exposure) {
  std::vector<int> all_patches(scene.patches.size());
  std::iota(all_patches.begin(), all_patches.end(), 0);
  const std::vector<RenderElement> elements = render_elements(scene, solution, all_patches);
  // The patch of each element, in the same scene order as render_elements.
  std::vector<int> patch_of;
  std::vector<Rgb> element_radiosity;
  for (const PatchSolution& patch : solution) {
    patch_of.insert(patch_of.end(), patch.cells.size(), patch.patch);
    element_radiosity.insert(element_radiosity.end(), patch.radiosity.begin(), patch.radiosity.end());
  }

  std::map<VertexKey, int> index;
  std::vector<MeshVertex> vertices;
  std::vector<std::vector<int>> faces;
  for (const RenderElement& element : elements) {
    std::vector<int>& face = faces.emplace_back();
    const int patch = patch_of[std::size_t(element.element)];
    for (const MeshVertex& v : element.boundary) {
      const VertexKey key{patch, bits(v.position.x), bits(v.position.y), bits(v.position.z)};
      const auto [it, added] = index.try_emplace(key, int(vertices.size()));
      if (added) vertices.push_back(v);
      face.push_back(it->second);
    }
  }

  // A face has its corners and its T-vertices: more than 255 only with deep subdivision
  // next to a coarse element; the common case keeps the most widely read count type.
  std::size_t largest = 0;
  for (const std::vector<int>& face : faces) largest = std::max(largest, face.size());
  const bool wide_counts = largest > 255;
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\n"
         << "comment radiosity solution of scene " << scene.name << " (ncube simulate --mesh)\n"
         << "comment exposure " << exposure << " (the picture's tone mapping)\n"
         << "element vertex " << vertices.size() << "\n"
         << "property double x\nproperty double y\nproperty double z\n"
         << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
         << "property double radiosity_r\nproperty double radiosity_g\nproperty double radiosity_b\n"
         << "element face " << faces.size() << "\n"
         << "property list " << (wide_counts ? "uint" : "uchar")
         << " int vertex_indices\nproperty int patch\nproperty int element\n"
         << "property double radiosity_r\nproperty double radiosity_g\nproperty double radiosity_b\n"
         << "end_header\n";
  std::string out = header.str();
  for (const MeshVertex& v : vertices) {
    put(out, v.position.x);
    put(out, v.position.y);
    put(out, v.position.z);
    for (double c : {v.radiosity.r, v.radiosity.g, v.radiosity.b})
      put(out, display_byte(c, exposure));
    put(out, v.radiosity.r);
    put(out, v.radiosity.g);
    put(out, v.radiosity.b);
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (wide_counts)
      put(out, std::uint32_t(faces[f].size()));
    else
      put(out, std::uint8_t(faces[f].size()));
    for (int i : faces[f]) put(out, std::int32_t(i));
    put(out, std::int32_t(patch_of[std::size_t(elements[f].element)]));
    put(out, std::int32_t(elements[f].element));
    const Rgb& radiosity = element_radiosity[std::size_t(elements[f].element)];
    put(out, radiosity.r);
    put(out, radiosity.g);
    put(out, radiosity.b);
  }
  return out;
}

}  // namespace ncube
