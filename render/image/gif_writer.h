#pragma once
// Animated GIF (GIF89a) written by our own encoder, so that no external program is needed: one
// global palette of 255 colours chosen over every frame (median cut, nearest-colour mapping), LZW,
// and frames after the first reduced to what changed (the 256th entry marks unchanged pixels).
#include <string>
#include <vector>

#include "render/image/image.h"

namespace stanceplan::render {

struct GifOptions {
  int delay_cs = 100;       // time each frame is shown, in hundredths of a second
  int last_delay_cs = 250;  // the last frame stays longer before the loop restarts
  int loop_count = 0;       // 0 = loop forever
};

// Every frame must have the same size; alpha is ignored. Throws std::invalid_argument otherwise.
std::string encode_gif(const std::vector<Image>& frames, const GifOptions& options = {});
// Writes atomically; throws std::runtime_error naming the path.
void write_gif(const std::string& path, const std::vector<Image>& frames,
               const GifOptions& options = {});

}  // namespace stanceplan::render
