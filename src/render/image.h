// A small RGB float image and its PNG writer: the output of the renderer.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace ncube {

// Pixels are display values in [0, 1] (already tone mapped and sRGB encoded), row-major,
// top row first.
struct Image {
  int width = 0, height = 0;
  std::vector<glm::vec3> pixels;

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h)) {}
  glm::vec3& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const glm::vec3& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

// The image as an 8-bit RGB PNG file's bytes (values clamped to [0, 1], rounded to 0..255).
std::string encode_png(const Image& image);

// Writes an 8-bit RGB PNG (values clamped to [0, 1], rounded to 0..255). The file is
// written under a temporary name next to `path` and renamed, so a failure leaves neither
// a partial file nor a changed target. Throws InputError naming the file on failure.
void write_png(const Image& image, const std::string& path);

}  // namespace ncube
