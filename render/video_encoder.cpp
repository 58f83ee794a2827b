#include "render/video_encoder.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include "render/av_error.h"
#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

struct VideoEncoder::Impl {
  VideoSettings settings;
  std::string final_path, temp_path, codec_name, note;
  std::unique_ptr<RemovedOnSignal> temp_guard;  // Ctrl-C or kill mid-render leaves no temporary
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  std::int64_t next_pts = 0;
  bool finished = false;

  ~Impl() {
    if (sws) sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
    if (!finished && !temp_path.empty()) {
      std::error_code ec;
      std::filesystem::remove(temp_path, ec);
    }
  }

  // Sends `f` (nullptr: drain) and writes every packet the encoder gives back.
  void encode(AVFrame* f) {
    int rc = avcodec_send_frame(codec, f);
    if (rc < 0) throw std::runtime_error("video encoder refused a frame: " + av_error(rc));
    for (;;) {
      rc = avcodec_receive_packet(codec, packet);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      if (rc < 0) throw std::runtime_error("video encoding failed: " + av_error(rc));
      // One frame per packet: the muxer sums durations into the track length (frames/fps).
      packet->duration = 1;
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format, packet);
      if (rc < 0) throw InputError(final_path + ": cannot write video (" + av_error(rc) + ")");
    }
  }
};

VideoEncoder::VideoEncoder(const std::string& path, const VideoSettings& settings) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  // libx264 and the muxer report statistics at info level; the CLI prints its own summary.
  av_log_set_level(AV_LOG_ERROR);
  m.settings = settings;
  m.final_path = path;
  const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
  const char* container = "mp4";
  if (!encoder) {
    encoder = avcodec_find_encoder_by_name("libvpx-vp9");
    if (!encoder) throw std::runtime_error("neither libx264 (H.264) nor libvpx-vp9 is available in libavcodec");
    container = "webm";
    m.final_path = std::filesystem::path(path).replace_extension(".webm").string();
    m.note = "H.264 (libx264) is not available in this libavcodec; wrote VP9 in WebM instead: " + m.final_path;
  }
  m.codec_name = encoder == nullptr ? "" : (std::string(container) == "mp4" ? "h264" : "vp9");
  // Hidden and unique to this process; removed if Ctrl-C or kill stops the render, and left by
  // kill -9 for the next render into this directory to remove (sim/io/output_file.h).
  m.temp_path = temporary_sibling(m.final_path);
  m.temp_guard = std::make_unique<RemovedOnSignal>(m.temp_path);

  if (avformat_alloc_output_context2(&m.format, nullptr, container, m.temp_path.c_str()) < 0 || !m.format)
    throw std::runtime_error(std::string("libavformat has no ") + container + " muxer");
  // Bit-exact: no library version strings or timestamps in the file, so bytes are reproducible.
  m.format->flags |= AVFMT_FLAG_BITEXACT;
  m.stream = avformat_new_stream(m.format, nullptr);
  m.codec = avcodec_alloc_context3(encoder);
  m.frame = av_frame_alloc();
  m.packet = av_packet_alloc();
  if (!m.stream || !m.codec || !m.frame || !m.packet) throw std::runtime_error("out of memory opening the video encoder");

  AVCodecContext* c = m.codec;
  c->width = settings.width;
  c->height = settings.height;
  c->time_base = AVRational{1, settings.fps};
  c->framerate = AVRational{settings.fps, 1};
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->gop_size = 2 * settings.fps;  // a keyframe every 2 s keeps seeking in a review player quick
  c->max_b_frames = 0;             // pts == dts: frame durations and the edit list stay trivial
  // A fixed thread count: the output must not depend on the machine's core count. One thread,
  // because rendering owns the other core of the pipeline.
  c->thread_count = 1;
  c->flags |= AV_CODEC_FLAG_BITEXACT;
  // sRGB pixels converted with BT.709 coefficients, limited range, and tagged as such.
  c->colorspace = AVCOL_SPC_BT709;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  if (m.format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (m.codec_name == "h264") {
    av_opt_set(c->priv_data, "preset", "superfast", 0);
    av_opt_set(c->priv_data, "crf", std::to_string(settings.crf).c_str(), 0);
  } else {
    av_opt_set(c->priv_data, "deadline", "realtime", 0);
    av_opt_set(c->priv_data, "cpu-used", "8", 0);
    av_opt_set(c->priv_data, "crf", "32", 0);
    c->bit_rate = 0;
  }
  int rc = avcodec_open2(c, encoder, nullptr);
  if (rc < 0) throw std::runtime_error("cannot open the " + m.codec_name + " encoder: " + av_error(rc));
  avcodec_parameters_from_context(m.stream->codecpar, c);
  m.stream->time_base = c->time_base;
  m.stream->avg_frame_rate = c->framerate;

  rc = avio_open(&m.format->pb, m.temp_path.c_str(), AVIO_FLAG_WRITE);
  if (rc < 0) throw InputError(m.final_path + ": cannot create video file (" + av_error(rc) + ")");
  AVDictionary* options = nullptr;
  // faststart: the muxer moves the index (moov) before the media data when it finishes.
  if (m.codec_name == "h264") av_dict_set(&options, "movflags", "+faststart", 0);
  rc = avformat_write_header(m.format, &options);
  av_dict_free(&options);
  if (rc < 0) throw InputError(m.final_path + ": cannot write video header (" + av_error(rc) + ")");

  m.frame->format = c->pix_fmt;
  m.frame->width = c->width;
  m.frame->height = c->height;
  if (av_frame_get_buffer(m.frame, 0) < 0) throw std::runtime_error("out of memory for a video frame");
  m.sws = sws_getContext(c->width, c->height, AV_PIX_FMT_RGBA, c->width, c->height, AV_PIX_FMT_YUV420P,
                         SWS_BILINEAR | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
  if (!m.sws) throw std::runtime_error("libswscale cannot convert RGBA to yuv420p");
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(m.sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
}

VideoEncoder::~VideoEncoder() = default;

const std::string& VideoEncoder::path() const { return impl_->final_path; }
const std::string& VideoEncoder::codec() const { return impl_->codec_name; }
const std::string& VideoEncoder::note() const { return impl_->note; }

void VideoEncoder::add_frame(const std::uint8_t* rgba) {
  Impl& m = *impl_;
  if (av_frame_make_writable(m.frame) < 0) throw std::runtime_error("video frame not writable");
  const std::uint8_t* src[1] = {rgba};
  const int stride[1] = {4 * m.settings.width};
  sws_scale(m.sws, src, stride, 0, m.settings.height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.next_pts++;
  m.encode(m.frame);
}

void VideoEncoder::finish() {
  Impl& m = *impl_;
  m.encode(nullptr);
  const int rc = av_write_trailer(m.format);
  if (rc < 0) throw InputError(m.final_path + ": cannot finish video (" + av_error(rc) + ")");
  // The last buffered bytes reach the file only now: a write error here (a full disk) must stop
  // the rename, or a truncated video would stand under the final name.
  avio_flush(m.format->pb);
  const int write_error = m.format->pb->error;
  const int closed = avio_closep(&m.format->pb);
  if (write_error < 0 || closed < 0)
    throw InputError(m.final_path + ": cannot finish video (" + av_error(write_error < 0 ? write_error : closed) + ")");
  std::error_code ec;
  std::filesystem::rename(m.temp_path, m.final_path, ec);
  if (ec) throw InputError(m.final_path + ": cannot rename the finished video (" + ec.message() + ")");
  m.finished = true;
}

VideoInfo probe_video(const std::string& path) {
  AVFormatContext* f = nullptr;
  if (avformat_open_input(&f, path.c_str(), nullptr, nullptr) < 0) throw InputError(path + ": cannot open video");
  struct Closer {
    AVFormatContext** f;
    ~Closer() { avformat_close_input(f); }
  } closer{&f};
  if (avformat_find_stream_info(f, nullptr) < 0) throw InputError(path + ": cannot read video stream info");
  const int index = av_find_best_stream(f, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (index < 0) throw InputError(path + ": no video stream");
  const AVStream* s = f->streams[index];
  VideoInfo info;
  info.container = f->iformat->name;
  info.codec = avcodec_get_name(s->codecpar->codec_id);
  const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(s->codecpar->format));
  info.pixel_format = pix ? pix : "?";
  info.width = s->codecpar->width;
  info.height = s->codecpar->height;
  info.fps = av_q2d(s->avg_frame_rate);
  info.duration = s->duration != AV_NOPTS_VALUE ? s->duration * av_q2d(s->time_base)
                                                : static_cast<double>(f->duration) / AV_TIME_BASE;
  AVPacket* p = av_packet_alloc();
  while (av_read_frame(f, p) >= 0) {
    if (p->stream_index == index) ++info.frames;
    av_packet_unref(p);
  }
  av_packet_free(&p);
  return info;
}

}  // namespace vascsim::render
