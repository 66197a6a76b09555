#include "crowdsim/render/mp4_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef CROWDSIM_RENDER_WITH_MP4
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.h"
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/imgutils.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}
#endif

namespace crowdsim::render {

#ifdef CROWDSIM_RENDER_WITH_MP4

namespace {

std::string AvError(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(code, buf, sizeof(buf));
  return buf;
}

}  // namespace

struct Mp4Writer::Impl {
  std::filesystem::path path;
  std::string temp;  // the file written, renamed to `path` by Finish; removed if never finished
  int fd = -1;
  int write_errno = 0;  // the first failed write's errno
  AVFormatContext* format = nullptr;
  AVCodecContext* encoder = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  int width = 0;
  int height = 0;
  int even_width = 0;  // yuv420p needs even sizes: frames are padded with white
  int even_height = 0;
  std::vector<std::uint8_t> padded;
  std::int64_t pts = 0;
  bool finished = false;

  void Check(int status, const char* what) const {
    if (status < 0)
      throw std::runtime_error("cannot write " + path.string() + " (" + what +
                               "): " + AvError(status));
  }

  void Encode(const AVFrame* f) {
    Check(avcodec_send_frame(encoder, f), "encoding");
    for (;;) {
      const int r = avcodec_receive_packet(encoder, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      Check(r, "encoding");
      av_packet_rescale_ts(packet, encoder->time_base, stream->time_base);
      packet->stream_index = stream->index;
      Check(av_interleaved_write_frame(format, packet), "muxing");
    }
  }

  // The muxer writes and seeks through the temp file's descriptor (custom I/O), never by name.
  static int WritePacket(void* opaque, uint8_t* buf, int size) {
    Impl& m = *static_cast<Impl*>(opaque);
    const int error =
        common::WriteAll(m.fd, reinterpret_cast<const char*>(buf), static_cast<size_t>(size));
    if (error == 0) return size;
    if (m.write_errno == 0) m.write_errno = error;
    return AVERROR(error);
  }
  static int64_t Seek(void* opaque, int64_t offset, int whence) {
    Impl& m = *static_cast<Impl*>(opaque);
    if (whence & AVSEEK_SIZE) {
      struct stat st {};
      return fstat(m.fd, &st) == 0 ? static_cast<int64_t>(st.st_size) : AVERROR(errno);
    }
    const off_t at = lseek(m.fd, static_cast<off_t>(offset), whence & ~AVSEEK_FORCE);
    return at < 0 ? AVERROR(errno) : static_cast<int64_t>(at);
  }

  ~Impl() {
    if (sws) sws_freeContext(sws);
    if (packet) av_packet_free(&packet);
    if (frame) av_frame_free(&frame);
    if (encoder) avcodec_free_context(&encoder);
    if (format) {
      if (format->pb) {
        av_freep(&format->pb->buffer);
        avio_context_free(&format->pb);
      }
      avformat_free_context(format);
    }
    if (fd >= 0) close(fd);
    if (!temp.empty()) unlink(temp.c_str());
  }
};

Mp4Writer::Mp4Writer(const std::filesystem::path& path, int width, int height, int fps)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  m.width = width;
  m.height = height;
  m.even_width = width + (width & 1);
  m.even_height = height + (height & 1);
  av_log_set_level(AV_LOG_ERROR);  // libx264 reports its settings and statistics otherwise
  m.Check(avformat_alloc_output_context2(&m.format, nullptr, "mp4", path.c_str()),
          "output context");
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_H264);
  if (codec == nullptr) codec = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
  if (codec == nullptr)
    throw std::runtime_error("cannot write " + path.string() +
                             ": libavcodec has no H.264 or MPEG-4 encoder");
  m.stream = avformat_new_stream(m.format, nullptr);
  if (m.stream == nullptr)
    throw std::runtime_error("cannot write " + path.string() + ": no stream");
  m.encoder = avcodec_alloc_context3(codec);
  m.encoder->width = m.even_width;
  m.encoder->height = m.even_height;
  m.encoder->time_base = AVRational{1, fps};
  m.encoder->framerate = AVRational{fps, 1};
  m.encoder->pix_fmt = AV_PIX_FMT_YUV420P;
  m.encoder->gop_size = 2 * fps;
  if (codec->id == AV_CODEC_ID_H264) {
    av_opt_set(m.encoder->priv_data, "crf", "20", 0);
    av_opt_set(m.encoder->priv_data, "preset", "medium", 0);
  } else {
    // Fixed quantiser: sharp lines and text on flat colours.
    m.encoder->flags |= AV_CODEC_FLAG_QSCALE;
    m.encoder->global_quality = FF_QP2LAMBDA * 3;
  }
  if (m.format->oformat->flags & AVFMT_GLOBALHEADER)
    m.encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  m.Check(avcodec_open2(m.encoder, codec, nullptr), "opening the encoder");
  m.Check(avcodec_parameters_from_context(m.stream->codecpar, m.encoder), "stream parameters");
  m.stream->time_base = m.encoder->time_base;
  // A new file beside `path`, renamed over it when whole: an interrupted render leaves the
  // previous video as it was.
  m.fd = common::CreateBeside(path, &m.temp);
  constexpr int kIoBuffer = 1 << 16;
  auto* buffer = static_cast<unsigned char*>(av_malloc(kIoBuffer));
  m.format->pb =
      avio_alloc_context(buffer, kIoBuffer, 1, &m, nullptr, &Impl::WritePacket, &Impl::Seek);
  if (m.format->pb == nullptr) {
    av_free(buffer);
    throw std::runtime_error("cannot write " + path.string() + ": out of memory");
  }
  m.format->flags |= AVFMT_FLAG_CUSTOM_IO;
  m.Check(avformat_write_header(m.format, nullptr), "header");
  m.frame = av_frame_alloc();
  m.frame->format = AV_PIX_FMT_YUV420P;
  m.frame->width = m.even_width;
  m.frame->height = m.even_height;
  m.Check(av_frame_get_buffer(m.frame, 0), "frame buffer");
  m.packet = av_packet_alloc();
  m.sws = sws_getContext(m.even_width, m.even_height, AV_PIX_FMT_RGB24, m.even_width, m.even_height,
                         AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
  if (m.sws == nullptr)
    throw std::runtime_error("cannot write " + path.string() + ": no colour converter");
  m.padded.assign(static_cast<size_t>(m.even_width) * m.even_height * 3, 255);
}

// Without Finish (an error or an interrupt), Impl removes the unfinished file: `path` stays.
Mp4Writer::~Mp4Writer() = default;

void Mp4Writer::AddFrame(const RgbImage& image) {
  Impl& m = *impl_;
  if (image.width != m.width || image.height != m.height) {
    throw std::invalid_argument("MP4 frame is " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ", the video is " +
                                std::to_string(m.width) + "x" + std::to_string(m.height));
  }
  for (int y = 0; y < m.height; ++y) {
    std::copy_n(&image.pixels[static_cast<size_t>(y) * m.width * 3],
                static_cast<size_t>(m.width) * 3,
                &m.padded[static_cast<size_t>(y) * m.even_width * 3]);
  }
  m.Check(av_frame_make_writable(m.frame), "frame buffer");
  const std::uint8_t* src[1] = {m.padded.data()};
  const int stride[1] = {m.even_width * 3};
  sws_scale(m.sws, src, stride, 0, m.even_height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.pts++;
  m.Encode(m.frame);
}

void Mp4Writer::Finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  m.finished = true;
  m.Encode(nullptr);
  m.Check(av_write_trailer(m.format), "trailer");
  avio_flush(m.format->pb);
  if (m.write_errno == 0 && close(m.fd) != 0) m.write_errno = errno;
  m.fd = -1;
  if (m.write_errno != 0) {
    throw std::runtime_error("cannot write " + m.path.string() + ": " +
                             std::strerror(m.write_errno) +
                             " (the previous file, if any, is unchanged)");
  }
  if (std::rename(m.temp.c_str(), m.path.c_str()) != 0) {
    throw std::runtime_error("cannot replace " + m.path.string() + ": " + std::strerror(errno));
  }
  m.temp.clear();
}

#else  // no libav: the class exists so callers compile; constructing it explains what to do

struct Mp4Writer::Impl {};

Mp4Writer::Mp4Writer(const std::filesystem::path& path, int, int, int) {
  throw std::runtime_error(
      "cannot write '" + path.string() +
      "': mp4 support was not built (libavcodec/libavformat not found at configure time); "
      "use .gif, or install libavcodec-dev libavformat-dev libswscale-dev and reconfigure");
}
Mp4Writer::~Mp4Writer() = default;
void Mp4Writer::AddFrame(const RgbImage&) {}
void Mp4Writer::Finish() {}

#endif

}  // namespace crowdsim::render
