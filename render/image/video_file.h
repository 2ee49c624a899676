#pragma once
// Videos of rendered frames through FFmpeg's libraries, the one file of the project that speaks
// FFmpeg: MP4 (or any container FFmpeg knows by the file's extension) in H.264 by libx264 where
// Debian's libavcodec has it, else MPEG-4 part 2 (FFmpeg's own encoder). Optional: a build without
// libavcodec-dev, libavformat-dev and libswscale-dev compiles this without them, video_support() is
// false and VideoWriter's constructor throws saying what to install.
#include <memory>
#include <string>
#include <vector>

#include "render/image/image.h"

namespace stanceplan::render {

struct VideoOptions {
  double fps = 10.0;  // frames per second, in (0, 240]
  int quality = 20;   // libx264's constant rate factor (0 lossless .. 51 worst); MPEG-4: q = /4
};

// Whether this build can write (and read back) videos.
bool video_support();

// Frames are added one at a time (a motion's hundreds of frames are never all in memory). Frames
// of odd width or height lose their last column or row (YUV 4:2:0 needs even sizes). The file is
// written beside the target and renamed over it by finish(): an abandoned writer (an exception, no
// finish) leaves no file.
class VideoWriter {
 public:
  // Throws std::invalid_argument for sizes below 2x2 or options out of range, std::runtime_error
  // naming the path when the file cannot be opened or no encoder is found (or no FFmpeg).
  VideoWriter(const std::string& path, int width, int height, const VideoOptions& options = {});
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  void add(const Image& frame);  // std::invalid_argument when its size differs from the writer's
  void finish();                 // flushes the encoder, closes and renames the file
  int frames() const;            // added so far
  std::string encoder() const;   // "libx264" or "mpeg4"

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Every frame of a video file, decoded to RGBA (for tests and checks). std::runtime_error naming
// the path when it cannot be read.
std::vector<Image> read_video(const std::string& path);

}  // namespace stanceplan::render
