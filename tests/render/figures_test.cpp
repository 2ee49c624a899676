// Image files and figure helpers: PNG round trip, the GIF encoder (decoded back by a reference
// LZW decoder written here), palette quantisation, strip layout, framing, captions.
#include <gtest/gtest.h>

#include <map>

#include "app/pipeline.h"
#include "planner/io/scenario.h"
#include "render/figures/sequence.h"
#include "render/figures/step_caption.h"
#include "render/image/color_quantizer.h"
#include "render/image/edge_smoothing.h"
#include "render/image/gif_writer.h"
#include "render/image/png_io.h"
#include "render/image/text.h"
#include "render/scene/camera.h"
#include "render/scene/contact_overlays.h"
#include "tests/render/render_fixtures.h"

namespace stanceplan::render {
namespace {

// A test pattern with few colours: stripes and a gradient of 64 greys.
Image pattern(int width, int height, int phase) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      if (y < height / 2) {
        const int stripe = ((x + phase) / 7) % 3;
        p[0] = stripe == 0 ? 220 : 20;
        p[1] = stripe == 1 ? 200 : 30;
        p[2] = stripe == 2 ? 240 : 40;
      } else {
        p[0] = p[1] = p[2] = static_cast<std::uint8_t>((x * 64 / width) * 4);
      }
    }
  }
  return image;
}

// Minimal GIF89a reader for the encoder's output: global palette, frames of LZW-coded indices.
struct DecodedGif {
  int width = 0, height = 0;
  std::vector<std::array<std::uint8_t, 3>> palette;
  std::vector<std::vector<std::uint8_t>> frames;
  int loop_count = -1;
};

std::vector<std::uint8_t> lzw_decode(const std::vector<std::uint8_t>& data, int min_code_size) {
  const int clear = 1 << min_code_size, end = clear + 1;
  std::vector<std::vector<std::uint8_t>> table;
  const auto reset = [&] {
    table.assign(clear + 2, {});
    for (int i = 0; i < clear; ++i) table[i] = {static_cast<std::uint8_t>(i)};
  };
  reset();
  int size = min_code_size + 1;
  size_t bit = 0;
  std::vector<std::uint8_t> out;
  int previous = -1;
  while (bit + size <= data.size() * 8) {
    int code = 0;
    for (int k = 0; k < size; ++k, ++bit) code |= ((data[bit / 8] >> (bit % 8)) & 1) << k;
    if (code == clear) {
      reset();
      size = min_code_size + 1;
      previous = -1;
      continue;
    }
    if (code == end) break;
    std::vector<std::uint8_t> entry;
    if (code < static_cast<int>(table.size())) {
      entry = table[code];
    } else {
      EXPECT_EQ(code, static_cast<int>(table.size())) << "code out of sequence";
      EXPECT_GE(previous, 0);
      if (previous < 0) return out;
      entry = table[previous];
      entry.push_back(table[previous][0]);
    }
    out.insert(out.end(), entry.begin(), entry.end());
    if (previous >= 0 && table.size() < 4096) {
      std::vector<std::uint8_t> added = table[previous];
      added.push_back(entry[0]);
      table.push_back(added);
      if (static_cast<int>(table.size()) == (1 << size) && size < 12) ++size;
    }
    previous = code;
  }
  return out;
}

DecodedGif decode_gif(const std::string& bytes) {
  DecodedGif gif;
  const auto u8 = [&](size_t i) { return static_cast<std::uint8_t>(bytes.at(i)); };
  const auto u16 = [&](size_t i) { return u8(i) | (u8(i + 1) << 8); };
  EXPECT_EQ(bytes.substr(0, 6), "GIF89a");
  gif.width = u16(6);
  gif.height = u16(8);
  const std::uint8_t flags = u8(10);
  size_t at = 13;
  if (flags & 0x80) {
    const int entries = 2 << (flags & 7);
    for (int i = 0; i < entries; ++i, at += 3)
      gif.palette.push_back({u8(at), u8(at + 1), u8(at + 2)});
  }
  std::vector<std::uint8_t> canvas(static_cast<size_t>(gif.width) * gif.height, 0);
  int transparent = -1;
  while (at < bytes.size()) {
    const std::uint8_t block = u8(at++);
    if (block == 0x3B) break;
    if (block == 0x21) {
      const std::uint8_t label = u8(at++);
      std::string payload;
      for (std::uint8_t n = u8(at++); n != 0; n = u8(at++)) {
        payload += bytes.substr(at, n);
        at += n;
      }
      if (label == 0xFF && payload.substr(0, 11) == "NETSCAPE2.0")
        gif.loop_count =
            static_cast<std::uint8_t>(payload[12]) | static_cast<std::uint8_t>(payload[13]) << 8;
      if (label == 0xF9)
        transparent = (payload[0] & 1) ? static_cast<std::uint8_t>(payload[3]) : -1;
      continue;
    }
    EXPECT_EQ(block, 0x2C);
    const int left = u16(at), top = u16(at + 2), w = u16(at + 4), h = u16(at + 6);
    EXPECT_LE(left + w, gif.width);
    EXPECT_LE(top + h, gif.height);
    at += 9;
    const int min_code_size = u8(at++);
    std::vector<std::uint8_t> data;
    for (std::uint8_t n = u8(at++); n != 0; n = u8(at++)) {
      data.insert(data.end(), bytes.begin() + at, bytes.begin() + at + n);
      at += n;
    }
    const std::vector<std::uint8_t> pixels = lzw_decode(data, min_code_size);
    EXPECT_EQ(pixels.size(), static_cast<size_t>(w) * h);
    if (pixels.size() != static_cast<size_t>(w) * h) return gif;
    // Each frame draws its rectangle over the canvas left by the previous one, skipping its
    // transparent pixels.
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (transparent < 0 || pixels[y * w + x] != transparent)
          canvas[static_cast<size_t>(top + y) * gif.width + left + x] = pixels[y * w + x];
    gif.frames.push_back(canvas);
  }
  return gif;
}

TEST(PngIo, RoundTripKeepsEveryPixel) {
  Image image = pattern(97, 41, 0);
  EXPECT_EQ(decode_png(encode_png(image)), image);  // opaque: written as RGB, read back as RGBA
  image.pixel(3, 4)[3] = 128;                       // translucent: written as RGBA
  EXPECT_EQ(decode_png(encode_png(image)), image);
}

TEST(PngIo, WritesAtomicallyAndReportsUnwritableFolders) {
  const std::string dir = test::fresh_dir("png");
  write_png(dir + "/a.png", pattern(16, 16, 0));
  EXPECT_EQ(read_png(dir + "/a.png"), pattern(16, 16, 0));
  EXPECT_THROW(write_png(dir + "/no/such/folder/a.png", pattern(16, 16, 0)), std::runtime_error);
  EXPECT_THROW(decode_png("not a png"), std::runtime_error);
}

TEST(GifWriter, FramesDecodeBackToTheirColours) {
  // 3 frames of a pattern with fewer than 256 colours: quantisation must be exact.
  std::vector<Image> frames = {pattern(150, 90, 0), pattern(150, 90, 3), pattern(150, 90, 9)};
  GifOptions options;
  options.loop_count = 0;
  const DecodedGif gif = decode_gif(encode_gif(frames, options));
  EXPECT_EQ(gif.width, 150);
  EXPECT_EQ(gif.height, 90);
  EXPECT_EQ(gif.loop_count, 0);
  ASSERT_EQ(gif.frames.size(), 3u);
  ASSERT_EQ(gif.palette.size(), 256u);
  for (size_t f = 0; f < frames.size(); ++f) {
    for (int i = 0; i < 150 * 90; ++i) {
      const std::array<std::uint8_t, 3>& c = gif.palette[gif.frames[f][i]];
      const std::uint8_t* p = &frames[f].rgba[4 * i];
      ASSERT_EQ(c[0], p[0]) << "frame " << f << " pixel " << i;
      ASSERT_EQ(c[1], p[1]);
      ASSERT_EQ(c[2], p[2]);
    }
  }
}

TEST(GifWriter, LaterFramesStoreOnlyWhatChanged) {
  Image first = pattern(120, 80, 0), second = first;
  for (int y = 10; y < 20; ++y)
    for (int x = 30; x < 45; ++x) second.pixel(x, y)[0] = 255;
  const std::string one = encode_gif({first});
  const std::string two = encode_gif({first, second});
  EXPECT_LT(two.size() - one.size(), 400u);  // a 15 x 10 rectangle, not a second full frame
  const DecodedGif gif = decode_gif(two);
  ASSERT_EQ(gif.frames.size(), 2u);
  const ColorQuantizer quantizer({first, second}, 255);
  EXPECT_EQ(gif.frames[1], quantizer.map(second));
  EXPECT_EQ(decode_gif(encode_gif({first, first})).frames[1], quantizer.map(first));
}

TEST(GifWriter, LongNoisyFramesExerciseDictionaryResets) {
  // Many colours and little repetition fill the 4096-entry dictionary several times.
  Image noise(300, 200);
  std::uint32_t state = 12345;
  for (size_t i = 0; i < noise.rgba.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    noise.rgba[i] = static_cast<std::uint8_t>(state >> 24);
  }
  const ColorQuantizer quantizer({noise}, 255);
  const DecodedGif gif = decode_gif(encode_gif({noise}));
  ASSERT_EQ(gif.frames.size(), 1u);
  EXPECT_EQ(gif.frames[0], quantizer.map(noise));
}

TEST(GifWriter, RejectsFramesOfDifferentSizes) {
  EXPECT_THROW(encode_gif({pattern(10, 10, 0), pattern(11, 10, 0)}), std::invalid_argument);
  EXPECT_THROW(encode_gif({}), std::invalid_argument);
}

TEST(ColorQuantizer, ManyColoursMapToNearbyPaletteEntries) {
  Image gradient(256, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 256; ++x) {
      std::uint8_t* p = gradient.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x);
      p[1] = static_cast<std::uint8_t>(y * 4);
      p[2] = static_cast<std::uint8_t>(255 - x);
    }
  const ColorQuantizer quantizer({gradient});
  EXPECT_LE(quantizer.palette().size(), 256u);
  double worst = 0.0;
  for (size_t i = 0; i < gradient.rgba.size(); i += 4) {
    const auto& c = quantizer.palette()[quantizer.index(&gradient.rgba[i])];
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(double(c[k]) - gradient.rgba[i + k]));
  }
  EXPECT_LT(worst, 24.0);
}

TEST(Figures, KeyStepsKeepFirstAndLastAndSpreadEvenly) {
  EXPECT_EQ(key_steps(3, 12), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(key_steps(0, 12), (std::vector<int>{}));
  EXPECT_EQ(key_steps(21, 5), (std::vector<int>{0, 5, 10, 15, 20}));
  const std::vector<int> steps = key_steps(100, 12);
  EXPECT_EQ(steps.size(), 12u);
  EXPECT_EQ(steps.front(), 0);
  EXPECT_EQ(steps.back(), 99);
}

TEST(Figures, KeyStepsShowEveryFirstContactAndSpreadTheRest) {
  // humanoid_sit_desk: 39 steps, the thighs land at 33 and 35, the forearms at 37 and 38.
  EXPECT_EQ(key_steps(39, 8, {33, 35, 37, 38}), (std::vector<int>{0, 8, 17, 25, 33, 35, 37, 38}));
  EXPECT_EQ(key_steps(21, 5, {}), key_steps(21, 5));
  // Too many: thinned evenly, first and last kept.
  EXPECT_EQ(key_steps(30, 4, {3, 6, 9, 12, 15, 18}), (std::vector<int>{0, 6, 15, 29}));
  // A gap is never given more panels than it has steps.
  EXPECT_EQ(key_steps(12, 6, {1, 2}), (std::vector<int>{0, 1, 2, 5, 8, 11}));
}

TEST(Figures, FirstContactStepsAreTheFirstUseOfASurface) {
  const SurfaceRef foot_l{0, 0}, foot_r{0, 1}, hand{0, 2}, floor{1, 0}, wall{1, 1};
  auto step = [](std::vector<Contact> contacts, std::string action,
                 std::optional<Contact> changed) {
    PlanStep s;
    s.stance = Stance(std::move(contacts));
    s.action = std::move(action);
    s.changed = changed;
    return s;
  };
  const Contact l{foot_l, floor}, r{foot_r, floor}, h{hand, wall};
  Plan plan;
  plan.steps = {step({l, r}, "initial", std::nullopt),
                step({l}, "remove", r),
                step({l, r}, "add", r),
                step({l, r, h}, "add", h),
                step({l, r}, "remove", h),
                step({l, r, h}, "add", h)};
  EXPECT_EQ(first_contact_steps(plan), (std::vector<int>{3}));  // the hand, the first time only
}

TEST(Figures, ConvexHullIsCounterClockwiseWithoutInnerPoints) {
  const std::vector<Eigen::Vector2d> hull =
      convex_hull_2d({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {0.5, 0}, {1, 1}});
  ASSERT_EQ(hull.size(), 4u);
  double area = 0.0;
  for (size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  EXPECT_NEAR(area, 1.0, 1e-12);  // positive: counter-clockwise
  EXPECT_EQ(convex_hull_2d({{0, 0}, {1, 1}}).size(), 2u);
}

TEST(Camera, FramingPutsEveryCornerInsideTheMargins) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-0.3, -0.2, 0.0), Eigen::Vector3d(0.4, 0.25, 1.6));
  for (View view : {View::Front, View::Side, View::Top, View::ThreeQuarter}) {
    for (double aspect : {16.0 / 9.0, 0.75}) {
      FrameMargins margins;
      margins.side = 0.05;
      margins.top = 0.1;
      const Camera camera = frame_box(box, view, aspect, margins);
      const Eigen::Matrix4d pv =
          camera.projection_matrix(aspect, 0.01, 100.0) * camera.view_matrix();
      double min_x = 9, max_x = -9, min_y = 9, max_y = -9;
      for (int i = 0; i < 8; ++i) {
        const Eigen::Vector4d c =
            pv * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)).homogeneous();
        min_x = std::min(min_x, c.x() / c.w());
        max_x = std::max(max_x, c.x() / c.w());
        min_y = std::min(min_y, c.y() / c.w());
        max_y = std::max(max_y, c.y() / c.w());
      }
      SCOPED_TRACE(to_string(view));
      EXPECT_GE(min_x, -0.9 - 1e-3);
      EXPECT_LE(max_x, 0.9 + 1e-3);
      EXPECT_GE(min_y, -0.9 - 1e-3);
      EXPECT_LE(max_y, 0.9 - 0.2 + 1e-3);
      // Tight: the box touches the window on at least one axis.
      EXPECT_TRUE(max_x - min_x > 1.8 - 0.02 || max_y - min_y > 1.6 - 0.02);
    }
  }
  EXPECT_EQ(parse_view("three-quarter"), View::ThreeQuarter);
  EXPECT_FALSE(parse_view("diagonal").has_value());
}

TEST(Text, CaptionFontIsInstalledAndDrawsInk) {
  const Font* font = default_font(FontWeight::Bold);
  ASSERT_NE(font, nullptr) << "install fonts-dejavu-core (scripts/bootstrap.sh)";
  Image image(200, 40);
  font->draw(image, 4.0f, 28.0f, "Step 3 \xc2\xb7 add", 20.0f, Color{0, 0, 0, 1});
  int ink = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) ink += image.rgba[i] < 128 ? 1 : 0;
  EXPECT_GT(ink, 100);
  EXPECT_GT(font->width("Step 3", 20.0f), 40.0f);
  EXPECT_LE(font->width(fit_text(*font, "a long caption that cannot fit", 20.0f, 100.0f), 20.0f),
            100.0f);
  EXPECT_EQ(decode_utf8("a\xc2\xb7\xe2\x86\x92"), (std::u32string{U'a', U'\u00b7', U'\u2192'}));
}

TEST(Figures, StepCaptionsNameStepActionAndStance) {
  const std::string dir = test::fresh_dir("captions");
  const LoadedPlan plan = read_plan(test::write_humanoid_plan(dir, 3), {.build_collision = false});
  const PlanView view = app::plan_view(plan);
  EXPECT_EQ(step_caption(view, 0),
            "Step 0 of 2  \u00b7  initial stance\nstance: l_sole, r_sole on floor");
  EXPECT_EQ(step_caption(view, 2).rfind("Step 2 of 2  \u00b7  add ", 0), 0u);
  EXPECT_EQ(plan_title(view), "humanoid_stand");
}

TEST(Figures, CaptionsNameTheEntityWhenTwoHaveASurfaceOfThatName) {
  // Two humanoids (r1, r2) with the same surface names, a table and the floor.
  const Scenario scenario = load_scenario(test::source_path("scenarios/two_humanoids_table.yaml"));
  const Scene& scene = scenario.scene;
  const auto ref = [&](const char* id) { return *scene.surfaces.find(scene.system, id); };
  const Stance stance({{ref("r1/l_sole"), ref("env/floor")}, {ref("r2/r_sole"), ref("env/floor")}});
  EXPECT_EQ(stance_summary(scene, stance), "r1/l_sole, r2/r_sole on floor");
}

TEST(EdgeSmoothing, SoftensStaircasesAndKeepsFlatAreas) {
  // A dark half-plane below a shallow line: an aliased staircase.
  Image image(120, 80, Color{1, 1, 1, 1});
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (y > 20 + 0.25 * x) std::fill_n(image.pixel(x, y), 3, std::uint8_t{30});
  Image smoothed = image;
  smooth_edges(smoothed);
  int blended = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const int v = smoothed.pixel(x, y)[0];
      const double distance = std::abs(y - (20 + 0.25 * x));
      if (distance > 3.0) {
        EXPECT_EQ(v, image.pixel(x, y)[0]) << x << "," << y;
      }
      blended += v > 30 && v < 255 ? 1 : 0;
    }
  }
  EXPECT_GT(blended, image.width / 2);  // intermediate shades along the edge
  Image flat(50, 50, Color{0.3f, 0.6f, 0.9f, 1.0f});
  Image flat_smoothed = flat;
  smooth_edges(flat_smoothed);
  EXPECT_EQ(flat_smoothed, flat);
}

TEST(Image, AreaResizeAveragesBlocks) {
  Image image(4, 2, Color{0, 0, 0, 1});
  image.pixel(0, 0)[0] = 255;
  image.pixel(1, 0)[0] = 255;
  const Image half = resize_area(image, 2, 1);
  EXPECT_EQ(half.pixel(0, 0)[0], 128);
  EXPECT_EQ(half.pixel(1, 0)[0], 0);
}

}  // namespace
}  // namespace stanceplan::render
