#include "vemd/sinks/preview_sink.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>

#include <opencv2/imgcodecs.hpp>

#include "frames/published_lights.h"
#include "recording/file_descriptor.h"

namespace vem::vemd {
namespace {

std::expected<void, std::string> writeAll(int fd, const std::vector<unsigned char>& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::unexpected(std::string(n < 0 ? std::strerror(errno) : "short write"));
    done += std::size_t(n);
  }
  return {};
}

}  // namespace

std::expected<void, std::string> replaceFileAtomically(const std::filesystem::path& path,
                                                       const std::vector<unsigned char>& bytes) {
  // Built by appending: GCC 12 at -O3 warns falsely (-Wrestrict) on "." + std::string + "...".
  std::string name = ".";
  name.append(path.filename().string()).append(".XXXXXX");
  std::string temp = (path.parent_path() / name).string();
  recording::FileDescriptor fd(::mkostemp(temp.data(), O_CLOEXEC));
  if (!fd.valid()) return std::unexpected(std::string(std::strerror(errno)));
  auto written = writeAll(fd.get(), bytes);
  if (written && ::fchmod(fd.get(), 0644) != 0) written = std::unexpected(std::strerror(errno));
  if (written && !fd.close()) written = std::unexpected(std::strerror(errno));
  if (written && ::rename(temp.c_str(), path.c_str()) != 0) {
    written = std::unexpected(std::strerror(errno));
  }
  if (!written) ::unlink(temp.c_str());
  return written;
}

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
  assert(frame.captured != nullptr && frame.polar != nullptr);  // the pipeline always sets them
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
    if (auto written = replaceFileAtomically(target, png); !written) {
      failed_ = true;
      return std::unexpected(SinkFailure{"preview: cannot write " + target.string() + " (" +
                                         written.error() + "); no more previews are written"});
    }
  }
  ++images_;
  return {};
}

}  // namespace vem::vemd
