#pragma once
// PNG files through libpng. Encoding uses zlib level 1 and the SUB filter: on rendered frames this
// is the fastest setting that still compresses well (docs/DEPENDENCIES.md section 5: stb is
// 3x slower).
#include <string>

#include "render/image/image.h"

namespace stanceplan::render {

// An opaque image (every alpha 255) is stored as RGB, otherwise as RGBA.
std::string encode_png(const Image& image, int compression_level = 1);
// Writes atomically (temporary file + rename); throws std::runtime_error naming the path.
void write_png(const std::string& path, const Image& image, int compression_level = 1);

// Decodes any PNG into RGBA; throws std::runtime_error (with `what` naming the source) on a fault.
Image decode_png(const std::string& bytes, const std::string& what = "PNG data");
Image read_png(const std::string& path);

}  // namespace stanceplan::render
