#include "client/vemview/video_output.h"

#include <fmt/format.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

namespace vem::view {

struct VideoOutput::Impl {
  std::string path;
  cv::VideoWriter writer;
  int widthPx = 0;
  int heightPx = 0;
  std::uint64_t frames = 0;
};

VideoOutput::VideoOutput(std::string path) : impl_(std::make_unique<Impl>()) {
  impl_->path = std::move(path);
}
VideoOutput::~VideoOutput() { close(); }
VideoOutput::VideoOutput(VideoOutput&&) noexcept = default;
VideoOutput& VideoOutput::operator=(VideoOutput&&) noexcept = default;

std::expected<void, std::string> VideoOutput::write(std::span<const std::uint8_t> srgb8,
                                                    int widthPx, int heightPx) {
  Impl& v = *impl_;
  if (!v.writer.isOpened()) {
    if (v.frames > 0) {
      return std::unexpected(fmt::format("--video {}: the file was closed", v.path));
    }
    const int fourcc = cv::VideoWriter::fourcc('m', 'p', '4', 'v');
    if (!v.writer.open(v.path, cv::CAP_FFMPEG, fourcc, 30.0, cv::Size(widthPx, heightPx))) {
      return std::unexpected(fmt::format(
          "--video {}: OpenCV cannot write an MPEG-4 video there (expected a writable .mp4 "
          "path)",
          v.path));
    }
    v.widthPx = widthPx;
    v.heightPx = heightPx;
  }
  if (widthPx != v.widthPx || heightPx != v.heightPx) {
    return std::unexpected(fmt::format("--video {}: a frame of {} x {} px in a video of {} x {}",
                                       v.path, widthPx, heightPx, v.widthPx, v.heightPx));
  }
  const cv::Mat rgb(heightPx, widthPx, CV_8UC3, const_cast<std::uint8_t*>(srgb8.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  v.writer.write(bgr);
  ++v.frames;
  return {};
}

std::uint64_t VideoOutput::frames() const { return impl_ ? impl_->frames : 0; }

void VideoOutput::close() {
  if (impl_ && impl_->writer.isOpened()) impl_->writer.release();
}

}  // namespace vem::view
