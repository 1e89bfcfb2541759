// An image as xval-shader-draw's bytes (shader_file/shader_image_bytes.h).
#include "shader_file/shader_image_bytes.h"

#include <cstring>
#include <stdexcept>

namespace xval::shaderfile {

std::string imageBytes(const Image& img) {
  std::string out(2 * sizeof(int), '\0');
  std::memcpy(&out[0], &img.width, sizeof(int));
  std::memcpy(&out[sizeof(int)], &img.height, sizeof(int));
  out.append(reinterpret_cast<const char*>(img.rgba.data()), img.rgba.size() * sizeof(float));
  out.append(reinterpret_cast<const char*>(img.raw.data()), img.raw.size() * sizeof(float));
  return out;
}

Image imageFromBytes(const std::string& bytes, int w, int h) {
  const size_t pixels = size_t(w) * h, expected = 2 * sizeof(int) + pixels * 7 * sizeof(float);
  int got_w = 0, got_h = 0;
  if (bytes.size() == expected) {
    std::memcpy(&got_w, &bytes[0], sizeof(int));
    std::memcpy(&got_h, &bytes[sizeof(int)], sizeof(int));
  }
  if (got_w != w || got_h != h)
    throw std::runtime_error("xval-shader-draw wrote " + std::to_string(bytes.size()) + " bytes, expected a " +
                            std::to_string(w) + " x " + std::to_string(h) + " image (" + std::to_string(expected) + ")");
  Image img(w, h, true);
  std::memcpy(img.rgba.data(), &bytes[2 * sizeof(int)], pixels * 4 * sizeof(float));
  std::memcpy(img.raw.data(), &bytes[2 * sizeof(int) + pixels * 4 * sizeof(float)], pixels * 3 * sizeof(float));
  return img;
}

}  // namespace xval::shaderfile
