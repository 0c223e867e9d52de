#include "vemd/sinks/jsonl_light_sink.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include "frames/published_lights.h"
#include "util/contract.h"
#include "util/write_all.h"
#include "vemd/sinks/light_json.h"

namespace vem::vemd {

nlohmann::ordered_json lightsLineJson(const ProcessedFrame& frame, std::uint64_t line) {
  const PublishedLights published = publishedLights(frame);
  const nlohmann::ordered_json lights =
      published.clustering ? clusteredFrameJson(*published.lights, *published.clustering, line)
                           : frameJson(*published.lights, line);
  nlohmann::ordered_json out;
  out["frame"] = line;
  out["seq"] = frame.captured->seq;
  out["capture_ts_ns"] = frame.captured->captureTsNs;
  out["filtered"] = published.filtered;
  if (published.filtered) out["filtered_seq"] = published.lightsSeq;
  for (const auto& [key, value] : lights.items()) {
    if (key != "frame") out[key] = value;
  }
  return out;
}

std::expected<JsonlLightSink, SinkFailure> JsonlLightSink::open(
    const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) {
    return std::unexpected(SinkFailure{"jsonl: cannot open " + path.string() + " for appending (" +
                                       std::strerror(errno) + ")"});
  }
  return JsonlLightSink(path, util::UniqueFd(fd));
}

JsonlLightSink::JsonlLightSink(std::filesystem::path path, util::UniqueFd fd)
    : path_(std::move(path)), fd_(std::move(fd)) {}

std::expected<void, SinkFailure> JsonlLightSink::consume(const ProcessedFrame& frame) {
  VEM_EXPECTS(frame.captured != nullptr);  // the pipeline always sets it
  if (failed_) return {};
  const std::string text = lightsLineJson(frame, lines_).dump() + '\n';
  if (auto done = util::writeAll(fd_.get(), std::as_bytes(std::span(text))); !done) {
    // Cut the partial line off again (regular files only; best effort) so the file stays lines.
    const std::size_t written = done.error().written;
    struct stat st {};
    if (written > 0 && ::fstat(fd_.get(), &st) == 0 && S_ISREG(st.st_mode)) {
      (void)::ftruncate(fd_.get(), st.st_size - off_t(written));
    }
    return std::unexpected(fail("cannot write line " + std::to_string(lines_), done.error().error));
  }
  ++lines_;
  return {};
}

std::expected<void, SinkFailure> JsonlLightSink::close() {
  if (failed_ || !fd_.valid()) return {};
  if (!fd_.close()) {
    failed_ = true;
    return std::unexpected(SinkFailure{"jsonl: " + path_.string() + ": cannot close the file (" +
                                       std::strerror(errno) + ")"});
  }
  return {};
}

SinkFailure JsonlLightSink::fail(const std::string& what, int error) {
  failed_ = true;
  (void)fd_.close();
  return SinkFailure{"jsonl: " + path_.string() + ": " + what + " (" + std::strerror(error) +
                     "); the " + std::to_string(lines_) +
                     " lines before it stay readable and no more are written"};
}

}  // namespace vem::vemd
