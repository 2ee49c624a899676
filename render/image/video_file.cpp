#include "render/image/video_file.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#if STANCEPLAN_HAS_FFMPEG
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}
#endif

namespace stanceplan::render {

namespace {

void check_writer_arguments(int width, int height, const VideoOptions& options) {
  if (width < 2 || height < 2 || width > 8192 || height > 8192)
    throw std::invalid_argument("VideoWriter: frame size " + std::to_string(width) + "x" +
                                std::to_string(height) + " out of range (2 to 8192)");
  if (!(options.fps > 0.0 && options.fps <= 240.0))
    throw std::invalid_argument("VideoWriter: fps " + std::to_string(options.fps) +
                                " out of range (0, 240]");
  if (options.quality < 0 || options.quality > 51)
    throw std::invalid_argument("VideoWriter: quality " + std::to_string(options.quality) +
                                " out of range [0, 51]");
}

}  // namespace

#if STANCEPLAN_HAS_FFMPEG

namespace {

std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(code, text, sizeof(text));
  return text;
}

// The temporary file keeps the target's extension (FFmpeg picks the container by the target's).
std::string part_path(const std::string& path) {
  const std::filesystem::path p(path);
  std::string name(".");  // appended, not "." + ...: GCC 12's -Wrestrict false positive
  name.append(p.stem().string()).append(".part").append(p.extension().string());
  return (p.parent_path() / name).string();
}

}  // namespace

struct VideoWriter::Impl {
  std::string path, part;
  int width = 0, height = 0;  // of the frames added; the video's are rounded down to even
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scale = nullptr;
  int frames = 0;
  bool finished = false;

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw std::runtime_error(path + ": cannot write the video: " + what +
                             (code < 0 ? " (" + av_error(code) + ")" : std::string()));
  }
  void open_container();
  void open_encoder(const VideoOptions& options);
  void encode(const AVFrame* f);
  void release();
};

void VideoWriter::Impl::open_container() {
  int code = avformat_alloc_output_context2(&format, nullptr, nullptr, path.c_str());
  if (code < 0 || format == nullptr) fail("no container for this file name's extension", code);
  code = avio_open(&format->pb, part.c_str(), AVIO_FLAG_WRITE);
  if (code < 0) fail("cannot open " + part, code);
}

void VideoWriter::Impl::open_encoder(const VideoOptions& options) {
  // libx264 prints its statistics at INFO level when closed: quiet, unless the embedding
  // program chose FFmpeg's log level itself.
  if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_ERROR);
  const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
  if (encoder == nullptr) encoder = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
  if (encoder == nullptr) fail("no H.264 or MPEG-4 encoder in this libavcodec", 0);
  codec = avcodec_alloc_context3(encoder);
  codec->width = width & ~1;
  codec->height = height & ~1;
  codec->pix_fmt = AV_PIX_FMT_YUV420P;
  codec->framerate = av_d2q(options.fps, 100000);
  codec->time_base = av_inv_q(codec->framerate);
  codec->gop_size = 50;
  codec->thread_count = 1;  // the same bytes whatever the machine
  if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (std::string(encoder->name) == "libx264") {
    av_opt_set(codec->priv_data, "preset", "medium", 0);
    av_opt_set(codec->priv_data, "crf", std::to_string(options.quality).c_str(), 0);
  } else {
    codec->flags |= AV_CODEC_FLAG_QSCALE;
    codec->global_quality = FF_QP2LAMBDA * std::max(2, options.quality / 4);
  }
  int code = avcodec_open2(codec, encoder, nullptr);
  if (code < 0) fail(std::string("cannot open the encoder ") + encoder->name, code);
  stream = avformat_new_stream(format, nullptr);
  if (stream == nullptr) fail("cannot add a stream", 0);
  stream->time_base = codec->time_base;
  code = avcodec_parameters_from_context(stream->codecpar, codec);
  if (code < 0) fail("cannot copy the encoder's parameters", code);
  code = avformat_write_header(format, nullptr);
  if (code < 0) fail("cannot write the header", code);
}

// Sends a frame (null: flush) and writes every packet the encoder has ready.
void VideoWriter::Impl::encode(const AVFrame* f) {
  int code = avcodec_send_frame(codec, f);
  if (code < 0) fail("the encoder refused a frame", code);
  while ((code = avcodec_receive_packet(codec, packet)) >= 0) {
    // One frame long: the MP4 muxer's edit list would otherwise end before the last frame,
    // which players (and read_video) then drop.
    if (packet->duration <= 0) packet->duration = 1;
    av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    code = av_interleaved_write_frame(format, packet);
    if (code < 0) fail("cannot write a packet", code);
  }
  if (code != AVERROR(EAGAIN) && code != AVERROR_EOF) fail("the encoder failed", code);
}

void VideoWriter::Impl::release() {
  sws_freeContext(scale);
  av_packet_free(&packet);
  av_frame_free(&frame);
  avcodec_free_context(&codec);
  if (format != nullptr && format->pb != nullptr) avio_closep(&format->pb);
  avformat_free_context(format);
  format = nullptr;
}

bool video_support() {
  return true;
}

VideoWriter::VideoWriter(const std::string& path, int width, int height,
                         const VideoOptions& options)
    : impl_(std::make_unique<Impl>()) {
  check_writer_arguments(width, height, options);
  Impl& v = *impl_;
  v.path = path;
  v.part = part_path(path);
  v.width = width;
  v.height = height;
  try {
    v.open_container();
    v.open_encoder(options);
    v.frame = av_frame_alloc();
    v.packet = av_packet_alloc();
    v.frame->format = v.codec->pix_fmt;
    v.frame->width = v.codec->width;
    v.frame->height = v.codec->height;
    if (const int code = av_frame_get_buffer(v.frame, 0); code < 0) v.fail("no frame buffer", code);
    v.scale =
        sws_getContext(v.codec->width, v.codec->height, AV_PIX_FMT_RGBA, v.codec->width,
                       v.codec->height, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
    if (v.scale == nullptr) v.fail("no RGBA to YUV conversion", 0);
  } catch (...) {
    v.release();
    std::remove(v.part.c_str());
    throw;
  }
}

VideoWriter::~VideoWriter() {
  impl_->release();
  if (!impl_->finished) std::remove(impl_->part.c_str());
}

void VideoWriter::add(const Image& image) {
  Impl& v = *impl_;
  if (v.finished) throw std::logic_error("VideoWriter::add after finish");
  if (image.width != v.width || image.height != v.height)
    throw std::invalid_argument("VideoWriter::add: frame " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ", the video's are " +
                                std::to_string(v.width) + "x" + std::to_string(v.height));
  if (const int code = av_frame_make_writable(v.frame); code < 0) v.fail("frame busy", code);
  const std::uint8_t* source[1] = {image.rgba.data()};
  const int stride[1] = {4 * image.width};  // an odd last column is left out by the width
  sws_scale(v.scale, source, stride, 0, v.codec->height, v.frame->data, v.frame->linesize);
  v.frame->pts = v.frames++;
  v.encode(v.frame);
}

void VideoWriter::finish() {
  Impl& v = *impl_;
  if (v.finished) return;
  v.encode(nullptr);
  if (const int code = av_write_trailer(v.format); code < 0)
    v.fail("cannot write the trailer", code);
  avio_closep(&v.format->pb);
  std::error_code error;
  std::filesystem::rename(v.part, v.path, error);
  if (error) v.fail("cannot rename " + v.part + ": " + error.message(), 0);
  v.finished = true;
}

int VideoWriter::frames() const {
  return impl_->frames;
}

std::string VideoWriter::encoder() const {
  return impl_->codec != nullptr ? impl_->codec->codec->name : "";
}

namespace {

// What read_video holds, freed however it leaves.
struct Decoder {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* scale = nullptr;
  ~Decoder() {
    sws_freeContext(scale);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
  }
  // Every frame the decoder has ready, converted to RGBA.
  void drain(std::vector<Image>& frames) {
    while (avcodec_receive_frame(codec, frame) >= 0) {
      scale = sws_getCachedContext(
          scale, frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
          frame->width, frame->height, AV_PIX_FMT_RGBA, SWS_BICUBIC, nullptr, nullptr, nullptr);
      Image image(frame->width, frame->height);
      std::uint8_t* target[1] = {image.rgba.data()};
      const int stride[1] = {4 * frame->width};
      sws_scale(scale, frame->data, frame->linesize, 0, frame->height, target, stride);
      frames.push_back(std::move(image));
    }
  }
};

}  // namespace

std::vector<Image> read_video(const std::string& path) {
  const auto fail = [&](const std::string& what, int code) {
    throw std::runtime_error(path + ": cannot read the video: " + what + " (" + av_error(code) +
                             ")");
  };
  Decoder d;
  int code = avformat_open_input(&d.format, path.c_str(), nullptr, nullptr);
  if (code < 0) fail("cannot open it", code);
  if ((code = avformat_find_stream_info(d.format, nullptr)) < 0) fail("no stream", code);
  const AVCodec* decoder = nullptr;
  const int index = av_find_best_stream(d.format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (index < 0 || decoder == nullptr) fail("no video stream", index);
  d.codec = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(d.codec, d.format->streams[index]->codecpar);
  d.codec->thread_count = 1;
  if ((code = avcodec_open2(d.codec, decoder, nullptr)) < 0) fail("cannot open the decoder", code);
  std::vector<Image> frames;
  while (av_read_frame(d.format, d.packet) >= 0) {
    if (d.packet->stream_index == index && avcodec_send_packet(d.codec, d.packet) >= 0)
      d.drain(frames);
    av_packet_unref(d.packet);
  }
  avcodec_send_packet(d.codec, nullptr);  // flush
  d.drain(frames);
  return frames;
}

#else  // no FFmpeg in this build

struct VideoWriter::Impl {};

bool video_support() {
  return false;
}

VideoWriter::VideoWriter(const std::string& path, int width, int height,
                         const VideoOptions& options) {
  check_writer_arguments(width, height, options);
  throw std::runtime_error(path +
                           ": cannot write the video: this build has no FFmpeg (install "
                           "libavcodec-dev libavformat-dev libswscale-dev and configure again)");
}

VideoWriter::~VideoWriter() = default;
void VideoWriter::add(const Image&) {}
void VideoWriter::finish() {}
int VideoWriter::frames() const {
  return 0;
}
std::string VideoWriter::encoder() const {
  return "";
}

std::vector<Image> read_video(const std::string& path) {
  throw std::runtime_error(path + ": cannot read the video: this build has no FFmpeg");
}

#endif

}  // namespace stanceplan::render
