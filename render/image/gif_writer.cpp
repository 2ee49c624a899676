#include "render/image/gif_writer.h"

#include <algorithm>
#include <stdexcept>

#include "planner/util/atomic_file.h"
#include "render/image/color_quantizer.h"

namespace stanceplan::render {
namespace {

constexpr int kMinCodeSize = 8;    // 256-colour palette
constexpr int kMaxCodes = 4096;    // 12-bit codes
constexpr int kTransparent = 255;  // palette entry kept for "unchanged since the last frame"

void put_u16(std::string& out, int v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>((v >> 8) & 0xff));
}

// Packs variable-width codes least-significant bit first into 255-byte data sub-blocks.
class CodeWriter {
 public:
  explicit CodeWriter(std::string& out) : out_(out) {}
  void put(int code, int bits) {
    acc_ |= static_cast<std::uint32_t>(code) << nbits_;
    nbits_ += bits;
    while (nbits_ >= 8) {
      byte(static_cast<std::uint8_t>(acc_ & 0xff));
      acc_ >>= 8;
      nbits_ -= 8;
    }
  }
  void finish() {
    if (nbits_ > 0) byte(static_cast<std::uint8_t>(acc_ & 0xff));
    flush_block();
    out_.push_back('\0');  // block terminator
  }

 private:
  void byte(std::uint8_t b) {
    block_[block_size_++] = b;
    if (block_size_ == 255) flush_block();
  }
  void flush_block() {
    if (block_size_ == 0) return;
    out_.push_back(static_cast<char>(block_size_));
    out_.append(reinterpret_cast<const char*>(block_), block_size_);
    block_size_ = 0;
  }

  std::string& out_;
  std::uint32_t acc_ = 0;
  int nbits_ = 0;
  std::uint8_t block_[255] = {};
  int block_size_ = 0;
};

// GIF's variable-length LZW (GIF89a appendix F). The dictionary is a trie stored as a dense
// [code][next byte] -> code table; 0 means "no child" (no real child code can be 0).
void lzw_encode(const std::vector<std::uint8_t>& indices, std::string& out) {
  const int clear = 1 << kMinCodeSize, end_of_information = clear + 1;
  std::vector<std::uint16_t> trie(static_cast<size_t>(kMaxCodes) * 256, 0);
  CodeWriter writer(out);
  int code_size = kMinCodeSize + 1;
  int next = clear + 2;
  writer.put(clear, code_size);
  int prefix = indices.empty() ? 0 : indices[0];
  for (size_t i = 1; i < indices.size(); ++i) {
    const int c = indices[i];
    const std::uint16_t child = trie[static_cast<size_t>(prefix) * 256 + c];
    if (child != 0) {
      prefix = child;
      continue;
    }
    writer.put(prefix, code_size);
    if (next < kMaxCodes) {
      trie[static_cast<size_t>(prefix) * 256 + c] = static_cast<std::uint16_t>(next++);
      // The decoder lags one code behind: widen once it will have filled 2^code_size entries.
      if (next - 1 == (1 << code_size) && code_size < 12) ++code_size;
    } else {
      writer.put(clear, code_size);
      std::fill(trie.begin(), trie.end(), 0);
      code_size = kMinCodeSize + 1;
      next = clear + 2;
    }
    prefix = c;
  }
  writer.put(prefix, code_size);
  writer.put(end_of_information, code_size);
  writer.finish();
}

void put_header(std::string& out, int width, int height, const ColorQuantizer& quantizer,
                const GifOptions& options) {
  out += "GIF89a";
  put_u16(out, width);
  put_u16(out, height);
  out.push_back(static_cast<char>(0xF7));  // global colour table of 256 entries, 8-bit colour
  out.push_back('\0');                     // background colour index
  out.push_back('\0');                     // square pixels
  for (int i = 0; i < 256; ++i) {
    const auto& palette = quantizer.palette();
    const std::array<std::uint8_t, 3> c =
        i < static_cast<int>(palette.size()) ? palette[i] : std::array<std::uint8_t, 3>{0, 0, 0};
    for (std::uint8_t v : c) out.push_back(static_cast<char>(v));
  }
  // NETSCAPE2.0 application extension: loop count.
  out += "\x21\xFF\x0B";
  out += "NETSCAPE2.0";
  out += "\x03\x01";
  put_u16(out, options.loop_count);
  out.push_back('\0');
}

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
};

// The smallest rectangle holding every pixel that differs from the previous frame (the whole
// canvas for the first frame; one pixel when nothing changed, as a frame needs an image).
Rect changed_rect(const std::vector<std::uint8_t>& indices,
                  const std::vector<std::uint8_t>* previous, int width, int height) {
  if (previous == nullptr) return {0, 0, width, height};
  int x0 = width, y0 = height, x1 = -1, y1 = -1;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (indices[i] == (*previous)[i]) continue;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return {0, 0, 1, 1};
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

// Frames after the first store only the rectangle that changed, and inside it the pixels that did
// not change are transparent (long runs that LZW packs tightly); the rest of the canvas stays from
// the frame before (disposal "leave in place"). A figure sequence changes little: the robot and
// the caption.
void put_frame(std::string& out, const std::vector<std::uint8_t>& indices,
               const std::vector<std::uint8_t>* previous, int width, int height, int delay_cs) {
  const Rect r = changed_rect(indices, previous, width, height);
  out += "\x21\xF9\x04";
  out.push_back(
      previous != nullptr ? 0x05 : 0x04);  // disposal: leave in place; transparency after the first
  put_u16(out, delay_cs);
  out.push_back(static_cast<char>(kTransparent));
  out.push_back('\0');
  out.push_back(0x2C);  // image descriptor: no local colour table, not interlaced
  put_u16(out, r.x);
  put_u16(out, r.y);
  put_u16(out, r.w);
  put_u16(out, r.h);
  out.push_back('\0');
  out.push_back(static_cast<char>(kMinCodeSize));
  std::vector<std::uint8_t> sub(static_cast<size_t>(r.w) * r.h);
  for (int y = 0; y < r.h; ++y) {
    for (int x = 0; x < r.w; ++x) {
      const size_t i = static_cast<size_t>(r.y + y) * width + r.x + x;
      const bool same = previous != nullptr && (*previous)[i] == indices[i];
      sub[static_cast<size_t>(y) * r.w + x] = same ? kTransparent : indices[i];
    }
  }
  lzw_encode(sub, out);
}

}  // namespace

std::string encode_gif(const std::vector<Image>& frames, const GifOptions& options) {
  if (frames.empty()) throw std::invalid_argument("encode_gif: no frame");
  const int width = frames[0].width, height = frames[0].height;
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535)
    throw std::invalid_argument("encode_gif: frame size out of range");
  for (const Image& f : frames) {
    if (f.width != width || f.height != height)
      throw std::invalid_argument("encode_gif: frames differ in size");
  }
  const ColorQuantizer quantizer(frames,
                                 kTransparent);  // 255 colours: the last entry is transparent
  std::string out;
  put_header(out, width, height, quantizer, options);
  std::vector<std::uint8_t> previous;
  for (size_t i = 0; i < frames.size(); ++i) {
    const bool last = i + 1 == frames.size();
    std::vector<std::uint8_t> indices = quantizer.map(frames[i]);
    put_frame(out, indices, i == 0 ? nullptr : &previous, width, height,
              last ? options.last_delay_cs : options.delay_cs);
    previous = std::move(indices);
  }
  out.push_back(0x3B);  // trailer
  return out;
}

void write_gif(const std::string& path, const std::vector<Image>& frames,
               const GifOptions& options) {
  write_file_atomically(path, encode_gif(frames, options));
}

}  // namespace stanceplan::render
