#include "render/image/texture_color.h"

#include <stb_image.h>

#include <memory>
#include <stdexcept>

namespace stanceplan::render {

std::array<float, 3> mean_texture_color(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load(path.c_str(), &width, &height, &channels, 4), stbi_image_free);
  if (!pixels || width <= 0 || height <= 0) {
    const char* reason = stbi_failure_reason();
    throw std::runtime_error("texture \"" + path + "\" could not be read: " +
                             (reason != nullptr ? reason : "unknown error"));
  }
  // Sums in double: a 4096 x 4096 texture would lose precision in float.
  double weighted[3] = {0, 0, 0}, plain[3] = {0, 0, 0}, alpha = 0.0;
  const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
  for (size_t i = 0; i < count; ++i) {
    const stbi_uc* p = pixels.get() + 4 * i;
    for (int k = 0; k < 3; ++k) {
      weighted[k] += static_cast<double>(p[k]) * p[3];
      plain[k] += p[k];
    }
    alpha += p[3];
  }
  std::array<float, 3> mean;
  for (int k = 0; k < 3; ++k) {
    const double m = alpha > 0.0 ? weighted[k] / alpha : plain[k] / static_cast<double>(count);
    mean[k] = static_cast<float>(m / 255.0);
  }
  return mean;
}

}  // namespace stanceplan::render
