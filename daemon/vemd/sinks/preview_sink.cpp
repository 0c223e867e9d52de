#include "vemd/sinks/preview_sink.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>

#include <opencv2/imgcodecs.hpp>

#include "frames/published_lights.h"
#include "util/atomic_file.h"
#include "util/contract.h"

namespace vem::vemd {

std::expected<PreviewSink, SinkFailure> PreviewSink::create(const std::filesystem::path& dir,
                                                            PreviewOptions options) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    return std::unexpected(SinkFailure{"preview: cannot use " + dir.string() +
                                       " as the preview folder (" +
                                       (error ? error.message() : "not a folder") + ")"});
  }
  options.every = std::max(1, options.every);
  options.style.scale = std::max(1, options.style.scale);
  return PreviewSink(dir, options);
}

PreviewSink::PreviewSink(std::filesystem::path dir, PreviewOptions options)
    : dir_(std::move(dir)), options_(options) {}

std::filesystem::path PreviewSink::numberedPath(std::uint64_t seq) const {
  char name[40];
  std::snprintf(name, sizeof name, "preview-%010llu.png", static_cast<unsigned long long>(seq));
  return dir_ / name;
}

std::expected<void, SinkFailure> PreviewSink::consume(const ProcessedFrame& frame) {
  // The pipeline always sets both.
  VEM_EXPECTS(frame.captured != nullptr && frame.polar != nullptr);
  if (failed_ || frame.polar->pixelCount() == 0) {
    return {};
  }
  if (frames_++ % std::uint64_t(options_.every) != 0) return {};
  const PublishedLights published = publishedLights(frame);
  const cv::Mat image =
      previewImage(*frame.polar, *published.lights, published.clustering, options_.style);
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", image, png)) {
    failed_ = true;
    return std::unexpected(SinkFailure{"preview: cannot encode frame " +
                                       std::to_string(frame.captured->seq) +
                                       " as PNG; no more previews are written"});
  }
  std::vector<std::filesystem::path> targets{latestPath()};
  if (options_.numbered) targets.push_back(numberedPath(frame.captured->seq));
  for (const std::filesystem::path& target : targets) {
    if (auto written = util::replaceFileAtomically(target, std::as_bytes(std::span(png)));
        !written) {
      failed_ = true;
      return std::unexpected(SinkFailure{"preview: cannot write " + target.string() + " (" +
                                         std::strerror(written.error().error) +
                                         "); no more previews are written"});
    }
  }
  ++images_;
  return {};
}

}  // namespace vem::vemd
