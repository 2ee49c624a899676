#include "render/image/color_quantizer.h"

#include <algorithm>
#include <limits>

namespace stanceplan::render {
namespace {

constexpr int kBins = 1 << 15;

struct Bin {
  int key = 0;
  std::uint64_t count = 0;
  std::uint64_t sum[3] = {0, 0, 0};  // of the true 8-bit values, for an unbiased mean colour
  int channel(int c) const { return (key >> (10 - 5 * c)) & 31; }
};

struct Box {
  int begin = 0;
  int end = 0;  // range of bins
  std::uint64_t count = 0;
  int longest_channel = 0;
  int longest_range = 0;
};

Box make_box(const std::vector<Bin>& bins, int begin, int end) {
  Box box{begin, end, 0, 0, 0};
  int lo[3] = {31, 31, 31}, hi[3] = {0, 0, 0};
  for (int i = begin; i < end; ++i) {
    box.count += bins[i].count;
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], bins[i].channel(c));
      hi[c] = std::max(hi[c], bins[i].channel(c));
    }
  }
  for (int c = 0; c < 3; ++c) {
    if (hi[c] - lo[c] > box.longest_range) {
      box.longest_range = hi[c] - lo[c];
      box.longest_channel = c;
    }
  }
  return box;
}

// Splits the box at its population median along its longest channel.
std::pair<Box, Box> split(std::vector<Bin>& bins, const Box& box) {
  const int c = box.longest_channel;
  std::sort(bins.begin() + box.begin, bins.begin() + box.end, [c](const Bin& a, const Bin& b) {
    return a.channel(c) != b.channel(c) ? a.channel(c) < b.channel(c) : a.key < b.key;
  });
  std::uint64_t acc = 0;
  int cut = box.begin + 1;
  for (int i = box.begin; i < box.end - 1; ++i) {
    acc += bins[i].count;
    cut = i + 1;
    if (2 * acc >= box.count) break;
  }
  return {make_box(bins, box.begin, cut), make_box(bins, cut, box.end)};
}

}  // namespace

bool ColorQuantizer::build_exact(const std::vector<Image>& frames, int max_colors) {
  for (const Image& frame : frames) {
    for (size_t i = 0; i < frame.rgba.size(); i += 4) {
      const std::uint32_t c = packed(&frame.rgba[i]);
      if (exact_.contains(c)) continue;
      if (static_cast<int>(exact_.size()) == max_colors) {
        exact_.clear();
        palette_.clear();
        return false;
      }
      exact_.emplace(c, static_cast<std::uint8_t>(palette_.size()));
      palette_.push_back({frame.rgba[i], frame.rgba[i + 1], frame.rgba[i + 2]});
    }
  }
  return true;
}

std::uint8_t ColorQuantizer::index(const std::uint8_t* rgb) const {
  if (!exact_.empty()) {
    const auto it = exact_.find(packed(rgb));
    return it != exact_.end() ? it->second : 0;
  }
  return lut_[key(rgb)];
}

ColorQuantizer::ColorQuantizer(const std::vector<Image>& frames, int max_colors) {
  if (build_exact(frames, max_colors)) return;
  std::vector<Bin> all(kBins);
  for (int k = 0; k < kBins; ++k) all[k].key = k;
  for (const Image& frame : frames) {
    for (size_t i = 0; i < frame.rgba.size(); i += 4) {
      Bin& bin = all[key(&frame.rgba[i])];
      ++bin.count;
      for (int c = 0; c < 3; ++c) bin.sum[c] += frame.rgba[i + c];
    }
  }
  std::vector<Bin> bins;
  for (const Bin& b : all)
    if (b.count > 0) bins.push_back(b);
  if (bins.empty()) bins.push_back(all[0]);

  std::vector<Box> boxes = {make_box(bins, 0, static_cast<int>(bins.size()))};
  while (static_cast<int>(boxes.size()) < max_colors) {
    // The box whose colours spread most, weighted by how many pixels it holds.
    int best = -1;
    double best_score = 0.0;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
      const double score = static_cast<double>(boxes[i].count) * boxes[i].longest_range;
      if (boxes[i].end - boxes[i].begin > 1 && score > best_score) {
        best_score = score;
        best = i;
      }
    }
    if (best < 0) break;
    auto [a, b] = split(bins, boxes[best]);
    boxes[best] = a;
    boxes.push_back(b);
  }

  for (const Box& box : boxes) {
    std::uint64_t sum[3] = {0, 0, 0}, count = 0;
    for (int i = box.begin; i < box.end; ++i) {
      for (int c = 0; c < 3; ++c) sum[c] += bins[i].sum[c];
      count += bins[i].count;
    }
    std::array<std::uint8_t, 3> color{0, 0, 0};
    for (int c = 0; c < 3 && count > 0; ++c)
      color[c] = static_cast<std::uint8_t>((sum[c] + count / 2) / count);
    palette_.push_back(color);
  }

  // A colour present in the frames maps to the box that holds it; others to the nearest entry.
  lut_.assign(kBins, 0);
  std::vector<bool> present(kBins, false);
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    for (int j = boxes[i].begin; j < boxes[i].end; ++j) {
      lut_[bins[j].key] = static_cast<std::uint8_t>(i);
      present[bins[j].key] = true;
    }
  }
  for (int k = 0; k < kBins; ++k) {
    if (present[k]) continue;
    const int r = ((k >> 10) << 3) + 4, g = (((k >> 5) & 31) << 3) + 4, b = ((k & 31) << 3) + 4;
    int best = 0, best_d = std::numeric_limits<int>::max();
    for (int i = 0; i < static_cast<int>(palette_.size()); ++i) {
      const int dr = r - palette_[i][0], dg = g - palette_[i][1], db = b - palette_[i][2];
      const int d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;  // rough perceptual weights
      if (d < best_d) {
        best_d = d;
        best = i;
      }
    }
    lut_[k] = static_cast<std::uint8_t>(best);
  }
}

std::vector<std::uint8_t> ColorQuantizer::map(const Image& frame) const {
  std::vector<std::uint8_t> out(static_cast<size_t>(frame.width) * frame.height);
  if (exact_.empty()) {
    for (size_t i = 0; i < out.size(); ++i) out[i] = lut_[key(&frame.rgba[i * 4])];
  } else {
    for (size_t i = 0; i < out.size(); ++i) out[i] = index(&frame.rgba[i * 4]);
  }
  return out;
}

}  // namespace stanceplan::render
