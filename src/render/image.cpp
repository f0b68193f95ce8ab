#include "render/image.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>

#include "util/input_error.h"

namespace ncube {

namespace {

std::vector<std::uint8_t> rgb_bytes(const Image& image, const std::string& what) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != std::size_t(image.width) * std::size_t(image.height))
    throw InputError(what + ": cannot write an empty or malformed image");
  std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
  for (std::size_t k = 0; k < image.pixels.size(); ++k)
    for (int c = 0; c < 3; ++c)
      bytes[3 * k + c] =
          std::uint8_t(std::lround(std::clamp(image.pixels[k][c], 0.0f, 1.0f) * 255.0f));
  return bytes;
}

png_image png_header(const Image& image) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = PNG_FORMAT_RGB;
  return png;
}

}  // namespace

std::string encode_png(const Image& image) {
  const std::vector<std::uint8_t> bytes = rgb_bytes(image, "PNG");
  // libpng's simplified API: the first call measures, the second writes.
  png_image png = png_header(image);
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, bytes.data(), 0, nullptr)) {
    const std::string detail = png.message;
    png_image_free(&png);
    throw InputError("PNG: cannot encode the image: " + detail);
  }
  std::string encoded(size, '\0');
  png = png_header(image);
  const bool written =
      png_image_write_to_memory(&png, encoded.data(), &size, 0, bytes.data(), 0, nullptr) != 0;
  const std::string detail = written ? "" : png.message;
  png_image_free(&png);
  if (!written) throw InputError("PNG: cannot encode the image: " + detail);
  encoded.resize(size);
  return encoded;
}

void write_png(const Image& image, const std::string& path) {
  const std::vector<std::uint8_t> bytes = rgb_bytes(image, path);

  // libpng's simplified API reports errors by return value, so no setjmp/longjmp crosses
  // C++ frames; opening the FILE ourselves lets us catch errors at fclose (e.g. disk full).
  const std::string temp = path + ".tmp";
  std::FILE* file = std::fopen(temp.c_str(), "wb");
  if (!file) throw InputError(path + ": cannot open for writing");
  png_image png = png_header(image);
  const bool written = png_image_write_to_stdio(&png, file, 0, bytes.data(), 0, nullptr) != 0;
  const std::string detail = written ? "" : std::string(": ") + png.message;
  png_image_free(&png);
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed || std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw InputError(path + ": cannot write PNG" + detail);
  }
}

}  // namespace ncube
