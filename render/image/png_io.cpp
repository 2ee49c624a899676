#include "render/image/png_io.h"

#include <png.h>

#include <csetjmp>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "planner/util/atomic_file.h"

namespace stanceplan::render {
namespace {

void append_to_string(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

void flush_nothing(png_structp) {}

bool is_opaque(const Image& image) {
  for (size_t i = 3; i < image.rgba.size(); i += 4)
    if (image.rgba[i] != 255) return false;
  return true;
}

// libpng reports errors with longjmp: this function holds the setjmp and owns no C++ object
// with a destructor, so jumping back into it skips nothing. Returns false on a libpng error.
bool write_rows(png_structp png, png_infop info, const Image& image, int level, bool opaque,
                png_bytepp rows, std::string* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, append_to_string, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8,
               opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, level);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_write_info(png, info);
  if (opaque) png_set_filler(png, 0, PNG_FILLER_AFTER);  // drop the alpha byte of every pixel
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string encode_png(const Image& image, int compression_level) {
  if (image.empty()) throw std::runtime_error("encode_png: empty image");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) throw std::runtime_error("encode_png: libpng could not start");
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep> rows(static_cast<size_t>(image.height));
  for (int y = 0; y < image.height; ++y)
    rows[y] = const_cast<png_bytep>(image.pixel(0, y));  // libpng only reads them
  std::string out;
  out.reserve(image.rgba.size() / 4);
  const bool ok = info != nullptr && write_rows(png, info, image, compression_level,
                                                is_opaque(image), rows.data(), &out);
  png_destroy_write_struct(&png, info != nullptr ? &info : nullptr);
  if (!ok) throw std::runtime_error("encode_png: libpng failed to encode the image");
  return out;
}

void write_png(const std::string& path, const Image& image, int compression_level) {
  write_file_atomically(path, encode_png(image, compression_level));
}

Image decode_png(const std::string& bytes, const std::string& what) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()))
    throw std::runtime_error(what + ": not a PNG (" + png.message + ")");
  png.format = PNG_FORMAT_RGBA;
  Image image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgba.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
    png_image_free(&png);
    throw std::runtime_error(what + ": broken PNG (" + png.message + ")");
  }
  return image;
}

Image read_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::stringstream bytes;
  bytes << in.rdbuf();
  return decode_png(bytes.str(), path);
}

}  // namespace stanceplan::render
