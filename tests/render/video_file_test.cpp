// Videos through FFmpeg (render/image/video_file.h): what is written decodes back to the frames
// given (count, size, colours), odd sizes are cropped to even, and faults name the file. Skipped
// where the build has no FFmpeg (optional: scripts/bootstrap.sh installs it).
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "render/image/video_file.h"
#include "tests/render/render_fixtures.h"

namespace stanceplan::render {
namespace {

namespace fs = std::filesystem;

bool near(const std::uint8_t* p, int r, int g, int b, int tolerance) {
  return std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
         std::abs(p[2] - b) <= tolerance;
}

TEST(VideoFile, FramesDecodeBackInOrderWithTheirColours) {
  if (!video_support()) GTEST_SKIP() << "this build has no FFmpeg";
  const std::string path = test::fresh_dir("video") + "/colours.mp4";
  {
    VideoWriter video(path, 64, 48, {10.0});
    for (int k = 0; k < 20; ++k)  // ten red frames, then ten blue ones
      video.add(
          Image(64, 48, k < 10 ? Color{0.9f, 0.1f, 0.1f, 1.0f} : Color{0.1f, 0.2f, 0.9f, 1.0f}));
    EXPECT_FALSE(fs::exists(path)) << "written beside the target until finish()";
    video.finish();
    EXPECT_EQ(video.frames(), 20);
  }
  const std::vector<Image> frames = read_video(path);
  ASSERT_EQ(frames.size(), 20u);
  EXPECT_EQ(frames[0].width, 64);
  EXPECT_EQ(frames[0].height, 48);
  EXPECT_TRUE(near(frames[3].pixel(32, 24), 230, 26, 26, 20));
  EXPECT_TRUE(near(frames[15].pixel(32, 24), 26, 51, 230, 20));
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(fs::path(path).parent_path()))
    ++files;
  EXPECT_EQ(files, 1) << "no temporary file left";
}

TEST(VideoFile, AnOddSizeIsCroppedToEven) {
  if (!video_support()) GTEST_SKIP() << "this build has no FFmpeg";
  const std::string path = test::fresh_dir("video_odd") + "/odd.mp4";
  VideoWriter video(path, 65, 49);
  video.add(Image(65, 49, Color{0.2f, 0.8f, 0.2f, 1.0f}));
  video.finish();
  const std::vector<Image> frames = read_video(path);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].width, 64);
  EXPECT_EQ(frames[0].height, 48);
}

TEST(VideoFile, FaultsNameTheFileOrTheSize) {
  if (!video_support()) GTEST_SKIP() << "this build has no FFmpeg";
  const std::string dir = test::fresh_dir("video_faults");
  try {
    VideoWriter video("/nonexistent/folder/a.mp4", 64, 48);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/folder/a.mp4: cannot write the video: ", 0),
              0u)
        << e.what();
  }
  EXPECT_THROW(VideoWriter(dir + "/small.mp4", 1, 48), std::invalid_argument);
  EXPECT_THROW(VideoWriter(dir + "/fps.mp4", 64, 48, {0.0}), std::invalid_argument);
  {
    VideoWriter video(dir + "/size.mp4", 64, 48);
    EXPECT_THROW(video.add(Image(32, 48)), std::invalid_argument);
  }  // abandoned: no file
  EXPECT_FALSE(fs::exists(dir + "/size.mp4"));
  EXPECT_TRUE(fs::is_empty(dir)) << "an abandoned writer leaves no temporary file";
  try {
    read_video(dir + "/missing.mp4");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(dir + "/missing.mp4: cannot read the video: ", 0), 0u)
        << e.what();
  }
}

TEST(VideoFile, WithoutFFmpegTheWriterSaysWhatToInstall) {
  if (video_support()) GTEST_SKIP() << "this build has FFmpeg";
  try {
    VideoWriter video("a.mp4", 64, 48);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "a.mp4: cannot write the video: this build has no FFmpeg (install "
                 "libavcodec-dev libavformat-dev libswscale-dev and configure again)");
  }
}

}  // namespace
}  // namespace stanceplan::render
